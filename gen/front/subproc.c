#include "subproc.h"

#include <errno.h>
#include <spawn.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

extern char **environ;

int pf_spawn(char *const argv[], int in_fd, int out_fd, int err_fd)
{
    /* posix_spawn, not fork: the caller may run OpenMP threads */
    posix_spawn_file_actions_t fa;
    if (posix_spawn_file_actions_init(&fa) != 0)
        return 127;
    int ok = 1;
    if (in_fd >= 0)
        ok &= posix_spawn_file_actions_adddup2(&fa, in_fd, 0) == 0;
    if (out_fd >= 0)
        ok &= posix_spawn_file_actions_adddup2(&fa, out_fd, 1) == 0;
    if (err_fd >= 0)
        ok &= posix_spawn_file_actions_adddup2(&fa, err_fd, 2) == 0;
    pid_t pid;
    int rc = ok ? posix_spawnp(&pid, argv[0], &fa, NULL, argv, environ) : -1;
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0)
        return 127;
    int st;
    while (waitpid(pid, &st, 0) < 0)
        if (errno != EINTR)
            return -1;
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

int pf_argv_push(pf_argv *a, const char *s)
{
    if (a->n + 2 > a->cap) {
        size_t cap = 2 * a->cap + 16;
        char **v = realloc(a->v, cap * sizeof *v);
        if (!v)
            return -1;
        a->v = v;
        a->cap = cap;
    }
    a->v[a->n++] = (char *)s;
    a->v[a->n] = NULL;
    return 0;
}

int pf_argv_cc(pf_argv *a)
{
    memset(a, 0, sizeof *a);
    const char *cc = getenv("CC");
    if (!cc || !cc[strspn(cc, " \t")])
        cc = "cc";
    a->words = strdup(cc);
    if (!a->words)
        return -1;
    char *save = NULL;
    for (char *w = strtok_r(a->words, " \t", &save); w; w = strtok_r(NULL, " \t", &save))
        if (pf_argv_push(a, w) != 0)
            return -1;
    return 0;
}

void pf_argv_free(pf_argv *a)
{
    free(a->words);
    free(a->v);
    memset(a, 0, sizeof *a);
}
