/* The benchmark's error column is the sweep's: pfbench measures every
 * candidate on the values its array form returned (pfb_err_arrays), pfsweep
 * calls the scalar function input by input (pf_sweep_one, pf_sweep_random).
 * On the same inputs both must give the same count, maximum, worst input,
 * correctly-rounded count and histogram — so the numbers in the table and
 * the picture are the sweep's numbers.  Also: the sampler stays inside the
 * declared domains, and the Pareto front and median are right. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "pfbench.h"
#include "pfbench_fixed.h"
#include "pffixed.h"
#include "pfmath.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define N (1u << 20) /* the bench's error sample size */

static uint32_t bits(float f) { uint32_t u; memcpy(&u, &f, 4); return u; }

static const pfb_domain *domain_of(pf_func f)
{
    int n;
    const pfb_domain *d = pfb_domains(&n);
    for (int i = 0; i < n; i++)
        if (d[i].f == f)
            return &d[i];
    return NULL;
}

/* worst_x2 is compared for two-argument functions only (pf_sweep_random
   hands one-argument functions an unused second input) */
static void assert_same_stats(const pf_sweep_stats *a, const pf_sweep_stats *b, int arity)
{
    assert_int_equal(a->count, b->count);
    assert_int_equal(a->cr, b->cr);
    assert_true(a->max_ulp == b->max_ulp);
    assert_int_equal(bits(a->worst_x), bits(b->worst_x));
    if (arity == 2)
        assert_int_equal(bits(a->worst_x2), bits(b->worst_x2));
    assert_int_equal(bits(a->worst_got), bits(b->worst_got));
    for (int i = 0; i < PF_HIST_BINS; i++)
        assert_int_equal(a->hist[i], b->hist[i]);
    /* the sum is accumulated per chunk by the bench: rounding order only */
    assert_true(fabs(a->sum_ulp - b->sum_ulp) <= 1e-9 * b->sum_ulp);
}

/* pf_logf over the bench's log domain: array form + pfb_err_arrays against
   the scalar form + pf_sweep_one, input by input */
static void test_log_domain_matches_sweep(void **st)
{
    (void)st;
    const pfb_domain *d = domain_of(PF_LOG);
    assert_non_null(d);
    float *x = malloc(N * sizeof *x), *y = malloc(N * sizeof *y);
    assert_true(x && y);
    pfb_sample(d, 1, x, NULL, N);
    pf_logf_array(x, y, N);
    pf_sweep_stats b, s;
    pf_sweep_init(&b);
    pfb_err_arrays(&b, PF_LOG, x, NULL, y, N);
    pf_sweep_init(&s);
    for (size_t i = 0; i < N; i++)
        pf_sweep_one(&s, PF_LOG, pf_logf, NULL, x[i], 1.0f);
    assert_same_stats(&b, &s, 1);
    print_message("log on %s: max %.6f ULP at %a, mean %.6f, CR %.3f%%\n", d->desc, b.max_ulp,
                  (double)b.worst_x, pf_sweep_mean(&b), pf_sweep_cr_percent(&b));
    assert_true(b.max_ulp > 0 && b.max_ulp <= 1.0); /* exact variant, and not vacuous */
    free(x);
    free(y);
}

/* PFB_BITS reproduces pfsweep's seeded full-range sample: same statistics as
   pf_sweep_random (what `pfsweep --func log --seed 5 --samples N` prints as
   "seeded full-range sample") */
static void test_bits_matches_pfsweep_random(void **st)
{
    (void)st;
    pfb_domain d = {PF_LOG, "bits", "every finite float", PFB_BITS, 0, 0, PFB_BITS, 0, 0};
    const size_t n = 1u << 18;
    float *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
    assert_true(x && y);
    pfb_sample(&d, 5, x, NULL, n);
    pf_logf_array(x, y, n);
    pf_sweep_stats b, s;
    pf_sweep_init(&b);
    pfb_err_arrays(&b, PF_LOG, x, NULL, y, n);
    pf_sweep_init(&s);
    pf_sweep_random(&s, PF_LOG, pf_logf, NULL, 5, n);
    assert_same_stats(&b, &s, 1);
    free(x);
    free(y);
}

/* two-argument path: glibc's atan2f(y, x) on the atan2 domain; and the same
   values with the arguments swapped must be far off (the order is seen) */
static void test_atan2_argument_order(void **st)
{
    (void)st;
    const pfb_domain *d = domain_of(PF_ATAN2);
    assert_non_null(d);
    const size_t n = 1u << 16;
    float *yv = malloc(n * sizeof *yv), *xv = malloc(n * sizeof *xv), *o = malloc(n * sizeof *o);
    assert_true(yv && xv && o);
    pfb_sample(d, 3, yv, xv, n);
    for (size_t i = 0; i < n; i++)
        o[i] = atan2f(yv[i], xv[i]);
    pf_sweep_stats b, s;
    pf_sweep_init(&b);
    pfb_err_arrays(&b, PF_ATAN2, yv, xv, o, n);
    pf_sweep_init(&s);
    for (size_t i = 0; i < n; i++)
        pf_sweep_one(&s, PF_ATAN2, NULL, atan2f, yv[i], xv[i]);
    assert_same_stats(&b, &s, 2);
    assert_true(b.max_ulp < 2);
    for (size_t i = 0; i < n; i++)
        o[i] = atan2f(xv[i], yv[i]);
    pf_sweep_init(&b);
    pfb_err_arrays(&b, PF_ATAN2, yv, xv, o, n);
    assert_true(b.max_ulp > 1e6);
    free(yv);
    free(xv);
    free(o);
}

/* a candidate one ULP off everywhere: the error column must say (1, 1.5]
   and nothing correctly rounded (built on the correctly rounded result, not
   on pf_logf, whose own error may now reach 0.9 ULP) */
static float logf_plus_ulp(float x) { return nextafterf(pfref_f_fast(PF_LOG, x, 0), INFINITY); }

static void test_detects_one_ulp(void **st)
{
    (void)st;
    const pfb_domain *d = domain_of(PF_LOG);
    const size_t n = 1u << 16;
    float *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
    assert_true(x && y);
    pfb_sample(d, 9, x, NULL, n);
    for (size_t i = 0; i < n; i++)
        y[i] = logf_plus_ulp(x[i]);
    pf_sweep_stats b, s;
    pf_sweep_init(&b);
    pfb_err_arrays(&b, PF_LOG, x, NULL, y, n);
    pf_sweep_init(&s);
    for (size_t i = 0; i < n; i++)
        pf_sweep_one(&s, PF_LOG, logf_plus_ulp, NULL, x[i], 1.0f);
    assert_same_stats(&b, &s, 1);
    assert_true(b.max_ulp > 1.0 && b.max_ulp <= 1.6);
    assert_true(pf_sweep_mean(&b) > 0.5);
    assert_true(b.cr < n / 100);
    free(x);
    free(y);
}

/* every declared domain: samples inside it, both halves visited, the first k
   of an n-sample are the k-sample (the timing inputs are the error sample's
   first 2^16) */
static void test_sampler(void **st)
{
    (void)st;
    int nd;
    const pfb_domain *d = pfb_domains(&nd);
    assert_true(nd >= 11);
    enum { M = 1 << 14 };
    static float x[M], x2[M], p[100], p2[100];
    int seen[PF_NFUNCS] = {0};
    for (int k = 0; k < nd; k++) {
        seen[d[k].f] = 1;
        pfb_sample(&d[k], 11, x, x2, M);
        pfb_sample(&d[k], 11, p, p2, 100);
        int two = pfref_arity(d[k].f) == 2;
        assert_memory_equal(p, x, sizeof p);
        if (two)
            assert_memory_equal(p2, x2, sizeof p2);
        double mid = d[k].dist == PFB_LOGUNIFORM ? sqrt(d[k].lo * d[k].hi)
                   : d[k].dist == PFB_LOGSYM ? 0 : 0.5 * (d[k].lo + d[k].hi);
        int below = 0;
        for (int i = 0; i < M; i++) {
            float v = d[k].dist == PFB_LOGSYM ? fabsf(x[i]) : x[i];
            assert_true(v >= (float)d[k].lo && v <= (float)d[k].hi);
            if (two)
                assert_true(x2[i] >= (float)d[k].lo2 && x2[i] <= (float)d[k].hi2);
            below += x[i] < mid;
        }
        /* a fair coin 2^14 times: 0.5 +- 0.03 is > 7 sigma */
        assert_true(fabs((double)below / M - 0.5) < 0.03);
    }
    for (int f = 0; f < PF_NFUNCS; f++)
        if (f != PF_SQRT)
            assert_true(seen[f]); /* every float function has a domain */
}

static void test_pareto_and_median(void **st)
{
    (void)st;
    /* (t, e): a dominates c and e; b and d trade off; f absent */
    double t[6] = {1, 0.5, 2, 3, 1, NAN}, e[6] = {1, 4, 2, 0.5, 1.5, 0.1};
    int on[6];
    pfb_pareto(t, e, 6, on);
    int want[6] = {1, 1, 0, 1, 0, 0};
    assert_memory_equal(on, want, sizeof want);
    /* ties: two identical points are both on the front */
    double t2[2] = {1, 1}, e2[2] = {2, 2};
    int on2[2];
    pfb_pareto(t2, e2, 2, on2);
    assert_true(on2[0] && on2[1]);
    double v[5] = {5, 1, 4, 2, 3}, med, mn, mx;
    pfb_median(v, 5, &med, &mn, &mx);
    assert_true(med == 3 && mn == 1 && mx == 5);
    double w[4] = {4, 1, 3, 2};
    pfb_median(w, 4, &med, &mn, &mx);
    assert_true(med == 2.5 && mn == 1 && mx == 4);
}

/* a goal's measured value never prints as the goal itself unless equal:
   0.997 against 1 would read "1.00x" beside MISS with two decimals */
static void test_goal_text(void **st)
{
    (void)st;
    static const struct {
        double m, want;
        const char *unit, *text;
    } c[] = {
        {0.997, 1.0, "x", "0.997x"},
        {0.99996, 1.0, "x", "0.99996x"},
        {1.5004, 1.5, "x", "1.5004x"},
        {1.5, 1.5, "x", "1.50x"},
        {1.2345, 1.5, "x", "1.23x"},
        {0.81, 1.0, "", "0.81"},
        /* closer than 10^-6: six decimals, the most it prints (a tie at this precision) */
        {1.0 - 1e-9, 1.0, "x", "1.000000x"},
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
        char b[64];
        pfb_goal_fmt(b, sizeof b, c[i].m, c[i].want, c[i].unit);
        assert_string_equal(b, c[i].text);
    }
}

/* the fixed-point rows' machinery, on pffixed.h's correctly rounded sqrt
   (ufixed<16,8> -> ufixed<16,12>): every input visited once, max error
   <= 0.5 LSB, and 1 LSB more when the result is bumped by one */
static const pf_fmt fx_in = {0, 16, 8}, fx_out = {0, 16, 12};
static uint16_t fx_sqrt(uint16_t a) { return (uint16_t)pf_fx_sqrt(a, fx_in, fx_out); }
static uint16_t fx_sqrt_bumped(uint16_t a)
{
    int64_t r = pf_fx_sqrt(a, fx_in, fx_out);
    return (uint16_t)(r < 65535 ? r + 1 : r);
}
static void fx_sqrt_array(const uint16_t *x, uint16_t *y, size_t n)
{
    for (size_t i = 0; i < n; i++)
        y[i] = fx_sqrt(x[i]);
}

static void test_fixed_rows(void **st)
{
    (void)st;
    const pfb_fixed_row r = {PF_SQRT, "sqrt", "ufixed<16,8>", "ufixed<16,12>", PFB_U16, PFB_U16, 8, 12, 0, 256};
    static uint16_t in[1 << 16], out[1 << 16];
    static unsigned char seen[1 << 16];
    assert_int_equal(pfb_fx_inputs(&r, 1, in, 1u << 20), 1u << 16);
    for (size_t i = 0; i < 1u << 16; i++)
        seen[in[i]]++;
    for (size_t i = 0; i < 1u << 16; i++)
        assert_int_equal(seen[i], 1);
    uint16_t (*f)(uint16_t) = fx_sqrt, (*g)(uint16_t) = fx_sqrt_bumped;
    void (*fa)(const uint16_t *, uint16_t *, size_t) = fx_sqrt_array;
    void *pf, *pg, *pa;
    memcpy(&pf, &f, sizeof pf);
    memcpy(&pg, &g, sizeof pg);
    memcpy(&pa, &fa, sizeof pa);
    double mx, mean;
    int64_t worst;
    assert_int_equal(pfb_fx_loop(&r, pf, in, out, 1u << 16), 0);
    pfb_fx_err(&r, in, out, 1u << 16, &mx, &mean, &worst);
    print_message("fixed sqrt: max %.4f LSB at stored %lld, mean %.4f\n", mx, (long long)worst, mean);
    assert_true(mx <= 0.5 && mx > 0.45 && mean > 0.2 && mean < 0.3);
    memset(out, 0, sizeof out);
    assert_int_equal(pfb_fx_array(&r, pa, in, out, 1u << 16), 0);
    double mx2, mean2;
    pfb_fx_err(&r, in, out, 1u << 16, &mx2, &mean2, &worst);
    assert_true(mx2 == mx && mean2 == mean);
    assert_int_equal(pfb_fx_loop(&r, pg, in, out, 1u << 16), 0);
    pfb_fx_err(&r, in, out, 1u << 16, &mx, &mean, &worst);
    assert_true(mx > 1.45 && mx <= 1.5 && mean > 0.5);
    /* a storage pair the bench has no pointer type for is refused */
    pfb_fixed_row bad = r;
    bad.in_st = PFB_U32;
    bad.out_st = PFB_I16;
    assert_int_equal(pfb_fx_loop(&bad, pf, in, out, 1), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_log_domain_matches_sweep),
        cmocka_unit_test(test_bits_matches_pfsweep_random),
        cmocka_unit_test(test_atan2_argument_order),
        cmocka_unit_test(test_detects_one_ulp),
        cmocka_unit_test(test_sampler),
        cmocka_unit_test(test_pareto_and_median),
        cmocka_unit_test(test_goal_text),
        cmocka_unit_test(test_fixed_rows),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
