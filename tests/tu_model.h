/* The error-model check shared by the float family tests (include after
 * cmocka.h and tu_exec.h).
 *
 * The library's exact variants are emitted at the default order, where the
 * spec's error model bounds every rounding of the float scheme: that bound
 * must be within 1 ULP (the exhaustive sweep, `make sweep`, confirms it; a
 * lower order is stated above 1 ULP, not emitted silently as exact). */
#ifndef PF_TU_MODEL_H
#define PF_TU_MODEL_H

/* the model's bound pfmathgen reports for these options; negative when the
 * report says it is above 1 ULP */
static double tu_model_bound(const char *args)
{
    tu_run_result *r = malloc(sizeof *r);
    tu_runs("pfmathgen", args, r);
    assert_int_equal(r->status, 0);
    const char *p = strstr(r->err, "error model  at most ");
    assert_non_null(p);
    double b = atof(p + strlen("error model  at most "));
    int above = strstr(r->err, "above 1 ULP") != NULL;
    free(r);
    print_message("%s: error model %.3f ULP\n", args, b);
    return above ? -b : b;
}

/* every default-order exact variant in (0.5, 1] ULP, the low order above 1 */
static void tu_check_models(const char *const *args, int n, const char *low)
{
    for (int i = 0; i < n; i++) {
        double b = tu_model_bound(args[i]);
        assert_true(b > 0.5 && b <= 1.0);
    }
    assert_true(tu_model_bound(low) < -1.0);
}

#endif
