/* The table-driven reduction of log and log2 (gen/float/funcs_logtab.c). */
#ifndef PF_FUNCS_LOGTAB_H
#define PF_FUNCS_LOGTAB_H

#include "funcs.h"

#include <stddef.h>
#include <stdint.h>

/* the fit's domain, |r| <= PF_LOGTAB_R: above the table's max |r|
   (0x1.e5737p-6 for the offset pf_logtab_off chooses; the emitted file
   fails to compile with an #error if a change of the table exceeds it) */
#define PF_LOGTAB_R 0x1.e6p-6

uint32_t pf_logtab_off(void);
/* subinterval i (of 16) of offset off: z in [zl, zh], the floats it holds */
void pf_logtab_sub_range(uint32_t off, int i, double *zl, double *zh);
int pf_extra_logtab(char *buf, size_t n);
int pf_extra_log2tab(char *buf, size_t n);
int pf_model_logtab(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_log2tab(const fit_poly *p, int order, pf_scheme *sc);
/* the float-lane rows (gen/float/funcs_logtabf.c) */
int pf_extra_logtabf(char *buf, size_t n);
int pf_extra_log2tabf(char *buf, size_t n);
int pf_model_logtabf(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_log2tabf(const fit_poly *p, int order, pf_scheme *sc);
/* the same tables, compensated (variant "tabc", @NCOMP@ = 1) */
int pf_model_logtabc(const fit_poly *p, int order, pf_scheme *sc);
int pf_model_log2tabc(const fit_poly *p, int order, pf_scheme *sc);

/* the lean rows (variant "tabl", gen/templates/log_tabl.c.in): two
   tables, INVC chosen so that -log_b(INVC) is near the grid 2^-16; its fit
   domain |r| <= PF_LOGTL_R leaves the search room above the natural max |r| */
#define PF_LOGTL_R 0x1.f4p-6
int pf_extra_log2tabl(char *buf, size_t n);
int pf_model_log2tabl(const fit_poly *p, int order, pf_scheme *sc);
int pf_extra_logtabl(char *buf, size_t n);
int pf_model_logtabl(const fit_poly *p, int order, pf_scheme *sc);

#endif
