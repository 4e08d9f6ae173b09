/* sin, cos, tan end to end: the C that pfmathgen emits, compiled inside the
 * test, and the library's copies, swept against MPFR (ref/); the hardest
 * inputs of the argument reduction (floats next to multiples of pi/2, found
 * here by an exhaustive search with the bits of 2/pi from MPFR); the fast
 * variants' error bound for |x| <= 2^17, finiteness beyond, slope continuity
 * across every fold; array forms against scalar forms. */
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

typedef struct {
    pf_func f;
    const char *name;
    pf_fn1 exact, fast;
} trig_fn;

static const trig_fn fns[3] = {
    {PF_SIN, "sin", pf_sinf, pf_sinf_fast},
    {PF_COS, "cos", pf_cosf, pf_cosf_fast},
    {PF_TAN, "tan", pf_tanf, pf_tanf_fast},
};

/* ---- hard inputs: floats nearest multiples of pi/2 ---- */

/* Bits b_i (i >= 1) of 2/pi = sum b_i 2^-i, from MPFR; b_i = 0 for i < 1. */
#define NBITS 512
static unsigned char twoopi_bit[NBITS];
static void init_twoopi_bits(void)
{
    mpfr_t v;
    mpfr_init2(v, NBITS + 64);
    mpfr_const_pi(v, MPFR_RNDN);
    mpfr_ui_div(v, 2, v, MPFR_RNDN);
    for (int i = 1; i < NBITS; i++) {
        mpfr_mul_2ui(v, v, 1, MPFR_RNDN);
        twoopi_bit[i] = mpfr_cmp_ui(v, 1) >= 0;
        if (twoopi_bit[i])
            mpfr_sub_ui(v, v, 1, MPFR_RNDN);
    }
    mpfr_clear(v);
}

/* The float of biased exponent e (>= 127) closest to a multiple of pi/2, by
   an exhaustive scan of its 2^23 significands: x = M 2^(e-150), and
   x 2/pi mod 4 = (M W mod 2^128) 2^-126 with W the 128 bits of 2/pi from
   bit e-151 on (earlier bits give multiples of 4; later ones < 2^-100). */
static float closest_to_pio2_multiple(int e, double *dist)
{
    unsigned __int128 W = 0;
    for (int i = e - 151; i < e - 151 + 128; i++)
        W = W << 1 | (unsigned)(i >= 1 ? twoopi_bit[i] : 0);
    uint64_t wh = (uint64_t)(W >> 64), wl = (uint64_t)W;
    const unsigned __int128 one = 1, mask = (one << 126) - 1;
    unsigned __int128 best = mask;
    uint32_t bm = 0;
    for (uint32_t m = 1u << 23; m < 1u << 24; m++) {
        unsigned __int128 p = ((unsigned __int128)(m * wh) << 64) + (unsigned __int128)m * wl;
        unsigned __int128 fr = p & mask;
        unsigned __int128 d = fr < (one << 125) ? fr : (one << 126) - fr;
        if (d < best)
            best = d, bm = m;
    }
    *dist = ldexp((double)best, -126); /* in units of pi/2 */
    return ldexpf((float)bm, e - 150);
}

#define NHARD_E 64
static float hard_x[NHARD_E];
static double hard_dist[NHARD_E];
static int nhard;

/* every exponent of |x| in [1, 2^17) (the fast variants' range) and every
   third one above, up to 2^127; that includes 2^95 (e = 222), the binade of
   the worst case of all floats (0x1.f37c8ap+95, 2^-29.86 of pi/2 from a
   multiple: docs/trig.md) */
static void find_hard_inputs(void)
{
    int es[NHARD_E], n = 0;
    for (int e = 127; e <= 254; e += e < 144 ? 1 : 3)
        es[n++] = e;
#pragma omp parallel for schedule(dynamic, 1)
    for (int i = 0; i < n; i++)
        hard_x[i] = closest_to_pio2_multiple(es[i], &hard_dist[i]);
    nhard = n;
    double dmin = 1;
    for (int i = 0; i < n; i++)
        dmin = fmin(dmin, hard_dist[i]);
    print_message("%d binades searched; the closest float to a multiple of pi/2 is 2^%.2f (units of pi/2) away\n",
                  n, log2(dmin));
}

/* The floats next to k pi/2, for k up to kmax (both signs) plus the searched
   ones and the cases, each with 2 neighbours either side. */
static int hard_list(float *v, int cap, int kmax, int step)
{
    int n = 0;
    static float centre[1 << 18];
    int nc = 0;
    for (int k = 1; k <= kmax; k += k < 4096 ? 1 : step)
        centre[nc++] = (float)(k * 1.5707963267948966);
    for (int i = 0; i < nhard; i++)
        centre[nc++] = hard_x[i];
    centre[nc++] = 1e22f;               /* the float nearest 1e22 rad */
    centre[nc++] = 1e30f;
    centre[nc++] = asf(0x3fc90fdbu);    /* 0x1.921fb6p+0, nearest pi/2 */
    centre[nc++] = FLT_MAX;
    for (int i = 0; i < nc; i++)
        for (int d = -2; d <= 2 && n + 2 <= cap; d++) {
            float x = asf(asu(centre[i]) + (uint32_t)d);
            v[n++] = x;
            v[n++] = -x;
        }
    return n;
}

/* ---- exact variants ---- */

/* every float of the reduced domain [2^-7, 2 pi] (ref/sweep.c), every 16th
   below it (the polynomial near 0), a seeded full-range sample, the
   directed list and the hard inputs: within 1 ULP */
static void sweep_exact(pf_func f, pf_fn1 fn, const char *what, int thin)
{
    pf_sweep_stats s;
    pf_sweep_init(&s);
    uint32_t lo, hi;
    pf_sweep_reduced_range(f, &lo, &hi);
    if (thin) {
        for (uint32_t b = lo; b <= hi; b += thin)
            pf_sweep_one(&s, f, fn, NULL, asf(b), 1);
    } else {
        pf_sweep_bits(&s, f, fn, NULL, lo, hi, 0);
    }
    for (uint32_t b = 0x39800000u; b < lo; b += 16) /* [2^-12, 2^-7) */
        pf_sweep_one(&s, f, fn, NULL, asf(b), 1);
    for (uint32_t b = 0; b < 0x39800000u; b += 4099) /* below: f(x) = x or 1 */
        pf_sweep_one(&s, f, fn, NULL, asf(b), 1);
    pf_sweep_random(&s, f, fn, NULL, 20261121, 1u << 21);
    pf_sweep_directed(&s, f, fn, NULL);
    static float hv[1 << 20];
    int n = hard_list(hv, 1 << 20, 1 << 17, 7);
    for (int i = 0; i < n; i++)
        pf_sweep_one(&s, f, fn, NULL, hv[i], 1);
    pf_sweep_print(stdout, what, f, &s);
    assert_true(s.max_ulp <= 1.0);
}

static void *emit_and_load(const char *args, const char *sym, void **fn)
{
    char a[512], err[512], path[96];
    tu_scratch(path, "trig.c");
    snprintf(a, sizeof a, "%s -o %s", args, path);
    tu_run_result *r = malloc(sizeof *r);
    tu_runs("pfmathgen", a, r);
    assert_int_equal(r->status, 0);
    free(r);
    void *h = pf_compile_load_file(path, err, sizeof err);
    if (!h)
        print_message("%s\n", err);
    assert_non_null(h);
    unlink(path);
    *fn = dlsym(h, sym);
    assert_non_null(*fn);
    return h;
}

/* pfmathgen's own output, compiled here (the library's copies are the same
   text: tests/check-regen.sh) */
static void test_emitted_exact(void **st)
{
    (void)st;
    for (int k = 0; k < 3; k++) {
        void *fn;
        char args[64], sym[32];
        snprintf(args, sizeof args, "--func %s --no-sweep", fns[k].name);
        snprintf(sym, sizeof sym, "pf_%sf", fns[k].name);
        void *h = emit_and_load(args, sym, &fn);
        pf_fn1 f = (pf_fn1)(uintptr_t)fn;
        char what[64];
        snprintf(what, sizeof what, "emitted %s (every 61st float)", sym);
        sweep_exact(fns[k].f, f, what, 61);
        dlclose(h);
    }
}

static void test_library_exact(void **st)
{
    (void)st;
    for (int k = 0; k < 3; k++) {
        char what[64];
        snprintf(what, sizeof what, "libpfmath pf_%sf", fns[k].name);
        sweep_exact(fns[k].f, fns[k].exact, what, 0);
    }
}

/* The named cases, and tan's sign on either side of its pole at pi/2. */
static void test_hard_cases(void **st)
{
    (void)st;
    float x22 = 1e22f;
    for (int k = 0; k < 3; k++) {
        assert_true(pfref_ulp_err(fns[k].f, fns[k].exact(x22), x22, 1) <= 1.0);
        assert_true(pfref_ulp_err(fns[k].f, fns[k].exact(-x22), -x22, 1) <= 1.0);
    }
    /* 0x1.921fb4p+0 < pi/2 < 0x1.921fb6p+0: tan = +1.3e7, -2.3e7 */
    float below = asf(0x3fc90fdau), above = asf(0x3fc90fdbu);
    assert_true(pf_tanf(below) > 1e7f && pf_tanf(above) < -1e7f);
    assert_true(pf_tanf_fast(below) > 1e7f && pf_tanf_fast(above) < -1e7f);
    assert_true(pf_tanf(-below) < -1e7f && pf_tanf(-above) > 1e7f);
    assert_true(pfref_ulp_err(PF_TAN, pf_tanf(above), above, 1) <= 1.0);
    assert_true(pfref_ulp_err(PF_COS, pf_cosf(above), above, 1) <= 1.0);
    /* the searched worst cases were checked in sweep_exact; that list must
       reach the known depth of float's worst case (~2^-29.9 of pi/2) */
    double dmin = 1;
    for (int i = 0; i < nhard; i++)
        dmin = fmin(dmin, hard_dist[i]);
    assert_true(dmin < 0x1p-29);
}

/* IEEE / C99 Annex F values (the table tests/special/trig.txt checks them
   too); tiny arguments go through p'(0) = 1 exactly. */
static void test_special(void **st)
{
    (void)st;
    for (int k = 0; k < 3; k++)
        for (int v = 0; v < 2; v++) {
            pf_fn1 fn = v ? fns[k].fast : fns[k].exact;
            assert_true(isnan(fn(INFINITY)) && isnan(fn(-INFINITY)) && isnan(fn(NAN)) && isnan(fn(-NAN)));
            if (fns[k].f == PF_COS) {
                assert_true(fn(0.0f) == 1.0f && fn(-0.0f) == 1.0f);
                assert_true(fn(asf(1)) == 1.0f && fn(0x1p-13f) == 1.0f);
            } else {
                assert_true(asu(fn(0.0f)) == 0 && asu(fn(-0.0f)) == 0x80000000u);
                for (uint32_t b = 1; b < 0x39800000u; b = b * 3 + 1) /* |x| < 2^-12: f(x) = x */
                    assert_true(fn(asf(b)) == asf(b) && fn(-asf(b)) == -asf(b));
            }
        }
}

/* ---- fast variants ---- */

/* relative error of fn(x); *abs_err (may be NULL) gets the absolute one */
static double rel_err(pf_func f, pf_fn1 fn, float x, double *abs_err)
{
    double ex = pfref_exact_d(f, x, 1), got = fn(x);
    if (abs_err)
        *abs_err = fabs(got - ex);
    return ex == 0 ? fabs(got) : fabs(got - ex) / fabs(ex);
}

/* The fast variants' bound (issue 13): |got - f(x)| <= max(2^-10 |f(x)|,
   2^-11) for every finite float.  Returns the error over that allowance
   (<= 1 within the bound; NaN counts as over). */
static double fast_excess(pf_func f, pf_fn1 fn, float x)
{
    double ex = pfref_exact_d(f, x, 1), got = fn(x);
    double e = fabs(got - ex) / fmax(0x1p-10 * fabs(ex), 0x1p-11);
    return e == e ? e : INFINITY;
}

/* The fast bound max(2^-10 relative, 2^-11 absolute) for |x| <= 2^17 (the
   Cody-Waite lanes): every 61st float of either sign and every hard input
   there; tan's reduction keeps r's relative accuracy next to the poles, so
   tan is held to 2^-10 relative as well.  Beyond 2^17 (Payne-Hanek lanes) the
   hard inputs up to 2^127, 1e22, 1e30 and FLT_MAX keep the bound too. */
static void test_fast_bound(void **st)
{
    (void)st;
    static float hv[1 << 20];
    int nh = hard_list(hv, 1 << 20, 83443, 1); /* k pi/2 <= 2^17 */
    for (int k = 0; k < 3; k++) {
        double worst = 0, wrel = 0, wabs = 0;
        float wx = 0;
#pragma omp parallel
        {
            double lw = 0, lr = 0, la = 0;
            float lx = 0;
#pragma omp for schedule(static)
            for (uint32_t b = 0; b <= 0x48000000u; b += 61)
                for (int s = 0; s < 2; s++) {
                    float x = asf(b | (s ? 0x80000000u : 0));
                    double e = fast_excess(fns[k].f, fns[k].fast, x), a;
                    if (e > lw)
                        lw = e, lx = x;
                    lr = fmax(lr, rel_err(fns[k].f, fns[k].fast, x, &a));
                    la = fmax(la, a);
                }
#pragma omp critical
            {
                if (lw > worst)
                    worst = lw, wx = lx;
                wrel = fmax(wrel, lr);
                wabs = fmax(wabs, la);
            }
        }
        double hbig = 0;
        float hbx = 0;
        for (int i = 0; i < nh; i++) {
            if (!isfinite(hv[i]))
                continue;
            double e = fast_excess(fns[k].f, fns[k].fast, hv[i]);
            if (fabsf(hv[i]) <= 0x1p17f) {
                if (e > worst)
                    worst = e, wx = hv[i];
                wrel = fmax(wrel, rel_err(fns[k].f, fns[k].fast, hv[i], NULL));
            } else if (e > hbig) {
                hbig = e, hbx = hv[i];
            }
        }
        print_message("%s fast, |x| <= 2^17: %.3f of the bound at %a (max rel error 2^%.2f, abs 2^%.2f); "
                      "hard inputs beyond: %.3f of the bound at %a\n",
                      fns[k].name, worst, wx, log2(wrel), log2(wabs), hbig, hbx);
        assert_true(worst <= 1);
        assert_true(hbig <= 1);
        if (fns[k].f == PF_TAN)
            assert_true(wrel <= 0x1p-10);
    }
}

/* beyond 2^17: the bound for a dense sample and the ends of every binade;
   sin and cos within [-1, 1] */
static void test_fast_huge(void **st)
{
    (void)st;
    uint64_t s = 77;
    double worst[3] = {0, 0, 0};
    for (int i = 0; i < (1 << 20) + 2 * 256; i++) {
        float x;
        if (i < 1 << 20) {
            s = s * 6364136223846793005ull + 1442695040888963407ull;
            uint32_t b = (uint32_t)(s >> 32);
            x = asf(0x48000000u + b % (0x7f800000u - 0x48000000u));
        } else {
            int j = i - (1 << 20);
            x = asf((uint32_t)(j / 2) << 23 | (j & 1 ? 0x7fffffu : 0));
            if (!isfinite(x))
                continue;
        }
        for (int sg = 0; sg < 2; sg++, x = -x) {
            assert_true(fabsf(pf_sinf_fast(x)) <= 1 && fabsf(pf_cosf_fast(x)) <= 1);
            for (int k = 0; k < 3; k++)
                worst[k] = fmax(worst[k], fast_excess(fns[k].f, fns[k].fast, x));
        }
    }
    print_message("fast, sample of |x| >= 2^17: sin %.3f, cos %.3f, tan %.3f of the bound\n", worst[0],
                  worst[1], worst[2]);
    for (int k = 0; k < 3; k++)
        assert_true(worst[k] <= 1);
    /* and |sin|, |cos| <= 1 right at the ends of the polynomial's domain */
    for (uint32_t b = 0x3f000000u; b < 0x40000000u; b++) {
        float x = asf(b);
        assert_true(fabsf(pf_sinf_fast(x)) <= 1 && fabsf(pf_cosf_fast(x)) <= 1);
    }
}

/* Slope continuity at the folds: sin at (k + 1/2) pi, cos at (k + 1/2) pi
   (its even polynomial's folds, where q(pi/2) = 0 must hold too: a value
   jump shows as a slope jump) and at k pi (where the exact variant's
   sin(x + pi/2) folds), tan at (n + 1/2) pi/2.  The one-sided difference quotients of the fast function,
   minus those of the true function (which differ by about h f''), agree to
   within float rounding (8 ulps of f over h), 2^-10 of the slope and 2^-5 of
   the curvature term h f'' (the error's own curvature at the fold).  A
   polynomial not matched in slope at the domain's end jumps by twice its
   slope error there, ~2^-6 for an unconstrained fit of this accuracy: far
   above the tolerance (~2^-13). */
static void seams(const trig_fn *t, double first, double period, double fpp)
{
    int checked = 0;
    for (int k = 0; k < 4000; k += k < 200 ? 1 : 97) {
        double xs_d = first + k * period;
        if (xs_d > 0x1p17)
            break;
        float xs = (float)xs_d;
        float ulp = nextafterf(xs, INFINITY) - xs;
        float h = fmaxf(0x1p-10f, 16 * ulp);
        double fm = t->fast(xs - h), f0 = t->fast(xs), fp = t->fast(xs + h);
        double em = pfref_exact_d(t->f, xs - h, 1), e0 = pfref_exact_d(t->f, xs, 1),
               ep = pfref_exact_d(t->f, xs + h, 1);
        double left = (f0 - fm) / h, right = (fp - f0) / h;
        double tleft = (e0 - em) / h, tright = (ep - e0) / h;
        double jump = (left - right) - (tleft - tright);
        double tol = 8 * fabs(f0) * 0x1p-24 / h + 0x1p-10 * (fabs(tleft) + fabs(tright)) + 0x1p-5 * h * fpp;
        if (!(fabs(jump) <= tol))
            print_message("%s fast: slope jump %.3g > %.3g at the fold %a\n", t->name, jump, tol, xs);
        assert_true(fabs(jump) <= tol);
        checked++;
    }
    assert_true(checked > 100);
}

static void test_fast_seams(void **st)
{
    (void)st;
    const double pi = 3.14159265358979323846;
    seams(&fns[0], pi / 2, pi, 1);     /* |sin''| = 1 at the fold */
    seams(&fns[1], pi / 2, pi, 1);     /* |cos''| <= 1 near its zeros */
    seams(&fns[1], pi, pi, 1);
    seams(&fns[2], pi / 4, pi / 2, 4); /* tan'' = 2 tan sec^2 = 4 at pi/4 */
}

/* ---- array forms ---- */
/* Three mixes, so each of the array form's block paths runs: half random
   bits (most blocks hold many rare lanes: both paths, selected), every
   37th lane rare (a few per block: Cody-Waite, then the rare lanes one by
   one) and none rare but specials at the start; also in place (y == x). */
static void test_arrays_match_scalar(void **st)
{
    (void)st;
    enum { N = 4099 };
    static float x[N], y[N], z[N];
    void (*arr[6])(const float *, float *, size_t) = {pf_sinf_array, pf_sinf_fast_array, pf_cosf_array,
                                                       pf_cosf_fast_array, pf_tanf_array, pf_tanf_fast_array};
    float (*sc[6])(float) = {pf_sinf, pf_sinf_fast, pf_cosf, pf_cosf_fast, pf_tanf, pf_tanf_fast};
    for (int mix = 0; mix < 3; mix++) {
        uint64_t s = 5 + (uint64_t)mix;
        for (int i = 0; i < N; i++) {
            s = s * 6364136223846793005ull + 1442695040888963407ull;
            uint32_t b = (uint32_t)(s >> 32);
            float small = ((float)(b >> 8) * 0x1p-24f - 0.5f) * 2000;
            int rare = mix == 0 ? i & 1 : mix == 1 ? i % 37 == 5 : 0;
            x[i] = rare ? asf(b) : small;
        }
        if (mix != 2)
            x[0] = INFINITY, x[1] = -0.0f, x[2] = NAN, x[3] = 1e22f, x[4] = FLT_MAX;
        else
            x[0] = 0.0f, x[1] = -0.0f, x[2] = 0x1p-140f;
        for (int f = 0; f < 6; f++) {
            arr[f](x, y, N);
            memcpy(z, x, sizeof z);
            arr[f](z, z, N); /* in place */
            for (int i = 0; i < N; i++) {
                float w = sc[f](x[i]);
                assert_true(memcmp(&w, &y[i], 4) == 0 || (isnan(w) && isnan(y[i])));
                assert_true(memcmp(&w, &z[i], 4) == 0 || (isnan(w) && isnan(z[i])));
            }
        }
    }
}

static int setup(void **st)
{
    (void)st;
    init_twoopi_bits();
    find_hard_inputs();
    return 0;
}

/* `test_trig --fast-all`: the fast bound on every one of the 2^32 floats,
   with the worst case of each function; not part of `make test` (minutes
   on 2 cores).  Below 2^17 against glibc's double functions
   (pfref_exact_d).  Above, glibc's reduction of huge doubles is slow, so a
   first estimate takes the exact variant, pf_<f>f, which the exhaustive
   MPFR sweep (`make sweep`) proves within 1 ULP, 2^-23 relative, of f(x):
   |fast - f| <= |fast - exact| + 2^-23 |f|.  Where that estimate is above
   3/4 of the bound, pfref_exact_d decides. */
static int fast_all(void)
{
    int bad = 0;
    for (int k = 0; k < 3; k++) {
        double worst = 0, wrel = 0;
        float wx = 0;
        long nref = 0;
#pragma omp parallel
        {
            double lw = 0, lr = 0;
            float lx = 0;
            long lref = 0;
#pragma omp for schedule(dynamic, 65536)
            for (int64_t b = 0; b < 0x100000000ll; b++) {
                float x = asf((uint32_t)b);
                if (!isfinite(x))
                    continue;
                double e;
                if (fabsf(x) <= 0x1p17f) {
                    e = fast_excess(fns[k].f, fns[k].fast, x);
                    lr = fmax(lr, rel_err(fns[k].f, fns[k].fast, x, NULL));
                } else {
                    double ex = fns[k].exact(x), got = fns[k].fast(x);
                    e = (fabs(got - ex) + 0x1p-23 * fabs(ex) / (1 - 0x1p-23)) /
                        fmax(0x1p-10 * fabs(ex) * (1 - 0x1p-23), 0x1p-11);
                    if (!(e <= 0.75)) {
                        e = fast_excess(fns[k].f, fns[k].fast, x);
                        lref++;
                    }
                }
                if (e > lw)
                    lw = e, lx = x;
            }
#pragma omp critical
            {
                if (lw > worst)
                    worst = lw, wx = lx;
                wrel = fmax(wrel, lr);
                nref += lref;
            }
        }
        printf("%s fast, every finite float: max %.4f of the bound max(2^-10 |f|, 2^-11) at %a "
               "(%ld huge inputs decided by pfref); max rel error for |x| <= 2^17: 2^%.2f\n",
               fns[k].name, worst, wx, nref, log2(wrel));
        fflush(stdout);
        bad |= !(worst <= 1);
    }
    return bad;
}

int main(int argc, char **argv)
{
    if (argc > 1 && !strcmp(argv[1], "--fast-all"))
        return fast_all();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_special),      cmocka_unit_test(test_hard_cases),
        cmocka_unit_test(test_library_exact), cmocka_unit_test(test_emitted_exact),
        cmocka_unit_test(test_fast_bound),   cmocka_unit_test(test_fast_huge),
        cmocka_unit_test(test_fast_seams),   cmocka_unit_test(test_arrays_match_scalar),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
