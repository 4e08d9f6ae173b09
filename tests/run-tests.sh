#!/usr/bin/env bash
# Runs each test program given as an argument; each is a cmocka program.
# Sums cmocka's per-program counts and ends with the line
# "N passed, N failed, N skipped".  A program that crashes or exits non-zero
# without a cmocka summary counts as one failure.
#
# The programs are independent (each works in its own per-process scratch
# names), so PF_TEST_JOBS of them (default: the number of online CPUs) run
# at once; their outputs are still printed whole and in the order given, as
# soon as every program before them has finished.
set -u
jobs_max=${PF_TEST_JOBS:-$(nproc 2>/dev/null || echo 1)}
case $jobs_max in '' | *[!0-9]* | 0) echo "run-tests.sh: PF_TEST_JOBS must be a positive integer" >&2; exit 2 ;; esac
tmp=$(mktemp -d "${TMPDIR:-/tmp}/pf-tests.XXXXXX") || exit 2
trap 'rm -rf -- "$tmp"' EXIT
trap 'exit 130' INT TERM

passed=0; failed=0; skipped=0
progs=("$@")
next=0 # the first program whose output is not printed yet

# prints, in order, the outputs of the programs that have finished
flush() {
  while [ "$next" -lt "${#progs[@]}" ] && [ -e "$tmp/$next.rc" ]; do
    local t=${progs[$next]} out rc p f s
    out=$(cat -- "$tmp/$next.out"); rc=$(cat -- "$tmp/$next.rc")
    echo "=== $t"
    printf '%s\n' "$out"
    p=$(printf '%s\n' "$out" | sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' | awk '{s+=$1} END {print s+0}')
    f=$(printf '%s\n' "$out" | sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' | awk '{s+=$1} END {print s+0}')
    s=$(printf '%s\n' "$out" | sed -n 's/^\[  SKIPPED \] \([0-9]*\) test.*/\1/p' | awk '{s+=$1} END {print s+0}')
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; echo "!!! $t exited with status $rc"; fi
    passed=$((passed+p)); failed=$((failed+f)); skipped=$((skipped+s))
    next=$((next+1))
  done
}

running=0
for i in "${!progs[@]}"; do
  while [ "$running" -ge "$jobs_max" ]; do
    wait -n; running=$((running-1)); flush
  done
  # the .rc file appears only once the output is complete (written, then
  # renamed); the subshell's own stderr (bash's "Segmentation fault") goes
  # after the program's output
  ( "${progs[$i]}" > "$tmp/$i.out" 2>&1; echo $? > "$tmp/$i.rc.part"; mv -- "$tmp/$i.rc.part" "$tmp/$i.rc" ) 2>> "$tmp/$i.out" &
  running=$((running+1))
done
while [ "$running" -gt 0 ]; do
  wait -n; running=$((running-1)); flush
done
flush

echo
echo "$passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
