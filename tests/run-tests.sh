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

# Start order: the longest programs first, so that two long ones do not end
# up as the run's tail on a 2-core machine (a long program started last keeps
# one core busy after everything else is done).  weight: CPU seconds of the
# program on the 2-core Zen 3 of 2026-12-07 (the ladder tests: 2026-12-08,
# after the fit cache; /usr/bin/time, user + sys;
# "asan/": the copy in the sanitizer build); a program not listed counts 5 s.
# Only the start order depends on this table; outputs are printed in the
# order given, as before, and a wrong or stale weight only costs time.
weight() {
  local k=${1##*/}
  case $1 in */asan/*) k=asan/$k ;; esac
  case $k in
    asan/test_ladder_atrig) echo 30 ;;
    test_ladder_atrig) echo 28 ;;
    test_fixed_hash) echo 56 ;;
    test_fixedgen_funcs) echo 56 ;;
    asan/test_ladder_trig) echo 31 ;;
    asan/test_fixedgen) echo 48 ;;
    check-regen-fixed) echo 34 ;;
    asan/test_ref) echo 33 ;;
    asan/test_trig) echo 32 ;;
    test_ladder_trig) echo 23 ;;
    asan/test_noisegen) echo 31 ;;
    asan/test_fixedgen_funcs) echo 30 ;;
    test_fixedgen) echo 30 ;;
    test_noisegen) echo 30 ;;
    asan/test_scene) echo 29 ;;
    asan/test_fit) echo 27 ;;
    asan/test_sollya) echo 27 ;;
    test_fit) echo 26 ;;
    asan/test_ladder_log) echo 20 ;;
    asan/check-regen) echo 22 ;;
    test_trig) echo 21 ;;
    asan/test_exp) echo 20 ;;
    asan/test_ladder) echo 10 ;;
    test_scene) echo 20 ;;
    test_ladder_log) echo 16 ;;
    check-readme-examples) echo 19 ;;
    check-doc-links) echo 0 ;;
    asan/check-regen-fixed) echo 18 ;;
    test_sollya) echo 18 ;;
    check-regen) echo 16 ;;
    asan/test_atrig) echo 15 ;;
    check-vectorize) echo 15 ;;
    test_ref) echo 13 ;;
    asan/test_gen_fuzz) echo 12 ;;
    test_exp) echo 12 ;;
    asan/test_cli) echo 11 ;;
    asan/test_noise_spectrum) echo 11 ;;
    test_gen_fuzz) echo 11 ;;
    asan/test_log) echo 10 ;;
    asan/test_tools_cli) echo 10 ;;
    test_atrig) echo 10 ;;
    test_ladder) echo 7 ;;
    test_cli) echo 8 ;;
    test_log) echo 6 ;;
    test_noise_spectrum) echo 6 ;;
    asan/test_hostile) echo 5 ;;
    asan/test_bitwidth) echo 4 ;;
    asan/test_pffixed_portable) echo 4 ;;
    test_hostile) echo 4 ;;
    test_tools_cli) echo 4 ;;
    asan/test_noise) echo 3 ;;
    asan/test_noise_fixed) echo 3 ;;
    asan/test_pffixed) echo 3 ;;
    asan/test_clones) echo 2 ;;
    asan/test_fixed_lib) echo 2 ;;
    asan/test_noise_fbm) echo 2 ;;
    asan/test_noise_fixed_fast) echo 2 ;;
    check-install) echo 2 ;;
    test_bitwidth) echo 2 ;;
    test_pffixed) echo 2 ;;
    test_pffixed_portable) echo 2 ;;
    asan/test_bench) echo 1 ;;
    asan/test_noise_scalar) echo 1 ;;
    test_clones) echo 1 ;;
    test_fixed_lib) echo 1 ;;
    test_fx_bw_emul) echo 1 ;;
    test_noise) echo 1 ;;
    test_noise_fbm) echo 1 ;;
    test_noise_fixed) echo 1 ;;
    test_noise_fixed_fast) echo 1 ;;
    asan/check-install) echo 0 ;;
    asan/check-readme-examples) echo 0 ;;
    asan/test_fixedtype) echo 0 ;;
    asan/test_funcset) echo 0 ;;
    asan/test_noise_ctor) echo 0 ;;
    asan/test_special) echo 0 ;;
    test_bench) echo 0 ;;
    test_fixedtype) echo 0 ;;
    test_funcset) echo 0 ;;
    test_noise_ctor) echo 0 ;;
    test_noise_scalar) echo 0 ;;
    test_special) echo 0 ;;
    *) echo 5 ;;
  esac
}
order=$(for i in "${!progs[@]}"; do echo "$(weight "${progs[$i]}") $i"; done | sort -s -k1,1nr | cut -d' ' -f2)

running=0
for i in $order; do
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
