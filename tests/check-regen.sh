#!/usr/bin/env bash
# Regenerates every library source in a scratch tree with the same commands
# and checks the committed files are byte-identical (generation is
# deterministic and nothing in libpfmath/generated/ was edited by hand).
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
[ -d "$root/libpfmath/generated" ] || root=$(pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/libpfmath/generated"
pass=0; fail=0
for fv in @LIBGEN@; do
  f=${fv%%:*}; v=${fv##*:}; s=""; [ "$v" = fast ] && s=_fast
  out=libpfmath/generated/pf_${f}f$s.c
  (cd "$tmp" && @PFMATHGEN@ --func "$f" --variant "$v" -o "$out" 2>/dev/null)
  if cmp -s "$tmp/$out" "$root/$out"; then pass=$((pass+1)); echo "[       OK ] $out is current"
  else fail=$((fail+1)); echo "[  FAILED  ] $out differs from a fresh pfmathgen run (make regen)"; fi
done
echo "[  PASSED  ] $pass test(s)."
[ $fail -eq 0 ] || echo "[  FAILED  ] $fail test(s), listed above"
[ $fail -eq 0 ]
