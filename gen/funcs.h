/* Templates (gen/templates/<tmpl>.c.in) see these substitutions:
 *   @NAME@    emitted function name        @REAL@    evaluation type
 *   @HORNER@  pf_horner_d or pf_horner_f   @NCOEF@   entries of @NAME@_C
 *   @KSCALE@ @PSCALE@  the spec's constants (default 1)
 * @NAME@_C holds the coefficients lowest degree first; for an odd fit it
 * holds only c1, c3, c5, ... (evaluate r * @HORNER@(r*r, @NAME@_C, @NCOEF@)),
 * for an even fit c0, c2, ... (evaluate @HORNER@(r*r, ...)).
 *
 * The generator's function table: for each function, reduction and variant,
 * what is fitted (target, domain in the fit variable t, parity, constraints)
 * and which template turns the coefficients into C.  Adding a function means
 * adding a row here, a target below and a template in gen/templates/. */
#ifndef PF_FUNCS_H
#define PF_FUNCS_H

#include "fit.h"

#define PF_SPEC_MAXCON 8

typedef struct {
    const char *func;       /* "log" */
    const char *reduction;  /* the first listed for a func is its default */
    const char *variant;    /* "exact" or "fast" */
    const char *tmpl;       /* template gen/templates/<tmpl>.c.in */
    int arity;              /* 1, or 2 for atan2 */
    const char *reduction_text;  /* one line for the report/provenance */
    const char *target_text;     /* what is fitted, e.g. "log(1+t)" */
    fit_target_fn g;
    double a, b;            /* domain in t */
    int parity, errkind;
    int ncon;
    struct { int kind; double t; const char *text; } con[PF_SPEC_MAXCON];
    int default_order;      /* 0: smallest order meeting fast_target */
    double fast_target;     /* max error the default order must reach */
    const char *real;       /* evaluation type: "double" or "float" */
    const char *kscale;     /* template constant (log: ln2 as a C literal) */
    double ulp_bound;       /* what the sweep must prove for the library */
    const char *pscale;     /* template constant multiplying p (log2: 1/ln2), NULL = 1 */
    /* Optional: C text (tables of constants computed at generation time, e.g.
       the bits of 2/pi from MPFR) written before the template body; returns
       the length written, like snprintf. */
    int (*extra)(char *buf, size_t n);
} pf_spec;

const pf_spec *pf_spec_find(const char *func, const char *variant, const char *reduction);
int pf_spec_func_known(const char *func);
const char *pf_spec_func_list(void);   /* "log, log2, ..." for messages */
int pf_spec_count(void);
const pf_spec *pf_spec_at(int i);
void pf_spec_problem(const pf_spec *s, int order, fit_problem *pb);

#endif
