/* Per-thread MPFR environment for pfref's internal computations. */
#include "pfref_impl.h"

#include <stdio.h>
#include <stdlib.h>

void pfref__env_enter(pfref__env *save, mpfr_exp_t emin, mpfr_exp_t emax)
{
    /* Without TLS, MPFR's exponent range and flags are process-wide and two
       OpenMP threads setting them would race. */
    if (!mpfr_buildopt_tls_p()) {
        fputs("pfref: MPFR is not built thread-safe (mpfr_buildopt_tls_p() == 0)\n", stderr);
        abort();
    }
    save->emin = mpfr_get_emin();
    save->emax = mpfr_get_emax();
    save->flags = mpfr_flags_save();
    /* Both setters fail (and change nothing) only outside MPFR's absolute
       limits, which the callers here never ask for. */
    mpfr_set_emin(emin);
    mpfr_set_emax(emax);
}

void pfref__env_leave(const pfref__env *save)
{
    mpfr_set_emin(save->emin);
    mpfr_set_emax(save->emax);
    mpfr_flags_restore(save->flags, MPFR_FLAGS_ALL);
}
