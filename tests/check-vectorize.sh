#!/usr/bin/env bash
# Every array form in the library vectorizes: compile each generated source
# with -O3 -march=native -fopt-info-vec and require a vectorized loop in its
# _array function (GCC reports "loop vectorized" on the loop's line).
set -u
cd "$(dirname "$0")/../.." 2>/dev/null && [ -d libpfmath/generated ] || cd "$OLDPWD"
pass=0; fail=0
for f in libpfmath/generated/*.c; do
  line=$(grep -n '_array(' "$f" | head -1 | cut -d: -f1)
  # flags a file names on a "/* Build flags: -f... (" line (pf_asinf_fast.c: -fno-math-errno)
  extra=$(sed -n 's|^/\* Build flags: \(-[-a-z0-9= ]*\) (.*|\1|p' "$f" | head -1)
  out=$(${CC:-gcc} -std=c17 -O3 -march=native $extra -fopt-info-vec -c "$f" -o /dev/null 2>&1)
  # the loop sits a few lines below the array function's signature
  if printf '%s\n' "$out" | awk -F: -v l="$line" '$2 > l && /loop vectorized/ {ok=1} END {exit !ok}'; then
    pass=$((pass+1)); echo "[       OK ] $f: $(printf '%s\n' "$out" | grep -o 'using [0-9]* byte vectors' | sort -u | tr '\n' ' ')"
  else
    fail=$((fail+1)); echo "[  FAILED  ] $f: array loop not vectorized"
  fi
done
echo "[  PASSED  ] $pass test(s)."
[ $fail -eq 0 ] || echo "[  FAILED  ] $fail test(s), listed above"
[ $fail -eq 0 ]
