/* pfmath fitting engine: one polynomial p(t) = sum c_k t^k over a domain
 * D = [a, b], minimizing least-squares relative (or absolute) error against
 * a target g(t) evaluated with MPFR, subject to linear equality constraints
 * on p and p' at chosen points (Olano, PixelFlow, eq. 4.1/4.2).
 *
 * Numerics: the least-squares problem is posed in a Chebyshev basis on D
 * (well conditioned at any order we allow) and solved by Householder QR in
 * binary128 (_Float128, 113-bit significand); constraints are eliminated by
 * the null-space method (QR of C^T).  Only the final answer is converted to
 * the monomial basis in t, still in binary128. */
#ifndef PF_FIT_H
#define PF_FIT_H

#include <mpfr.h>
#include <stddef.h>

typedef _Float128 fit_real;

#define FIT_MAX_ORDER 30
#define FIT_MAX_CON (FIT_MAX_ORDER + 8)

enum fit_parity { FIT_PARITY_NONE = 0, FIT_PARITY_ODD = 1, FIT_PARITY_EVEN = 2 };
enum fit_errkind { FIT_REL = 0, FIT_ABS = 1 };
enum fit_conkind { FIT_CON_VALUE = 0, FIT_CON_DERIV = 1, FIT_CON_COEF = 2 };
enum fit_coeffmt { FIT_COEF_REAL = 0, FIT_COEF_FLOAT = 1, FIT_COEF_DOUBLE = 2, FIT_COEF_FIXED = 3 };

/* Target function in the fit variable t: y = g(t), rounded to y's precision. */
typedef void (*fit_target_fn)(mpfr_t y, const mpfr_t t, const void *ctx);

typedef struct {
    int kind;        /* FIT_CON_VALUE: p(t) = value; FIT_CON_DERIV: p'(t) = value;
                        FIT_CON_COEF: c_k = value (k = index) */
    int index;       /* coefficient index for FIT_CON_COEF */
    fit_real t;      /* point, for VALUE/DERIV */
    fit_real value;  /* right-hand side; for VALUE/DERIV the fitter fills it from g */
} fit_constraint;

typedef struct {
    fit_target_fn g;
    const void *ctx;
    fit_real a, b;          /* domain D in t */
    int order;              /* degree of p */
    int parity;             /* FIT_PARITY_*: ODD/EVEN need a == 0 */
    int errkind;            /* FIT_REL or FIT_ABS */
    int ncon;
    fit_constraint con[FIT_MAX_CON];
    int nodes;              /* Gauss-Legendre nodes; 0 = choose */
} fit_problem;

typedef struct {
    int order;
    fit_real c[FIT_MAX_ORDER + 1];    /* monomial coefficients in t */
    /* measured on the emitted coefficients (see fit_measure) */
    double max_err;                   /* max |p-g|/|g| (REL) or |p-g| (ABS) */
    double max_err_at;                /* t where it occurs */
} fit_poly;

/* Fixed-point coefficient format: value = stored * 2^-exp, |stored| < 2^bits. */
typedef struct {
    int fmt;                 /* FIT_COEF_* */
    int fixed_bits;          /* magnitude bits available per coefficient (FIXED) */
} fit_coeffmt;

/* Least-squares fit of problem.  Returns 0, or -1 with a one-line reason in
 * err (inconsistent or dependent constraints, order too low for them, ...). */
int fit_lsq(const fit_problem *pb, fit_poly *out, char *err, size_t errlen);

/* The same, plus the expected cost of rounding each free coefficient c_k by
 * a relative coef_u later (a ridge term; see fit/lsq.c).  0 = fit_lsq. */
int fit_lsq_pen(const fit_problem *pb, fit_real coef_u, fit_poly *out, char *err, size_t errlen);

/* Minimax refinement: start from the least-squares fit and minimize the
 * maximum relative (or absolute) error over a dense set of D, keeping the
 * same equality constraints.  Epigraph form, solved with nlopt's SLSQP:
 * minimize s subject to |e(x_i)| <= s, e linear in the free coefficients
 * (the null space of the constraints). */
int fit_minimax(const fit_problem *pb, fit_poly *out, char *err, size_t errlen);

/* Round the coefficients to fmt the way one does by hand with Sollya: from
 * the lowest degree up, round c_k, pin it as a constraint, re-fit the rest
 * (by refit(), which is fit_lsq or the minimax refiner).  A coefficient that
 * the constraints already determine is rounded last, so those constraints
 * then hold to rounding.  fixed_exp (may be NULL) receives the chosen
 * exponent of each coefficient for FIT_COEF_FIXED. */
typedef int (*fit_refit_fn)(const fit_problem *pb, fit_poly *out, char *err, size_t errlen);
int fit_round(const fit_problem *pb, fit_coeffmt fmt, fit_refit_fn refit,
              fit_poly *inout, int *fixed_exp, char *err, size_t errlen);

/* Round one real to the coefficient format (exp is the fixed exponent). */
fit_real fit_round_coef(fit_real v, fit_coeffmt fmt, int *exp);

/* Max error of out->c over D against g, measured on a dense grid in binary128
 * with g from MPFR, refined around the largest peaks by golden-section
 * search; fills out->max_err and out->max_err_at. */
void fit_measure(const fit_problem *pb, fit_poly *p);

/* Between these two calls (one thread; fit_round brackets its chains with
 * them, the float generator every fit of one function, the ladder search
 * all its candidates) fit_eval_target remembers g(t) by the target, its
 * context and t.  They nest: only the outermost pair allocates and frees.
 * A target's context must not change in between. */
void fit_target_cache_begin(void);
void fit_target_cache_end(void);
/* for tests: a scope whose table has the given number of slots (1: every
   value shares one probe chain), and how many values the open scope holds
   (0 outside a scope) */
void fit_target_cache_begin_n(size_t slots);
size_t fit_target_cache_count(void);

/* g(t) and g'(t) in binary128 (g' by a central difference at 512 bits). */
fit_real fit_eval_target(const fit_problem *pb, fit_real t);
fit_real fit_eval_target_deriv(const fit_problem *pb, fit_real t);
fit_real fit_eval_poly(const fit_poly *p, fit_real t);
fit_real fit_eval_poly_deriv(const fit_poly *p, fit_real t);

/* Gauss-Legendre nodes/weights on [-1, 1] (n <= 512). */
void fit_gauss_legendre(int n, fit_real *x, fit_real *w);

/* binary128 <-> mpfr helpers (exact: mpfr at >= 113 bits). */
void fit_set_mpfr(mpfr_t y, fit_real v);
fit_real fit_get_mpfr(const mpfr_t v);

#endif
