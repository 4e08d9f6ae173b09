#!/usr/bin/env bash
# Runs every pfmathgen and pfsweep example command of README.md, as written,
# with the programs of this build first in PATH, in a scratch copy of
# examples/ (so `-o out/`, `-o f.c` land there).  Each must exit 0.
# pfsweep --all examples (minutes: `make sweep` territory) are listed, not run.
# The ASan build skips this (same commands, several times slower).
set -u
bin=@BIN@
root=$(pwd)
[ -f "$root/README.md" ] || { echo "run from the repository root"; exit 1; }
case "$bin" in */asan*) echo "[  SKIPPED ] 1 test(s): README examples run in the plain build only"; exit 0;; esac
tmp=$(mktemp -d /tmp/pfreadme.XXXXXX); trap 'rm -rf "$tmp"' EXIT
cp -r "$root/examples" "$tmp/" && mkdir -p "$tmp/build"
pass=0; fail=0; skip=0
# indented README lines that call the programs (a quick-start line's
# "... && build/pfmathgen ..." tail counts too)
grep -E '^    .*\b(build/)?(pfmathgen|pfsweep) ' "$root/README.md" | sed -E 's/^.*&& //; s/^ +//' > "$tmp/cmds"
while IFS= read -r cmd; do
  case "$cmd" in
    *pfsweep*--all*) skip=$((skip+1)); echo "[  SKIPPED ] $cmd (exhaustive: make sweep)"; continue;;
  esac
  run=${cmd#build/}
  if (cd "$tmp" && PATH="$bin:$PATH" bash -c "$run" >/dev/null 2>"$tmp/err"); then
    pass=$((pass+1)); echo "[       OK ] $cmd"
  else
    fail=$((fail+1)); echo "[  FAILED  ] $cmd"; sed 's/^/    /' "$tmp/err" | tail -5
  fi
done < "$tmp/cmds"
[ $((pass+fail)) -gt 10 ] || { echo "[  FAILED  ] only $((pass+fail)) examples found in README.md"; fail=$((fail+1)); }
echo "[  PASSED  ] $pass test(s)."
[ $skip -eq 0 ] || echo "[  SKIPPED ] $skip test(s)."
[ $fail -eq 0 ] || echo "[  FAILED  ] $fail test(s), listed above"
[ $fail -eq 0 ]
