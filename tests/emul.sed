# tests/emul.sed: turns a generated 16-bit function (libpfmath/generated/
# pf_fx_*.c) into a file whose AVX-512BW loop runs on any x86-64, through
# SIMDe's portable _mm512_* (tests/simde_fill.h is -include'd first); used
# by mk/emul.mk for test_fx_bw_emul.  Only the functions emitted for
# x86-64-v4 change: from their attribute line to the next line that is "}" alone,
# the v4 target is dropped (no AVX-512 code is generated) and every
# intrinsic and vector type gets SIMDe's name (_mm512_x -> simde_mm512_x,
# __m512i -> simde__m512i, __mmask32 -> simde__mmask32).  The AVX2 loops
# and the scalar form stay as they are (native AVX2, target attribute kept).
# The dispatch's target_clones line goes (one clone is enough here).
# mk/emul.mk refuses a result that still holds a v4 target or a native
# _mm512_ name (a v4 function in a form this script does not know).
/__attribute__((target("arch=x86-64-v4")/,/^}$/{
s/__attribute__((target("arch=x86-64-v4"), *noinline))/__attribute__((noinline))/
s/__attribute__((target("arch=x86-64-v4"))) *//
s/\b_mm\(512\|256\|\)_/simde&/g
s/\b__m\(128\|256\|512\)/simde&/g
s/\b__mmask/simde&/g
}
/^__attribute__((target_clones(/d
