/* Every file pfmathgen writes goes through here (README "Output rules"):
 *  - a regular file, or a name that does not exist yet, is written to a
 *    temporary file in the target's directory and renamed over it, so a
 *    reader sees the old file or the whole new one, never a partial one;
 *  - a symlink is written through: the file it (finally) points to is
 *    replaced the same way, the link itself stays;
 *  - a device, FIFO or other special file is opened and written, never
 *    replaced or created;
 *  - a directory is an error.
 * pf_out_check is the same resolution without writing, run before any fit so
 * that a bad output name costs nothing (exit 2). */
#ifndef PF_OUTPUT_H
#define PF_OUTPUT_H

#include <stddef.h>

/* 0, or -1 with a one-line reason in err ("what" names the option, e.g. "-o") */
int pf_out_check(const char *what, const char *path, char *err, size_t errlen);
int pf_out_write(const char *path, const char *data, size_t n, char *err, size_t errlen);

/* Two-step form for writing several files with nothing changed on error
 * (scenes): pf_out_stage writes data to a temporary file beside the final
 * target (or, for a special file, only records it); pf_out_commit renames it
 * into place (or writes the special file); pf_out_abort removes the
 * temporary.  A staged output owns malloc'd strings: commit or abort it. */
typedef struct {
    char *target;   /* the resolved path written (after symlinks) */
    char *tmp;      /* the temporary file, NULL for a special file */
    const char *data;
    size_t n;
} pf_out_staged;

int pf_out_stage(const char *path, const char *data, size_t n, pf_out_staged *s, char *err, size_t errlen);
int pf_out_commit(pf_out_staged *s, char *err, size_t errlen);
void pf_out_abort(pf_out_staged *s);
/* Commits n staged outputs (those with no target are skipped): the special
 * files first, written in place, which cannot be taken back, then the
 * renames; the first failure stops it and the rest are aborted.  So a
 * device that fails (--plot /dev/full) leaves every regular file as it was;
 * in the order given, -o's file was renamed into place before the plot's
 * failure, and the run said 1.  0, or -1 with a reason. */
int pf_out_commit_all(pf_out_staged *s, int n, char *err, size_t errlen);

/* 1 when a and b reach the same file (the same name after symlinks and
   the directory's canonical path, or one existing file by two links) */
int pf_out_same(const char *a, const char *b);

/* the directory part of a path ("." when there is none); malloc'd */
char *pf_out_dirname(const char *path);

#endif
