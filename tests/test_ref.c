/* Tests for ref/: correctly rounded references and error measurement.
 *
 * Expected values come from mathematical facts (exact cases, Annex F tables,
 * identities such as sin(x) = x for tiny x) or from an independent MPFR
 * computation written here: the function evaluated at 300+ bits in MPFR's
 * widest exponent range, then rounded to binary32 by scaling to the float
 * ulp and rounding to an integer (ties to even), which shares nothing with
 * ref/'s exponent-range-and-subnormalize method or its glibc fast path.
 * PF_QUICK=1 in the environment cuts the random sample sizes by 10.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <float.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pfref.h"

#define REF_PREC 300

static int quick;

/* ---------------------------------------------------------------- helpers */

static uint32_t fb(float x) { uint32_t u; memcpy(&u, &x, 4); return u; }
static float bf(uint32_t u) { float x; memcpy(&x, &u, 4); return x; }
static int same(float a, float b) { return (isnan(a) && isnan(b)) || fb(a) == fb(b); }

static uint64_t rng = 0x9e3779b97f4a7c15ull;
static uint64_t rnd64(void)
{
    rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17;
    return rng;
}
static uint32_t rnd32(void) { return (uint32_t)(rnd64() >> 32); }
static double unif(double a, double b) { return a + (b - a) * (double)(rnd64() >> 11) * 0x1p-53; }

#define CHECK(cond, ...) do { if (!(cond)) fail_msg(__VA_ARGS__); } while (0)

/* The test's own dispatch, written independently of pfref_mpfr's. */
static void ref_exact2(pf_func f, mpfr_t y, const mpfr_t a, const mpfr_t b)
{
    switch (f) {
    case PF_LOG:   mpfr_log(y, a, MPFR_RNDN); break;
    case PF_LOG2:  mpfr_log2(y, a, MPFR_RNDN); break;
    case PF_EXP:   mpfr_exp(y, a, MPFR_RNDN); break;
    case PF_EXP2:  mpfr_exp2(y, a, MPFR_RNDN); break;
    case PF_SIN:   mpfr_sin(y, a, MPFR_RNDN); break;
    case PF_COS:   mpfr_cos(y, a, MPFR_RNDN); break;
    case PF_TAN:   mpfr_tan(y, a, MPFR_RNDN); break;
    case PF_ASIN:  mpfr_asin(y, a, MPFR_RNDN); break;
    case PF_ACOS:  mpfr_acos(y, a, MPFR_RNDN); break;
    case PF_ATAN:  mpfr_atan(y, a, MPFR_RNDN); break;
    case PF_ATAN2: mpfr_atan2(y, a, b, MPFR_RNDN); break;
    case PF_SQRT:  mpfr_sqrt(y, a, MPFR_RNDN); break;
    default:       fail_msg("bad function %d", (int)f);
    }
}

/* y (initialized by the caller) = f(x, x2), at y's precision. */
static void ref_exact(pf_func f, mpfr_t y, float x, float x2)
{
    mpfr_t a, b;
    mpfr_inits2(24, a, b, (mpfr_ptr)0);
    mpfr_set_flt(a, x, MPFR_RNDN);
    mpfr_set_flt(b, x2, MPFR_RNDN);
    ref_exact2(f, y, a, b);
    mpfr_clears(a, b, (mpfr_ptr)0);
}

/* floor(log2|y|) for the ulp of pfref.h: clamped to [-126, 127]. */
static long ref_k(const mpfr_t y)
{
    if (mpfr_zero_p(y))
        return -126;
    long k = (long)mpfr_get_exp(y) - 1;
    return k < -126 ? -126 : k > 127 ? 127 : k;
}

/* Round y to binary32, nearest-even, by scaling to the ulp and rint. */
static float ref_round(const mpfr_t y)
{
    if (mpfr_nan_p(y))
        return NAN;
    if (mpfr_inf_p(y))
        return mpfr_sgn(y) > 0 ? INFINITY : -INFINITY;
    if (mpfr_zero_p(y))
        return mpfr_signbit(y) ? -0.0f : 0.0f;
    if (mpfr_get_exp(y) > 129)
        return mpfr_sgn(y) > 0 ? INFINITY : -INFINITY;
    long k = ref_k(y);
    mpfr_t t;
    mpfr_init2(t, mpfr_get_prec(y) + 8);
    mpfr_mul_2si(t, y, 23 - k, MPFR_RNDN);
    mpfr_rint(t, t, MPFR_RNDN);                 /* ties to even */
    double n = mpfr_get_d(t, MPFR_RNDN);        /* |n| <= 2^24: exact */
    mpfr_clear(t);
    float r = ldexpf((float)n, (int)(k - 23));  /* exact, or inf at 2^128 */
    return r == 0 ? (mpfr_signbit(y) ? -0.0f : 0.0f) : r;
}

static float ref_cr(pf_func f, float x, float x2)
{
    mpfr_t y;
    mpfr_init2(y, REF_PREC);
    ref_exact(f, y, x, x2);
    float r = ref_round(y);
    mpfr_clear(y);
    return r;
}

/* |got - y| / ulp(y), plain distance, for finite got and y. */
static double ref_ulp(const mpfr_t y, float got)
{
    mpfr_t t;
    mpfr_init2(t, mpfr_get_prec(y) + 32);
    mpfr_set_flt(t, got, MPFR_RNDN);
    mpfr_sub(t, t, y, MPFR_RNDN);
    mpfr_mul_2si(t, t, 23 - ref_k(y), MPFR_RNDN);
    double e = fabs(mpfr_get_d(t, MPFR_RNDN));
    mpfr_clear(t);
    return e;
}

/* Distance of y from the nearest binary32 midpoint, in ulps of y. */
static double ref_middist(const mpfr_t y)
{
    mpfr_t t;
    mpfr_init2(t, mpfr_get_prec(y) + 8);
    mpfr_mul_2si(t, y, 23 - ref_k(y), MPFR_RNDN);
    mpfr_frac(t, t, MPFR_RNDN);
    double d = fabs(fabs(mpfr_get_d(t, MPFR_RNDN)) - 0.5);
    mpfr_clear(t);
    return d;
}

/* A random float: half arbitrary bit patterns, half the function's
   interesting range. */
static float rnd_arg(pf_func f, int which)
{
    if (rnd32() & 1)
        return bf(rnd32());
    switch (f) {
    case PF_LOG: case PF_LOG2: case PF_SQRT:
        if (rnd32() & 1)
            return (float)unif(0.9, 1.1);
        return bf(rnd32() & 0x7fffffffu);
    case PF_EXP:  return (float)unif(-105, 90);
    case PF_EXP2: return (float)unif(-151, 129);
    case PF_SIN: case PF_COS: case PF_TAN:
        return (float)ldexp(unif(-1, 1), (int)(rnd32() % 40) - 8);
    case PF_ASIN: case PF_ACOS:
        return (rnd32() & 1) ? (float)unif(-1, 1) : copysignf(1.0f - (float)ldexp(unif(0, 1), -(int)(rnd32() % 24)), (float)unif(-1, 1));
    case PF_ATAN2:
        return (float)ldexp(unif(-1, 1), (int)(rnd32() % 60) - 30 + 10 * which);
    default:
        return (float)ldexp(unif(-1, 1), (int)(rnd32() % 80) - 40);
    }
}

static long nrand(long n) { return quick ? n / 10 : n; }

/* ------------------------------------------------ consistency with MPFR */

/* Everything ref/ says about f at (x, x2) against the test's own MPFR
   computation: pfref_f_fast, pfref_is_cr, pfref_ulp_err(_raw) for the
   correctly rounded result, its neighbours and a farther value, and
   pfref_exact_d within 1 double-ulp.  check_f also runs the slow pfref_f. */
static void check_point(pf_func f, float x, float x2, int check_f)
{
    const char *nm = pfref_name(f);
    mpfr_t y;
    mpfr_init2(y, REF_PREC);
    ref_exact(f, y, x, x2);
    float c = ref_round(y);

    CHECK(same(pfref_f_fast(f, x, x2), c), "%s(%a, %a): f_fast %a, want %a", nm, x, x2,
          pfref_f_fast(f, x, x2), c);
    if (check_f)
        CHECK(same(pfref_f(f, x, x2), c), "%s(%a, %a): pfref_f %a, want %a", nm, x, x2,
              pfref_f(f, x, x2), c);
    CHECK(pfref_is_cr(f, c, x, x2) == 1, "%s(%a, %a): is_cr(%a) != 1", nm, x, x2, c);
    CHECK(pfref_ulp_err(f, c, x, x2) == 0.0, "%s(%a, %a): ulp_err(cr) = %g", nm, x, x2,
          pfref_ulp_err(f, c, x, x2));

    if (isnan(c)) {
        int crf = -1;
        CHECK(pfref_ulp_err_cr(f, NAN, x, x2, &crf) == 0 && crf == 1, "%s(%a, %a): err_cr NaN", nm, x, x2);
        CHECK(pfref_ulp_err(f, 1.0f, x, x2) == INFINITY, "%s(%a, %a): NaN vs 1", nm, x, x2);
        CHECK(pfref_is_cr(f, 1.0f, x, x2) == 0, "%s(%a, %a): is_cr(1) for NaN", nm, x, x2);
        mpfr_clear(y);
        return;
    }
    CHECK(pfref_ulp_err(f, NAN, x, x2) == INFINITY, "%s(%a, %a): NaN got", nm, x, x2);

    /* Neighbours and a farther value. */
    float up = nextafterf(c, INFINITY), dn = nextafterf(c, -INFINITY);
    int32_t k = (int32_t)(rnd32() % 2000) - 1000;
    float far = bf(fb(c) + (uint32_t)k);
    float gots[3] = { up, dn, far };
    for (int i = 0; i < 3; i++) {
        float g = gots[i];
        if (same(g, c) || isnan(g))
            continue;
        CHECK(pfref_is_cr(f, g, x, x2) == 0, "%s(%a, %a): is_cr(%a) = 1, cr %a", nm, x, x2, g, c);
        double e = pfref_ulp_err(f, g, x, x2), er = pfref_ulp_err_raw(f, g, x, x2);
        int crf = -1;
        double ecr = pfref_ulp_err_cr(f, g, x, x2, &crf);
        CHECK(e == er && ecr == er && crf == 0, "%s(%a, %a): err %g, raw %g, err_cr %g (cr %d) for non-cr %a",
              nm, x, x2, e, er, ecr, crf, g);
        if (isinf(g) || isinf(c) || (g == 0 && c == 0)) {
            CHECK(e == INFINITY, "%s(%a, %a): got %a cr %a: err %g, want inf", nm, x, x2, g, c, e);
            continue;
        }
        double want = ref_ulp(y, g);
        CHECK(e >= 0.5, "%s(%a, %a): non-cr %a has err %.9g < 0.5", nm, x, x2, g, e);
        CHECK(fabs(e - want) <= 1e-6 + 1e-9 * want, "%s(%a, %a): err(%a) = %.12g, want %.12g",
              nm, x, x2, g, e, want);
        /* Near the thresholds 0.5 and 1 the error is computed by MPFR. */
        if (fabs(want - 0.5) < 0x1p-17 || fabs(want - 1) < 0x1p-17)
            CHECK(fabs(e - want) <= 1e-14, "%s(%a, %a): err(%a) = %.17g, want %.17g (exact)",
                  nm, x, x2, g, e, want);
    }
    if (isfinite(c)) {
        double want = ref_ulp(y, c), er = pfref_ulp_err_raw(f, c, x, x2);
        int crf = -1;
        CHECK(pfref_ulp_err_cr(f, c, x, x2, &crf) == er && crf == 1, "%s(%a, %a): ulp_err_cr(cr)",
              nm, x, x2);
        CHECK(want <= 0.5 && fabs(er - want) <= 1e-6, "%s(%a, %a): raw err(cr %a) = %.12g, want %.12g",
              nm, x, x2, c, er, want);
        /* With the exact value between c and n1 and everything in one
           binade: err(n1) = 1 - err(c), err(n2) = 1 + err(c). */
        int cmp = mpfr_cmp_d(y, (double)c);
        if (cmp != 0 && isfinite(up) && isfinite(dn) && fabsf(c) >= FLT_MIN) {
            float n1 = cmp > 0 ? up : dn, n2 = cmp > 0 ? dn : up;
            int e1, e2, ec;
            frexpf(n1, &e1); frexpf(n2, &e2); frexpf(c, &ec);
            if (e1 == ec && e2 == ec && ec - 1 == ref_k(y) && n1 != 0 && n2 != 0) {
                double r1 = pfref_ulp_err_raw(f, n1, x, x2), r2 = pfref_ulp_err_raw(f, n2, x, x2);
                CHECK(r1 >= 0.5 && r1 <= 1 && fabs(r1 + er - 1) <= 1e-6,
                      "%s(%a, %a): err(n1) %.9g + err(c) %.9g != 1", nm, x, x2, r1, er);
                CHECK(r2 >= 1 && r2 <= 1.5 && fabs(r2 - er - 1) <= 1e-6,
                      "%s(%a, %a): err(n2) %.9g - err(c) %.9g != 1", nm, x, x2, r2, er);
            }
        }
    }

    /* pfref_exact_d: within 1 double-ulp (2^(exp-53)) of the exact value. */
    if (mpfr_number_p(y) && !mpfr_zero_p(y) && mpfr_get_exp(y) < 1024 && mpfr_get_exp(y) > -1021) {
        double d = pfref_exact_d(f, x, x2);
        mpfr_t t;
        mpfr_init2(t, REF_PREC);
        mpfr_sub_d(t, y, d, MPFR_RNDN);
        mpfr_mul_2si(t, t, 53 - mpfr_get_exp(y), MPFR_RNDN);
        double ed = fabs(mpfr_get_d(t, MPFR_RNDN));
        mpfr_clear(t);
        CHECK(ed <= 1.0, "%s(%a, %a): exact_d %a off by %g double-ulps", nm, x, x2, d, ed);
    }
    mpfr_clear(y);
}

static void test_random_vs_mpfr(void **state)
{
    (void)state;
    long n = nrand(100000);
    for (int f = 0; f < PF_NFUNCS; f++)
        for (long i = 0; i < n; i++) {
            float x = rnd_arg(f, 0), x2 = rnd_arg(f, 1);
            check_point(f, x, x2, i % 16 == 0);
        }
}

/* Inputs whose exact result lies within 2^-20 ulp of a midpoint between two
   floats, so the fast path must hand over to MPFR.  Found by scanning float
   ranges for a double estimate within 2^-22 ulp of a midpoint; only the
   inputs are listed, and test_hard_cases re-checks their hardness. */
static const struct { pf_func f; float x, x2; } hard[] = {
    { PF_LOG, 0x1.5c1bd8p-122f, 0.0f },
    { PF_LOG, 0x1.0286c8p-116f, 0.0f },
    { PF_LOG, 0x1.ae89p-76f, 0.0f },
    { PF_LOG, 0x1.1cb978p-75f, 0.0f },
    { PF_LOG, 0x1.fffffcp-1f, 0.0f },
    { PF_LOG2, 0x1.22952p-127f, 0.0f },
    { PF_LOG2, 0x1.d7012p-122f, 0.0f },
    { PF_LOG2, 0x1.22952p-121f, 0.0f },
    { PF_LOG2, 0x1.bf3588p-120f, 0.0f },
    { PF_LOG2, 0x1.fc64e8p-1f, 0.0f },
    { PF_EXP, -0x1.65cf3p+6f, 0.0f },
    { PF_EXP, -0x1.5800a4p+6f, 0.0f },
    { PF_EXP, -0x1.5768a8p+6f, 0.0f },
    { PF_EXP, -0x1.6dc968p+5f, 0.0f },
    { PF_EXP, 0x1.3f024ap-10f, 0.0f },
    { PF_EXP, 0x1.01753ap-9f, 0.0f },
    { PF_EXP, 0x1.6438b6p-8f, 0.0f },
    { PF_EXP, 0x1.707136p-6f, 0.0f },
    { PF_EXP2, -0x1.e65b1cp+3f, 0.0f },
    { PF_EXP2, -0x1.c65b1cp+3f, 0.0f },
    { PF_EXP2, -0x1.a65b1cp+3f, 0.0f },
    { PF_EXP2, -0x1.865b1cp+3f, 0.0f },
    { PF_EXP2, 0x1.632a1ap-10f, 0.0f },
    { PF_EXP2, 0x1.853a6ep-9f, 0.0f },
    { PF_EXP2, 0x1.ed13d2p-8f, 0.0f },
    { PF_EXP2, 0x1.05535ap-7f, 0.0f },
    { PF_SIN, 0x1.61246ep-10f, 0.0f },
    { PF_SIN, 0x1.dcfea2p-9f, 0.0f },
    { PF_SIN, 0x1.59a062p-8f, 0.0f },
    { PF_SIN, 0x1.e57bf6p-8f, 0.0f },
    { PF_SIN, -0x1.0caa34p+82f, 0.0f },
    { PF_SIN, -0x1.821474p+81f, 0.0f },
    { PF_COS, 0x1.645642p-10f, 0.0f },
    { PF_COS, 0x1.d1ed56p-10f, 0.0f },
    { PF_COS, 0x1.41989ap-9f, 0.0f },
    { PF_COS, 0x1.79464ap-9f, 0.0f },
    { PF_COS, 0x1.cece7cp+19f, 0.0f },
    { PF_COS, 0x1.bd0d8cp+23f, 0.0f },
    { PF_TAN, 0x1.c8dad2p-8f, 0.0f },
    { PF_TAN, 0x1.db3dcep-5f, 0.0f },
    { PF_TAN, 0x1.0ed7c6p-4f, 0.0f },
    { PF_TAN, 0x1.76cf86p-4f, 0.0f },
    { PF_ASIN, -0x1.107434p-1f, 0.0f },
    { PF_ASIN, -0x1.e5af18p-2f, 0.0f },
    { PF_ASIN, -0x1.ba793ap-2f, 0.0f },
    { PF_ASIN, -0x1.9b7b4p-2f, 0.0f },
    { PF_ASIN, 0x1.d12eccp-12f, 0.0f },
    { PF_ASIN, 0x1.d12ecep-12f, 0.0f },
    { PF_ASIN, 0x1.d12edp-12f, 0.0f },
    { PF_ASIN, 0x1.d12ed2p-12f, 0.0f },
    { PF_ACOS, -0x1.f721a8p-1f, 0.0f },
    { PF_ACOS, -0x1.b37e4p-1f, 0.0f },
    { PF_ACOS, -0x1.00c66p-1f, 0.0f },
    { PF_ACOS, -0x1.c70642p-2f, 0.0f },
    { PF_ATAN, 0x1.588696p-10f, 0.0f },
    { PF_ATAN, 0x1.695ba4p-10f, 0.0f },
    { PF_ATAN, 0x1.f83792p-9f, 0.0f },
    { PF_ATAN, 0x1.e35c7ep-5f, 0.0f },
    { PF_ATAN, -0x1.e00a5p+25f, 0.0f },
    { PF_ATAN, -0x1.e00a42p+25f, 0.0f },
    { PF_ATAN2, -0x1.2f0b38p+2f, 0x1.cp+1f },
    { PF_ATAN2, -0x1.27b6fap+2f, 0x1.cp+1f },
    { PF_ATAN2, -0x1.df936ap+1f, 0x1.cp+1f },
    { PF_ATAN2, -0x1.ba4816p+1f, 0x1.cp+1f },
    { PF_ATAN2, 0x1.1af7p-9f, -0x1.8p-1f },
    { PF_ATAN2, 0x1.69101p-8f, -0x1.8p-1f },
    { PF_ATAN2, 0x1.8b00e8p-7f, -0x1.8p-1f },
    { PF_ATAN2, 0x1.3ce614p-6f, -0x1.8p-1f },
};

static void test_hard_cases(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof hard / sizeof hard[0]; i++) {
        mpfr_t y;
        mpfr_init2(y, REF_PREC);
        ref_exact(hard[i].f, y, hard[i].x, hard[i].x2);
        double md = ref_middist(y);
        mpfr_clear(y);
        CHECK(md < 0x1p-20, "hard case %zu (%s(%a)) is %g ulp from a midpoint", i,
              pfref_name(hard[i].f), hard[i].x, md);
        check_point(hard[i].f, hard[i].x, hard[i].x2, 1);
        /* Signs: odd functions give the mirrored hard case. */
        pf_func f = hard[i].f;
        if (f == PF_SIN || f == PF_TAN || f == PF_ASIN || f == PF_ATAN || f == PF_ATAN2)
            check_point(f, -hard[i].x, hard[i].x2, 1);
    }
}

/* sin, cos, tan need exact reduction of huge arguments. */
static void test_huge_trig(void **state)
{
    (void)state;
    const float xs[] = { 1e22f, -1e22f, FLT_MAX, -FLT_MAX, 0x1.921fb6p+0f, 0x1.921fb6p+1f,
                         0x1.921fb6p+24f, 0x1p127f, 3.0e38f, 0x1.8p100f };
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++)
        for (pf_func f = PF_SIN; f <= PF_TAN; f++) {
            mpfr_t y;
            mpfr_init2(y, 2000);
            ref_exact(f, y, xs[i], 0);
            float want = ref_round(y);
            mpfr_clear(y);
            CHECK(same(pfref_f(f, xs[i], 0), want), "%s(%a) = %a, want %a", pfref_name(f), xs[i],
                  pfref_f(f, xs[i], 0), want);
            check_point(f, xs[i], 0, 1);
        }
}

/* pfref_f against glibc's double functions rounded to float, where the
   double is far (2^-30 relative) from a midpoint so rounding it is safe
   under glibc's documented < 2 ulp accuracy. */
static void test_vs_glibc(void **state)
{
    (void)state;
    long n = nrand(20000), compared = 0;
    for (int f = 0; f < PF_NFUNCS; f++)
        for (long i = 0; i < n; i++) {
            float x = rnd_arg(f, 0), x2 = rnd_arg(f, 1);
            double d;
            switch (f) {
            case PF_LOG: d = log(x); break;
            case PF_LOG2: d = log2(x); break;
            case PF_EXP: d = exp(x); break;
            case PF_EXP2: d = exp2(x); break;
            case PF_SIN: d = sin(x); break;
            case PF_COS: d = cos(x); break;
            case PF_TAN: d = tan(x); break;
            case PF_ASIN: d = asin(x); break;
            case PF_ACOS: d = acos(x); break;
            case PF_ATAN: d = atan(x); break;
            case PF_ATAN2: d = atan2(x, x2); break;
            default: d = sqrt(x); break;
            }
            double m = fabs(d) * 0x1p-30;
            if (fb((float)(d - m)) != fb((float)(d + m)) || fabs(d) < 0x1p-140)
                continue;
            compared++;
            float r = pfref_f(f, x, f == PF_ATAN2 ? x2 : 0);
            CHECK(same(r, (float)d), "%s(%a, %a): pfref_f %a, glibc %a", pfref_name(f), x, x2, r, d);
        }
    CHECK(compared > 8 * n, "only %ld compared", compared);
}

/* ------------------------------------------------------- known values */

#define EQ(f, x, x2, want) do { \
        float w_ = (want), r_ = pfref_f(f, x, x2), q_ = pfref_f_fast(f, x, x2); \
        CHECK(same(r_, w_) && same(q_, w_) && pfref_is_cr(f, w_, x, x2) \
              && pfref_ulp_err(f, w_, x, x2) == 0.0, \
              "%s(%a, %a): pfref_f %a, f_fast %a, want %a", pfref_name(f), \
              (double)(x), (double)(x2), r_, q_, w_); \
    } while (0)

static void test_names(void **state)
{
    (void)state;
    static const char *const want[PF_NFUNCS] = { "log", "log2", "exp", "exp2", "sin", "cos",
        "tan", "asin", "acos", "atan", "atan2", "sqrt" };
    for (int f = 0; f < PF_NFUNCS; f++) {
        assert_string_equal(pfref_name(f), want[f]);
        assert_int_equal(pfref_lookup(want[f]), f);
        assert_int_equal(pfref_arity(f), f == PF_ATAN2 ? 2 : 1);
    }
    assert_int_equal(pfref_lookup("foo"), -1);
    assert_int_equal(pfref_lookup(""), -1);
    assert_int_equal(pfref_lookup("Log"), -1);
    assert_null(pfref_name(PF_NFUNCS));
}

/* pfref_mpfr: directed roundings bracket the test's own 300-bit value
   (catches a wrong entry in the dispatch) with consistent ternary values. */
static void test_mpfr_dispatch(void **state)
{
    (void)state;
    mpfr_t x, x2, d, u, r;
    mpfr_inits2(60, x, x2, d, u, (mpfr_ptr)0);
    mpfr_init2(r, REF_PREC);
    for (int f = 0; f < PF_NFUNCS; f++)
        for (int i = 0; i < 200; i++) {
            mpfr_set_d(x, unif(0.01, 0.99), MPFR_RNDN);
            mpfr_set_d(x2, unif(0.01, 0.99), MPFR_RNDN);
            int td = pfref_mpfr(f, d, x, x2, MPFR_RNDD);
            int tu = pfref_mpfr(f, u, x, x2, MPFR_RNDU);
            ref_exact2(f, r, x, x2);
            CHECK(td <= 0 && tu >= 0 && mpfr_cmp(d, r) <= 0 && mpfr_cmp(u, r) >= 0
                  && (td == 0) == (tu == 0) && (td == 0 || mpfr_cmp(d, u) < 0),
                  "%s: pfref_mpfr does not bracket f(x)", pfref_name(f));
        }
    mpfr_clears(x, x2, d, u, r, (mpfr_ptr)0);
}

static void test_exact_values(void **state)
{
    (void)state;
    const float pi = 0x1.921fb6p+1f, pi2 = 0x1.921fb6p+0f;   /* 3.14159274f, 1.57079637f */
    EQ(PF_LOG, 1.0f, 0, 0.0f);
    EQ(PF_LOG2, 1.0f, 0, 0.0f);
    for (int k = -149; k <= 127; k++) {
        EQ(PF_LOG2, ldexpf(1.0f, k), 0, (float)k);
        EQ(PF_EXP2, (float)k, 0, ldexpf(1.0f, k));
    }
    EQ(PF_EXP, 0.0f, 0, 1.0f);
    EQ(PF_EXP, -0.0f, 0, 1.0f);
    EQ(PF_EXP2, -0.0f, 0, 1.0f);
    EQ(PF_COS, 0.0f, 0, 1.0f);
    EQ(PF_COS, -0.0f, 0, 1.0f);
    EQ(PF_ACOS, 1.0f, 0, 0.0f);
    EQ(PF_ACOS, -1.0f, 0, pi);
    EQ(PF_ACOS, 0.0f, 0, pi2);
    EQ(PF_ASIN, 1.0f, 0, pi2);
    EQ(PF_ASIN, -1.0f, 0, -pi2);
    EQ(PF_ATAN, INFINITY, 0, pi2);
    EQ(PF_ATAN, -INFINITY, 0, -pi2);
    EQ(PF_ATAN, 1.0f, 0, 0x1.921fb6p-1f);
    EQ(PF_SQRT, 4.0f, 0, 2.0f);
    EQ(PF_SQRT, 0x1p-148f, 0, 0x1p-74f);
    EQ(PF_SQRT, FLT_MAX, 0, 0x1.fffffep+63f);   /* sqrt((2-2^-23) 2^127) = (2 - 2^-24 - ...) 2^63 */
    EQ(PF_SQRT, INFINITY, 0, INFINITY);
    for (int s = 0; s < 2; s++) {
        float z = s ? -0.0f : 0.0f;
        EQ(PF_SIN, z, 0, z);
        EQ(PF_TAN, z, 0, z);
        EQ(PF_ASIN, z, 0, z);
        EQ(PF_ATAN, z, 0, z);
        EQ(PF_SQRT, z, 0, z);
        EQ(PF_LOG, z, 0, -INFINITY);
        EQ(PF_LOG2, z, 0, -INFINITY);
    }
    /* Domain errors and NaN propagation. */
    const struct { pf_func f; float x; } dom[] = {
        { PF_LOG, -1.0f }, { PF_LOG, -INFINITY }, { PF_LOG2, -0x1p-149f }, { PF_SQRT, -1.0f },
        { PF_SQRT, -INFINITY }, { PF_SQRT, -0x1p-149f }, { PF_SIN, INFINITY }, { PF_COS, -INFINITY },
        { PF_TAN, INFINITY }, { PF_ASIN, 2.0f }, { PF_ASIN, INFINITY }, { PF_ACOS, -0x1.000002p+0f },
        { PF_ACOS, 0x1.000002p+0f },
    };
    for (size_t i = 0; i < sizeof dom / sizeof dom[0]; i++)
        EQ(dom[i].f, dom[i].x, 0, NAN);
    for (int f = 0; f < PF_NFUNCS; f++) {
        EQ(f, NAN, 1.0f, NAN);
        EQ(f, -NAN, 1.0f, NAN);
    }
    EQ(PF_ATAN2, 1.0f, NAN, NAN);
    EQ(PF_ATAN2, INFINITY, NAN, NAN);
    EQ(PF_LOG, INFINITY, 0, INFINITY);
    EQ(PF_EXP, INFINITY, 0, INFINITY);
    EQ(PF_EXP, -INFINITY, 0, 0.0f);
    EQ(PF_EXP2, -INFINITY, 0, 0.0f);
    /* x2 is ignored by one-argument functions. */
    assert_true(same(pfref_f(PF_SIN, 1.0f, NAN), pfref_f(PF_SIN, 1.0f, 0)));
    assert_true(pfref_exact_d(PF_SIN, 1.0f, NAN) == sin(1.0));
}

/* Tiny arguments: sin, tan, asin, atan(x) = x(1 + O(x^2)), and the O(x^2) is
   below half an ulp when |x| < 2^-13; likewise cos(x) = 1 and, for
   |x| < 2^-26, exp(x) = exp2(x) = 1.  Symmetries on random arguments. */
static void test_identities(void **state)
{
    (void)state;
    for (int i = 0; i < 3000; i++) {
        float t = (float)ldexp(unif(-1, 1), -13 - (int)(rnd32() % 140));
        if (i == 0)
            t = 0x1p-149f;
        EQ(PF_SIN, t, 0, t);
        EQ(PF_TAN, t, 0, t);
        EQ(PF_ASIN, t, 0, t);
        EQ(PF_ATAN, t, 0, t);
        EQ(PF_COS, t, 0, 1.0f);
        if (fabsf(t) < 0x1p-26f) {
            EQ(PF_EXP, t, 0, 1.0f);
            EQ(PF_EXP2, t, 0, 1.0f);
        }
        /* sqrt(r*r) = |r| when r has at most 12 significant bits (r*r exact). */
        float r = ldexpf((float)(rnd32() % 4096), (int)(rnd32() % 100) - 60);
        EQ(PF_SQRT, r * r, 0, r);
    }
    for (int i = 0; i < 3000; i++) {
        float x = (float)ldexp(unif(-1, 1), (int)(rnd32() % 60) - 30), y = rnd_arg(PF_ATAN2, 1);
        assert_true(same(pfref_f_fast(PF_SIN, -x, 0), -pfref_f_fast(PF_SIN, x, 0)));
        assert_true(same(pfref_f_fast(PF_TAN, -x, 0), -pfref_f_fast(PF_TAN, x, 0)));
        assert_true(same(pfref_f_fast(PF_ATAN, -x, 0), -pfref_f_fast(PF_ATAN, x, 0)));
        assert_true(same(pfref_f_fast(PF_COS, -x, 0), pfref_f_fast(PF_COS, x, 0)));
        assert_true(same(pfref_f_fast(PF_ATAN2, -x, y), -pfref_f_fast(PF_ATAN2, x, y)));
        float a = (float)unif(-1, 1);
        assert_true(same(pfref_f_fast(PF_ASIN, -a, 0), -pfref_f_fast(PF_ASIN, a, 0)));
    }
}

/* C99 Annex F.9.1.4. */
static void test_atan2_annex_f(void **state)
{
    (void)state;
    const float pi = 0x1.921fb6p+1f, pi2 = 0x1.921fb6p+0f, pi4 = 0x1.921fb6p-1f;
    const float pi34 = (float)(0.75 * M_PI);
    const float fin[] = { 1.0f, 3.5f, 0x1p-149f, FLT_MIN, FLT_MAX, 1e10f };
    for (int s = 0; s < 2; s++) {
        float sg = s ? -1.0f : 1.0f, z = s ? -0.0f : 0.0f;
        EQ(PF_ATAN2, z, -0.0f, sg * pi);
        EQ(PF_ATAN2, z, 0.0f, z);
        CHECK(pfref_ulp_err(PF_ATAN2, -z, z, 0.0f) == INFINITY, "atan2 zero sign");
        EQ(PF_ATAN2, sg * INFINITY, -INFINITY, sg * pi34);
        EQ(PF_ATAN2, sg * INFINITY, INFINITY, sg * pi4);
        for (size_t i = 0; i < sizeof fin / sizeof fin[0]; i++) {
            float v = fin[i];
            EQ(PF_ATAN2, z, -v, sg * pi);
            EQ(PF_ATAN2, z, v, z);
            EQ(PF_ATAN2, -v, sg * 0.0f, -pi2);
            EQ(PF_ATAN2, v, sg * 0.0f, pi2);
            EQ(PF_ATAN2, sg * v, -INFINITY, sg * pi);
            EQ(PF_ATAN2, sg * v, INFINITY, z);
            EQ(PF_ATAN2, sg * INFINITY, v, sg * pi2);
            EQ(PF_ATAN2, sg * INFINITY, -v, sg * pi2);
            CHECK(pfref_ulp_err(PF_ATAN2, -z, sg * v, INFINITY) == INFINITY, "atan2 zero sign");
        }
    }
}

static void test_overflow_underflow(void **state)
{
    (void)state;
    EQ(PF_EXP, 89.0f, 0, INFINITY);
    EQ(PF_EXP, 88.7229f, 0, INFINITY);        /* > 128 ln 2 = 88.72283906 */
    float big = pfref_f(PF_EXP, 88.72f, 0);   /* < 128 ln 2 */
    CHECK(isfinite(big) && big > 0x1p127f, "exp(88.72) = %a", big);
    EQ(PF_EXP, 1e30f, 0, INFINITY);
    EQ(PF_EXP2, 128.0f, 0, INFINITY);
    float b2 = pfref_f(PF_EXP2, nextafterf(128.0f, 0), 0);
    CHECK(isfinite(b2) && b2 > 0x1.fffp127f, "exp2(128-) = %a", b2);
    /* -103.9 / ln 2 = -149.895: 0.538 * 2^-149 rounds up to 2^-149;
       -104 / ln 2 = -150.04: below the midpoint 2^-150, rounds to +0. */
    EQ(PF_EXP, -103.9f, 0, 0x1p-149f);
    EQ(PF_EXP, -104.0f, 0, 0.0f);
    EQ(PF_EXP, -1e30f, 0, 0.0f);
    EQ(PF_EXP, -800.0f, 0, 0.0f);          /* beyond double's range too */
    EQ(PF_EXP2, -150.0f, 0, 0.0f);         /* exactly the midpoint: to even, 0 */
    EQ(PF_EXP2, nextafterf(-150.0f, 0), 0, 0x1p-149f);
    EQ(PF_EXP2, -149.5f, 0, 0x1p-149f);
    EQ(PF_EXP2, -150.5f, 0, 0.0f);
    EQ(PF_EXP2, -140.25f, 0, 431 * 0x1p-149f);   /* 2^8.75 = 430.54 */
    EQ(PF_EXP2, -1e30f, 0, 0.0f);
    EQ(PF_EXP2, -1074.5f, 0, 0.0f);
    /* A subnormal result, with tie-free double rounding avoided. */
    for (float x = -87.5f; x > -104.0f; x -= 0.37f)
        check_point(PF_EXP, x, 0, 1);
    for (int i = 0; i < 200; i++)
        check_point(PF_EXP, (float)unif(-1000, -80), 0, 1);
}

/* ------------------------------------------------ ulp_err special rules */

static void test_ulp_special(void **state)
{
    (void)state;
    assert_true(pfref_ulp_err(PF_SQRT, NAN, -1.0f, 0) == 0.0);
    assert_true(pfref_ulp_err(PF_SQRT, -NAN, -1.0f, 0) == 0.0);
    assert_true(pfref_is_cr(PF_SQRT, -NAN, -1.0f, 0) == 1);
    assert_true(pfref_ulp_err(PF_SQRT, 0.0f, -1.0f, 0) == INFINITY);
    assert_true(pfref_is_cr(PF_SQRT, 0.0f, -1.0f, 0) == 0);
    assert_true(pfref_ulp_err(PF_LOG, NAN, 2.0f, 0) == INFINITY);
    assert_true(pfref_ulp_err(PF_EXP, INFINITY, 100.0f, 0) == 0.0);
    assert_true(pfref_ulp_err_raw(PF_EXP, INFINITY, 100.0f, 0) == 0.0);
    assert_true(pfref_ulp_err(PF_EXP, FLT_MAX, 100.0f, 0) == INFINITY);
    assert_true(pfref_ulp_err(PF_EXP, -INFINITY, 100.0f, 0) == INFINITY);
    assert_true(pfref_ulp_err(PF_EXP, INFINITY, 1.0f, 0) == INFINITY);
    assert_true(pfref_ulp_err(PF_LOG, -INFINITY, 0.0f, 0) == 0.0);
    assert_true(pfref_ulp_err(PF_LOG, INFINITY, 0.0f, 0) == INFINITY);
    assert_true(pfref_ulp_err(PF_LOG, -FLT_MAX, 0.0f, 0) == INFINITY);
    /* Signed zeros. */
    assert_true(pfref_ulp_err(PF_SIN, 0.0f, -0.0f, 0) == INFINITY);
    assert_true(pfref_ulp_err(PF_SIN, -0.0f, -0.0f, 0) == 0.0);
    assert_true(pfref_ulp_err(PF_SIN, 0x1p-149f, -0.0f, 0) == 1.0);
    assert_true(pfref_ulp_err(PF_LOG, -0.0f, 1.0f, 0) == INFINITY);
    assert_true(pfref_ulp_err(PF_LOG, -0x1p-149f, 1.0f, 0) == 1.0);
    assert_true(pfref_ulp_err(PF_EXP, 0.0f, -200.0f, 0) == 0.0);
    assert_true(pfref_ulp_err(PF_EXP, -0.0f, -200.0f, 0) == INFINITY);
    assert_true(pfref_ulp_err_raw(PF_EXP, 0.0f, -200.0f, 0) < 1e-30);
    assert_true(pfref_ulp_err(PF_EXP, 0x1p-149f, -200.0f, 0) == 1.0);   /* 1 - 2^-139 */
    assert_true(pfref_ulp_err(PF_EXP, 0.0f, -103.9f, 0) > 0.5);
    /* The correctly rounded result errs by 0 ULP, even near a midpoint. */
    assert_true(pfref_ulp_err(PF_EXP2, 0.0f, -150.0f, 0) == 0.0);
    assert_true(pfref_ulp_err_raw(PF_EXP2, 0.0f, -150.0f, 0) == 0.5);
    assert_true(pfref_ulp_err(PF_EXP2, 0x1p-149f, -150.0f, 0) == 0.5);
}

/* Exact results at powers of two: the ulp changes across 2^k, so the error
   of the float below is 0.5 ULP and of the float above 1 ULP (exactly). */
static void test_binade_edges(void **state)
{
    (void)state;
    for (int k = -149; k <= 127; k++) {
        float p = ldexpf(1.0f, k), dn = nextafterf(p, 0), up = nextafterf(p, INFINITY);
        double edn = pfref_ulp_err(PF_EXP2, dn, (float)k, 0), eup = pfref_ulp_err(PF_EXP2, up, (float)k, 0);
        CHECK(edn == (k > -126 ? 0.5 : 1.0), "exp2(%d): err(below) %.17g", k, edn);
        CHECK(eup == 1.0, "exp2(%d): err(above) %.17g", k, eup);
        CHECK(pfref_ulp_err_raw(PF_EXP2, p, (float)k, 0) == 0.0, "exp2(%d): raw", k);
        /* The same through log2: log2(2^k) = k. */
        if (k != 0) {
            float fk = (float)k, a = nextafterf(fk, 0), b = nextafterf(fk, 2 * fk);
            int pow2 = (abs(k) & (abs(k) - 1)) == 0;
            CHECK(pfref_ulp_err(PF_LOG2, b, p, 0) == 1.0, "log2(2^%d): err(%a)", k, b);
            CHECK(pfref_ulp_err(PF_LOG2, a, p, 0) == (pow2 ? 0.5 : 1.0), "log2(2^%d): err(%a)", k, a);
        }
    }
}

/* --------------------------------------------------- double references */

static double rnd_darg(pf_func f)
{
    switch (f) {
    case PF_LOG: case PF_LOG2: case PF_SQRT:
        return (rnd32() & 1) ? unif(0, 4) : ldexp(unif(0.5, 1), (int)(rnd32() % 200) - 100);
    case PF_EXP: case PF_EXP2: return unif(-40, 40);
    case PF_ASIN: case PF_ACOS: return unif(-1, 1);
    case PF_ATAN: return ldexp(unif(-1, 1), (int)(rnd32() % 40) - 20);
    default: return unif(-10, 10);
    }
}

static void ref_exact_d(pf_func f, mpfr_t y, double x, double x2)
{
    mpfr_t a, b;
    mpfr_inits2(53, a, b, (mpfr_ptr)0);
    mpfr_set_d(a, x, MPFR_RNDN);
    mpfr_set_d(b, x2, MPFR_RNDN);
    ref_exact2(f, y, a, b);
    mpfr_clears(a, b, (mpfr_ptr)0);
}

static void test_exact_dd(void **state)
{
    (void)state;
    assert_true(isnan(pfref_exact_dd(PF_LOG, -1.0, 0)));
    assert_true(isnan(pfref_exact_dd(PF_LOG2, -1e-300, 0)));
    assert_true(isnan(pfref_exact_dd(PF_SQRT, -1e-300, 0)));
    assert_true(isnan(pfref_exact_dd(PF_ASIN, 1.5, 0)));
    assert_true(isnan(pfref_exact_dd(PF_SIN, INFINITY, 0)));
    assert_true(pfref_exact_dd(PF_LOG, 0.0, 0) == -INFINITY);
    assert_true(pfref_exact_dd(PF_ACOS, -1.0, 0) == M_PI);      /* M_PI is pi rounded */
    assert_true(pfref_exact_dd(PF_ATAN2, 0.0, -0.0) == M_PI);
    assert_true(pfref_exact_dd(PF_ATAN2, -0.0, -0.0) == -M_PI);
    assert_true(pfref_exact_dd(PF_EXP2, -3.0, 0) == 0.125);
    assert_true(pfref_exact_dd(PF_SQRT, 0x1p-1074, 0) == 0x1p-537);
    double s = pfref_exact_dd(PF_SIN, -0.0, 0);
    assert_true(s == 0 && signbit(s));
    mpfr_t y, t;
    mpfr_init2(y, REF_PREC);
    mpfr_init2(t, REF_PREC);
    for (int f = 0; f < PF_NFUNCS; f++)
        for (int i = 0; i < 1000; i++) {
            double x = rnd_darg(f), x2 = rnd_darg(f), r = pfref_exact_dd(f, x, x2);
            ref_exact_d(f, y, x, x2);
            if (mpfr_zero_p(y)) {
                CHECK(r == 0, "%s(%a): %a, want 0", pfref_name(f), x, r);
                continue;
            }
            mpfr_sub_d(t, y, r, MPFR_RNDN);
            mpfr_mul_2si(t, t, 53 - mpfr_get_exp(y), MPFR_RNDN);
            double e = fabs(mpfr_get_d(t, MPFR_RNDN));
            CHECK(e <= 0.5 + 1e-6, "%s(%a, %a): exact_dd %a off by %g ulp", pfref_name(f), x, x2, r, e);
        }
    mpfr_clears(y, t, (mpfr_ptr)0);
}

/* |got - f(x) 2^e| by the test's own MPFR computation. */
static double ref_lsb(pf_func f, int64_t got, int e, double x, double x2)
{
    mpfr_t y, g;
    mpfr_init2(y, 2 * REF_PREC);
    mpfr_init2(g, 64);
    ref_exact_d(f, y, x, x2);
    mpfr_mul_2si(y, y, e, MPFR_RNDN);
    mpfr_set_sj(g, got, MPFR_RNDN);
    mpfr_sub(y, y, g, MPFR_RNDN);
    double r = fabs(mpfr_get_d(y, MPFR_RNDN));
    mpfr_clears(y, g, (mpfr_ptr)0);
    return r;
}

static void test_lsb(void **state)
{
    (void)state;
    assert_true(pfref_lsb_err(PF_SIN, 0, 30, 0.0, 0) == 0.0);
    assert_true(pfref_lsb_err(PF_SIN, 1, 30, 0.0, 0) == 1.0);
    assert_true(pfref_lsb_err(PF_SIN, -3, 30, 0.0, 0) == 3.0);
    assert_true(pfref_lsb_err(PF_SQRT, 2 << 20, 20, 4.0, 0) == 0.0);
    assert_true(pfref_lsb_err(PF_SQRT, (2 << 20) + 1, 20, 4.0, 0) == 1.0);
    assert_true(pfref_lsb_err(PF_EXP, INT64_C(1) << 62, 62, 0.0, 0) == 0.0);
    assert_true(pfref_lsb_err(PF_EXP, (INT64_C(1) << 62) + 1, 62, 0.0, 0) == 1.0);
    assert_true(pfref_lsb_err(PF_EXP, (INT64_C(1) << 62) - 7, 62, 0.0, 0) == 7.0);
    assert_true(pfref_lsb_err(PF_LOG2, -2048, 10, 0.25, 0) == 0.0);
    assert_true(pfref_lsb_err(PF_LOG2, -2047, 10, 0.25, 0) == 1.0);
    assert_true(pfref_lsb_err(PF_EXP2, 65536, -4, 20.0, 0) == 0.0);   /* 65536 * 16 = 2^20 */
    assert_true(pfref_lsb_err(PF_EXP2, 65537, -4, 20.0, 0) == 1.0);
    assert_true(pfref_lsb_err(PF_ATAN2, 0, 20, 0.0, 1.0) == 0.0);
    assert_true(isnan(pfref_lsb_err(PF_LOG, 0, 10, -1.0, 0)));
    assert_true(isnan(pfref_lsb_err(PF_SQRT, 0, 10, -1.0, 0)));
    assert_true(isnan(pfref_lsb_err(PF_ASIN, 0, 10, 1.5, 0)));
    assert_true(pfref_lsb_err(PF_LOG, 0, 10, 0.0, 0) == INFINITY);
    /* sqrt(2) * 2^30 = 1518500249.98802...: floor errs by 0.98802 LSB,
       ceil by 0.01198 (the two add up to 1). */
    double e0 = pfref_lsb_err(PF_SQRT, 1518500249, 30, 2.0, 0);
    double e1 = pfref_lsb_err(PF_SQRT, 1518500250, 30, 2.0, 0);
    CHECK(fabs(e0 + e1 - 1) < 1e-9 && e1 > 0.01197 && e1 < 0.01198, "sqrt2: %.12g %.12g", e0, e1);

    /* Results within 2^-13 of 0.5 or 1 LSB must be exact (MPFR): inputs
       chosen through the inverse function so that f(x) 2^31 is within about
       1e-6 of n + 1/2 or n, and got = n or n + 1. */
    int near = 0;
    for (int i = 0; i < 300; i++) {
        double n = floor(unif(0x1p29, 0x1p30)), h = (i & 1) ? 0.5 : 0.0, t = (n + h) * 0x1p-31;
        const struct { pf_func f; double x; } c[] = {
            { PF_EXP2, log2(t) }, { PF_LOG, exp(t) }, { PF_SIN, asin(t) }, { PF_ATAN, tan(t) },
            { PF_SQRT, t * t }, { PF_COS, acos(t) },
        };
        for (size_t j = 0; j < sizeof c / sizeof c[0]; j++) {
            int64_t got = (int64_t)n + (h == 0 ? 1 : 0);
            double want = ref_lsb(c[j].f, got, 31, c[j].x, 0), r = pfref_lsb_err(c[j].f, got, 31, c[j].x, 0);
            if (fabs(want - 0.5) < 0x1p-13 || fabs(want - 1) < 0x1p-13) {
                near++;
                CHECK(fabs(r - want) <= 1e-14, "%s(%a): lsb err %.17g, want %.17g (exact)",
                      pfref_name(c[j].f), c[j].x, r, want);
            }
        }
    }
    CHECK(near > 1000, "only %d near-threshold cases", near);

    /* Random: out_exp up to 62 (the MPFR path for |got| >= 2^53), results
       rounded and off by a few LSBs or many. */
    mpfr_t y;
    mpfr_init2(y, 2 * REF_PREC);
    long n = nrand(3000);
    for (int f = 0; f < PF_NFUNCS; f++)
        for (long i = 0; i < n; i++) {
            double x = rnd_darg(f), x2 = rnd_darg(f);
            ref_exact_d(f, y, x, x2);
            if (!mpfr_number_p(y))
                continue;
            long ey = mpfr_zero_p(y) ? 0 : (long)mpfr_get_exp(y);
            int e = (int)(rnd32() % 63) - 4;
            if (e + ey > 60)
                e = (int)(60 - ey);
            mpfr_mul_2si(y, y, e, MPFR_RNDN);
            mpfr_rint(y, y, MPFR_RNDN);
            int64_t got = (int64_t)mpfr_get_sj(y, MPFR_RNDN);
            int64_t off = (rnd32() & 1) ? (int64_t)(rnd32() % 7) - 3 : (int64_t)(rnd32() % 100000) - 50000;
            got += off;
            double want = ref_lsb(f, got, e, x, x2), r = pfref_lsb_err(f, got, e, x, x2);
            CHECK(fabs(r - want) <= 1e-6 + 1e-12 * want, "%s(%a, %a) e=%d got=%lld: %.12g, want %.12g",
                  pfref_name(f), x, x2, e, (long long)got, r, want);
        }
    mpfr_clear(y);
}

/* ------------------------------------------------ threads, environment */

#define NT 4000
static float t_x[NT], t_x2[NT], t_g[NT];
static double t_err[NT];
static float t_cr[NT];

static void *thread_body(void *arg)
{
    long id = (long)(intptr_t)arg, bad = 0;
    /* A thread with its own exponent range must get the same answers and
       keep its range. */
    mpfr_set_emin(id == 0 ? -5000 : -100);
    mpfr_set_emax(id == 0 ? 5000 : 100);
    for (int rep = 0; rep < 3; rep++)
        for (int i = 0; i < NT; i++) {
            int j = (int)((i + id * 977) % NT);
            pf_func f = (pf_func)(j % PF_NFUNCS);
            if (!same(pfref_f(f, t_x[j], t_x2[j]), t_cr[j])
                || pfref_ulp_err(f, t_g[j], t_x[j], t_x2[j]) != t_err[j]
                || pfref_is_cr(f, t_cr[j], t_x[j], t_x2[j]) != 1)
                bad++;
        }
    if (mpfr_get_emin() != (id == 0 ? -5000 : -100) || mpfr_get_emax() != (id == 0 ? 5000 : 100))
        bad += 1000000;
    mpfr_free_cache();   /* MPFR's per-thread constant caches (pi, log 2) */
    return (void *)(intptr_t)bad;
}

static void test_threads(void **state)
{
    (void)state;
    const size_t nh = sizeof hard / sizeof hard[0];
    for (int i = 0; i < NT; i++) {
        pf_func f = (pf_func)(i % PF_NFUNCS);
        t_x[i] = rnd_arg(f, 0);
        t_x2[i] = rnd_arg(f, 1);
        if (i % 3 == 0) {          /* hard cases: the MPFR paths */
            size_t h = (size_t)i % nh;
            while (hard[h].f != f && h + 1 < nh)
                h++;
            if (hard[h].f == f) {
                t_x[i] = hard[h].x;
                t_x2[i] = hard[h].x2;
            }
        }
        t_cr[i] = ref_cr(f, t_x[i], t_x2[i]);
        t_g[i] = (i & 1) ? t_cr[i] : nextafterf(t_cr[i], INFINITY);
        t_err[i] = pfref_ulp_err(f, t_g[i], t_x[i], t_x2[i]);
    }
    pthread_t th[2];
    for (long t = 0; t < 2; t++)
        assert_int_equal(pthread_create(&th[t], NULL, thread_body, (void *)(intptr_t)t), 0);
    for (int t = 0; t < 2; t++) {
        void *ret;
        assert_int_equal(pthread_join(th[t], &ret), 0);
        CHECK((intptr_t)ret == 0, "thread %d: %ld mismatches", t, (long)(intptr_t)ret);
    }
}

/* The caller's exponent range and flags survive every entry point. */
static void test_env_restored(void **state)
{
    (void)state;
    mpfr_exp_t emin = mpfr_get_emin(), emax = mpfr_get_emax();
    mpfr_set_emin(-1000);
    mpfr_set_emax(1000);
    mpfr_clear_flags();
    mpfr_set_inexflag();
    (void)pfref_f(PF_EXP, -103.9f, 0);
    (void)pfref_f(PF_EXP, 100.0f, 0);
    (void)pfref_ulp_err(PF_EXP2, 0.0f, -150.0f, 0);
    (void)pfref_ulp_err(PF_SIN, 1.0f, 1e22f, 0);
    (void)pfref_is_cr(hard[0].f, 0.0f, hard[0].x, hard[0].x2);
    (void)pfref_exact_dd(PF_EXP, 1e6, 0);
    (void)pfref_lsb_err(PF_EXP, INT64_C(1) << 62, 62, 0.0, 0);
    assert_true(mpfr_get_emin() == -1000 && mpfr_get_emax() == 1000);
    assert_true(mpfr_flags_save() == MPFR_FLAGS_INEXACT);
    mpfr_clear_flags();
    mpfr_set_emin(emin);
    mpfr_set_emax(emax);
}

int main(void)
{
    const char *q = getenv("PF_QUICK");
    quick = q && *q && strcmp(q, "0") != 0;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_names),
        cmocka_unit_test(test_mpfr_dispatch),
        cmocka_unit_test(test_exact_values),
        cmocka_unit_test(test_identities),
        cmocka_unit_test(test_atan2_annex_f),
        cmocka_unit_test(test_overflow_underflow),
        cmocka_unit_test(test_ulp_special),
        cmocka_unit_test(test_binade_edges),
        cmocka_unit_test(test_huge_trig),
        cmocka_unit_test(test_hard_cases),
        cmocka_unit_test(test_vs_glibc),
        cmocka_unit_test(test_random_vs_mpfr),
        cmocka_unit_test(test_exact_dd),
        cmocka_unit_test(test_lsb),
        cmocka_unit_test(test_threads),
        cmocka_unit_test(test_env_restored),
    };
    int r = cmocka_run_group_tests(tests, NULL, NULL);
    mpfr_free_cache();
    return r;
}
