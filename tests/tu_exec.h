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

/* An argument vector built without a shell: tu_argv_words splits a string
 * into words at blanks, where a single-quoted span belongs to its word with
 * the quotes dropped ("--type 'unsigned fixed<16,14>'" gives two words);
 * nothing else is special (no expansion, no escapes, no redirection), so
 * what a test writes is what the program gets.  tu_argv_add appends one
 * word as is (a path that may hold blanks or quotes). */
typedef struct {
    const char *v[128];
    int n;
    char buf[8192];
    size_t used;
} tu_argv;

static inline void tu_argv_add(tu_argv *a, const char *w)
{
    size_t k = strlen(w) + 1;
    if (a->n >= 127 || a->used + k > sizeof a->buf) {
        fprintf(stderr, "tu_argv: too many or too long words\n");
        abort();
    }
    memcpy(a->buf + a->used, w, k);
    a->v[a->n++] = a->buf + a->used;
    a->v[a->n] = NULL;
    a->used += k;
}

static inline void tu_argv_words(tu_argv *a, const char *s)
{
    char w[1024];
    size_t k = 0;
    int inword = 0, quoted = 0;
    for (;; s++) {
        if (!*s || (!quoted && strchr(" \t\n", *s))) {
            if (quoted) {
                fprintf(stderr, "tu_argv: unbalanced quote\n");
                abort();
            }
            if (inword) {
                w[k] = 0;
                tu_argv_add(a, w);
            }
            k = 0;
            inword = 0;
            if (!*s)
                return;
            continue;
        }
        inword = 1;
        if (*s == '\'') {
            quoted = !quoted;
            continue;
        }
        if (k + 1 >= sizeof w) {
            fprintf(stderr, "tu_argv: word too long\n");
            abort();
        }
        w[k++] = *s;
    }
}

/* $CC split on blanks as gen/front/subproc.c does (unset or blank: cc) */
static inline void tu_argv_cc(tu_argv *a)
{
    const char *cc = getenv("CC");
    tu_argv_words(a, cc && cc[strspn(cc, " \t")] ? cc : "cc");
}

/* build/<...>/<prog> with args split as tu_argv_words does: the tests'
 * fixed option strings ("--func sin --type 'fixed<15,12>' -o /tmp/x.c") */
static inline void tu_runs(const char *prog, const char *args, tu_run_result *r)
{
    tu_argv *a = calloc(1, sizeof *a);
    tu_argv_words(a, args);
    tu_runv(prog, a->v, r);
    free(a);
}

/* tu_runl_cmd(&r, "cc", "-c", path, NULL): argv[0] searched in PATH (a
 * system program, not one of ours), output captured */
static inline void tu_runl_cmd(tu_run_result *r, const char *cmd, ...)
{
    const char *v[64];
    int n = 0;
    v[n++] = cmd;
    va_list ap;
    va_start(ap, cmd);
    for (const char *a; n < 63 && (a = va_arg(ap, const char *));)
        v[n++] = a;
    va_end(ap);
    v[n] = NULL;
    tu_execvp_in(NULL, v, r);
}

/* removes a scratch tree this test made (no shell: nftw, depth first);
 * 0 when every entry went */
#include <ftw.h>
static inline int tu_rm_cb(const char *p, const struct stat *sb, int flag, struct FTW *f)
{
    (void)sb;
    (void)flag;
    (void)f;
    return remove(p);
}
static inline int tu_rm_tree(const char *dir)
{
    return nftw(dir, tu_rm_cb, 16, FTW_DEPTH | FTW_PHYS);
}

/* This process's scratch directory (mkdtemp on first use, removed at exit):
 * fixed /tmp names collided when two `make test` runs (two clones) ran at
 * once.  tu_scratch(buf, name) writes the path of NAME inside it. */
static inline void tu_scratch_rm(void);
static inline const char *tu_scratch_dir(void)
{
    static char d[] = "/tmp/pf-test-XXXXXX";
    static int made;
    if (!made) {
        if (!mkdtemp(d)) {
            perror("mkdtemp");
            exit(1);
        }
        made = 1;
        atexit(tu_scratch_rm);
    }
    return d;
}
static inline void tu_scratch_rm(void)
{
    tu_rm_tree(tu_scratch_dir());
}
#define tu_scratch(buf, name) (snprintf((buf), sizeof(buf), "%s/%s", tu_scratch_dir(), (name)), (buf))

#endif
