/* Function table: names, arity and the MPFR dispatch. */
#include "pfref_impl.h"

#include <string.h>

static const char *const names[PF_NFUNCS] = {
    [PF_LOG] = "log",   [PF_LOG2] = "log2", [PF_EXP] = "exp",   [PF_EXP2] = "exp2",
    [PF_SIN] = "sin",   [PF_COS] = "cos",   [PF_TAN] = "tan",   [PF_ASIN] = "asin",
    [PF_ACOS] = "acos", [PF_ATAN] = "atan", [PF_ATAN2] = "atan2", [PF_SQRT] = "sqrt",
};

const char *pfref_name(pf_func f)
{
    return ((unsigned)f < PF_NFUNCS) ? names[f] : NULL;
}

int pfref_lookup(const char *name)
{
    if (name)
        for (int i = 0; i < PF_NFUNCS; i++)
            if (strcmp(name, names[i]) == 0)
                return i;
    return -1;
}

int pfref_arity(pf_func f)
{
    return f == PF_ATAN2 ? 2 : 1;
}

/* MPFR's functions are correctly rounded at any target precision, with the
   special values of C99 Annex F (atan2 included, see MPFR's manual). */
int pfref_mpfr(pf_func f, mpfr_t y, const mpfr_t x, const mpfr_t x2, mpfr_rnd_t rnd)
{
    switch (f) {
    case PF_LOG:   return mpfr_log(y, x, rnd);
    case PF_LOG2:  return mpfr_log2(y, x, rnd);
    case PF_EXP:   return mpfr_exp(y, x, rnd);
    case PF_EXP2:  return mpfr_exp2(y, x, rnd);
    case PF_SIN:   return mpfr_sin(y, x, rnd);
    case PF_COS:   return mpfr_cos(y, x, rnd);
    case PF_TAN:   return mpfr_tan(y, x, rnd);
    case PF_ASIN:  return mpfr_asin(y, x, rnd);
    case PF_ACOS:  return mpfr_acos(y, x, rnd);
    case PF_ATAN:  return mpfr_atan(y, x, rnd);
    case PF_ATAN2: return mpfr_atan2(y, x, x2, rnd);
    case PF_SQRT:  return mpfr_sqrt(y, x, rnd);
    default:
        mpfr_set_nan(y);
        return 0;
    }
}

int pfref__mpfr_flt(pf_func f, mpfr_t y, float x, float x2)
{
    mpfr_t mx, mx2;
    /* 24 bits hold any float exactly, subnormals included. */
    mpfr_inits2(24, mx, mx2, (mpfr_ptr)0);
    mpfr_set_flt(mx, x, MPFR_RNDN);
    mpfr_set_flt(mx2, x2, MPFR_RNDN);
    int t = pfref_mpfr(f, y, mx, mx2, MPFR_RNDN);
    mpfr_clears(mx, mx2, (mpfr_ptr)0);
    return t;
}
