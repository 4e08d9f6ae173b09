/* Function table rows for log and log2 (see gen/funcs.h). */
#include "funcs.h"

/* ---- fit targets, in the fit variable t ---- */
static void g_log1p(mpfr_t y, const mpfr_t t, const void *c)
{
    (void)c;
    mpfr_log1p(y, t, MPFR_RNDN);
}

/* m ranges of the reductions, as the templates compute them */
#define BAL_LO (0x1.6a09e6p-1 - 1) /* float just below sqrt(2)/2, minus 1 */
#define BAL_HI (0x1.6a09e6p+0 - 1)

#define LOG_CON_ZERO {FIT_CON_VALUE, 0, "p(0) = 0"}
#define LOG_CON_SLOPE(s) {FIT_CON_DERIV, 0, s}

const pf_spec pf_specs_log[] = {
    {"log", "balanced", "exact", "log_balanced", 1,
     "x = 2^k m, m in [0x1.6a09e6p-1, 0x1.6a09e6p+0) (balanced about 1), t = m - 1",
     "log(1+t)", g_log1p, BAL_LO, BAL_HI, FIT_PARITY_NONE, FIT_REL, 2,
     {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1")}, 10, 0, "double",
     "0x1.62e42fefa39efp-1", 1.0, NULL, NULL, NULL},
    {"log", "balanced", "fast", "log_balanced", 1,
     "x = 2^k m, m in [0x1.6a09e6p-1, 0x1.6a09e6p+0) (balanced about 1), t = m - 1",
     "log(1+t)", g_log1p, BAL_LO, BAL_HI, FIT_PARITY_NONE, FIT_REL, 6,
     {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1"),
      {FIT_CON_VALUE, BAL_LO, "p(a) = log(1+a)"}, {FIT_CON_DERIV, BAL_LO, "p'(a) = 1/(1+a)"},
      {FIT_CON_VALUE, BAL_HI, "p(b) = log(1+b)"}, {FIT_CON_DERIV, BAL_HI, "p'(b) = 1/(1+b)"}},
     0, 0x1p-10, "float", "0x1.62e42fefa39efp-1", 0, NULL, NULL, NULL},
    {"log", "seed", "exact", "log_seed", 1,
     "x = 2^k m, m in [1, 2) (the seed's reduction), t = m - 1",
     "log(1+t)", g_log1p, 0, 1, FIT_PARITY_NONE, FIT_REL, 2,
     {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1")}, 10, 0, "double",
     "0x1.62e42fefa39efp-1", 0, NULL, NULL, NULL},
    {"log", "seed", "fast", "log_seed", 1,
     "x = 2^k m, m in [1, 2) (the seed's reduction), t = m - 1",
     "log(1+t)", g_log1p, 0, 1, FIT_PARITY_NONE, FIT_REL, 4,
     {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1"),
      {FIT_CON_VALUE, 1, "p(1) = log 2"}, {FIT_CON_DERIV, 1, "p'(1) = 1/2"}},
     0, 0x1p-10, "float", "0x1.62e42fefa39efp-1", 0, NULL, NULL, NULL},
    {"log2", "balanced", "exact", "log_balanced", 1,
     "x = 2^k m, m in [0x1.6a09e6p-1, 0x1.6a09e6p+0) (balanced about 1), t = m - 1",
     "log(1+t)", g_log1p, BAL_LO, BAL_HI, FIT_PARITY_NONE, FIT_REL, 2,
     {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1")}, 10, 0, "double", "1.0", 1.0,
     "0x1.71547652b82fep+0", NULL, NULL},
    {"log2", "balanced", "fast", "log_balanced", 1,
     "x = 2^k m, m in [0x1.6a09e6p-1, 0x1.6a09e6p+0) (balanced about 1), t = m - 1",
     "log(1+t)", g_log1p, BAL_LO, BAL_HI, FIT_PARITY_NONE, FIT_REL, 6,
     {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1"),
      {FIT_CON_VALUE, BAL_LO, "p(a) = log(1+a)"}, {FIT_CON_DERIV, BAL_LO, "p'(a) = 1/(1+a)"},
      {FIT_CON_VALUE, BAL_HI, "p(b) = log(1+b)"}, {FIT_CON_DERIV, BAL_HI, "p'(b) = 1/(1+b)"}},
     0, 0x1p-10, "float", "1.0", 0, "0x1.71547652b82fep+0", NULL, NULL},
    {0},
};
