/* Internals of the fixed-point generator (gen/fixed/fixed_*.c): one generation's
 * state, the per-function hooks, and the shared helpers. */
#ifndef PF_FIXED_INTERNAL_H
#define PF_FIXED_INTERNAL_H

#include "bitwidth.h"
#include "emit.h"
#include "fit.h"
#include "fixedtype.h"
#include "pfref.h"
#include "sweep_fixed.h"

#include <stddef.h>
#include <stdint.h>

#define FX_MAXC (FIT_MAX_ORDER + 1)
#define FX_MAX_SEARCH 24 /* highest order tried when searching */

typedef struct fx_gen fx_gen;

/* One function's hooks.  prepare() checks the types and sets the reduction
 * up for G->W; it returns 0, -1 (with a message: a bad type pair, exit 2)
 * or -2 (this word size cannot do it: try 64 bits).  budget() turns the
 * formats and the measured polynomial into the error model G->R, G->A;
 * emit() writes the body's snippets. */
typedef struct {
    const char *name;
    pf_func ref;
    const char *tmpl;          /* gen/templates/<tmpl>.c.in */
    const char *target_text;   /* what P fits, e.g. "sin(pi/2 t)" */
    fit_target_fn g;
    double a, b;               /* domain of t */
    int parity;                /* FIT_PARITY_ODD: P is in s = t^2 */
    int errkind;               /* FIT_ABS or FIT_REL */
    int errkind_fast;          /* the same for the fast variant */
    int con_zero;              /* constraint p(0) = g(0) */
    const char *con_text;
    int (*prepare)(fx_gen *G, char *err, size_t errlen);
    void (*budget)(fx_gen *G);
    void (*emit)(fx_gen *G, pf_buf *body);
    /* optional, 16-bit storage: the function's own coefficient formats for
       its current reduction kind; returns 0 or -1 as fit_at16, or 1: use
       fit_at16 (the 16-bit Horner of pf_bw_horner_word) */
    int (*fit16)(fx_gen *G, char *err, size_t errlen);
} fx_func;

/* The reductions' constants, one struct per function family, filled by
 * its prepare() (gen/fixed/fixed_<family>.c says how each is derived). */
typedef struct {               /* sin, cos */
    int64_t c64;               /* kind 1: round(2/pi 2^(62-Ei)) mod 2^64 */
    int sh;                    /* kind 0: Ei + 1, the shift of x (2/pi 2^31) to 2^-30 */
    int64_t a16, b16;          /* kind 2, 16-bit lanes: w = x A + mulhrs(x, B) */
    int64_t th, tl;            /* kind 3, 32-bit lanes: z = x TH (+ (x TL) >> 16) mod 2^32 */
    int two;                   /* kind 3: the TL product is used */
    int ey;                    /* kind 3: y = s T(s) in 2^-ey units */
    /* kind 4, 16-bit lanes, the register-table kernel (fixed_trig.c) */
    int64_t kl, kh, hoff;      /* U = |x| (KH 2^16 + KL) + HOFF 2^16 mod 2^32 */
    int16_t tc0[32], tc1[32], tc2[32], tc3[32]; /* per-segment polynomial, 2^-16 units */
    int tns, tord;             /* kind 4: 16 segments of cubics or 32 of quadratics */
    double terr, tred;         /* pre-rounding error (output lsb), phase error (quarter turns) */
    /* kind 6 (fast): one odd quintic on the folded quarter turn, p = C1 - s (C3 - s C5) */
    int32_t pc1, pc3, pc5;
    double fR, fA, fworst;     /* the bound R |f| + A (+ 1/2 lsb); largest error / allowed */
} fx_trig_red;

typedef struct {               /* exp, exp2 */
    int64_t xlo, xhi;          /* clamp range of the stored input */
    int64_t xsat;              /* first saturating input, or > max */
    int64_t cexp;              /* exp: round(log2e 2^(Ft+Ei)) */
    int64_t klo, khi;          /* range of k = floor(t) */
    int64_t k0;                /* bias in units of 2^Ft */
    int ft;                    /* Ft, the fraction bits of t */
    int loclamp;               /* inputs below xlo exist: clamp them */
    int sat;                   /* inputs from xsat up exist: saturate them */
    int64_t b16;               /* 16-bit lanes, exp: round((log2(e) - 1) 2^15) */
    double dt16;               /* 16-bit lanes: |error of t| */
    /* 16-bit lanes, exact: the table kernel (kind 1, fixed_exp.c) */
    int64_t toff, tl1, tl2, tcl; /* exp: u = x + toff, T = u tl1 + (u tl2 >> 16) + tcl */
    int tj;                    /* table index bits J: 2^J entries; T at 2^-(16 + J) */
    int tcarry0;               /* exp: lo = q occurs (u tl1 = 0 mod 2^16) */
    int64_t tk0;               /* T = (t + tk0) 2^(16 + J) */
    int64_t tc1, tc2;          /* 2^r - 1 = r (tc1 2^-16 + tc2 2^(J - 16) r) */
    int64_t tcc;               /* c = s - 1 = tcc - (hi >> J) */
    uint16_t ta[64], tu[64], td[64], tp[32];
    double terr, tkern, tred, tpoly; /* pre-rounding error (lsb); kernel (2^-16), t (2^-22), E (2^-22) */
    int tet;                   /* exp2 with r of <= 5 bits (6 with J < 6): E from a table te (vpermw, vpermi2w) */
    int tnohi;                 /* exp2, J = 4: no clamp at the top (from xsat up, P = 65535 saturates) */
    uint16_t te[64];
    /* 16-bit lanes, fast: the segment-table kernel (kind 2, fixed_exp.c) */
    int64_t fd, fl;            /* u = fd - min(x, fd); exp: w = u fl 2^-16 (w = (t(fd) - t) 2^fb) */
    int ffb, fq;               /* fb; the table's offset, (fq & 3)/4 of W's lsb; fq >> 2: V[0] = the max */
    uint16_t fv[16], fs[16];   /* segment values and drops */
    double fratio, fr;         /* max error / fast bound; R of the bound (relative, beyond 1 lsb) */
} fx_exp_red;

typedef struct {               /* log, log2 */
    int64_t kz;                /* round(ln2 2^Ez) or 2^Ez */
    int64_t emax;              /* max |e| */
    int64_t k15;               /* 16-bit lanes, log: round(ln2 2^15) */
    int ez;                    /* Ez: e K + P summed at 2^-Ez in 64 bits */
    int a16;                   /* 16-bit lanes: e K and P summed at 2^-a */
    double dk16;               /* 16-bit lanes: |error of e K| */
    int ez32;                  /* 16-bit lanes, wide sum: e K + P at 2^-Ez32 in 32 bits */
    int64_t kz32;              /* round(ln2 2^Ez32) or 2^Ez32 */
    int wide;                  /* 16-bit lanes: 1 if the sum is in 32-bit lanes */
    int split;                 /* 16-bit lanes, log: e ln2 = e H 2^-Eo + e L 2^-Ep (two words) */
    int64_t hs, ls;            /* H = round(ln2 2^Eo), L = round(ln2 2^Ep) - H 2^(Ep-Eo) */
    double dsplit;             /* |error of e ln2| in the split form: emax |ln2 2^Ep - round(.)| 2^-Ep */
    /* 16-bit lanes, the table kernel (kind 1, fixed_log.c): y = TH[lz] +
       round((V[j] + floor(S[j] f 2^-16) + TL[lz]) 2^-td), 2^tjb-segment tables */
    int td, tlo, tjb;          /* the final shift; TL used; segment bits (3, 4 or 5) */
    int32_t tv[32], ts[32], th[32], tl[32];
    double terr, tseg;         /* max |y - f| (lsb, every input); max segment-line error (2^-Ef) */
    /* 16-bit lanes, the cubic kernel (kind 2, fixed_log.c, fast): y = e's part
       + floor(a4 t 2^-16), a4 = C1 - floor(a2 t 2^-16), a2 = D2 - floor(C3 t 2^-16),
       t = t's top Eo bits at 2^-16 */
    int32_t pc3, pd2, pc1;
    int pbase2;                /* log2 (e's part e 2^Eo) or log (round(e 2^Eo k15 2^-15)) */
    double pfit;               /* the fitter's cubic: max |p - log2(1+t)| on [0, 1] */
} fx_log_red;

typedef struct {               /* sqrt */
    int64_t qs;                /* round(sqrt2 2^Eq) */
    int64_t j0;                /* bias: e + 2 j0 >= 0 */
    int64_t jlo, jhi;          /* range of j = floor(e / 2) */
    int eq;                    /* Eq: q = sqrt2 or 1 in 2^-Eq units */
    int corr;                  /* exact: emit the correction */
    int gsh;                   /* G = 2 Eo - Ei + 2 */
    int64_t qs15;              /* 16-bit lanes: round(2^15 / sqrt2) */
    double dq16;               /* 16-bit lanes: relative error of P / sqrt2 */
} fx_sqrt_red;

struct fx_gen {
    const fx_func *fn;
    int exact;
    pf_type in, out;
    char in_text[64], out_text[64];
    const char *it, *ot;       /* C storage types */
    char name[128];
    const char *command;
    int order_req;             /* --order, 0: smallest meeting the bound */
    int minimax;
    int errkind;               /* of the fit: the function's, exact or fast */

    /* kernel: W-bit values, 2W-bit products */
    int W;
    const char *wt;            /* "int32_t" / "int64_t" */
    const char *mul;           /* "pf_fx_mul32" / "pf_fx_mul64" */

    /* the fit and its rounded polynomial */
    fit_problem pb;
    fit_poly real, poly;
    int order;
    double poly_err;           /* max error (errkind) of the rounded polynomial */
    double below_err;          /* the order below's bound in LSB when searched, else -1 */

    /* P(x) = sum C[j] 2^-E[j] x^j, Horner in x of type xt = ufixed<W-1,W-1> */
    int m;                     /* degree of P */
    int deg[FX_MAXC];          /* degree in t of P's coefficient j */
    int64_t C[FX_MAXC];
    int E[FX_MAXC];
    pf_bw_step st[FX_MAXC];
    pf_type xt, pt;            /* Horner variable; p_0 */
    int Ep;                    /* p_0's exponent */
    int root_sat;              /* p_0 was trimmed: saturate it */
    double arith;              /* Horner rounding bound, in P's units */
    double dP;                 /* bound of |P'| on [0, 1] */

    /* error model before the final rounding: |z - f(x)| <= R |f(x)| + A,
       with |f| <= fmax where it is not saturated */
    double R, A, fmax;
    double bound_lsb;          /* 0.5 + (R fmax + A) / lsb */
    double dred;               /* reduction's own error (function's units) */

    /* function-specific reduction parameters: kind, and the constants of
       the function's reduction (the member its prepare() fills) */
    int kind;                  /* reduction variant */
    union {
        fx_trig_red trig;
        fx_exp_red exp;
        fx_log_red log;
        fx_sqrt_red sqrt;
    };
    char red_text[600];
    char sat_text[300];        /* the defined saturations, for the provenance */
    char bound_note[160];      /* appended to the error bound's line */

    /* 16-bit lanes (W = 16, issue 14): the Horner steps' formats from
       pf_bw_horner_word; the constants the body reads through k[] (GCC
       only recognizes the rounding multiply-high for a non-constant
       operand, see fx_tail16.c.in) */
    pf_bw_wstep ws[FX_MAXC];
    int nk;                    /* <= FX_MAXC coefficients + 15 roundings of x + 6 others */
    int64_t kval[64];
    char kwhat[64][64];
    char wide_text[400];       /* steps in wider lanes, and why (provenance) */
    int bw16;                  /* the kernel has an AVX-512BW form (fx_emit_vshift16); 2: the
                                  function's emit() wrote its own <name>_array_bw (fx_emit
                                  only adds the run-time dispatch to it); 3: and an AVX2 loop,
                                  <name>_array_avx2, for x86-64-v3 */
    /* a scheme without the Horner polynomial on the family's domain (exp's
       table kernel): when set, these replace the provenance lines built
       from the fit (Domain, Order, Method, Constraints, Formats, Polynomial) */
    char alt_domain[200], alt_order[300], alt_method[400], alt_con[200], alt_formats[1400], alt_poly[400];
    char alt_arith[400];       /* ... and the Arithmetic line */
    char order_text[120];      /* if set: the Order line's word text (a function's own fit16) */
    char alt_bound[400];       /* if set: the Error bound line */
    int nopoly;                /* a kernel without a polynomial (sqrt from IEEE sqrtf): no Domain,
                                  Method, Constraints, Formats or Polynomial line; alt_order says
                                  what it computes */

    /* sweep of the compiled code */
    int swept, exhaustive;
    pf_fx_stats sw;
    char sweep_desc[200];
};

/* the functions (gen/fixed/fixed_trig.c, fixed_exp.c, fixed_log.c, fixed_sqrt.c) */
extern const fx_func fx_func_sin, fx_func_cos, fx_func_exp, fx_func_exp2, fx_func_log, fx_func_log2,
    fx_func_sqrt;
const fx_func *fx_func_find(const char *name);
const char *fx_func_list(void);

/* ---- helpers (gen/fixed/fixed_core.c) ---- */
double fx_lsb(const fx_gen *G);                 /* output lsb 2^-Eo */
/* does the error model R |f| + A meet the variant's bound? */
int fx_within(const fx_gen *G, double R, double A);
int fx_bitlen(uint64_t v);
/* "INT64_C(-123)" (w64) or "-123" for the kernel's word */
#define fx_lit(buf, n, v, w64) pf_int_lit(buf, n, v, (w64) ? PF_LIT_INT64 : PF_LIT_PLAIN)
/* the Horner block: "p = C_m; p = mul(p, x, sh) + C_j; ..." on variable x */
void fx_emit_horner(fx_gen *G, pf_buf *b, const char *x, const char *indent);
/* 16-bit lanes: "k[i]" for the constant v (appended to G's table) */
const char *fx_k16(fx_gen *G, int64_t v, const char *what);
/* bound on max |P_k(x)| over [0, 1] for the partial Horner sums of the
   coefficients a[0..m] (a sampled maximum plus a Lipschitz margin) */
void fx_partial_max(const double *a, int m, double *pmax);
/* 16-bit lanes: "(int16_t)((expr) * k[i])" with k[i] = 1, which hides
   expr's range from GCC (see fx_tail16.c.in) */
const char *fx_opaque16(fx_gen *G, const char *expr);
/* 16-bit lanes: "return (OT)r" with r in [lo, hi] clamped to the output */
void fx_emit_return16(const fx_gen *G, pf_buf *b, const char *r, int64_t lo, int64_t hi);
/* 16-bit lanes: a staged normalization of ux (unsigned, nb significant
   bits at most) to u with bit 15 set and n = bitlen - 1, for log/sqrt
   (bw = 1: a leading-zero count; sets G->bw16) */
void fx_emit_norm16(fx_gen *G, pf_buf *b, int nb);
/* the same u and n, and "int16_t tq": t = u & k[i] with k[i] = 0x7fff, the
   Horner variable itself (the opaque mask hides t's range from GCC as
   fx_opaque16's product by 1 does, one vector instruction fewer) */
void fx_emit_norm16_tq(fx_gen *G, pf_buf *b, int nb);
/* 32/64-bit words: ux = x (x > 0, stored in at most 32 bits), n =
   bitlen(ux) - 1 and t = ux 2^-n - 1 in [0, 1), for log/sqrt */
void fx_emit_norm(const fx_gen *G, pf_buf *b);
/* 16-bit lanes: r16 = min(round(a 2^-s), omax) (ties up) for a in
   [0, amax] and the variable shift s = sexpr in [smin, smax] (smin may be
   negative): in 32-bit lanes for bw = 0 and, where a 2 and s fit, in
   16-bit lanes for bw = 1 (vpsrlvw: sets G->bw16); the same values */
void fx_emit_vshift16(fx_gen *G, pf_buf *b, const char *a, int64_t amax, const char *sexpr, int smin, int smax,
                      int64_t omax);
/* description of the formats, for the provenance */
void fx_formats_text(const fx_gen *G, char *buf, size_t n);
/* largest value of the output type, as a double */
double fx_out_max(const fx_gen *G);

/* the fixed-point front end's --help text (gen/fixed/fixedgen.c) */
const char *fx_usage_text(void);

/* gradient noise (gen/noise/fixed_noise.c): fx_noise_is("noise3") etc.; the
 * generator is pf_run_noise (gen/front/request.h) */
int fx_noise_is(const char *func);

/* the whole generation (gen/fixed/fixed_core.c) */
int fx_generate(fx_gen *G, int sweep, char *err, size_t errlen);
void fx_report_text(FILE *o, const fx_gen *G);
void fx_report_json(FILE *o, const fx_gen *G);
/* emitted C (malloc'ed, NUL-terminated) */
char *fx_emit(const fx_gen *G, size_t *len);

/* (fixed_core.c) a vector loop over blocks of L words, software pipelined:
   stage 1 (s1, from x + i up to the variables cv[0..nc-1]) of block i and
   stage 2 (s2, from them to r) of block i - L in one pass; store (of r at
   y + i - L) after stage 2; the scalar form for the rest; closes the
   function and its #if */
void fx_pipe_loop(pf_buf *kern, const char *vt, int L, const char *s1, const char *s2, const char *const *cv, int nc,
                      const char *store, const char *scalar);

#endif
