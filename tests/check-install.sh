#!/usr/bin/env bash
# make install into a scratch prefix, then build and run a small program
# against the installed copy with `pkg-config --cflags --libs pfmath`.
set -u
root=$(pwd)
build=${1:-build}
case "$build" in */asan) echo "sanitizer build: the install test runs in the plain build only"; echo "[  SKIPPED ] 1 test(s)."; exit 0;; esac
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "[  FAILED  ] $1"; echo "[  FAILED  ] 1 test(s), listed above"; exit 1; }
make -s -C "$root" BUILD="$build" install PREFIX="$tmp/prefix" >"$tmp/install.log" 2>&1 || fail "make install: $(tail -1 "$tmp/install.log")"
[ -f "$tmp/prefix/lib/libpfmath.so.0" ] && [ -L "$tmp/prefix/lib/libpfmath.so" ] || fail "shared library or symlink missing"
soname=$(objdump -p "$tmp/prefix/lib/libpfmath.so.0" | awk '/SONAME/ {print $2}')
[ "$soname" = "libpfmath.so.0" ] || fail "soname is '$soname'"
cat > "$tmp/use.c" <<'C'
#include <math.h>
#include <pfmath.h>
#include <stdio.h>
int main(void)
{
    float x[4] = {1.0f, 2.0f, 0.5f, 10.0f}, y[4];
    pf_logf_array(x, y, 4);
    for (int i = 0; i < 4; i++)
        if (fabsf(y[i] - logf(x[i])) > 2e-7f * fabsf(logf(x[i])) || pf_logf(x[i]) != y[i]) {
            printf("bad log(%g) = %a\n", x[i], y[i]);
            return 1;
        }
    puts("ok");
    return 0;
}
C
export PKG_CONFIG_PATH="$tmp/prefix/lib/pkgconfig"
flags=$(pkg-config --cflags --libs pfmath) || fail "pkg-config does not know pfmath"
${CC:-cc} -std=c11 -Wall -Werror "$tmp/use.c" -o "$tmp/use" $flags -lm || fail "cannot build against the installed copy"
out=$(LD_LIBRARY_PATH="$tmp/prefix/lib" "$tmp/use") || fail "installed program failed: $out"
ldd "$tmp/use" | grep -q "$tmp/prefix/lib/libpfmath.so.0" 2>/dev/null || LD_LIBRARY_PATH="$tmp/prefix/lib" ldd "$tmp/use" | grep -q "$tmp/prefix/lib/libpfmath.so.0" || fail "not linked against the installed libpfmath.so.0"
# the programs, run from the installed copy only: a scratch working
# directory, a PATH without the build tree, and a library path for the
# installed libpfmath.so.0 only
bin="$tmp/prefix/bin"
[ -x "$bin/pfmathgen" ] && [ -x "$bin/pfsweep" ] || fail "pfmathgen or pfsweep not installed in PREFIX/bin"
mkdir "$tmp/work"
( cd "$tmp/work" && env PATH="$bin:/usr/bin:/bin" CC="${CC:-cc}" pfmathgen --func exp --variant fast -o e.c ) \
  >"$tmp/gen.log" 2>&1 || fail "installed pfmathgen failed: $(tail -1 "$tmp/gen.log")"
grep -q "Sweep:" "$tmp/work/e.c" || fail "installed pfmathgen did not compile and sweep its output"
# the installed pfsweep on the installed library (found by itself) and on the emitted C
( cd "$tmp/work" && env PATH="$bin:/usr/bin:/bin" pfsweep --func exp --variant fast --samples 1000 --max-ulp 1000 ) \
  >"$tmp/sweep.log" 2>&1 || fail "installed pfsweep on the installed library: $(tail -1 "$tmp/sweep.log")"
grep -q "^TOTAL pf_expf_fast" "$tmp/sweep.log" || fail "installed pfsweep printed no TOTAL line"
( cd "$tmp/work" && env PATH="$bin:/usr/bin:/bin" CC="${CC:-cc}" pfsweep --func exp --variant fast --source e.c --samples 1000 ) \
  >"$tmp/sweep2.log" 2>&1 || fail "installed pfsweep --source: $(tail -1 "$tmp/sweep2.log")"
echo "[       OK ] install, pkg-config ($flags), soname $soname; installed pfmathgen and pfsweep run"
echo "[  PASSED  ] 1 test(s)."
