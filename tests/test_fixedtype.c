/* fit/fixedtype.c: parsing, canonical spelling, storage choice and ranges of
 * pf_type; ranges checked against MPFR. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <float.h>
#include <math.h>
#include <mpfr.h>
#include <stdio.h>
#include <string.h>

#include "fixedtype.h"

static void expect_ok(const char *s, int is_signed, int size, int exp)
{
    pf_type t;
    char err[200] = "";
    memset(&t, 0x55, sizeof t);
    if (pf_type_parse(s, &t, err, sizeof err) != 0) {
        print_error("'%s' rejected: %s\n", s, err);
        fail();
    }
    if (t.is_float || t.is_signed != is_signed || t.size != size || t.exp != exp) {
        print_error("'%s' parsed as float=%d signed=%d size=%d exp=%d\n", s, t.is_float, t.is_signed, t.size, t.exp);
        fail();
    }
}

static void test_parse_accepts(void **state)
{
    (void)state;
    expect_ok("fixed<15,12>", 1, 15, 12);
    expect_ok("fixed < 15 , 12 >", 1, 15, 12);
    expect_ok("  fixed<15,12>\t", 1, 15, 12);
    expect_ok("fixed<15,\n12>", 1, 15, 12);
    expect_ok("signed fixed<15,12>", 1, 15, 12);
    expect_ok("signed  fixed <15,12>", 1, 15, 12);
    expect_ok("unsigned fixed<16,8>", 0, 16, 8);
    expect_ok("unsigned fixed < 16 , 8 >", 0, 16, 8);
    expect_ok("ufixed<16,8>", 0, 16, 8);
    expect_ok("ufixed <16, 8>", 0, 16, 8);
    expect_ok("fixed<1,0>", 1, 1, 0);
    expect_ok("fixed<63,0>", 1, 63, 0);
    expect_ok("fixed<7,-3>", 1, 7, -3);
    expect_ok("fixed<4,10>", 1, 4, 10);
    expect_ok("fixed< 8 , -256 >", 1, 8, -256);
    expect_ok("unsigned fixed<63,256>", 0, 63, 256);
    expect_ok("fixed<007,08>", 1, 7, 8);

    pf_type t;
    char err[100];
    assert_int_equal(pf_type_parse("float", &t, err, sizeof err), 0);
    assert_true(t.is_float);
    assert_int_equal(t.storage_bits, 32);
    assert_int_equal(pf_type_parse("  float ", &t, NULL, 0), 0);
    assert_true(t.is_float);
}

static void expect_err(const char *s, const char *want)
{
    pf_type t = pf_type_fixed(1, 5, 5), keep = t;
    char err[300];
    memset(err, 'X', sizeof err);
    if (pf_type_parse(s, &t, err, sizeof err) != -1) {
        print_error("'%s' accepted\n", s);
        fail();
    }
    assert_memory_equal(&t, &keep, sizeof t); /* untouched on error */
    assert_non_null(memchr(err, 0, sizeof err));
    assert_true(strlen(err) > 10);
    assert_null(strchr(err, '\n'));
    if (want && strcmp(err, want) != 0) {
        print_error("'%s': message '%s', want '%s'\n", s, err, want);
        fail();
    }
    /* NULL or tiny buffers are fine */
    assert_int_equal(pf_type_parse(s, &t, NULL, 0), -1);
    char small[6];
    assert_int_equal(pf_type_parse(s, &t, small, sizeof small), -1);
    assert_int_equal(strlen(small), 5);
}

static void test_parse_rejects(void **state)
{
    (void)state;
    expect_err("fixed<15>", "malformed fixed type 'fixed<15>': expected fixed<size,exp>");
    expect_err("fixed<70,3>", "fixed<70,3>: size must be 1..63");
    expect_err("fixed<0,3>", "fixed<0,3>: size must be 1..63");
    expect_err("fixed<64,0>", "fixed<64,0>: size must be 1..63");
    expect_err("fixed<-3,2>", "fixed<-3,2>: size must be 1..63");
    expect_err("  unsigned fixed<99999999999999999999,0> ", "unsigned fixed<99999999999999999999,0>: size must be 1..63");
    expect_err("fixed<15,300>", "fixed<15,300>: exp must be -256..256");
    expect_err("fixed<15,-257>", NULL);
    expect_err("fixed<15,12", "malformed fixed type 'fixed<15,12': expected fixed<size,exp>");
    expect_err("ufixed<15 12>", "malformed fixed type 'ufixed<15 12>': expected ufixed<size,exp>");
    expect_err("unsigned fixed<16;8>", "malformed fixed type 'unsigned fixed<16;8>': expected unsigned fixed<size,exp>");
    expect_err("fixed<15,12>x", NULL);
    expect_err("fixed<15,12> >", NULL);
    expect_err("fixed<15,12>>", NULL);
    expect_err("fixed<15,12> fixed<1,1>", NULL);
    expect_err("fixed15,12>", NULL);
    expect_err("fixed<,12>", NULL);
    expect_err("fixed<15,>", NULL);
    expect_err("fixed<a,3>", NULL);
    expect_err("fixed<15,1 2>", NULL);
    expect_err("fixed<15,--1>", NULL);
    expect_err("fixed<+15,1>", NULL);
    expect_err("fixed<15.0,1>", NULL);
    expect_err("fixed", NULL);
    expect_err("fixed<", NULL);
    expect_err("Fixed<15,12>", NULL);
    expect_err("signedfixed<15,12>", NULL);
    expect_err("unsigned ufixed<8,0>", NULL);
    expect_err("signed ufixed<8,0>", NULL);
    expect_err("signed float", NULL);
    expect_err("unsigned", NULL);
    expect_err("float x", NULL);
    expect_err("floats", NULL);
    expect_err("double", "malformed type 'double': expected float, fixed<size,exp>, signed fixed<size,exp>, "
                         "unsigned fixed<size,exp> or ufixed<size,exp>");
    expect_err("", NULL);
    expect_err("   ", NULL);
    expect_err(NULL, NULL);
    expect_err("fixed<15,\n12", NULL); /* the message stays one line */
    /* a very long input is cut in the message */
    char longs[400];
    memset(longs, 'z', sizeof longs - 1);
    longs[sizeof longs - 1] = 0;
    expect_err(longs, NULL);
}

/* storage: smallest of 8/16/32/64 holding size bits + a sign bit if signed */
static void test_storage(void **state)
{
    (void)state;
    static const struct { const char *s, *ctype; int bits; } c[] = {
        { "fixed<15,0>", "int16_t", 16 },           { "signed fixed<15,0>", "int16_t", 16 },
        { "fixed<16,8>", "int32_t", 32 },           { "unsigned fixed<16,8>", "uint16_t", 16 },
        { "fixed<7,3>", "int8_t", 8 },              { "ufixed<8,8>", "uint8_t", 8 },
        { "ufixed<9,0>", "uint16_t", 16 },          { "fixed<8,0>", "int16_t", 16 },
        { "fixed<31,30>", "int32_t", 32 },          { "fixed<32,30>", "int64_t", 64 },
        { "ufixed<32,0>", "uint32_t", 32 },         { "ufixed<33,0>", "uint64_t", 64 },
        { "fixed<63,0>", "int64_t", 64 },           { "ufixed<63,0>", "uint64_t", 64 },
        { "ufixed<1,0>", "uint8_t", 8 },            { "float", "float", 32 },
    };
    for (size_t i = 0; i < sizeof c / sizeof *c; i++) {
        pf_type t;
        assert_int_equal(pf_type_parse(c[i].s, &t, NULL, 0), 0);
        if (t.storage_bits != c[i].bits || strcmp(pf_type_ctype(&t), c[i].ctype) != 0) {
            print_error("%s: %d bits, %s\n", c[i].s, t.storage_bits, pf_type_ctype(&t));
            fail();
        }
    }
    /* exhaustively: the chosen C type holds every stored value, the next
     * smaller one does not */
    for (int sg = 0; sg < 2; sg++)
        for (int size = 1; size <= 63; size++) {
            pf_type t = pf_type_fixed(sg, size, 0);
            int bits = t.storage_bits;
            assert_true(bits == 8 || bits == 16 || bits == 32 || bits == 64);
            int need = size + sg; /* bits of a two's complement / unsigned word */
            assert_true(need <= bits);
            assert_true(bits == 8 || need > bits / 2);
            assert_int_equal(pf_type_ctype(&t)[0] == 'u', !sg);
        }
}

static void test_format_roundtrip(void **state)
{
    (void)state;
    char buf[64];
    pf_type t = pf_type_fixed(0, 16, 8);
    pf_type_format(&t, buf, sizeof buf);
    assert_string_equal(buf, "unsigned fixed<16,8>");
    t = pf_type_fixed(1, 15, -12);
    pf_type_format(&t, buf, sizeof buf);
    assert_string_equal(buf, "fixed<15,-12>");
    t = pf_type_float();
    pf_type_format(&t, buf, sizeof buf);
    assert_string_equal(buf, "float");
    for (int sg = 0; sg < 2; sg++)
        for (int size = 1; size <= 63; size++)
            for (int exp = -256; exp <= 256; exp += 17) {
                pf_type a = pf_type_fixed(sg, size, exp), b;
                pf_type_format(&a, buf, sizeof buf);
                assert_int_equal(pf_type_parse(buf, &b, NULL, 0), 0);
                assert_memory_equal(&a, &b, sizeof a);
                pf_fmt f = pf_type_to_fmt(&a);
                b = pf_type_from_fmt(f);
                assert_memory_equal(&a, &b, sizeof a);
            }
}

/* lsb = 2^-exp; max = (2^size - 1) 2^-exp and min = -2^size 2^-exp (signed)
 * or 0, correctly rounded: from MPFR */
static void test_ranges(void **state)
{
    (void)state;
    mpfr_t m;
    mpfr_init2(m, 128);
    for (int sg = 0; sg < 2; sg++)
        for (int size = 1; size <= 63; size++)
            for (int exp = -256; exp <= 256; exp += 5) {
                pf_type t = pf_type_fixed(sg, size, exp);
                mpfr_set_ui_2exp(m, 1, (mpfr_exp_t)size, MPFR_RNDN);
                mpfr_sub_ui(m, m, 1, MPFR_RNDN); /* exact at 128 bits */
                assert_true(mpfr_cmp_si(m, 0) > 0);
                assert_true((uint64_t)pf_type_max_stored(&t) == mpfr_get_uj(m, MPFR_RNDN));
                mpfr_mul_2si(m, m, -exp, MPFR_RNDN);
                assert_true(pf_type_max(&t) == mpfr_get_d(m, MPFR_RNDN));
                if (sg) {
                    mpfr_set_si_2exp(m, -1, (mpfr_exp_t)size, MPFR_RNDN);
                    assert_true(pf_type_min_stored(&t) == mpfr_get_sj(m, MPFR_RNDN));
                    mpfr_mul_2si(m, m, -exp, MPFR_RNDN);
                    assert_true(pf_type_min(&t) == mpfr_get_d(m, MPFR_RNDN));
                } else {
                    assert_true(pf_type_min_stored(&t) == 0);
                    assert_true(pf_type_min(&t) == 0.0);
                }
                mpfr_set_si_2exp(m, 1, -exp, MPFR_RNDN);
                assert_true(pf_type_lsb(&t) == mpfr_get_d(m, MPFR_RNDN));
            }
    mpfr_clear(m);
    pf_type f = pf_type_float();
    assert_true(pf_type_max(&f) == FLT_MAX);
    assert_true(pf_type_min(&f) == -FLT_MAX);
    assert_true(pf_type_lsb(&f) == 0.0);
    assert_true(pf_type_max_stored(&f) == 0 && pf_type_min_stored(&f) == 0);
    /* the seed's examples: fixed<10,10> is [-1, 1), fixed<15,12> is [-8, 8) */
    pf_type x = pf_type_fixed(1, 10, 10), z = pf_type_fixed(1, 15, 12);
    assert_true(pf_type_min(&x) == -1.0 && pf_type_max(&x) == 1.0 - 0x1p-10);
    assert_true(pf_type_min(&z) == -8.0 && pf_type_max(&z) == 8.0 - 0x1p-12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parse_accepts),
        cmocka_unit_test(test_parse_rejects),
        cmocka_unit_test(test_storage),
        cmocka_unit_test(test_format_roundtrip),
        cmocka_unit_test(test_ranges),
    };
    return cmocka_run_group_tests_name("fixedtype", tests, NULL, NULL);
}
