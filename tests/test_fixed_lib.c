/* The library's default fixed-point set (libpfmath/pfmath_fixed.h): every
 * 16-bit function over all 2^16 inputs, the Q16.16 ones over every input
 * within 2^16 of 0 and a seeded sample (all 2^32: `make sweep`), against
 * MPFR; scalar and array forms agree; the defined saturations; exact
 * values (powers of two, perfect squares, sin 0, cos 0); the exact sqrt is
 * pffixed.h's correctly rounded pf_fx_sqrt; sin is odd and cos even;
 * every array form gives the same bits in place (y == x). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "funcset.h"
#include "pffixed.h"
#include "pfmath_fixed.h"
#include "sweep_fixed.h"

#include <stdlib.h>
#include <string.h>

static void *vp(void (*f)(void))
{
    void *v;
    memcpy(&v, &f, sizeof v);
    return v;
}

typedef struct {
    const char *name;
    pf_func f;
    void (*scalar)(void), (*array)(void);
    pf_fmt in, out;
    int exact;
    double exact_lsb; /* the exact variant's bound, in output LSBs */
} lib_fn;

/* the PF_FIXED rows of libpfmath/functions.def, exact and fast */
static const lib_fn fns[] = {
#define PF_FIXED(n, fn, id, ist, isg, isz, ie, ost, osg, osz, oe, lsb, lo, hi)                                 \
    {"pf_" #n, id, (void (*)(void))pf_##n, (void (*)(void))pf_##n##_array, PF_FS_FMT(isg, isz, ie),          \
     PF_FS_FMT(osg, osz, oe), 1, lsb},                                                                       \
    {"pf_" #n "_fast", id, (void (*)(void))pf_##n##_fast, (void (*)(void))pf_##n##_fast_array,               \
     PF_FS_FMT(isg, isz, ie), PF_FS_FMT(osg, osz, oe), 0, lsb},
#include "functions.def"
};
#define NFNS ((int)(sizeof fns / sizeof fns[0]))

static pf_fx_fn fx(const lib_fn *l)
{
    pf_fx_fn f = {vp(l->scalar), vp(l->array), l->in, l->out};
    return f;
}

static void test_sweeps(void **st)
{
    (void)st;
    int bad = 0;
    for (int i = 0; i < NFNS; i++) {
        const lib_fn *l = &fns[i];
        pf_fx_fn fn = fx(l);
        pf_fx_stats s;
        pf_fx_stats_init(&s);
        int64_t lo = pf_fmt_min_stored(l->in), hi = pf_fmt_max_stored(l->in);
        char title[200];
        if (pf_fmt_storage_bits(l->in) <= 16) {
            pf_fx_sweep_range(&s, l->f, &fn, lo, hi, 1, 0);
            snprintf(title, sizeof title, "%s: every input", l->name);
        } else {
            pf_fx_sweep_range(&s, l->f, &fn, -65536, 65536, 1, 0);
            pf_fx_sweep_random(&s, l->f, &fn, 0x5eed + (uint64_t)i, 1u << 18);
            snprintf(title, sizeof title, "%s: |x| <= 2^16 and 2^18 random inputs", l->name);
        }
        pf_fx_stats_print(stdout, title, l->f, l->in, l->out, &s, !l->exact);
        int ok = s.mismatch == 0 && (l->exact ? s.max_err < l->exact_lsb : s.over_fast == 0);
        if (!ok) {
            print_message("FAILED: %s\n", l->name);
            bad++;
        }
    }
    assert_int_equal(bad, 0);
}

static void test_defined_values(void **st)
{
    (void)st;
    /* saturation: exp above ln 256 is the max of unsigned fixed<16,8> */
    assert_int_equal(pf_exp_q11_uq8(32767), 65535);
    assert_int_equal(pf_exp_q11_uq8_fast(32767), 65535);
    assert_int_equal(pf_exp2_q11_uq8(8 << 11), 65535);
    assert_int_equal(pf_exp_q16(INT32_MAX), INT32_MAX);
    assert_int_equal(pf_exp2_q16(15 << 16), INT32_MAX);
    /* and underflow is 0 */
    assert_int_equal(pf_exp_q11_uq8(-32768), 0);
    assert_int_equal(pf_exp_q16(INT32_MIN), 0);
    /* log(0), log(negative): the most negative output */
    assert_int_equal(pf_log_uq8_q11(0), INT16_MIN);
    assert_int_equal(pf_log2_uq8_q11_fast(0), INT16_MIN);
    for (int32_t x = -5; x <= 0; x++) {
        assert_int_equal(pf_log_q16(x), INT32_MIN);
        assert_int_equal(pf_log2_q16(x), INT32_MIN);
        assert_int_equal(pf_log_q16_fast(x), INT32_MIN);
        assert_int_equal(pf_sqrt_q16(x), 0); /* sqrt of x <= 0: 0 */
        assert_int_equal(pf_sqrt_q16_fast(x), 0);
    }
    assert_int_equal(pf_log_q16(INT32_MIN), INT32_MIN);
    assert_int_equal(pf_sqrt_q16(INT32_MIN), 0);
    /* exact values: powers of two through exp2 and log2, sin 0, cos 0 */
    for (int k = -8; k <= 7; k++) {
        assert_int_equal(pf_exp2_q11_uq8((int16_t)(k * 2048)), 256 >> (k < 0 ? -k : 0) << (k > 0 ? k : 0));
        assert_int_equal(pf_log2_uq8_q11((uint16_t)(256u << (k + 8) >> 8)), k * 2048);
    }
    for (int k = -16; k <= 14; k++) {
        assert_int_equal(pf_exp2_q16(k * 65536), k >= -16 ? (int32_t)(((int64_t)65536 << 16 >> 16 << (k + 16)) >> 16) : 0);
        assert_int_equal(pf_log2_q16((int32_t)((int64_t)65536 << (k + 16) >> 16)), k * 65536);
    }
    assert_int_equal(pf_sin_q12_q14(0), 0);
    assert_int_equal(pf_cos_q12_q14(0), 16384);
    assert_int_equal(pf_sin_q16(0), 0);
    assert_int_equal(pf_cos_q16(0), 65536);
    assert_int_equal(pf_exp_q16(0), 65536);
    assert_int_equal(pf_log_q16(65536), 0);
    /* perfect squares: sqrt(k^2) = k */
    for (int k = 0; k < 16; k++)
        assert_int_equal(pf_sqrt_uq8_uq12((uint16_t)(k * k * 256)), k * 4096);
    for (int k = 0; k < 181; k++)
        assert_int_equal(pf_sqrt_q16(k * k * 65536), k * 65536);
}

static void test_sqrt_correctly_rounded(void **st)
{
    (void)st;
    for (int32_t x = 0; x <= 65535; x++)
        assert_int_equal(pf_sqrt_uq8_uq12((uint16_t)x), pf_fx_sqrt(x, pf_fmt_make(0, 16, 8), pf_fmt_make(0, 16, 12)));
    uint64_t s = 12345;
    for (int i = 0; i < 1 << 20; i++) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        int32_t x = (int32_t)(uint32_t)(s >> 32);
        assert_int_equal(pf_sqrt_q16(x), pf_fx_sqrt(x, pf_fmt_make(1, 31, 16), pf_fmt_make(1, 31, 16)));
    }
}

static void test_symmetry(void **st)
{
    (void)st;
    for (int32_t x = -32767; x <= 32767; x++) {
        assert_int_equal(pf_sin_q12_q14((int16_t)-x), -pf_sin_q12_q14((int16_t)x));
        assert_int_equal(pf_cos_q12_q14((int16_t)-x), pf_cos_q12_q14((int16_t)x));
        assert_int_equal(pf_sin_q12_q14_fast((int16_t)-x), -pf_sin_q12_q14_fast((int16_t)x));
    }
    uint64_t s = 777;
    for (int i = 0; i < 1 << 18; i++) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        int32_t x = (int32_t)(uint32_t)(s >> 33);
        assert_int_equal(pf_sin_q16(-x), -pf_sin_q16(x));
        assert_int_equal(pf_cos_q16(-x), pf_cos_q16(x));
    }
}

/* pfmath_fixed.h allows y == x: every array form (here, the one the CPU
   dispatches to: the AVX-512 or AVX2 loop, else the plain clone) called in
   place gives the scalar form's bits, on pieces whose lengths run through
   the ends of its loops (blocks of 16 and 32 lanes, pipelined pairs and
   fours, the scalar tail) */
static void test_in_place(void **st)
{
    (void)st;
    static const size_t piece[] = {1, 15, 16, 17, 31, 32, 33, 47, 63, 64, 65, 96, 127, 128, 129, 255, 256};
    const size_t np = sizeof piece / sizeof piece[0];
    int bad = 0;
    for (int i = 0; i < NFNS; i++) {
        const lib_fn *l = &fns[i];
        pf_fx_fn fn = fx(l);
        int64_t lo = pf_fmt_min_stored(l->in);
        size_t n = pf_fmt_storage_bits(l->in) <= 16 ? (size_t)1 << 16 : (size_t)1 << 18;
        int64_t *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
        assert_non_null(x);
        assert_non_null(y);
        uint64_t s = 0x1234567 + (uint64_t)i;
        for (size_t j = 0; j < n; j++) {
            s = s * 6364136223846793005ull + 1442695040888963407ull;
            x[j] = n == (size_t)1 << 16 ? lo + (int64_t)j : (int64_t)(int32_t)(uint32_t)(s >> 32);
        }
        size_t m;
        for (size_t at = 0, k = 0; at < n; at += m, k++) {
            m = piece[k % np] < n - at ? piece[k % np] : n - at;
            assert_true(pf_fx_call_array_inplace(&fn, x + at, y + at, m));
        }
        for (size_t j = 0; j < n; j++)
            if (y[j] != pf_fx_call_scalar(&fn, x[j])) {
                print_message("FAILED: %s_array in place gives %lld at x = %lld, the scalar form %lld\n", l->name,
                              (long long)y[j], (long long)x[j], (long long)pf_fx_call_scalar(&fn, x[j]));
                bad++;
                break;
            }
        free(x);
        free(y);
    }
    assert_int_equal(bad, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sweeps),
        cmocka_unit_test(test_defined_values),
        cmocka_unit_test(test_sqrt_correctly_rounded),
        cmocka_unit_test(test_symmetry),
        cmocka_unit_test(test_in_place),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
