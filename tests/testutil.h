/* Helpers shared by the tests: locate and run the built programs. */
#ifndef PF_TESTUTIL_H
#define PF_TESTUTIL_H

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

/* build/<...>/tests/test_x -> build/<...>/<prog> */
static inline void tu_prog_path(const char *prog, char *out, size_t n)
{
    char self[PATH_MAX - 64];
    ssize_t k = readlink("/proc/self/exe", self, sizeof self - 1);
    self[k > 0 ? k : 0] = 0;
    char *s = strrchr(self, '/');
    if (s)
        *s = 0;
    s = strrchr(self, '/');
    if (s)
        *s = 0;
    out[0] = 0;
    if (strlen(self) + strlen(prog) + 2 <= n) {
        strcpy(out, self);
        strcat(out, "/");
        strcat(out, prog);
    }
}

typedef struct {
    int status;          /* exit status, or -1 */
    char out[1 << 16];   /* stdout (truncated) */
    char err[1 << 14];   /* stderr (truncated) */
} tu_run_result;

static inline int tu_count_lines(const char *s)
{
    int n = 0;
    for (; *s; s++)
        n += *s == '\n';
    return n;
}

/* The whole file, NUL-terminated (malloc'd; *n gets its size if n), or NULL. */
static inline char *tu_slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = len >= 0 ? malloc((size_t)len + 1) : NULL;
    size_t got = s ? fread(s, 1, (size_t)len, f) : 0;
    fclose(f);
    if (s)
        s[got] = 0;
    if (n)
        *n = got;
    return s;
}

/* C source without its comments (malloc'd), to check what the code uses. */
static inline char *tu_strip_comments(const char *s)
{
    char *o = malloc(strlen(s) + 1), *q = o;
    while (*s) {
        if (s[0] == '/' && s[1] == '*') {
            const char *e = strstr(s + 2, "*/");
            s = e ? e + 2 : s + strlen(s);
        } else if (s[0] == '/' && s[1] == '/') {
            while (*s && *s != '\n')
                s++;
        } else {
            *q++ = *s++;
        }
    }
    *q = 0;
    return o;
}

#endif
