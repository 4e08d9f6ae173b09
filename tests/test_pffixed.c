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

static int64_t ref_op(int op, int64_t a, pf_fmt fa, int64_t b, pf_fmt fb, pf_fmt out)
{
    q_fixed(rq, a, fa.exp);
    if (op == OP_CONV)
        return q_to(rq, out);
    if (op == OP_SQRT) {
        /* MPFR sqrt at 400 bits, then rint at out's lsb.  Exact square roots
         * (all ties) are exact at 400 bits; an inexact root of a*2^t differs
         * from a half-integer by more than 2^(min(t,-2)-70) > 2^-300 for the
         * |exp| <= 64 used here, far above the 2^-330 error. */
        if (a <= 0)
            return 0;
        mpfr_t m;
        mpfr_init2(m, 400);
        mpfr_set_q(m, rq, MPFR_RNDN);
        mpfr_sqrt(m, m, MPFR_RNDN);
        mpfr_mul_2si(m, m, out.exp, MPFR_RNDN);
        mpfr_rint(m, m, MPFR_RNDN);
        mpfr_get_z(rz, m, MPFR_RNDN);
        mpfr_clear(m);
        return z_sat(out);
    }
    mpq_t qb;
    mpq_init(qb);
    q_fixed(qb, b, fb.exp);
    int64_t r;
    if (op == OP_DIV && b == 0) {
        r = a >= 0 ? pf_fmt_max_stored(out) : pf_fmt_min_stored(out);
    } else {
        if (op == OP_ADD)
            mpq_add(rq, rq, qb);
        else if (op == OP_SUB)
            mpq_sub(rq, rq, qb);
        else if (op == OP_MUL)
            mpq_mul(rq, rq, qb);
        else
            mpq_div(rq, rq, qb);
        r = q_to(rq, out);
    }
    mpq_clear(qb);
    return r;
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
    default: return lo + (int64_t)(rnd() % ((uint64_t)hi - (uint64_t)lo + 1));
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
