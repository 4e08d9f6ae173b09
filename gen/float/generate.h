/* One generation: fit a function's polynomial, round its coefficients,
 * measure it, emit C from the template, compile and sweep the emitted code. */
#ifndef PF_GENERATE_H
#define PF_GENERATE_H

#include "fit.h"
#include "funcs.h"
#include "sweep.h"

#include <stdio.h>

typedef struct {
    const char *func, *variant, *reduction, *name, *method;
    int order;            /* 0: the spec's default (fast: smallest meeting its target) */
    double target;        /* > 0: smallest order whose emitted polynomial meets it */
    int target_abs;       /* the target is an absolute error */
    const char *target_text;  /* e.g. "float (2^-24 relative)" */
    int sweep;            /* compile the emitted code and sweep it */
    const char *command;  /* the pfmathgen command line, recorded in the file */
} pf_gen_req;

typedef struct {
    const pf_spec *spec;
    fit_problem pb;
    fit_poly real;        /* before rounding (measured) */
    fit_poly poly;        /* emitted coefficients (measured) */
    int order;
    double below_err;     /* error of order-1 when the order was searched, else -1 */
    int minimax;          /* method: 1 minimax, 0 least squares */
    int searched;         /* the order was searched (smallest meeting the target) */
    fit_poly lsq_poly;    /* with minimax: the rounded LSQ fit of the same order, for comparison */
    double target;
    int target_abs;
    char target_text[96];
    char name[128];
    char *csrc;
    size_t clen;
    int swept;
    pf_sweep_stats sweep;
    char sweep_desc[256];
    int has_scheme;       /* the spec has a model: scheme below is filled */
    pf_scheme scheme;
} pf_gen_result;

int pf_generate(const pf_gen_req *rq, pf_gen_result *res, char *err, size_t errlen);
void pf_gen_free(pf_gen_result *res);
void pf_report_text(FILE *out, const pf_gen_result *r);
void pf_report_json(FILE *out, const pf_gen_result *r);

#endif
