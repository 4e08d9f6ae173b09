#!/usr/bin/env bash
# The library's fixed-point sources (libpfmath/generated/pf_fx_*.c) are what
# pfmathgen writes today: each is regenerated in a scratch tree with the
# command `make regen-fixed` uses (and its provenance records), and compared
# byte for byte.  Each function's declarations must be in pfmath_fixed.h.
# Under the sanitizers (an asan pfmathgen, slow) only sin, exp and log's
# exact 16-bit files are redone: the point there is pfmathgen's sanitizer run.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
[ -d "$root/libpfmath/generated" ] || root=$(pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/libpfmath/generated"
gen=@PFMATHGEN@
pass=0; fail=0
for e in @FXLIB@; do
  n=${e%%/*}; r=${e#*/}; f=${r%%/*}; r=${r#*/}; in=${r%%/*}; out=${r#*/}
  variants="exact fast"
  case "$gen" in */asan/*) case "$n" in sin_q12_q14|exp_q11_uq8|log_uq8_q11) variants=exact;; *) continue;; esac;; esac
  for v in $variants; do
    s=""; [ $v = fast ] && s=_fast
    o=libpfmath/generated/pf_fx_$n$s.c
    if [ $v = fast ]; then
      (cd "$tmp" && "$gen" --func "$f" --type "$in" --out-type "$out" --variant fast -o "$o" 2>/dev/null)
    else
      (cd "$tmp" && "$gen" --func "$f" --type "$in" --out-type "$out" -o "$o" 2>/dev/null)
    fi
    if cmp -s "$tmp/$o" "$root/$o"; then
      pass=$((pass+1)); echo "[       OK ] $o is current"
    else
      fail=$((fail+1)); echo "[  FAILED  ] $o differs from a fresh pfmathgen run (make regen-fixed)"
    fi
    # the public declarations match the definitions
    sig=$(grep -m1 -E "^[a-z0-9_]+ pf_$n$s\(" "$root/$o" | sed 's/$/;/')
    asig=$(grep -m1 -E "^void pf_$n${s}_array\(" "$root/$o" | sed 's/$/;/')
    if [ -n "$sig" ] && grep -qF "$sig" "$root/libpfmath/pfmath_fixed.h" && grep -qF "$asig" "$root/libpfmath/pfmath_fixed.h"; then
      pass=$((pass+1)); echo "[       OK ] pfmath_fixed.h declares pf_$n$s"
    else
      fail=$((fail+1)); echo "[  FAILED  ] pfmath_fixed.h lacks '$sig' or '$asig'"
    fi
  done
done
echo "[  PASSED  ] $pass test(s)."
[ $fail -eq 0 ] || echo "[  FAILED  ] $fail test(s), listed above"
[ $fail -eq 0 ]
