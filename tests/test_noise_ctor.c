/* Noise called before main (issue 11, item 6): a program's own constructor
 * -- here with the earliest priority a program may use, so it runs before
 * any default-priority constructor, the library's included -- and a
 * program linked statically with libpfmath.a (mk/noise.mk) must see the
 * default table already valid.  It used to be filled by a constructor that
 * ran after this one: pf_noise3f(3.14, 42, 7) gave -0.118.
 *
 * Checked in the constructor itself, against Perlin's published value
 * 0.13691995878400012 (same tolerance as tests/test_noise.c), for the
 * value, gradient, array, _t(NULL) and fixed-point forms; main then only
 * reports. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>

#include "pfnoise.h"

static const double PERLIN = 0.13691995878400012;
static float before[6];
static int ran;

__attribute__((constructor(101))) static void early(void)
{
    float g[3], x = 3.14f, y = 42.0f, z = 7.0f;
    before[0] = pf_noise3f(x, y, z);
    before[1] = pf_noise3f_d(x, y, z, g);
    pf_noise3f_array(NULL, &before[2], &x, &y, &z, 1);
    before[3] = pf_noise3f_t(NULL, x, y, z);
    before[4] = pf_noise3f_t(pf_noise_default_table(), x, y, z);
    /* Q16.16 input (3.14 rounds to 205783 / 65536), Q15 output */
    before[5] = (float)pf_noise3_q15(205783, 42 << 16, 7 << 16) * 0x1p-15f;
    ran = 1;
}

static void test_noise_before_main(void **state)
{
    (void)state;
    assert_int_equal(ran, 1);
    for (int i = 0; i < 5; i++)
        assert_true(fabs(before[i] - PERLIN) < 2e-6);
    assert_true(fabs(before[5] - PERLIN) < 2 * 0x1p-15); /* 1 LSB + the input's rounding */
    assert_true(before[0] == pf_noise3f(3.14f, 42.0f, 7.0f)); /* and the same as after */
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_noise_before_main)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
