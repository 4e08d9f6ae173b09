/* Steps the ladder tests share (test_ladder_log.c, test_ladder_trig.c,
 * test_ladder_atrig.c): a generated level's scalar and array forms looked up
 * in its loaded file, and the check that the array form returns the scalar
 * form's bits.  Static functions, included after <cmocka.h> and "sweep.h". */
#ifndef PF_LADDER_CHECK_H
#define PF_LADDER_CHECK_H

#include <dlfcn.h>
#include <stdio.h>

typedef void (*lc_array1)(const float *, float *, size_t);

/* NAME and NAME_array from h; both must exist */
static void lc_syms1(void *h, const char *name, pf_fn1 *s1, lc_array1 *a1)
{
    char arr[128];
    snprintf(arr, sizeof arr, "%s_array", name);
    *(void **)s1 = dlsym(h, name);
    *(void **)a1 = dlsym(h, arr);
    assert_non_null(*s1);
    assert_non_null(*a1);
}

/* the array form over x[0..n) gives, bit for bit, the scalar form's results */
static void lc_array_is_scalar(pf_fn1 s1, lc_array1 a1, const float *x, float *y, size_t n)
{
    a1(x, y, n);
    for (size_t i = 0; i < n; i++) {
        float s = s1(x[i]);
        assert_memory_equal(&s, &y[i], 4);
    }
}

#endif
