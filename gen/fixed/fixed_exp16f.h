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
/* (fixed_exp.c) a vector loop over blocks of L words, software pipelined:
   stage 1 (s1, from x + i up to the variables cv[0..nc-1]) of block i and
   stage 2 (s2, from them to r) of block i - L in one pass; store (of r at
   y + i - L) after stage 2; the scalar form for the rest; closes the
   function and its #if */
void fx_exp_pipe_loop(pf_buf *kern, const char *vt, int L, const char *s1, const char *s2, const char *const *cv, int nc,
                      const char *store, const char *scalar);

#endif
