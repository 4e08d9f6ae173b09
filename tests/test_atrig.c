/* asin, acos, atan, atan2 (exact and fast), end to end: the library's
 * generated code swept against MPFR over every float of the reductions' folds,
 * seeded full-range samples, the hard cases, the fast variants' error
 * bound and slope continuity at every fold, array forms against scalar forms,
 * and pfmathgen's emitted code compiled inside the test. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "compile.h"
#include "pfmath.h"
#include "sweep.h"
#include "tu_exec.h"

#include <dlfcn.h>
#include <float.h>
#include <math.h>

static float asf(uint32_t u) { float f; memcpy(&f, &u, 4); return f; }
static uint32_t asu(float f) { uint32_t u; memcpy(&u, &f, 4); return u; }

/* ---- exact variants: every float around each fold, samples, directed ---- */

/* every float of [lo, hi] (OpenMP), and every step-th of [-hi, -lo] (every
   float too when step is 1: a branch of its own, not a sign flip) */
static void sweep_range(pf_sweep_stats *s, pf_func f, pf_fn1 fn, float lo, float hi, uint32_t step)
{
    pf_sweep_bits(s, f, fn, NULL, asu(lo), asu(hi), 0);
    if (step == 1)
        pf_sweep_bits(s, f, fn, NULL, asu(-lo), asu(-hi), 0);
    else
        for (uint32_t b = asu(-lo); b <= asu(-hi); b += step)
            pf_sweep_one(s, f, fn, NULL, asf(b), 1.0f);
}

static void finish(pf_sweep_stats *s, pf_func f, pf_fn1 fn1, pf_fn2 fn2, const char *what)
{
    pf_sweep_random(s, f, fn1, fn2, 20261121, 1u << 22);
    pf_sweep_directed(s, f, fn1, fn2);
    pf_sweep_print(stdout, what, f, s);
    assert_true(s->max_ulp <= 1.0);
}

static void test_asin_exact(void **st)
{
    (void)st;
    pf_sweep_stats s;
    pf_sweep_init(&s);
    /* [1/4, 1]: the polynomial's upper half directly, the fold at 1/2, the
       sqrt branch up to 1 (2^24 floats; the negative side is the same
       arithmetic with the sign bit set: every 7th) */
    sweep_range(&s, PF_ASIN, pf_asinf, 0.25f, 1.0f, 7);
    sweep_range(&s, PF_ASIN, pf_asinf, 0x1p-12f, 0x1p-11f, 7); /* where x^3/6 meets rounding */
    finish(&s, PF_ASIN, pf_asinf, NULL, "libpfmath pf_asinf");
}

static void test_acos_exact(void **st)
{
    (void)st;
    pf_sweep_stats s;
    pf_sweep_init(&s);
    /* both folds (+-1/2) and both ends (+-1): three branches */
    sweep_range(&s, PF_ACOS, pf_acosf, 0.25f, 1.0f, 1);
    finish(&s, PF_ACOS, pf_acosf, NULL, "libpfmath pf_acosf");
}

static void test_atan_exact(void **st)
{
    (void)st;
    pf_sweep_stats s;
    pf_sweep_init(&s);
    sweep_range(&s, PF_ATAN, pf_atanf, 0.5f, 2.0f, 7); /* the fold at 1: 2^24 floats */
    sweep_range(&s, PF_ATAN, pf_atanf, 0x1p24f, 0x1p25f, 7); /* 1/x tiny: pi/2 - 1/x */
    finish(&s, PF_ATAN, pf_atanf, NULL, "libpfmath pf_atanf");
}

/* ---- atan2: seeded pairs (tests/pfsweep_pairs.c: the same generator as
   pfsweep --all) and the four quadrants of the fold |y| = |x| ---- */
int pfsweep_pairs(pf_sweep_stats *s, pf_func f, pf_fn2 fn, uint64_t seed, uint64_t n);

static void test_atan2_exact(void **st)
{
    (void)st;
    pf_sweep_stats s;
    pf_sweep_init(&s);
    int nsp = pfsweep_pairs(&s, PF_ATAN2, pf_atan2f, 7, 1u << 22);
    print_message("atan2: 2^22 dense seeded pairs and %d special pairs\n", nsp);
    /* every 16th y in [1/2, 2] against x = +-1 (the fold |y| = |x| in all four
       quadrants), and the same angles scaled by huge and tiny factors */
    const float xs[] = {1.0f, -1.0f};
    const float scale[] = {1.0f, 0x1p100f, 0x1p-120f};
    for (int k = 0; k < 3; k++)
        for (int j = 0; j < 2; j++)
            for (uint32_t b = asu(0.5f); b <= asu(2.0f); b += k ? 61 : 16) {
                float y = asf(b) * scale[k], x = xs[j] * scale[k];
                pf_sweep_one(&s, PF_ATAN2, NULL, pf_atan2f, y, x);
                pf_sweep_one(&s, PF_ATAN2, NULL, pf_atan2f, -y, x);
            }
    finish(&s, PF_ATAN2, NULL, pf_atan2f, "libpfmath pf_atan2f");
}

/* ---- hard cases named in the issue ---- */
static void test_hard_cases(void **st)
{
    (void)st;
    double worst = 0;
    /* asin/acos at +-1 and the 2^16 floats below; +-1/2 and neighbours */
    for (uint32_t b = asu(1.0f) - 65536; b <= asu(1.0f); b++)
        for (int sg = 0; sg < 2; sg++) {
            float x = asf(b | (uint32_t)sg << 31);
            worst = fmax(worst, pfref_ulp_err(PF_ASIN, pf_asinf(x), x, 1));
            worst = fmax(worst, pfref_ulp_err(PF_ACOS, pf_acosf(x), x, 1));
        }
    assert_true(worst <= 1.0);
    /* just outside [-1, 1]: NaN from both variants (domain error) */
    const float out[] = {0x1.000002p0f, -0x1.000002p0f, 1.5f, -2.0f, FLT_MAX, -INFINITY, INFINITY};
    for (size_t i = 0; i < sizeof out / sizeof out[0]; i++) {
        assert_true(isnan(pf_asinf(out[i])) && isnan(pf_asinf_fast(out[i])));
        assert_true(isnan(pf_acosf(out[i])) && isnan(pf_acosf_fast(out[i])));
    }
    /* acos(1) = +0 exactly, acos near 1 is 2 asin(sqrt((1-x)/2)): relative
       accuracy down to the last float below 1 */
    assert_true(asu(pf_acosf(1.0f)) == 0 && asu(pf_acosf_fast(1.0f)) == 0);
    /* atan2 with huge and tiny ratios: every combination of extreme
       magnitudes and signs, within 1 ULP (subnormal results included) */
    const float mag[] = {0x1p-149f, 0x1p-126f, 0x1.fffffep-127f, 0x1p-75f, 1.0f, 0x1p75f,
                         0x1p100f, FLT_MAX, 0x1.000002p0f, 3.0f};
    int nm = sizeof mag / sizeof mag[0];
    double w2 = 0;
    for (int i = 0; i < nm; i++)
        for (int j = 0; j < nm; j++)
            for (int q = 0; q < 4; q++) {
                float y = q & 1 ? -mag[i] : mag[i], x = q & 2 ? -mag[j] : mag[j];
                w2 = fmax(w2, pfref_ulp_err(PF_ATAN2, pf_atan2f(y, x), y, x));
            }
    print_message("hard cases: asin/acos near +-1 max %.4f ULP, atan2 extreme ratios max %.4f ULP\n",
                  worst, w2);
    assert_true(w2 <= 1.0);
}

/* ---- fast variants ---- */

/* |got - f| <= 2^-10 |f| (results below FLT_MIN: half a subnormal ULP more,
   the format's own limit).  Every 3rd float of the folds' binades ([1/4, 1]
   for asin, acos; [1/2, 2] for atan, and atan2 against x = +-1), both signs,
   a seeded sample over all floats (scaled into [-1, 1] for asin, acos; for
   atan2 half the pairs with |y|/|x| in [2^-32, 2^32]). */
static double fast_err(pf_func f, float got, float y, float x)
{
    double ex = pfref_exact_d(f, y, x);
    if (isnan(ex))
        return isnan(got) ? 0 : INFINITY;
    double e = fabs((double)got - ex) - 0x1p-150;
    return e <= 0 ? 0 : e / fmax(fabs(ex), 0x1p-126);
}

static void fast_bound(pf_func f, pf_fn1 fn1, pf_fn2 fn2)
{
    double worst = 0;
    float wy = 0, wx = 0;
    int inv = f == PF_ASIN || f == PF_ACOS;
    float lo = inv ? 0.25f : 0.5f, top = inv ? 1.0f : 2.0f;
    if (fn1) {
        for (uint32_t b = asu(lo); b <= asu(top); b += 3)
            for (int sg = 0; sg < 2; sg++) {
                float x = asf(b | (uint32_t)sg << 31);
                double e = fast_err(f, fn1(x), x, 1);
                if (e > worst)
                    worst = e, wy = x;
            }
    } else {
        /* every 3rd y in [1/2, 2] against x = +-1 (all four quadrants) */
        for (uint32_t b = asu(lo); b <= asu(top); b += 3)
            for (int q = 0; q < 4; q++) {
                float y = q & 1 ? -asf(b) : asf(b), x = q & 2 ? -1.0f : 1.0f;
                double e = fast_err(f, fn2(y, x), y, x);
                if (e > worst)
                    worst = e, wy = y, wx = x;
            }
    }
    uint64_t s = 99;
    for (int i = 0; i < 1 << 22; i++) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        float y = asf((uint32_t)(s >> 32) & 0xff7fffffu); /* finite */
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        float x = fn2 ? asf((uint32_t)(s >> 32) & 0xff7fffffu) : 1.0f;
        if (fn2 && (s & 0x100))
            x = ldexpf(y, (int)(s >> 16 & 63) - 32) * (1 + 0x1p-7f * (float)(s >> 24 & 127));
        if (fn1 && (f == PF_ASIN || f == PF_ACOS))
            y = ldexpf(y, -(int)(s >> 16 & 127)) ; /* most of the sample inside [-1, 1] */
        float got = fn1 ? fn1(y) : fn2(y, x);
        double e = fast_err(f, got, y, x);
        if (e > worst)
            worst = e, wy = y, wx = x;
    }
    print_message("%s fast: max rel error %.3g (2^%.2f) at (%a, %a)\n", pfref_name(f), worst,
                  log2(worst), wy, wx);
    assert_true(worst <= 0x1p-10);
}

static void test_fast_bounds(void **st)
{
    (void)st;
    fast_bound(PF_ASIN, pf_asinf_fast, NULL);
    fast_bound(PF_ACOS, pf_acosf_fast, NULL);
    fast_bound(PF_ATAN, pf_atanf_fast, NULL);
    fast_bound(PF_ATAN2, NULL, pf_atan2f_fast);
}

/* Value and slope at a fold x0.  Second-order one-sided difference quotients
   (3f(x0) - 4f(x0 -+ h) + f(x0 -+ 2h)) / (+-2h), h = 2^16 float steps: their
   error is the values' rounding (8 times its bound vulp, in ULPs, over 2h)
   plus h^2/3 times the third derivative (below 2^-15 of the slope here).
   vulp is 1/2 where the fast scheme ends in one rounding of a sum whose
   other roundings are far smaller (atan, atan2); asin and acos round the
   square root S (1/2 ULP of S), q(z) in [1, 2) (1/2 ULP of q, times |t| <=
   1) and the final fmaf, which is 0.5 + 0.53 + 1 = 2.03 ULPs of a result in
   [1/2, 1) at the asin fold (S = 1, q = 1.05), less elsewhere: 2.1.  Left and
   right must agree (continuity of the slope) and both must equal the true
   derivative d to 2^-12 (the fit's slope constraint: without it the slope is
   off by about 2^-10 for asin at 1/2). */
static void seam_h(const char *what, double (*fd)(float), float x0, double d, float h, double vulp)
{
    double f0 = fd(x0), l1 = fd(x0 - h), l2 = fd(x0 - 2 * h), r1 = fd(x0 + h), r2 = fd(x0 + 2 * h);
    double left = (3 * f0 - 4 * l1 + l2) / (2 * h), right = (-3 * f0 + 4 * r1 - r2) / (2 * h);
    double ulp = fmax(fmax(fabs(l2), fabs(r2)), fabs(f0)) * 0x1p-23;
    double round = 8 * vulp * ulp / (2 * h) + 0x1p-15 * fabs(d);
    int ok = fabs(left - right) <= round && fabs(left - d) <= round + 0x1p-12 * fabs(d) &&
             fabs(right - d) <= round + 0x1p-12 * fabs(d);
    if (!ok)
        print_message("seam %s at %a: slope left %.9g, right %.9g, want %.9g (rounding %.3g)\n", what,
                      x0, left, right, d, round);
    assert_true(ok);
}

static void seam(const char *what, double (*fd)(float), float x0, double d, double vulp)
{
    seam_h(what, fd, x0, d, 0x1p16f * (nextafterf(fabsf(x0), INFINITY) - fabsf(x0)), vulp);
}

static double asin_f(float x) { return pf_asinf_fast(x); }
static double acos_f(float x) { return pf_acosf_fast(x); }
static double atan_f(float x) { return pf_atanf_fast(x); }
static double atan2_y_xp(float y) { return pf_atan2f_fast(y, 1.0f); }  /* |y| = |x| at y = +-1 */
static double atan2_y_xm(float y) { return pf_atan2f_fast(y, -1.0f); }
static double atan2_x_yp(float x) { return pf_atan2f_fast(1.0f, x); }  /* x through 0, and |x| = 1 */
static double atan2_x_ym(float x) { return pf_atan2f_fast(-1.0f, x); }
static double atan2_y_big(float y) { return pf_atan2f_fast(y * 0x1p40f, -0x1p40f); }

static void test_fast_seams(void **st)
{
    (void)st;
    const double d_asin = 2 / sqrt(3.0); /* asin'(+-1/2) = 1/sqrt(1 - 1/4) */
    for (int sg = -1; sg <= 1; sg += 2) {
        seam("asin", asin_f, sg * 0.5f, d_asin, 2.1);
        seam("acos", acos_f, sg * 0.5f, -d_asin, 2.1);
        seam("atan", atan_f, sg * 1.0f, 0.5, 0.5); /* 1/(1 + x^2) */
        /* d/dy atan2(y, x) = x/(x^2 + y^2), d/dx = -y/(x^2 + y^2) */
        seam("atan2(y, 1)", atan2_y_xp, sg * 1.0f, 0.5, 0.5);
        seam("atan2(y, -1)", atan2_y_xm, sg * 1.0f, -0.5, 0.5);
        seam("atan2(1, x)", atan2_x_yp, sg * 1.0f, -0.5, 0.5);
        seam("atan2(-1, x)", atan2_x_ym, sg * 1.0f, 0.5, 0.5);
        seam("atan2(2^40 y, -2^40)", atan2_y_big, sg * 1.0f, -0.5, 0.5); /* only the ratio matters */
    }
    /* x = 0 for atan2(+-1, x): pi/2 -+ p(|x|) on both sides, slope -+1 (c1 = 1) */
    seam_h("atan2(1, x)", atan2_x_yp, 0.0f, -1.0, 0x1p-7f, 0.5);
    seam_h("atan2(-1, x)", atan2_x_ym, 0.0f, 1.0, 0x1p-7f, 0.5);
}

/* ---- array forms = scalar forms, bit for bit ---- */
static void test_arrays_match_scalar(void **st)
{
    (void)st;
    enum { N = 4099 };
    static float x[N], y[N], out[N];
    uint64_t s = 5;
    for (int i = 0; i < N; i++) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        x[i] = asf((uint32_t)(s >> 32));
        y[i] = asf((uint32_t)s);
        if (i % 3 == 0) /* plenty inside [-1, 1] and near |y| = |x| */
            x[i] = ldexpf(x[i], -(int)(s >> 8 & 255)), y[i] = x[i] * (float)(s >> 20 & 7);
    }
    const uint32_t sp[] = {0, 0x80000000u, 0x7f800000u, 0xff800000u, 0x7fc00000u, 0x3f800000u,
                           0xbf800000u, 0x3f800001u, 0x3f000000u, 0x00000001u};
    for (int i = 0; i < 10; i++)
        for (int j = 0; j < 10; j++)
            y[10 * i + j] = asf(sp[i]), x[10 * i + j] = asf(sp[j]);
    void (*arr[6])(const float *, float *, size_t) = {pf_asinf_array, pf_asinf_fast_array,
                                                       pf_acosf_array, pf_acosf_fast_array,
                                                       pf_atanf_array, pf_atanf_fast_array};
    float (*sc[6])(float) = {pf_asinf, pf_asinf_fast, pf_acosf, pf_acosf_fast, pf_atanf, pf_atanf_fast};
    for (int f = 0; f < 6; f++) {
        arr[f](x, out, N);
        for (int i = 0; i < N; i++) {
            float z = sc[f](x[i]);
            assert_true(memcmp(&z, &out[i], 4) == 0 || (isnan(z) && isnan(out[i])));
        }
    }
    void (*arr2[2])(const float *, const float *, float *, size_t) = {pf_atan2f_array,
                                                                       pf_atan2f_fast_array};
    float (*sc2[2])(float, float) = {pf_atan2f, pf_atan2f_fast};
    for (int f = 0; f < 2; f++) {
        arr2[f](y, x, out, N);
        for (int i = 0; i < N; i++) {
            float z = sc2[f](y[i], x[i]);
            assert_true(memcmp(&z, &out[i], 4) == 0 || (isnan(z) && isnan(out[i])));
        }
    }
}

/* ---- pfmathgen end to end: the emitted source compiles and is the
   library's function (same bits on a sample) ---- */
static void test_emitted_matches_library(void **st)
{
    (void)st;
    const char *fn[] = {"asin", "atan2"};
    for (int k = 0; k < 2; k++) {
        char a[256], err[512], sym[64];
        char path[64];
        tu_scratch(path, "atrig.c");
        snprintf(a, sizeof a, "--func %s --no-sweep -o %s", fn[k], path);
        tu_run_result *r = malloc(sizeof *r);
        tu_runs("pfmathgen", a, r);
        assert_int_equal(r->status, 0);
        free(r);
        void *h = pf_compile_load_file(path, err, sizeof err);
        if (!h)
            print_message("%s\n", err);
        assert_non_null(h);
        unlink(path);
        snprintf(sym, sizeof sym, "pf_%sf", fn[k]);
        void *p = dlsym(h, sym);
        assert_non_null(p);
        uint64_t s = 11;
        for (int i = 0; i < 1 << 16; i++) {
            s = s * 6364136223846793005ull + 1442695040888963407ull;
            float x = asf((uint32_t)(s >> 32)), y = asf((uint32_t)s), got, want;
            if (k == 0) {
                float (*f1)(float);
                *(void **)&f1 = p;
                x = ldexpf(x, -(int)(s & 127));
                got = f1(x), want = pf_asinf(x);
            } else {
                float (*f2)(float, float);
                *(void **)&f2 = p;
                got = f2(y, x), want = pf_atan2f(y, x);
            }
            assert_true(asu(got) == asu(want) || (isnan(got) && isnan(want)));
        }
        dlclose(h);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_asin_exact),      cmocka_unit_test(test_acos_exact),
        cmocka_unit_test(test_atan_exact),      cmocka_unit_test(test_atan2_exact),
        cmocka_unit_test(test_hard_cases),      cmocka_unit_test(test_fast_bounds),
        cmocka_unit_test(test_fast_seams),      cmocka_unit_test(test_arrays_match_scalar),
        cmocka_unit_test(test_emitted_matches_library),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
