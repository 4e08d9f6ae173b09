/* libpfmath/pffixed.h against exact references: GMP rationals for
 * conversions and + - x /, MPFR for sqrt and the IEEE conversions.  The
 * references round to nearest, ties to even, and saturate, written
 * independently of the header's integer tricks.  Built twice: with
 * unsigned __int128 and with -DPF_FX_NO_INT128 (portable limbs). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <float.h>
#include <gmp.h>
#include <math.h>
#include <mpfr.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pffixed.h"

static int quick; /* PF_QUICK: fewer random cases (sanitizer runs) */

static uint64_t rng_state = 0x9e3779b97f4a7c15u;
static uint64_t rnd(void) /* splitmix64 */
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}
static int rnd_int(int lo, int hi) { return lo + (int)(rnd() % (uint64_t)(hi - lo + 1)); }

static const char *fs(pf_fmt f, char *buf)
{
    sprintf(buf, "%sfixed<%d,%d>", f.is_signed ? "" : "u", f.size, f.exp);
    return buf;
}

/* ---- reference -------------------------------------------------------- */

static mpq_t rq, rq2;
static mpz_t rz, rr, rlim;

static void q_fixed(mpq_t q, int64_t v, int exp) /* q = v * 2^-exp */
{
    mpz_set_si(rz, v);
    mpq_set_z(q, rz);
    if (exp >= 0)
        mpq_div_2exp(q, q, (unsigned long)exp);
    else
        mpq_mul_2exp(q, q, (unsigned long)-exp);
}

/* rz = x * 2^exp rounded to nearest integer, ties to even */
static void q_rne(const mpq_t x, int exp)
{
    if (exp >= 0)
        mpq_mul_2exp(rq2, x, (unsigned long)exp);
    else
        mpq_div_2exp(rq2, x, (unsigned long)-exp);
    mpz_fdiv_qr(rz, rr, mpq_numref(rq2), mpq_denref(rq2));
    mpz_mul_2exp(rr, rr, 1);
    int c = mpz_cmp(rr, mpq_denref(rq2));
    if (c > 0 || (c == 0 && mpz_odd_p(rz)))
        mpz_add_ui(rz, rz, 1);
}

/* saturate rz to f's range: [-2^size, 2^size) signed, [0, 2^size) unsigned */
static int64_t z_sat(pf_fmt f)
{
    mpz_set_ui(rlim, 1);
    mpz_mul_2exp(rlim, rlim, (unsigned long)f.size);
    if (mpz_cmp(rz, rlim) >= 0) {
        mpz_sub_ui(rz, rlim, 1);
    } else if (f.is_signed) {
        mpz_neg(rlim, rlim);
        if (mpz_cmp(rz, rlim) < 0)
            mpz_set(rz, rlim);
    } else if (mpz_sgn(rz) < 0) {
        mpz_set_ui(rz, 0);
    }
    return mpz_get_si(rz);
}

static int64_t q_to(const mpq_t x, pf_fmt f)
{
    q_rne(x, f.exp);
    return z_sat(f);
}

enum { OP_CONV, OP_ADD, OP_SUB, OP_MUL, OP_DIV, OP_SQRT };
static const char *opname[] = { "convert", "add", "sub", "mul", "div", "sqrt" };

/* rq = a op b exactly (not for sqrt, nor division by 0) */
static void exact_op(int op, int64_t a, pf_fmt fa, int64_t b, pf_fmt fb)
{
    static mpq_t qb;
    static int init;
    if (!init)
        mpq_init(qb), init = 1;
    q_fixed(rq, a, fa.exp);
    if (op == OP_CONV)
        return;
    q_fixed(qb, b, fb.exp);
    if (op == OP_ADD)
        mpq_add(rq, rq, qb);
    else if (op == OP_SUB)
        mpq_sub(rq, rq, qb);
    else if (op == OP_MUL)
        mpq_mul(rq, rq, qb);
    else
        mpq_div(rq, rq, qb);
}

/* x is a stored value of f: integral at f's lsb and inside the range */
static int q_fits(const mpq_t x, pf_fmt f)
{
    if (f.exp >= 0)
        mpq_mul_2exp(rq2, x, (unsigned long)f.exp);
    else
        mpq_div_2exp(rq2, x, (unsigned long)-f.exp);
    if (mpz_cmp_ui(mpq_denref(rq2), 1) != 0)
        return 0;
    mpz_set(rr, mpq_numref(rq2));
    mpz_set(rz, rr);
    z_sat(f);
    return mpz_cmp(rz, rr) == 0;
}

static int64_t ref_op(int op, int64_t a, pf_fmt fa, int64_t b, pf_fmt fb, pf_fmt out)
{
    if (op == OP_SQRT) {
        /* MPFR sqrt at 400 bits, then rint at out's lsb.  Exact roots (all
         * ties among them) are exact at 400 bits.  An inexact root R of
         * W = a*2^T (T = 2 eo - ea) is at least |W - h^2| / (R + h) >=
         * 2^min(T,-2) / (2R + 1) from any half-integer h, which for the
         * |exp| <= 64, R < 2^160 used here exceeds the 400-bit error
         * R * 2^-399 by far: one rounding of R, then rint, is exact. */
        if (a <= 0)
            return 0;
        mpfr_t m;
        mpfr_init2(m, 400);
        q_fixed(rq, a, fa.exp);
        mpfr_set_q(m, rq, MPFR_RNDN);
        mpfr_sqrt(m, m, MPFR_RNDN);
        mpfr_mul_2si(m, m, out.exp, MPFR_RNDN);
        mpfr_rint(m, m, MPFR_RNDN);
        mpfr_get_z(rz, m, MPFR_RNDN);
        mpfr_clear(m);
        return z_sat(out);
    }
    if (op == OP_DIV && b == 0) /* documented: x/0 -> max for x >= 0, min for x < 0 */
    {
        mpz_set_si(rz, a >= 0 ? 1 : -1);
        mpz_mul_2exp(rz, rz, 80);
        return z_sat(out);
    }
    exact_op(op, a, fa, b, fb);
    return q_to(rq, out);
}

static int64_t lib_op(int op, int64_t a, pf_fmt fa, int64_t b, pf_fmt fb, pf_fmt out)
{
    switch (op) {
    case OP_CONV: return pf_fx_convert(a, fa, out);
    case OP_ADD: return pf_fx_add(a, fa, b, fb, out);
    case OP_SUB: return pf_fx_sub(a, fa, b, fb, out);
    case OP_MUL: return pf_fx_mul(a, fa, b, fb, out);
    case OP_DIV: return pf_fx_div(a, fa, b, fb, out);
    default: return pf_fx_sqrt(a, fa, out);
    }
}

static int nfail;
static void check_op(int op, int64_t a, pf_fmt fa, int64_t b, pf_fmt fb, pf_fmt out)
{
    int64_t got = lib_op(op, a, fa, b, fb, out), want = ref_op(op, a, fa, b, fb, out);
    if (got != want && nfail++ < 10) {
        char s1[40], s2[40], s3[40];
        print_error("%s(%lld %s, %lld %s) -> %s: got %lld, want %lld\n", opname[op], (long long)a,
                    fs(fa, s1), (long long)b, fs(fb, s2), fs(out, s3), (long long)got, (long long)want);
    }
}

static int reset(void **state)
{
    (void)state;
    nfail = 0;
    return 0;
}

static void done(void)
{
    int n = nfail;
    nfail = 0;
    assert_int_equal(n, 0);
}

/* random stored value: boundaries of f (and just past them) or uniform */
static int64_t rnd_val(pf_fmt f)
{
    int64_t hi = pf_fmt_max_stored(f), lo = pf_fmt_min_stored(f);
    switch (rnd() % 8) {
    case 0: return hi;
    case 1: return lo;
    case 2: return rnd() % 2 ? hi - (int64_t)(rnd() % 3) : lo + (int64_t)(rnd() % 3);
    case 3: return (int64_t)(rnd() % 5) - 2;
    default: {
        uint64_t span = (uint64_t)hi - (uint64_t)lo + 1; /* 0: all 2^64 values */
        return (int64_t)((uint64_t)lo + (span ? rnd() % span : rnd()));
    }
    }
}

static pf_fmt rnd_fmt(int maxsize, int elo, int ehi)
{
    int s = rnd_int(1, maxsize);
    return pf_fmt_make((int)(rnd() % 2), s, rnd_int(elo, ehi));
}

/* ---- explicit boundary cases (expectations from the definitions) ------- */

static void test_fmt_basics(void **state)
{
    (void)state;
    pf_fmt s15 = pf_fmt_make(1, 15, 0), u16 = pf_fmt_make(0, 16, 8), s63 = pf_fmt_make(1, 63, 0);
    assert_int_equal(pf_fmt_max_stored(s15), 32767);
    assert_int_equal(pf_fmt_min_stored(s15), -32768);
    assert_int_equal(pf_fmt_max_stored(u16), 65535);
    assert_int_equal(pf_fmt_min_stored(u16), 0);
    assert_true(pf_fmt_max_stored(s63) == INT64_MAX);
    assert_true(pf_fmt_min_stored(s63) == INT64_MIN);
    assert_int_equal(pf_fmt_storage_bits(s15), 16);
    assert_int_equal(pf_fmt_storage_bits(u16), 16);
    assert_int_equal(pf_fmt_storage_bits(pf_fmt_make(1, 16, 8)), 32);
    assert_int_equal(pf_fmt_storage_bits(pf_fmt_make(1, 7, 3)), 8);
    assert_int_equal(pf_fmt_storage_bits(s63), 64);
}

static void test_fmt_rules(void **state)
{
    (void)state;
    /* Figure 4.8: fixed<10,10>*fixed<10,10> = fixed<20,20>; + fixed<15,12> = fixed<24,20> */
    pf_fmt x = pf_fmt_make(1, 10, 10), z = pf_fmt_make(1, 15, 12);
    pf_fmt t1 = pf_fmt_mul(x, x), t2 = pf_fmt_add(t1, z);
    assert_int_equal(t1.size, 20);
    assert_int_equal(t1.exp, 20);
    assert_int_equal(t2.size, 24);
    assert_int_equal(t2.exp, 20);
    assert_true(t2.is_signed);
    pf_fmt u = pf_fmt_make(0, 8, 4);
    assert_false(pf_fmt_add(u, u).is_signed);
    assert_true(pf_fmt_sub(u, u).is_signed);
    /* capping at 63 keeps the integer bits */
    pf_fmt big = pf_fmt_mul(pf_fmt_make(1, 40, 30), pf_fmt_make(1, 40, 35));
    assert_int_equal(big.size, 63);
    assert_int_equal(big.size - big.exp, 80 - 65);

    /* The rules hold every exact result (except the documented min*min):
     * exhaustive over small formats. */
    for (int sa = 1; sa <= 4; sa++)
        for (int sb = 1; sb <= 4; sb++)
            for (int ea = -3; ea <= 6; ea += 3)
                for (int eb = -2; eb <= 7; eb += 3)
                    for (int sg = 0; sg < 4; sg++) {
                        pf_fmt fa = pf_fmt_make(sg & 1, sa, ea), fb = pf_fmt_make(sg >> 1, sb, eb);
                        pf_fmt r[3] = { pf_fmt_mul(fa, fb), pf_fmt_add(fa, fb), pf_fmt_sub(fa, fb) };
                        for (int64_t a = pf_fmt_min_stored(fa); a <= pf_fmt_max_stored(fa); a++)
                            for (int64_t b = pf_fmt_min_stored(fb); b <= pf_fmt_max_stored(fb); b++)
                                for (int o = 0; o < 3; o++) {
                                    int minmin = o == 0 && a < 0 && b < 0 && a == pf_fmt_min_stored(fa) &&
                                                 b == pf_fmt_min_stored(fb);
                                    int op = o == 0 ? OP_MUL : o == 1 ? OP_ADD : OP_SUB;
                                    exact_op(op, a, fa, b, fb);
                                    if (q_fits(rq, r[o]) == minmin && nfail++ < 10) {
                                        char s1[40], s2[40], s3[40];
                                        print_error("%s %s %s -> %s: %lld, %lld %s\n", opname[op], fs(fa, s1), fs(fb, s2),
                                                    fs(r[o], s3), (long long)a, (long long)b,
                                                    minmin ? "fits (min*min should not)" : "does not fit");
                                    }
                                }
                    }
    done();
}

/* Rounding at and around the range ends.  from has 4 more fraction bits
 * than to, so stored value 16*k + j means k + j/16 lsb of to. */
static void test_convert_boundaries(void **state)
{
    (void)state;
    static const pf_fmt tos[] = {
        { 1, 7, 0 }, { 0, 8, 3 }, { 1, 15, 12 }, { 1, 3, -5 }, { 0, 4, 10 }, { 1, 31, 40 }, { 0, 40, -3 }, { 1, 58, 2 },
    };
    for (size_t i = 0; i < sizeof tos / sizeof *tos; i++) {
        pf_fmt to = tos[i], from = pf_fmt_make(1, to.size + 5, to.exp + 4);
        int64_t hi = pf_fmt_max_stored(to), lo = pf_fmt_min_stored(to); /* hi is odd, lo even */
        struct { int64_t k, j, want; } c[] = {
            { hi, 0, hi },          { hi, 7, hi },          /* max, just above */
            { hi, 8, hi },          /* tie max + 1/2: max + 1 is even, saturates */
            { hi, 16, hi },         { hi + 5, 0, hi },      /* beyond: saturate */
            { hi - 1, 8, hi - 1 },  /* tie (max - 1/2): down to even max - 1 */
            { hi - 2, 8, hi - 1 },  /* tie (max - 3/2): up to even max - 1 */
            { hi - 1, 9, hi },      { hi - 1, 7, hi - 1 },
            { lo, 0, lo },          { lo, 8, lo },          /* tie min + 1/2: down to even min */
            { lo + 1, 8, lo + 2 },  /* tie min + 3/2: up to even min + 2 */
            { lo - 1, 8, lo },      /* tie min - 1/2: up to even min (in range) */
            { lo - 1, 7, lo },      /* min - 9/16 -> min - 1: saturates */
            { lo - 7, 0, lo },      { 0, 8, 0 }, { 1, 8, 2 }, { -1, 8, 0 }, { -2, 8, -2 }, { 2, 8, 2 },
        };
        for (size_t t = 0; t < sizeof c / sizeof *c; t++) {
            int64_t want = c[t].want;
            if (!to.is_signed && c[t].k < 0)
                want = 0;
            int64_t v = c[t].k * 16 + c[t].j;
            int64_t got = pf_fx_convert(v, from, to);
            if (got != want) {
                char s1[40], s2[40];
                print_error("convert %lld %s -> %s: got %lld want %lld\n", (long long)v, fs(from, s1), fs(to, s2),
                            (long long)got, (long long)want);
                fail();
            }
            check_op(OP_CONV, v, from, 0, from, to);
        }
    }
    /* 64-bit extremes */
    pf_fmt s63 = pf_fmt_make(1, 63, 0), s63h = pf_fmt_make(1, 63, 1), s63d = pf_fmt_make(1, 63, -1);
    assert_true(pf_fx_convert(INT64_MAX, s63, s63h) == INT64_MAX);
    assert_true(pf_fx_convert(INT64_MIN, s63, s63h) == INT64_MIN);
    assert_true(pf_fx_convert(INT64_MIN, s63, s63d) == INT64_MIN / 2);
    assert_true(pf_fx_convert(INT64_MAX, s63, s63d) == INT64_MAX / 2 + 1); /* (2^63-1)/2: tie to even 2^62 */
    assert_true(pf_fx_convert(INT64_MIN + 1, s63, s63d) == INT64_MIN / 2);  /* -(2^62 - 1/2): tie to even */
    assert_true(pf_fx_convert(INT64_MAX, s63d, s63) == INT64_MAX);
    assert_true(pf_fx_convert(INT64_MIN, s63d, s63) == INT64_MIN);
    assert_true(pf_fx_convert(1, s63d, s63) == 2);
    assert_true(pf_fx_convert(-1, s63, pf_fmt_make(0, 63, 0)) == 0);
    assert_true(pf_fx_convert(INT64_MAX, s63, pf_fmt_make(1, 1, 0)) == 1);
    assert_true(pf_fx_convert(INT64_MIN, s63, pf_fmt_make(1, 1, 0)) == -2);
    /* huge exponent differences */
    assert_true(pf_fx_convert(INT64_MAX, pf_fmt_make(1, 63, 30000), s63) == 0);
    assert_true(pf_fx_convert(INT64_MIN, pf_fmt_make(1, 63, 30000), s63) == 0);
    assert_true(pf_fx_convert(1, pf_fmt_make(1, 63, -30000), s63) == INT64_MAX);
    assert_true(pf_fx_convert(-1, pf_fmt_make(1, 63, -30000), s63) == INT64_MIN);
    assert_true(pf_fx_convert(0, pf_fmt_make(1, 63, -30000), s63) == 0);
    done();
}

/* every stored value of 8-bit formats into many formats */
static void test_convert_exhaustive(void **state)
{
    (void)state;
    static const int exps[] = { -9, -3, 0, 1, 5, 8, 12 };
    static const int sizes[][2] = { { 1, 7 }, { 0, 8 }, { 1, 3 }, { 0, 1 }, { 1, 1 } };
    for (size_t i = 0; i < 5; i++)
        for (size_t j = 0; j < 5; j++)
            for (size_t ei = 0; ei < 7; ei++)
                for (size_t ej = 0; ej < 7; ej++) {
                    pf_fmt from = pf_fmt_make(sizes[i][0], sizes[i][1], exps[ei]);
                    pf_fmt to = pf_fmt_make(sizes[j][0], sizes[j][1], exps[ej]);
                    for (int64_t v = -300; v <= 300; v++) /* past the range too */
                        check_op(OP_CONV, v, from, 0, from, to);
                }
    done();
}

static void test_convert_random(void **state)
{
    (void)state;
    int n = quick ? 30000 : 600000;
    for (int i = 0; i < n; i++) {
        pf_fmt from = rnd_fmt(63, -80, 100), to = rnd_fmt(63, -80, 100);
        check_op(OP_CONV, rnd_val(from), from, 0, from, to);
    }
    done();
}

/* ---- float <-> fixed ---------------------------------------------------- */

static void check_from_double(double x, pf_fmt to)
{
    int64_t got = pf_fx_from_double(x, to), want;
    if (isnan(x)) {
        want = 0;
    } else if (isinf(x)) {
        mpz_set_si(rz, x > 0 ? 1 : -1);
        mpz_mul_2exp(rz, rz, 80);
        want = z_sat(to);
    } else {
        mpq_set_d(rq, x);
        want = q_to(rq, to);
    }
    if (got != want && nfail++ < 10) {
        char s1[40];
        print_error("from_double(%a) -> %s: got %lld want %lld\n", x, fs(to, s1), (long long)got, (long long)want);
    }
    if (isnan(x) || isinf(x) || (fabs(x) <= FLT_MAX && (double)(float)x == x)) {
        got = pf_fx_from_float((float)x, to);
        if (got != want && nfail++ < 10) {
            char s1[40];
            print_error("from_float(%a) -> %s: got %lld want %lld\n", x, fs(to, s1), (long long)got, (long long)want);
        }
    }
}

static void check_to_ieee(int64_t v, pf_fmt from)
{
    mpfr_t m;
    mpfr_init2(m, 64);
    mpfr_set_si_2exp(m, v, -from.exp, MPFR_RNDN); /* exact */
    double wd = mpfr_get_d(m, MPFR_RNDN), gd = pf_fx_to_double(v, from);
    float wf = mpfr_get_flt(m, MPFR_RNDN), gf = pf_fx_to_float(v, from);
    mpfr_clear(m);
    if (memcmp(&wd, &gd, sizeof wd) != 0 && nfail++ < 10) {
        char s1[40];
        print_error("to_double(%lld %s): got %a want %a\n", (long long)v, fs(from, s1), gd, wd);
    }
    if (memcmp(&wf, &gf, sizeof wf) != 0 && nfail++ < 10) {
        char s1[40];
        print_error("to_float(%lld %s): got %a want %a\n", (long long)v, fs(from, s1), (double)gf, (double)wf);
    }
}

static void test_float_conversions(void **state)
{
    (void)state;
    pf_fmt s7 = pf_fmt_make(1, 7, 3), u16 = pf_fmt_make(0, 16, 8), s63 = pf_fmt_make(1, 63, 0);
    /* specials, by definition */
    assert_true(pf_fx_from_double(NAN, s7) == 0);
    assert_true(pf_fx_from_float(-NAN, s63) == 0);
    assert_true(pf_fx_from_double(INFINITY, s7) == 127);
    assert_true(pf_fx_from_double(-INFINITY, s7) == -128);
    assert_true(pf_fx_from_double(-INFINITY, u16) == 0);
    assert_true(pf_fx_from_double(-0.0, s7) == 0);
    assert_true(pf_fx_from_double(DBL_MAX, s63) == INT64_MAX);
    assert_true(pf_fx_from_double(-DBL_MAX, s63) == INT64_MIN);
    assert_true(pf_fx_from_double(DBL_TRUE_MIN, s63) == 0);
    assert_true(pf_fx_from_double(0x1p63, s63) == INT64_MAX);
    assert_true(pf_fx_from_double(-0x1p63, s63) == INT64_MIN);
    assert_true(pf_fx_from_double(0x1p63 - 1024, s63) == INT64_MAX - 1023);
    assert_true(pf_fx_from_double(-0x1p63 - 2048, s63) == INT64_MIN);
    assert_true(pf_fx_from_double(0.0625, s7) == 0);  /* 1/2 lsb: tie to even 0 */
    assert_true(pf_fx_from_double(0.1875, s7) == 2);  /* 3/2 lsb: tie to even 2 */
    assert_true(pf_fx_from_double(-0.1875, s7) == -2);
    assert_true(pf_fx_from_double(15.9375, s7) == 127);   /* max + 1/2 lsb: saturates */
    assert_true(pf_fx_from_double(-16.0625, s7) == -128); /* min - 1/2 lsb: tie to even min */
    assert_true(pf_fx_from_double(-16.07, s7) == -128);   /* below: saturates */
    assert_true(pf_fx_to_double(-128, s7) == -16.0);
    assert_true(pf_fx_to_float(INT64_MIN, s63) == -0x1p63f);
    assert_true(pf_fx_to_double(INT64_MAX, s63) == 0x1p63);
    assert_true(isinf(pf_fx_to_float(1, pf_fmt_make(1, 7, -128))));
    assert_true(pf_fx_to_float(1, pf_fmt_make(1, 7, -127)) == 0x1p127f);
    assert_true(pf_fx_to_float(1, pf_fmt_make(1, 7, 149)) == 0x1p-149f);
    assert_true(pf_fx_to_float(1, pf_fmt_make(1, 7, 150)) == 0.0f);  /* tie to even 0 */
    assert_true(pf_fx_to_float(3, pf_fmt_make(1, 7, 151)) == 0x1p-149f);
    assert_true(pf_fx_to_double(-1, pf_fmt_make(1, 7, 1075)) == 0.0);
    assert_true(signbit(pf_fx_to_double(-1, pf_fmt_make(1, 7, 1075))));

    /* ties at every scale: (k + 1/2) lsb for random k, each way */
    for (int i = 0; i < 2000; i++) {
        pf_fmt to = rnd_fmt(52, -60, 80);
        int64_t k = rnd_val(to) / 2;
        check_from_double(ldexp((double)k + 0.5, -to.exp), to);
    }
    /* random doubles around each format's range, and specials */
    static const double spec[] = { 0.0, -0.0, DBL_TRUE_MIN, -DBL_MIN, DBL_MAX, -DBL_MAX, INFINITY, -INFINITY, NAN, 1.0, -1.0 };
    int n = quick ? 20000 : 200000;
    for (int i = 0; i < n; i++) {
        pf_fmt to = rnd_fmt(63, -100, 120);
        if (i % 16 == 1) /* subnormal and tiny doubles into very fine formats */
            to.exp = (int16_t)rnd_int(1000, 1150);
        double x;
        if (i % 16 == 0) {
            x = spec[rnd() % (sizeof spec / sizeof *spec)];
        } else {
            double m = (double)(rnd() >> 11) * 0x1p-53 + 0.5; /* [0.5, 1) */
            x = ldexp(rnd() % 2 ? -m : m, to.size - to.exp + rnd_int(-70, 3));
            if (i % 4 == 2 && fabs(x) <= FLT_MAX)
                x = (float)x;
        }
        check_from_double(x, to);
    }
    /* fixed -> IEEE: exhaustive 16-bit at several scales, then random */
    static const int exps[] = { -200, -150, -120, -10, 0, 3, 20, 140, 150, 160, 1070, 1085, 1100 };
    for (size_t e = 0; e < sizeof exps / sizeof *exps; e++)
        for (int64_t v = -32768; v <= 32767; v += quick ? 7 : 1)
            check_to_ieee(v, pf_fmt_make(1, 15, exps[e]));
    for (int i = 0; i < n; i++) {
        pf_fmt f = rnd_fmt(63, -1200, 1200);
        if (i % 2)
            f.exp = (int16_t)rnd_int(-200, 200);
        check_to_ieee(rnd_val(f), f);
    }
    done();
}

/* ---- arithmetic --------------------------------------------------------- */

/* all pairs of 8-bit stored values; formats with negative exps, exps above
 * the size, unsigned, mixed, outputs at the rule formats and trimmed ones */
static void test_arith_exhaustive8(void **state)
{
    (void)state;
    static const pf_fmt tri[][3] = {
        { { 1, 7, 7 }, { 1, 7, 7 }, { 1, 14, 14 } },  /* rule format of x */
        { { 1, 7, 7 }, { 1, 7, 7 }, { 1, 7, 7 } },    /* trimmed */
        { { 1, 7, 3 }, { 0, 8, 10 }, { 1, 9, 6 } },
        { { 0, 8, -2 }, { 1, 7, 12 }, { 0, 8, 4 } },
        { { 1, 7, 0 }, { 1, 7, -3 }, { 1, 3, -5 } },
        { { 0, 8, 8 }, { 0, 8, 4 }, { 1, 15, 30 } },
    };
    int step = quick ? 5 : 1;
    for (size_t t = 0; t < sizeof tri / sizeof *tri; t++) {
        pf_fmt fa = tri[t][0], fb = tri[t][1], out = tri[t][2];
        for (int op = OP_ADD; op <= OP_DIV; op++)
            for (int64_t a = pf_fmt_min_stored(fa); a <= pf_fmt_max_stored(fa); a += step)
                for (int64_t b = pf_fmt_min_stored(fb); b <= pf_fmt_max_stored(fb); b++)
                    check_op(op, a, fa, b, fb, out);
    }
    done();
}

static void test_arith_random(void **state)
{
    (void)state;
    int n = quick ? 20000 : 300000;
    for (int op = OP_ADD; op <= OP_DIV; op++)
        for (int i = 0; i < n; i++) {
            int kind = i % 3; /* 16-bit, 32-bit, anything up to 64 */
            int ms = kind == 0 ? 15 : kind == 1 ? 31 : 63;
            pf_fmt fa = rnd_fmt(ms, -40, 70), fb = rnd_fmt(ms, -40, 70), out;
            if (kind < 2) {
                fa.size = (int8_t)(ms + !fa.is_signed);
                fb.size = (int8_t)(ms + !fb.is_signed);
            }
            switch (i % 4) {
            case 0: out = op == OP_MUL ? pf_fmt_mul(fa, fb) : op == OP_DIV ? pf_fmt_div(fa, fb)
                        : op == OP_ADD ? pf_fmt_add(fa, fb) : pf_fmt_sub(fa, fb);
                    break;
            case 1: out = pf_fmt_make(1, ms, fa.exp + rnd_int(-3, 3)); break;
            default: out = rnd_fmt(63, -60, 100); break;
            }
            check_op(op, rnd_val(fa), fa, rnd_val(fb), fb, out);
        }
    done();
}

static void test_div_by_zero(void **state)
{
    (void)state;
    pf_fmt s = pf_fmt_make(1, 15, 8), u = pf_fmt_make(0, 16, 4);
    assert_true(pf_fx_div(5, s, 0, s, s) == 32767);
    assert_true(pf_fx_div(0, s, 0, s, s) == 32767);
    assert_true(pf_fx_div(-1, s, 0, s, s) == -32768);
    assert_true(pf_fx_div(-1, s, 0, s, u) == 0);
    assert_true(pf_fx_div(INT64_MIN, pf_fmt_make(1, 63, 0), 0, s, pf_fmt_make(1, 63, 0)) == INT64_MIN);
    /* and the largest quotients */
    pf_fmt s63 = pf_fmt_make(1, 63, 0);
    assert_true(pf_fx_div(INT64_MIN, s63, -1, s63, s63) == INT64_MAX);
    assert_true(pf_fx_div(INT64_MIN, s63, 1, s63, s63) == INT64_MIN);
    assert_true(pf_fx_div(INT64_MAX, s63, 1, pf_fmt_make(1, 63, 63), s63) == INT64_MAX);
    assert_true(pf_fx_div(1, s63, INT64_MIN, s63, pf_fmt_make(1, 63, 64)) == -2);
    assert_true(pf_fx_div(1, s63, 3, s63, pf_fmt_make(1, 7, 2)) == 1);  /* 4/3 -> 1 */
    assert_true(pf_fx_div(-1, s63, 3, s63, pf_fmt_make(1, 7, 3)) == -3); /* -8/3 -> -3 */
    assert_true(pf_fx_div(1, s63, 4, s63, pf_fmt_make(1, 7, 1)) == 0);  /* 1/2: tie to even */
    assert_true(pf_fx_div(3, s63, 4, s63, pf_fmt_make(1, 7, 1)) == 2);  /* 3/2: tie to even */
}

/* every input of unsigned fixed<16,8> into unsigned fixed<16,12> */
static void test_sqrt_exhaustive(void **state)
{
    (void)state;
    pf_fmt in = pf_fmt_make(0, 16, 8), out = pf_fmt_make(0, 16, 12);
    for (int64_t a = 0; a <= 65535; a++)
        check_op(OP_SQRT, a, in, 0, in, out);
    /* odd exponent difference, signed input, ties (sqrt(1/4) = 1/2 lsb) */
    pf_fmt in2 = pf_fmt_make(1, 15, 5), out2 = pf_fmt_make(1, 15, 7);
    for (int64_t a = -32768; a <= 32767; a += quick ? 11 : 1)
        check_op(OP_SQRT, a, in2, 0, in2, out2);
    assert_true(pf_fx_sqrt(1, pf_fmt_make(1, 7, 2), pf_fmt_make(1, 7, 0)) == 0);  /* 1/2: tie to even */
    assert_true(pf_fx_sqrt(9, pf_fmt_make(1, 7, 2), pf_fmt_make(1, 7, 0)) == 2);  /* 3/2: tie to even */
    assert_true(pf_fx_sqrt(25, pf_fmt_make(1, 7, 2), pf_fmt_make(1, 7, 0)) == 2); /* 5/2: tie to even */
    assert_true(pf_fx_sqrt(-4, pf_fmt_make(1, 7, 0), pf_fmt_make(1, 7, 0)) == 0);
    done();
}

static void test_sqrt_random(void **state)
{
    (void)state;
    int n = quick ? 10000 : 200000;
    for (int i = 0; i < n; i++) {
        pf_fmt in = rnd_fmt(63, -64, 64), out = i % 2 ? pf_fmt_sqrt(in) : rnd_fmt(63, -64, 64);
        check_op(OP_SQRT, rnd_val(in), in, 0, in, out);
    }
    done();
}

/* ---- multiply-shift and Horner ------------------------------------------ */

static int64_t ref_mulshift(int64_t a, int64_t b, int shift, int bits)
{
    mpz_set_si(rz, a);
    mpz_set_si(rr, b);
    mpz_mul(rz, rz, rr);
    mpq_set_z(rq, rz);
    q_rne(rq, -shift);
    return z_sat(pf_fmt_make(1, bits - 1, 0));
}

static void test_mulshift(void **state)
{
    (void)state;
    static const int64_t edge[] = { 0, 1, -1, 2, -2, 3, INT16_MAX, INT16_MIN, INT16_MIN + 1, INT32_MAX, INT32_MIN, INT32_MIN + 1,
                                    INT64_MAX, INT64_MIN, INT64_MIN + 1 };
    int n = quick ? 20000 : 300000;
    for (int i = 0; i < n; i++) {
        int shift = i % 8 == 0 ? rnd_int(-70, 130) : rnd_int(-3, 64);
        int64_t a = i % 5 == 0 ? edge[rnd() % 15] : (int64_t)rnd(), b = i % 7 == 0 ? edge[rnd() % 15] : (int64_t)rnd();
        int16_t a16 = (int16_t)(a & 0xffff), b16 = (int16_t)(b & 0xffff);
        int32_t a32 = (int32_t)(a & 0xffffffff), b32 = (int32_t)(b & 0xffffffff);
        if (i % 5 == 0)
            a16 = (int16_t)pf__sat16(pf__sat32(a)), a32 = pf__sat32(a);
        int64_t w16 = ref_mulshift(a16, b16, shift, 16), w32 = ref_mulshift(a32, b32, shift, 32),
                w64 = ref_mulshift(a, b, shift, 64);
        int64_t g16 = pf_mulshift16(a16, b16, shift), g32 = pf_mulshift32(a32, b32, shift), g64 = pf_mulshift64(a, b, shift);
        if ((g16 != w16 || g32 != w32 || g64 != w64) && nfail++ < 10)
            print_error("mulshift shift %d: 16: %d*%d got %lld want %lld; 32: %d*%d got %lld want %lld; "
                        "64: %lld*%lld got %lld want %lld\n",
                        shift, a16, b16, (long long)g16, (long long)w16, a32, b32, (long long)g32, (long long)w32,
                        (long long)a, (long long)b, (long long)g64, (long long)w64);
    }
    assert_int_equal(pf_mulshift16(1, 1, 1), 0);   /* 1/2: tie to even */
    assert_int_equal(pf_mulshift16(3, 1, 1), 2);   /* 3/2 */
    assert_int_equal(pf_mulshift16(-3, 1, 1), -2); /* -3/2 */
    assert_int_equal(pf_mulshift32(5, 1, 1), 2);   /* 5/2 */
    assert_int_equal(pf_mulshift32(INT32_MIN, INT32_MIN, 31), INT32_MAX); /* 2^31 saturates */
    assert_int_equal(pf_mulshift32(INT32_MIN, INT32_MAX, 31), INT32_MIN + 1);
    assert_int_equal(pf_mulshift16(INT16_MIN, INT16_MIN, 15), INT16_MAX);
    done();
}

/* Horner against a step-by-step exact evaluation:
 * p_k = sat_k(RNE(p_{k+1} x 2^-shift_k) + c_k) */
static int64_t ref_horner(int64_t x, const int64_t *c, const int8_t *shift, const pf_fmt *step, int n)
{
    int64_t p = c[n];
    for (int k = n - 1; k >= 0; k--) {
        mpz_set_si(rz, p);
        mpz_set_si(rr, x);
        mpz_mul(rz, rz, rr);
        mpq_set_z(rq, rz);
        q_rne(rq, -shift[k]);
        mpz_set_si(rr, c[k]);
        mpz_add(rz, rz, rr);
        p = z_sat(step[k]);
    }
    return p;
}

static void test_horner(void **state)
{
    (void)state;
    int n = quick ? 5000 : 100000;
    for (int i = 0; i < n; i++) {
        int deg = rnd_int(0, 9), wide = i % 2;
        pf_fmt fx = wide ? rnd_fmt(63, -10, 40) : pf_fmt_make(1, 31, rnd_int(-5, 40)), step[10];
        int64_t c[10];
        int8_t shift[10];
        int32_t c32[10];
        for (int k = 0; k <= deg; k++)
            step[k] = wide ? rnd_fmt(63, -10, 40) : pf_fmt_make(1, 31, rnd_int(-5, 40)); /* |shift| < 128 */
        for (int k = 0; k <= deg; k++) {
            c[k] = rnd_val(step[k]);
            c32[k] = (int32_t)c[k];
            if (k < deg)
                shift[k] = (int8_t)(step[k + 1].exp + fx.exp - step[k].exp);
        }
        int64_t x = rnd_val(fx);
        int64_t want = ref_horner(x, c, shift, step, deg), got = pf_fx_horner(x, c, shift, step, deg);
        int64_t got32 = wide ? want : pf_fx_horner32((int32_t)x, c32, shift, deg);
        if ((got != want || got32 != want) && nfail++ < 10)
            print_error("horner deg %d x %lld: got %lld (32-bit %lld) want %lld\n", deg, (long long)x, (long long)got,
                        (long long)got32, (long long)want);
    }
    done();
}

int main(void)
{
    quick = getenv("PF_QUICK") != NULL;
    mpq_init(rq);
    mpq_init(rq2);
    mpz_init(rz);
    mpz_init(rr);
    mpz_init(rlim);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_fmt_basics, reset),
        cmocka_unit_test_setup(test_fmt_rules, reset),
        cmocka_unit_test_setup(test_convert_boundaries, reset),
        cmocka_unit_test_setup(test_convert_exhaustive, reset),
        cmocka_unit_test_setup(test_convert_random, reset),
        cmocka_unit_test_setup(test_float_conversions, reset),
        cmocka_unit_test_setup(test_arith_exhaustive8, reset),
        cmocka_unit_test_setup(test_arith_random, reset),
        cmocka_unit_test_setup(test_div_by_zero, reset),
        cmocka_unit_test_setup(test_sqrt_exhaustive, reset),
        cmocka_unit_test_setup(test_sqrt_random, reset),
        cmocka_unit_test_setup(test_mulshift, reset),
        cmocka_unit_test_setup(test_horner, reset),
    };
    return cmocka_run_group_tests_name(PF_FX_INT128 ? "pffixed (__int128)" : "pffixed (portable)", tests, NULL, NULL);
}
