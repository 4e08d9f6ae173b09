#include "funcs.h"

#include <string.h>

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

static const pf_spec specs[] = {
    {"log", "balanced", "exact", "log_balanced", 1,
     "x = 2^k m, m in [0x1.6a09e6p-1, 0x1.6a09e6p+0) (balanced about 1), t = m - 1",
     "log(1+t)", g_log1p, BAL_LO, BAL_HI, FIT_PARITY_NONE, FIT_REL, 2,
     {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1")}, 10, 0, "double",
     "0x1.62e42fefa39efp-1", 1.0, NULL},
    {"log", "balanced", "fast", "log_balanced", 1,
     "x = 2^k m, m in [0x1.6a09e6p-1, 0x1.6a09e6p+0) (balanced about 1), t = m - 1",
     "log(1+t)", g_log1p, BAL_LO, BAL_HI, FIT_PARITY_NONE, FIT_REL, 6,
     {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1"),
      {FIT_CON_VALUE, BAL_LO, "p(a) = log(1+a)"}, {FIT_CON_DERIV, BAL_LO, "p'(a) = 1/(1+a)"},
      {FIT_CON_VALUE, BAL_HI, "p(b) = log(1+b)"}, {FIT_CON_DERIV, BAL_HI, "p'(b) = 1/(1+b)"}},
     0, 0x1p-10, "float", "0x1.62e42fefa39efp-1", 0, NULL},
    {"log", "seed", "exact", "log_seed", 1,
     "x = 2^k m, m in [1, 2) (the seed's reduction), t = m - 1",
     "log(1+t)", g_log1p, 0, 1, FIT_PARITY_NONE, FIT_REL, 2,
     {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1")}, 10, 0, "double",
     "0x1.62e42fefa39efp-1", 0, NULL},
    {"log", "seed", "fast", "log_seed", 1,
     "x = 2^k m, m in [1, 2) (the seed's reduction), t = m - 1",
     "log(1+t)", g_log1p, 0, 1, FIT_PARITY_NONE, FIT_REL, 4,
     {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1"),
      {FIT_CON_VALUE, 1, "p(1) = log 2"}, {FIT_CON_DERIV, 1, "p'(1) = 1/2"}},
     0, 0x1p-10, "float", "0x1.62e42fefa39efp-1", 0, NULL},
    {"log2", "balanced", "exact", "log_balanced", 1,
     "x = 2^k m, m in [0x1.6a09e6p-1, 0x1.6a09e6p+0) (balanced about 1), t = m - 1",
     "log(1+t)", g_log1p, BAL_LO, BAL_HI, FIT_PARITY_NONE, FIT_REL, 2,
     {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1")}, 10, 0, "double", "1.0", 1.0,
     "0x1.71547652b82fep+0"},
    {"log2", "balanced", "fast", "log_balanced", 1,
     "x = 2^k m, m in [0x1.6a09e6p-1, 0x1.6a09e6p+0) (balanced about 1), t = m - 1",
     "log(1+t)", g_log1p, BAL_LO, BAL_HI, FIT_PARITY_NONE, FIT_REL, 6,
     {LOG_CON_ZERO, LOG_CON_SLOPE("p'(0) = 1"),
      {FIT_CON_VALUE, BAL_LO, "p(a) = log(1+a)"}, {FIT_CON_DERIV, BAL_LO, "p'(a) = 1/(1+a)"},
      {FIT_CON_VALUE, BAL_HI, "p(b) = log(1+b)"}, {FIT_CON_DERIV, BAL_HI, "p'(b) = 1/(1+b)"}},
     0, 0x1p-10, "float", "1.0", 0, "0x1.71547652b82fep+0"},
};

#define NSPECS ((int)(sizeof specs / sizeof specs[0]))

int pf_spec_count(void) { return NSPECS; }
const pf_spec *pf_spec_at(int i) { return &specs[i]; }

const pf_spec *pf_spec_find(const char *func, const char *variant, const char *reduction)
{
    for (int i = 0; i < NSPECS; i++)
        if (!strcmp(specs[i].func, func) && !strcmp(specs[i].variant, variant) &&
            (!reduction || !strcmp(specs[i].reduction, reduction)))
            return &specs[i];
    return NULL;
}

int pf_spec_func_known(const char *func)
{
    for (int i = 0; i < NSPECS; i++)
        if (!strcmp(specs[i].func, func))
            return 1;
    return 0;
}

const char *pf_spec_func_list(void)
{
    static char buf[512];
    buf[0] = 0;
    for (int i = 0; i < NSPECS; i++) {
        int seen = 0;
        for (int j = 0; j < i; j++)
            if (!strcmp(specs[j].func, specs[i].func))
                seen = 1;
        if (seen)
            continue;
        if (buf[0])
            strcat(buf, ", ");
        strcat(buf, specs[i].func);
    }
    return buf;
}

void pf_spec_problem(const pf_spec *s, int order, fit_problem *pb)
{
    memset(pb, 0, sizeof *pb);
    pb->g = s->g;
    pb->a = s->a;
    pb->b = s->b;
    pb->order = order;
    pb->parity = s->parity;
    pb->errkind = s->errkind;
    pb->ncon = s->ncon;
    for (int i = 0; i < s->ncon; i++) {
        pb->con[i].kind = s->con[i].kind;
        pb->con[i].t = s->con[i].t;
    }
}
