/* Templates (gen/templates/<tmpl>.c.in) see these substitutions:
 *   @NAME@    emitted function name        @REAL@    evaluation type
 *   @HORNER@  pf_horner_d, pf_horner_f or pf_horner_fma (real "fma": float
 *             lanes, one fmaf per step)      @NCOEF@   entries of @NAME@_C
 *   @NCOMP@   steps the spec's model chose to compensate (0 without a model)
 *   @KSCALE@ @PSCALE@  the spec's constants (default 1)
 * @NAME@_C holds the coefficients lowest degree first; for an odd fit it
 * holds only c1, c3, c5, ... (evaluate r * @HORNER@(r*r, @NAME@_C, @NCOEF@)),
 * for an even fit c0, c2, ... (evaluate @HORNER@(r*r, ...)).
 *
 * The generator's function table: for each function, reduction and variant,
 * what is fitted (target, domain in the fit variable t, parity, constraints)
 * and which template turns the coefficients into C.  A row of variant "mid"
 * is a scheme only the accuracy ladder (--max-ulp) tries.  Adding a function means
 * adding a row here, a target below and a template in gen/templates/. */
#ifndef PF_FUNCS_H
#define PF_FUNCS_H

#include "fit.h"

#define PF_SPEC_MAXCON 8

struct pf_scheme;

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
    const char *real;       /* evaluation: "double", "float" or "fma" (float with fmaf) */
    const char *kscale;     /* template constant (log: ln2 as a C literal) */
    double ulp_bound;       /* what the sweep must prove for the library */
    const char *pscale;     /* template constant multiplying p (log2: 1/ln2), NULL = 1 */
    /* Optional: C text (tables of constants computed at generation time, e.g.
       the bits of 2/pi from MPFR) written before the template body; returns
       the length written, like snprintf. */
    int (*extra)(char *buf, size_t n);
    /* Optional: the evaluation scheme and its rounding-error model.  Given
       the emitted (rounded) polynomial, fills *sc: which steps run in float
       and which are compensated (ncomp, substituted as @NCOMP@), a one-line
       description for the provenance, and the model's bound on the emitted
       function's error in ULP (fit error plus every rounding).  Returns 0, or
       -1 with a message in sc->text when no scheme meets ulp_bound. */
    int (*model)(const fit_poly *p, int order, struct pf_scheme *sc);
    /* Optional templates (names without .in): head, emitted between the
       extra text and the body (helpers several templates share); tail, in
       place of tail_unary.c / tail_binary.c (the scalar and array forms). */
    const char *head, *tail;
    /* The ladder's static cost (gen/float/ladder.c) of a row whose template
       the default rule misjudges: 2 a Horner term plus this; 0 = the rule. */
    int ladder_cost;
} pf_spec;

typedef struct pf_scheme {
    int ncomp;              /* compensated steps, for the template (@NCOMP@) */
    double bound_ulp;       /* the model's bound, ULP of the result */
    char text[512];         /* "Horner in float with fmaf; last 2 steps double-float; ..." */
} pf_scheme;

const pf_spec *pf_spec_find(const char *func, const char *variant, const char *reduction);
int pf_spec_func_known(const char *func);
const char *pf_spec_func_list(void);   /* "log, log2, ..." for messages */
int pf_spec_count(void);
const pf_spec *pf_spec_at(int i);
void pf_spec_problem(const pf_spec *s, int order, fit_problem *pb);

#endif
