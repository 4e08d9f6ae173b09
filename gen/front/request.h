/* pfmathgen's one front end: every option is parsed once into a request,
 * and every combination is checked in one place (pf_request_parse) before
 * any fitting, so a bad command costs nothing: exit 2, one line, nothing
 * written.  The float, fixed-point, noise and scene generators then take the
 * request and return a status and a message; none of them exits. */
#ifndef PF_REQUEST_H
#define PF_REQUEST_H

#include "fixedtype.h"

#include <stddef.h>
#include <stdio.h>

/* the longest --name (and scene prefix + function name): leaves room for
 * the suffixes pfmathgen derives from it (NAME_array, NAME_C, ...) */
#define PF_NAME_MAX 100

typedef enum { PF_MODE_FLOAT, PF_MODE_FIXED, PF_MODE_NOISE, PF_MODE_SCENE } pf_mode;

typedef struct {
    pf_mode mode;
    int help;                   /* --help: print the usage, nothing else */
    const char *func, *variant, *reduction, *method, *name;
    const char *type_s, *out_type_s; /* as given (NULL: not given) */
    pf_type in, out;            /* parsed; float when not given */
    int order;                  /* 0: the generator chooses */
    double target;              /* > 0: --target / --max-rel-err / --max-abs-err */
    int target_abs;
    char target_text[96];
    double max_ulp;             /* > 0: --max-ulp, the accuracy ladder (gen/float/ladder.h) */
    int confirm_sample;         /* --confirm sample: the ladder's cheaper check (tests) */
    int json, sweep;
    int seeded;                 /* --seed (noise) */
    unsigned long long seed;
    const char *output, *plot;  /* -o, --plot */
    const char *scene, *prefix; /* --scene FILE, --prefix P */
    char *command;              /* the command line, quoted for a shell (provenance) */
} pf_request;

/* 0: *rq is complete and consistent; 2: err holds a one-line reason. */
int pf_request_parse(int argc, char **argv, pf_request *rq, char *err, size_t errlen);
void pf_request_free(pf_request *rq);

/* checks shared with the scene parser: 0, or -1 with a reason */
int pf_check_name(const char *what, const char *name, char *err, size_t errlen);
int pf_parse_type(const char *what, const char *s, pf_type *t, char *err, size_t errlen);

/* "pfmathgen: MSG" on stderr as exactly one line (control characters of
 * user text shown as '?') */
void pf_say(const char *msg);

/* The generators.  Each returns 0 (C in *src, malloc'd, *len bytes; the
 * report written to rep: text, or JSON when rq->json), 2 (bad usage or an
 * impossible request: err), or 1 (internal failure: err). */
int pf_run_fixed(const pf_request *rq, FILE *rep, char **src, size_t *len, char *err, size_t errlen);
int pf_run_noise(const pf_request *rq, FILE *rep, char **src, size_t *len, char *err, size_t errlen);

#endif
