/* pfbench: fixed-point rows (see pfbench_fixed.c). */
#ifndef PFBENCH_FIXED_H
#define PFBENCH_FIXED_H

#include "pfbench.h"

size_t pfb_fx_width(pfb_store s);                       /* bytes per stored value */
int64_t pfb_fx_get(pfb_store s, const void *buf, size_t i);
/* timing/error inputs of row r into buf: every stored value (shuffled) for
   16-bit inputs, else n seeded values over [lo, hi]; returns the count */
size_t pfb_fx_inputs(const pfb_fixed_row *r, uint64_t seed, void *buf, size_t n);
/* the array form, a loop over the scalar form, a dependent chain of the
   scalar form; -1 when the (in, out) storage pair has no pointer type here */
int pfb_fx_array(const pfb_fixed_row *r, void *fn, const void *in, void *out, size_t n);
int pfb_fx_loop(const pfb_fixed_row *r, void *fn, const void *in, void *out, size_t n);
int pfb_fx_chain(const pfb_fixed_row *r, void *fn, const void *in, size_t n, int64_t *sink);
/* error in LSBs of the output type against ref/ (pfref_lsb_err), over the
   inputs whose exact result lies inside the output range (outside it the
   functions saturate by design); NAN when there are none */
void pfb_fx_err(const pfb_fixed_row *r, const void *in, const void *out, size_t n, double *max_lsb,
                double *mean_lsb, int64_t *worst_in);

#endif
