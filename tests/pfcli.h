/* Strict command-line values and safe output files for pfsweep and pfbench.
 *
 * A number option is the whole argument and nothing else: decimal or 0x hex
 * digits (no sign, no blanks, no octal surprise from a leading 0), within
 * the option's range; strtoull alone would turn "-1" into 2^64-1 and "abc"
 * into 0.  A real option is a finite strtod number within its range ("nan"
 * passes every comparison, so it is refused by name).  Each option may be
 * given once.  Output files: pfcli_out.h. */
#ifndef PF_CLI_H
#define PF_CLI_H

#include <errno.h>
#include <getopt.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* 0 and *v = the value, or -1 */
static inline int pfcli_u64(const char *s, unsigned long long lo, unsigned long long hi,
                            unsigned long long *v)
{
    int base = 10;
    if (s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
        base = 16;
        s += 2;
    }
    const char *hexd = "0123456789abcdefABCDEF";
    if (!s[0] || !strchr(base == 16 ? hexd : "0123456789", s[0]))
        return -1; /* empty, sign, blank */
    char *e;
    errno = 0;
    unsigned long long x = strtoull(s, &e, base);
    if (errno || *e || x < lo || x > hi)
        return -1;
    *v = x;
    return 0;
}

static inline int pfcli_real(const char *s, double lo, double hi, double *v)
{
    if (!s[0] || strchr(" \t\n\v\f\r", s[0]))
        return -1;
    char *e;
    errno = 0;
    double x = strtod(s, &e);
    if (e == s || *e || errno == ERANGE || !isfinite(x) || !(x >= lo && x <= hi))
        return -1;
    *v = x;
    return 0;
}

/* A library the user names (--lib, --ladder) is a file: a name without '/'
 * is ./NAME, as every other file argument, never the dynamic linker's search
 * path (which would find a system copy, or none); "" (dlopen's "the program
 * itself") is refused.  0 and out = the path to dlopen, or -1. */
static inline int pfcli_lib_path(const char *s, char *out, size_t n)
{
    if (!*s)
        return -1;
    int k = snprintf(out, n, "%s%s", strchr(s, '/') ? "" : "./", s);
    return k < 0 || (size_t)k >= n ? -1 : 0;
}

/* s (nothing for NULL) on stderr with its control characters as '?' (a
   newline in a user's file name or option value does not make a second
   line) */
static inline void pfcli_put_clean(const char *s)
{
    for (const char *p = s; p && *p; p++)
        fputc((unsigned char)*p < 0x20 || *p == 0x7f ? '?' : *p, stderr);
}

/* one line on stderr: "PROG: AB", both cleaned (either may be NULL) */
static inline void pfcli_line(const char *prog, const char *a, const char *b)
{
    fprintf(stderr, "%s: ", prog);
    pfcli_put_clean(a);
    pfcli_put_clean(b);
    fputc('\n', stderr);
}

/* Standard output that could not be taken (> /dev/full, a closed pipe with
   SIGPIPE ignored) is a failure, not a run that said 0 with its results
   lost: registered at the start of main, this flushes it at exit and ends
   with status 1 and one line when that fails, whatever main returned. */
static inline const char **pfcli_stdout_prog(void)
{
    static const char *prog;
    return &prog;
}
static inline void pfcli_stdout_at_exit(void)
{
    if (fflush(stdout) != 0 || ferror(stdout)) {
        pfcli_line(*pfcli_stdout_prog(), "cannot write the standard output", NULL);
        _exit(1);
    }
}
static inline void pfcli_check_stdout(const char *prog)
{
    *pfcli_stdout_prog() = prog;
    atexit(pfcli_stdout_at_exit);
}

/* one line on stderr: "PROG: MSG'ARG'", control characters of ARG as '?'
   (a user's newline does not make a second line), then exit 2 */
static inline void pfcli_refuse(const char *prog, const char *msg, const char *arg)
{
    fprintf(stderr, "%s: %s", prog, msg);
    if (arg) {
        fputc('\'', stderr);
        pfcli_put_clean(arg);
        fputc('\'', stderr);
    }
    fputs(" (see --help)\n", stderr);
    exit(2);
}

/* The small bench programs' command line, PROG [N]: no argument gives def;
 * -h or --help prints usage and exits 0; N is a whole number in lo..hi
 * (pfcli_u64's rules); anything else, or a second argument, is exit 2 with
 * one line.  (atoi took "--help", "12x" or "-5" as some count, silently.) */
static inline unsigned long long pfcli_bench_count(int argc, char **argv, const char *prog, const char *usage,
                                                   unsigned long long lo, unsigned long long hi,
                                                   unsigned long long def)
{
    unsigned long long v = def;
    if (argc > 1 && (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help"))) {
        fputs(usage, stdout);
        exit(0);
    }
    if (argc > 1 && pfcli_u64(argv[1], lo, hi, &v) != 0) {
        char m[96];
        snprintf(m, sizeof m, "expected a whole number %llu..%llu, not ", lo, hi);
        pfcli_refuse(prog, m, argv[1]);
    }
    if (argc > 2)
        pfcli_refuse(prog, "unexpected argument ", argv[2]);
    return v;
}

/* the long name of option value c ("help" for 'h') */
static inline const char *pfcli_name(const struct option *opts, int c)
{
    for (; opts->name; opts++)
        if (opts->val == c)
            return opts->name;
    return "?";
}

/* 0 the first time option c is seen, -1 after */
static inline int pfcli_once(unsigned char seen[256], int c)
{
    if (seen[(unsigned char)c])
        return -1;
    seen[(unsigned char)c] = 1;
    return 0;
}

/* libpfmath.so for a program that was not told where it is: beside the
 * program (the build tree), else PREFIX/lib/libpfmath.so.0 for a program in
 * PREFIX/bin (make install).  0, or -1 when neither exists. */
static inline int pfcli_default_lib(char *path, size_t n)
{
    char self[PATH_MAX];
    ssize_t k = readlink("/proc/self/exe", self, sizeof self - 1);
    if (k <= 0)
        return -1;
    self[k] = 0;
    char *slash = strrchr(self, '/');
    if (!slash)
        return -1;
    *slash = 0;
    snprintf(path, n, "%.*s/libpfmath.so", (int)(n - 16 > 0 ? n - 16 : 0), self);
    if (access(path, R_OK) == 0)
        return 0;
    char *up = strrchr(self, '/');
    if (up && !strcmp(up, "/bin")) {
        *up = 0;
        snprintf(path, n, "%.*s/lib/libpfmath.so.0", (int)(n - 24 > 0 ? n - 24 : 0), self);
        if (access(path, R_OK) == 0)
            return 0;
    }
    return -1;
}

#endif
