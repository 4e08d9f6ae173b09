/* exp and exp2, fast variant in 16-bit lanes: the segment-table kernel
   (kind 2; gen/fixed/fixed_exp16f.c).  Used by fixed_exp.c only. */
#ifndef PF_FIXED_EXP16F_H
#define PF_FIXED_EXP16F_H

#include "fixed_internal.h"

/* 0: the kernel is set up and within the fast bound (G->exp.f*); -2: not
   for this type pair (the Horner form is used) */
int fx_exp16f_prep(fx_gen *G, int base2);
/* the provenance texts and the bound (G->R, G->A) */
void fx_exp16f_texts(fx_gen *G, int base2);
void fx_exp16f_budget(fx_gen *G);
/* the body, the tables and the AVX-512BW loop */
void fx_exp16f_emit(fx_gen *G, pf_buf *body, pf_buf *tabs, pf_buf *kern, int base2);

#endif
