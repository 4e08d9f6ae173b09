/* Running another program without a shell: the arguments go to it as they
 * are (no quoting, no word splitting, no expansion), so no file name or
 * option value can become a command. */
#ifndef PF_SUBPROC_H
#define PF_SUBPROC_H

#include <stddef.h>

/* Runs argv[0] (searched in PATH) with stdin from in_fd and stdout/stderr to
 * out_fd/err_fd (-1: inherit) and waits for it.  Returns its exit status
 * (0..255), 127 when it could not be started, -1 when a signal killed it. */
int pf_spawn(char *const argv[], int in_fd, int out_fd, int err_fd);

/* An argument vector: the words of $CC (default "cc"), split on blanks as
 * make does (no quoting, no shell), then whatever is pushed. */
typedef struct {
    char *words;    /* the split copy of $CC */
    char **v;       /* NULL-terminated */
    size_t n, cap;
} pf_argv;

int pf_argv_cc(pf_argv *a);                 /* 0, or -1 out of memory */
int pf_argv_push(pf_argv *a, const char *s); /* s must outlive a */
void pf_argv_free(pf_argv *a);

#endif
