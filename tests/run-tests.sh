#!/usr/bin/env bash
# Runs each test program given as an argument; each is a cmocka program.
# Sums cmocka's per-program counts and ends with the line
# "N passed, N failed, N skipped".  A program that crashes or exits non-zero
# without a cmocka summary counts as one failure.
set -u
passed=0; failed=0; skipped=0
for t in "$@"; do
  echo "=== $t"
  out=$("$t" 2>&1); rc=$?
  printf '%s\n' "$out"
  p=$(printf '%s\n' "$out" | sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' | awk '{s+=$1} END {print s+0}')
  f=$(printf '%s\n' "$out" | sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' | awk '{s+=$1} END {print s+0}')
  s=$(printf '%s\n' "$out" | sed -n 's/^\[  SKIPPED \] \([0-9]*\) test.*/\1/p' | awk '{s+=$1} END {print s+0}')
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; echo "!!! $t exited with status $rc"; fi
  passed=$((passed+p)); failed=$((failed+f)); skipped=$((skipped+s))
done
echo
echo "$passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
