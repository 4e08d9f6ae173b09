/* tests/simde_fill.h: SIMDe's portable AVX-512 (libsimde-dev), completed
 * with the intrinsics the generated 16-bit loops use and SIMDe 0.7.4 lacks
 * or computes otherwise than the hardware, for test_fx_bw_emul (each
 * transformed file, tests/emul.sed, is compiled with -include of this).
 *
 * Each fill is plain C over the lanes with Intel's semantics (one line
 * each below), named pf_emu_mm512_*; the SIMDe name is #undef'd and
 * #defined to it, so a newer SIMDe that has its own (function or macro)
 * neither clashes nor is used: the loops always run these, and
 * test_fx_bw_emul checks these against the native AVX2 instruction on both
 * 256-bit halves (or against the definition where AVX2 has none).
 *
 * vrsqrt14ps is an approximation (relative error < 2^-14, exact bits
 * unspecified), so its fill is adversarial: pf_emu_rsqrt14_mode picks
 * which in-spec answer it gives (PF_EMU_RSQRT14_*), and a loop that uses
 * it must give the same bits under every mode. */
#ifndef PF_SIMDE_FILL_H
#define PF_SIMDE_FILL_H

/* the transformed files include <immintrin.h> for their (native) AVX2
   loops; here, so that the precompiled header mk/emul.mk makes of this
   file holds it too (it is most of their parsing time) */
#include <immintrin.h>
#include <simde/x86/avx512.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

/* the lanes of a 512-bit vector as arrays (memcpy: no aliasing questions) */
typedef union { uint16_t u16[32]; int16_t i16[32]; uint32_t u32[16]; int32_t i32[16]; float f32[16]; } pf_emu_v512;
static inline pf_emu_v512 pf_emu_in(simde__m512i a) { pf_emu_v512 v; memcpy(&v, &a, 64); return v; }
static inline pf_emu_v512 pf_emu_inf(simde__m512 a) { pf_emu_v512 v; memcpy(&v, &a, 64); return v; }
static inline simde__m512i pf_emu_out(pf_emu_v512 v) { simde__m512i a; memcpy(&a, &v, 64); return a; }
static inline simde__m512 pf_emu_outf(pf_emu_v512 v) { simde__m512 a; memcpy(&a, &v, 64); return a; }

/* vpcmpuw (gt): bit i of the mask = a[i] > b[i], words as unsigned */
static inline simde__mmask32 pf_emu_mm512_cmpgt_epu16_mask(simde__m512i a, simde__m512i b)
{
    pf_emu_v512 x = pf_emu_in(a), y = pf_emu_in(b);
    uint32_t m = 0;
    for (int i = 0; i < 32; i++)
        m |= (uint32_t)(x.u16[i] > y.u16[i]) << i;
    return m;
}

/* vpcmpuw (lt): bit i of the mask = a[i] < b[i], words as unsigned */
static inline simde__mmask32 pf_emu_mm512_cmplt_epu16_mask(simde__m512i a, simde__m512i b)
{
    return pf_emu_mm512_cmpgt_epu16_mask(b, a);
}

/* vpmovdw: each 32-bit lane truncated to its low 16 bits (no saturation), 16 words */
static inline simde__m256i pf_emu_mm512_cvtepi32_epi16(simde__m512i a)
{
    pf_emu_v512 x = pf_emu_in(a);
    uint16_t d[16];
    for (int i = 0; i < 16; i++)
        d[i] = (uint16_t)x.u32[i];
    simde__m256i r;
    memcpy(&r, d, 32);
    return r;
}

/* vcvttps2dq: float to int32 toward zero; NaN, +-inf and anything outside
   [-2^31, 2^31) give 0x80000000 (the "integer indefinite") */
static inline simde__m512i pf_emu_mm512_cvttps_epi32(simde__m512 a)
{
    pf_emu_v512 x = pf_emu_inf(a), r;
    for (int i = 0; i < 16; i++) {
        float f = x.f32[i];
        r.i32[i] = (f >= -0x1p31f && f < 0x1p31f) ? (int32_t)f : INT32_MIN; /* NaN fails both */
    }
    return pf_emu_out(r);
}

/* vplzcntd: leading zeros of each 32-bit lane, 32 for 0 */
static inline simde__m512i pf_emu_mm512_lzcnt_epi32(simde__m512i a)
{
    pf_emu_v512 x = pf_emu_in(a), r;
    for (int i = 0; i < 16; i++)
        r.u32[i] = x.u32[i] ? (uint32_t)__builtin_clz(x.u32[i]) : 32u;
    return pf_emu_out(r);
}

/* vpsubw with merge mask: word i = a[i] - b[i] (mod 2^16) where bit i of k is set, else src[i] */
static inline simde__m512i pf_emu_mm512_mask_sub_epi16(simde__m512i src, simde__mmask32 k, simde__m512i a, simde__m512i b)
{
    pf_emu_v512 s = pf_emu_in(src), x = pf_emu_in(a), y = pf_emu_in(b);
    for (int i = 0; i < 32; i++)
        if ((k >> i) & 1)
            s.u16[i] = (uint16_t)(x.u16[i] - y.u16[i]);
    return pf_emu_out(s);
}

/* vpmulhuw: the high 16 bits of the unsigned 32-bit product of each pair of words */
static inline simde__m512i pf_emu_mm512_mulhi_epu16(simde__m512i a, simde__m512i b)
{
    pf_emu_v512 x = pf_emu_in(a), y = pf_emu_in(b);
    for (int i = 0; i < 32; i++)
        x.u16[i] = (uint16_t)(((uint32_t)x.u16[i] * y.u16[i]) >> 16);
    return pf_emu_out(x);
}

/* vfnmadd: -(a b) + c with ONE rounding (fmaf).  SIMDe 0.7.4 computes
   -(a * b) + c in C, two roundings, unless the build has FMA natively */
static inline simde__m512 pf_emu_mm512_fnmadd_ps(simde__m512 a, simde__m512 b, simde__m512 c)
{
    pf_emu_v512 x = pf_emu_inf(a), y = pf_emu_inf(b), z = pf_emu_inf(c);
    for (int i = 0; i < 16; i++)
        x.f32[i] = fmaf(-x.f32[i], y.f32[i], z.f32[i]);
    return pf_emu_outf(x);
}

/* vrsqrt14ps: an approximation r of 1/sqrt(a) with |r sqrt(a) - 1| < 2^-14;
   +0 -> +inf, -0 -> -inf, +inf -> +0, a < 0 -> NaN, NaN -> NaN.  Which r
   within the bound the hardware gives is not specified, so the test picks:
     NEAR   1/sqrt(a) rounded to the nearest float
     TRUNC  1/sqrt(a) truncated to 14 fraction bits (toward zero; below by
            up to one 2^-14 step)
     HIGH   1/sqrt(a) (1 + 2^-14 - 2^-20) rounded up (as far above as the
            bound allows, nearly)
     LOW    1/sqrt(a) (1 - 2^-14 + 2^-20) rounded down (as far below)
   The reference 1/sqrt(a) is in long double (64-bit significand). */
enum { PF_EMU_RSQRT14_NEAR, PF_EMU_RSQRT14_TRUNC, PF_EMU_RSQRT14_HIGH, PF_EMU_RSQRT14_LOW, PF_EMU_RSQRT14_MODES };
extern int pf_emu_rsqrt14_mode;             /* defined by the test program */
extern unsigned long pf_emu_rsqrt14_calls;  /* counts calls: which loops use it */

static inline float pf_emu_rsqrt14_1(float a, int mode)
{
    if (a != a)
        return a + a; /* quiet NaN */
    if (a == 0.0f)
        return copysignf(INFINITY, a);
    if (a < 0.0f)
        return NAN;
    if (a == INFINITY)
        return 0.0f;
    long double e = 1.0L / sqrtl((long double)a);
    float r;
    switch (mode) {
    case PF_EMU_RSQRT14_TRUNC: {
        int ex;
        long double m = frexpl(e, &ex); /* e = m 2^ex, m in [1/2, 1): 15 significant bits = 14 fraction bits */
        r = (float)ldexpl(floorl(ldexpl(m, 15)), ex - 15);
        break;
    }
    case PF_EMU_RSQRT14_HIGH: {
        long double v = e * (1.0L + 0x1p-14L - 0x1p-20L);
        r = (float)v;
        if ((long double)r < v)
            r = nextafterf(r, INFINITY);
        break;
    }
    case PF_EMU_RSQRT14_LOW: {
        long double v = e * (1.0L - 0x1p-14L + 0x1p-20L);
        r = (float)v;
        if ((long double)r > v)
            r = nextafterf(r, 0.0f);
        break;
    }
    default:
        r = (float)e;
        break;
    }
    return r;
}

static inline simde__m512 pf_emu_mm512_rsqrt14_ps(simde__m512 a)
{
    pf_emu_v512 x = pf_emu_inf(a);
    pf_emu_rsqrt14_calls++;
    for (int i = 0; i < 16; i++)
        x.f32[i] = pf_emu_rsqrt14_1(x.f32[i], pf_emu_rsqrt14_mode);
    return pf_emu_outf(x);
}

/* the loops (tests/emul.sed's output) call SIMDe's names: these */
#undef simde_mm512_cmpgt_epu16_mask
#define simde_mm512_cmpgt_epu16_mask pf_emu_mm512_cmpgt_epu16_mask
#undef simde_mm512_cmplt_epu16_mask
#define simde_mm512_cmplt_epu16_mask pf_emu_mm512_cmplt_epu16_mask
#undef simde_mm512_cvtepi32_epi16
#define simde_mm512_cvtepi32_epi16 pf_emu_mm512_cvtepi32_epi16
#undef simde_mm512_cvttps_epi32
#define simde_mm512_cvttps_epi32 pf_emu_mm512_cvttps_epi32
#undef simde_mm512_lzcnt_epi32
#define simde_mm512_lzcnt_epi32 pf_emu_mm512_lzcnt_epi32
#undef simde_mm512_mask_sub_epi16
#define simde_mm512_mask_sub_epi16 pf_emu_mm512_mask_sub_epi16
#undef simde_mm512_mulhi_epu16
#define simde_mm512_mulhi_epu16 pf_emu_mm512_mulhi_epu16
#undef simde_mm512_fnmadd_ps
#define simde_mm512_fnmadd_ps pf_emu_mm512_fnmadd_ps
#undef simde_mm512_rsqrt14_ps
#define simde_mm512_rsqrt14_ps pf_emu_mm512_rsqrt14_ps

#endif
