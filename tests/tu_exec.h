/* Running a built program without a shell: an argument vector goes to it as
 * is, so the tests can pass hostile names (quotes, spaces, newlines) and
 * know exactly what the program received. */
#ifndef PF_TU_EXEC_H
#define PF_TU_EXEC_H

#include "testutil.h"

#include <fcntl.h>
#include <stdarg.h>
#include <sys/stat.h>

/* Runs argv[0] (searched in PATH) with argv, in directory cwd (NULL: the
 * current one), stdin from /dev/null; captures stdout and stderr (truncated
 * to r's buffers).  r->status: exit status, -1 when a signal ended it (a
 * crash). */
static inline void tu_execvp_in(const char *cwd, const char *const *argv, tu_run_result *r)
{
    char of[] = "/tmp/pftest-o.XXXXXX", ef[] = "/tmp/pftest-e.XXXXXX";
    int ofd = mkstemp(of), efd = mkstemp(ef);
    r->status = -1;
    r->out[0] = r->err[0] = 0;
    if (ofd < 0 || efd < 0)
        return;
    pid_t pid = fork();
    if (pid == 0) {
        int in = open("/dev/null", O_RDONLY);
        if (in >= 0)
            dup2(in, 0);
        dup2(ofd, 1);
        dup2(efd, 2);
        if (cwd && chdir(cwd) != 0)
            _exit(126);
        execvp(argv[0], (char *const *)argv);
        _exit(127);
    }
    int st = 0;
    if (pid > 0)
        waitpid(pid, &st, 0);
    r->status = pid > 0 && WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    ssize_t k = pread(ofd, r->out, sizeof r->out - 1, 0);
    r->out[k > 0 ? k : 0] = 0;
    k = pread(efd, r->err, sizeof r->err - 1, 0);
    r->err[k > 0 ? k : 0] = 0;
    close(ofd);
    close(efd);
    unlink(of);
    unlink(ef);
}

/* build/<...>/<prog> with argv (NULL-terminated, without argv[0]) */
static inline void tu_runv_in(const char *cwd, const char *prog, const char *const *argv, tu_run_result *r)
{
    char path[PATH_MAX];
    tu_prog_path(prog, path, sizeof path);
    size_t n = 0;
    while (argv[n])
        n++;
    const char **v = calloc(n + 2, sizeof *v);
    v[0] = path;
    for (size_t i = 0; i < n; i++)
        v[i + 1] = argv[i];
    tu_execvp_in(cwd, v, r);
    free(v);
}

static inline void tu_runv(const char *prog, const char *const *argv, tu_run_result *r)
{
    tu_runv_in(NULL, prog, argv, r);
}

/* tu_runl(&r, "pfmathgen", "--func", "log", NULL) */
static inline void tu_runl(tu_run_result *r, const char *prog, ...)
{
    const char *v[64];
    int n = 0;
    va_list ap;
    va_start(ap, prog);
    for (const char *a; n < 63 && (a = va_arg(ap, const char *));)
        v[n++] = a;
    va_end(ap);
    v[n] = NULL;
    tu_runv(prog, v, r);
}

/* removes a scratch tree this test made (no shell: nftw, depth first) */
#include <ftw.h>
static inline int tu_rm_cb(const char *p, const struct stat *sb, int flag, struct FTW *f)
{
    (void)sb;
    (void)flag;
    (void)f;
    return remove(p);
}
static inline void tu_rm_tree(const char *dir)
{
    nftw(dir, tu_rm_cb, 16, FTW_DEPTH | FTW_PHYS);
}

#endif
