#include "compile.h"

#include "subproc.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

static void *build_and_load(const char *dir, const char *cpath, char *err, size_t errlen)
{
    char so[4200], log[4200];
    snprintf(so, sizeof so, "%s/f.so", dir);
    snprintf(log, sizeof log, "%s/cc.log", dir);
    /* $CC's words, then the fixed flags and our own file names: no shell */
    pf_argv a;
    int rc = 127;
    int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (pf_argv_cc(&a) == 0) {
        const char *args[] = {"-std=c17", "-O2", "-fPIC", "-shared", "-o", so, cpath, "-lm"};
        int ok = 1;
        for (size_t i = 0; i < sizeof args / sizeof args[0]; i++)
            ok &= pf_argv_push(&a, args[i]) == 0;
        if (ok && fd >= 0)
            rc = pf_spawn(a.v, -1, fd, fd);
    }
    if (fd >= 0)
        close(fd);
    const char *cc = a.v && a.v[0] ? a.v[0] : "cc";
    void *h = NULL;
    if (rc != 0) {
        char first[300] = "";
        FILE *f = fopen(log, "r");
        if (f) {
            if (!fgets(first, sizeof first, f))
                first[0] = 0;
            fclose(f);
        }
        first[strcspn(first, "\n")] = 0;
        snprintf(err, errlen, "compiling with '%s' failed: %s", cc,
                 first[0] ? first : rc == 127 ? "cannot run it (pfmathgen needs a C compiler; set CC)" : "(no output)");
    } else {
        h = dlopen(so, RTLD_NOW | RTLD_LOCAL);
        if (!h)
            snprintf(err, errlen, "dlopen: %s", dlerror());
    }
    pf_argv_free(&a);
    unlink(so);
    unlink(log);
    return h;
}

void *pf_compile_load(const char *src, size_t len, char *err, size_t errlen)
{
    char dir[] = "/tmp/pfmath.XXXXXX";
    if (!mkdtemp(dir)) {
        snprintf(err, errlen, "cannot create a temporary directory");
        return NULL;
    }
    char c[64];
    snprintf(c, sizeof c, "%s/f.c", dir);
    FILE *f = fopen(c, "w");
    void *h = NULL;
    /* closed whether or not the write worked (a short write must not leak
       the stream) */
    int ok = f && fwrite(src, 1, len, f) == len;
    if (f && fclose(f) != 0)
        ok = 0;
    if (!ok)
        snprintf(err, errlen, "cannot write %s", c);
    else
        h = build_and_load(dir, c, err, errlen);
    unlink(c);
    rmdir(dir);
    return h;
}

void *pf_compile_load_file(const char *path, char *err, size_t errlen)
{
    char dir[] = "/tmp/pfmath.XXXXXX";
    if (!mkdtemp(dir)) {
        snprintf(err, errlen, "cannot create a temporary directory");
        return NULL;
    }
    char *abs = realpath(path, NULL);
    void *h = NULL;
    if (!abs)
        snprintf(err, errlen, "cannot read %s", path);
    else
        h = build_and_load(dir, abs, err, errlen);
    free(abs);
    rmdir(dir);
    return h;
}
