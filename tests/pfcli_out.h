/* Output files of pfbench and pfnoise-demo, by pfmathgen's own rules
 * (gen/front/output.c; README "Output rules"), linked from the same object
 * so the two cannot drift apart: a regular file is replaced by a rename of
 * a complete temporary beside it, a symlink is written through (followed
 * link by link, so a dangling link whose target's directory exists is
 * created through), a FIFO or device is written in place, a directory or a
 * read-only file is refused.
 *
 * pfcli_out_open checks the name before the run's work and collects the
 * text in memory; pfcli_out_commit puts it in place.  A run that stops
 * before its commit leaves no temporary and the old file as it was. */
#ifndef PF_CLI_OUT_H
#define PF_CLI_OUT_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "output.h"

typedef struct {
    char *path;   /* the name given (resolved again at commit) */
    char *buf;    /* what was written, open_memstream's buffer */
    size_t len;
    FILE *f;      /* where to write */
} pfcli_out;

/* Opens o for path.  0, or -1 with a one-line reason in err. */
static inline int pfcli_out_open(pfcli_out *o, const char *path, char *err, size_t n)
{
    memset(o, 0, sizeof *o);
    if (pf_out_check("cannot write", path, err, n) != 0)
        return -1;
    o->path = strdup(path);
    o->f = o->path ? open_memstream(&o->buf, &o->len) : NULL;
    if (!o->f) {
        free(o->path);
        snprintf(err, n, "out of memory");
        return -1;
    }
    return 0;
}

/* Closes o and puts it in place.  0, or -1 with a reason (the target then
 * keeps its old content). */
static inline int pfcli_out_commit(pfcli_out *o, char *err, size_t n)
{
    int bad = ferror(o->f);
    bad |= fclose(o->f) != 0;
    int r = -1;
    if (bad)
        snprintf(err, n, "cannot write %.400s: write error", o->path);
    else
        r = pf_out_write(o->path, o->buf, o->len, err, n);
    free(o->buf);
    free(o->path);
    return r;
}

/* Closes o and drops what was written (the target keeps its old content). */
static inline void pfcli_out_abort(pfcli_out *o)
{
    fclose(o->f);
    free(o->buf);
    free(o->path);
}

#endif
