/* The one place where pfmathgen's options are read and judged (request.h). */
#include "request.h"

#include "cli.h"
#include "fixed_internal.h"
#include "funcs.h"
#include "output.h"

#include <ctype.h>
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

/* The best float-coefficient fits here reach about 2^-40 (exp at order 30:
 * 1.15e-12 = 2^-39.7; log: Sollya's fpminimax at order 30 gives 6.5e-12).
 * A target below 2^-44, 16 times under that, is refused at once instead of
 * after thirty orders' fits (minutes); the margin leaves room for better
 * fitting.  An empirical floor, not a proof: between it and the best fit
 * the order search still runs and answers. */
#define FLOAT_TARGET_FLOOR 0x1p-44

void pf_say(const char *msg)
{
    fputs("pfmathgen: ", stderr);
    for (const char *p = msg; *p; p++)
        fputc((unsigned char)*p < 0x20 || *p == 0x7f ? '?' : *p, stderr);
    fputc('\n', stderr);
}

__attribute__((format(printf, 3, 4))) static int bad(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
    return 2;
}

/* Names the headers of the emitted C declare (<math.h>, <string.h>,
 * <stddef.h>, <stdint.h>; C17 7.12, 7.24, 7.19, 7.20) or reserve for them
 * (7.31), or that are reserved at file scope (7.1.3): the reason, or NULL.
 * --name logf compiled, and its logf replaced libm's in every program
 * linking it; --name memcpy or fmaf failed in the sweep's compile, after
 * the fit (with --no-sweep: exit 0 and C that does not compile). */
static const char *libc_name(const char *n)
{
    /* <math.h>: each function also with the suffixes f and l */
    static const char *const math[] = {
        "acos", "asin", "atan", "atan2", "cos", "sin", "tan", "acosh", "asinh", "atanh", "cosh", "sinh", "tanh",
        "exp", "exp2", "expm1", "frexp", "ilogb", "ldexp", "log", "log10", "log1p", "log2", "logb", "modf",
        "scalbn", "scalbln", "cbrt", "fabs", "hypot", "pow", "sqrt", "erf", "erfc", "lgamma", "tgamma", "ceil",
        "floor", "nearbyint", "rint", "lrint", "llrint", "round", "lround", "llround", "trunc", "fmod",
        "remainder", "remquo", "copysign", "nan", "nextafter", "nexttoward", "fdim", "fmax", "fmin", "fma", NULL};
    static const char *const other[] = {
        /* <math.h> macros and types */
        "fpclassify", "isfinite", "isinf", "isnan", "isnormal", "signbit", "isgreater", "isgreaterequal",
        "isless", "islessequal", "islessgreater", "isunordered", "float_t", "double_t", "math_errhandling",
        "HUGE_VAL", "HUGE_VALF", "HUGE_VALL", "INFINITY", "NAN", "FP_INFINITE", "FP_NAN", "FP_NORMAL",
        "FP_SUBNORMAL", "FP_ZERO", "FP_FAST_FMA", "FP_FAST_FMAF", "FP_FAST_FMAL", "FP_ILOGB0", "FP_ILOGBNAN",
        "MATH_ERRNO", "MATH_ERREXCEPT",
        /* <stddef.h>, and <stdint.h>'s that the patterns below miss */
        "NULL", "offsetof", "ptrdiff_t", "size_t", "max_align_t", "wchar_t", "PTRDIFF_MIN", "PTRDIFF_MAX",
        "SIZE_MAX", "SIG_ATOMIC_MIN", "SIG_ATOMIC_MAX", "WCHAR_MIN", "WCHAR_MAX", "WINT_MIN", "WINT_MAX", NULL};
    size_t len = strlen(n);
    if (n[0] == '_')
        return "names starting with _ are reserved at file scope (C17 7.1.3)";
    for (int i = 0; math[i]; i++) {
        size_t k = strlen(math[i]);
        if (!strncmp(n, math[i], k) && (!n[k] || ((n[k] == 'f' || n[k] == 'l') && !n[k + 1])))
            return "a function of <math.h>, reserved for the library (C17 7.1.3)";
    }
    for (int i = 0; other[i]; i++)
        if (!strcmp(n, other[i]))
            return "a name of <math.h>, <stddef.h> or <stdint.h>, which the emitted C includes";
    /* <string.h>: str, mem, wcs and a lowercase letter (C17 7.31.13) */
    if ((!strncmp(n, "str", 3) || !strncmp(n, "mem", 3) || !strncmp(n, "wcs", 3)) && islower((unsigned char)n[3]))
        return "names starting with str, mem or wcs and a lowercase letter belong to <string.h> (C17 7.31.13)";
    /* <stdint.h>: int.../uint..._t types, INT.../UINT..._MAX, _MIN, _WIDTH, _C macros (C17 7.31.10) */
    if ((!strncmp(n, "int", 3) || !strncmp(n, "uint", 4)) && len > 2 && !strcmp(n + len - 2, "_t"))
        return "names starting with int or uint and ending in _t belong to <stdint.h> (C17 7.31.10)";
    if (!strncmp(n, "INT", 3) || !strncmp(n, "UINT", 4))
        for (const char *const *e = (const char *const[]){"_MAX", "_MIN", "_WIDTH", "_C", NULL}; *e; e++)
            if (len > strlen(*e) && !strcmp(n + len - strlen(*e), *e))
                return "names starting with INT or UINT and ending in _MAX, _MIN, _WIDTH or _C belong to <stdint.h> "
                       "(C17 7.31.10)";
    return NULL;
}

int pf_check_name(const char *what, const char *name, char *err, size_t errlen)
{
    /* C17 6.4.1 */
    static const char *const kw[] = {
        "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else", "enum",
        "extern", "float", "for", "goto", "if", "inline", "int", "long", "register", "restrict", "return",
        "short", "signed", "sizeof", "static", "struct", "switch", "typedef", "union", "unsigned", "void",
        "volatile", "while", "_Alignas", "_Alignof", "_Atomic", "_Bool", "_Complex", "_Generic",
        "_Imaginary", "_Noreturn", "_Static_assert", "_Thread_local", NULL};
    if (!pf_cli_is_identifier(name)) {
        snprintf(err, errlen, "bad %s '%.200s': not a C identifier (letters, digits, '_'; not starting with a digit)",
                 what, name);
        return -1;
    }
    for (int i = 0; kw[i]; i++)
        if (!strcmp(name, kw[i])) {
            snprintf(err, errlen, "bad %s '%s': a C keyword", what, name);
            return -1;
        }
    if (name[0] == '_' && (name[1] == '_' || isupper((unsigned char)name[1]))) {
        snprintf(err, errlen, "bad %s '%.200s': names starting with __ or _ and a capital are reserved (C17 7.1.3)",
                 what, name);
        return -1;
    }
    if (!strcmp(name, "main")) {
        snprintf(err, errlen, "bad %s 'main': the program's entry point", what);
        return -1;
    }
    const char *why = libc_name(name);
    if (why) {
        snprintf(err, errlen, "bad %s '%.200s': %s", what, name, why);
        return -1;
    }
    if (strlen(name) > PF_NAME_MAX) {
        snprintf(err, errlen, "bad %s: %zu characters, at most %d", what, strlen(name), PF_NAME_MAX);
        return -1;
    }
    return 0;
}

int pf_parse_type(const char *what, const char *s, pf_type *t, char *err, size_t errlen)
{
    char e[200];
    if (pf_type_parse(s, t, e, sizeof e) != 0) {
        snprintf(err, errlen, "bad %s: %s", what, e);
        return -1;
    }
    if (!t->is_float && t->storage_bits > 32) {
        char f[64];
        pf_type_format(t, f, sizeof f);
        snprintf(err, errlen, "unsupported %s %s: fixed-point functions take storage of at most 32 bits", what, f);
        return -1;
    }
    return 0;
}

/* a number, or 2^k with k in [kmin, kmax] */
static int parse_num_or_pow2(const char *s, long kmin, long kmax, double *v)
{
    char *end;
    if (!*s || isspace((unsigned char)*s))
        return -1;
    if (!strncmp(s, "2^", 2)) {
        errno = 0;
        long ex = strtol(s + 2, &end, 10);
        if (end == s + 2 || *end || errno || ex < kmin || ex > kmax)
            return -1;
        *v = ldexp(1.0, (int)ex);
        return 0;
    }
    *v = strtod(s, &end);
    return end == s || *end ? -1 : 0;
}

/* an error bound: in (0, 1) */
static int parse_bound(const char *s, double *v)
{
    return parse_num_or_pow2(s, -1000, 0, v) == 0 && *v > 0 && *v < 1 ? 0 : -1;
}

/* --max-ulp U: a finite number of float ULPs, >= 0.5 (0.5 is correct
   rounding; below it no float result can be), written as a number or 2^k */
static int parse_ulp(const char *s, double *v)
{
    return parse_num_or_pow2(s, -1, 1000, v) == 0 && isfinite(*v) && *v >= 0.5 ? 0 : -1;
}

/* long option name of a short code, for messages */
static const struct option opts[] = {
    {"func", required_argument, 0, 'f'},        {"variant", required_argument, 0, 'v'},
    {"order", required_argument, 0, 'n'},       {"reduction", required_argument, 0, 'r'},
    {"type", required_argument, 0, 't'},        {"out-type", required_argument, 0, 'O'},
    {"method", required_argument, 0, 'm'},      {"name", required_argument, 0, 'N'},
    {"output", required_argument, 0, 'o'},      {"json", no_argument, 0, 'j'},
    {"no-sweep", no_argument, 0, 'S'},          {"help", no_argument, 0, 'h'},
    {"target", required_argument, 0, 'T'},      {"max-rel-err", required_argument, 0, 'R'},
    {"max-abs-err", required_argument, 0, 'A'}, {"plot", required_argument, 0, 'P'},
    {"seed", required_argument, 0, 's'},        {"scene", required_argument, 0, 'C'},
    {"prefix", required_argument, 0, 'p'},      {"max-ulp", required_argument, 0, 'U'},
    {"confirm", required_argument, 0, 'K'},     {0, 0, 0, 0}};

static const char *long_name(int c)
{
    for (int i = 0; opts[i].name; i++)
        if (opts[i].val == c)
            return opts[i].name;
    return "?";
}

/* options that a mode does not take: the first one given, or 0 */
static int first_of(const unsigned char *seen, const char *codes)
{
    for (const char *c = codes; *c; c++)
        if (seen[(unsigned char)*c])
            return *c;
    return 0;
}

static int check_float(pf_request *rq, const unsigned char *seen, char *err, size_t errlen)
{
    int c = first_of(seen, "sp");
    if (c)
        return bad(err, errlen, "--%s does not apply to %s (see --help)", long_name(c),
                   c == 's' ? "float functions (it is for noise)" : "a single function (it is for --scene)");
    if (!pf_spec_func_known(rq->func)) {
        if (fx_func_find(rq->func))
            return bad(err, errlen, "%s is generated for fixed-point types only: give --type 'fixed<size,exp>'",
                       rq->func);
        return bad(err, errlen, "unknown function '%.200s' (known: %s)", rq->func, pf_spec_func_list());
    }
    int both = !strcmp(rq->variant, "both");
    if (strcmp(rq->variant, "exact") && strcmp(rq->variant, "fast") && !both)
        return bad(err, errlen, "unknown variant '%.200s' (use exact, fast, or both with --plot)", rq->variant);
    if (both && (!rq->plot || rq->output || rq->json))
        return bad(err, errlen, "--variant both is for --plot only (no -o, no --json)");
    if (rq->reduction) {
        const char *v[2] = {both ? "exact" : rq->variant, both ? "fast" : rq->variant};
        for (int i = 0; i < 2; i++)
            if (!pf_spec_find(rq->func, v[i], rq->reduction))
                return bad(err, errlen, "unknown reduction '%.200s' for %s", rq->reduction, rq->func);
    }
    if (seen['U'] || seen['K']) {
        int k = first_of(seen, "nvTRAS");
        if (!seen['U'])
            return bad(err, errlen, "--confirm is for --max-ulp");
        if (k)
            return bad(err, errlen, "--max-ulp chooses the %s itself: it does not combine with --%s",
                       k == 'v' ? "variant" : k == 'S' ? "check (an exhaustive sweep)" : "order and error target",
                       long_name(k));
    }
    if (rq->target > 0 && rq->target < FLOAT_TARGET_FLOOR)
        return bad(err, errlen,
                   "impossible target %s: below 2^-44, and float-coefficient fits reach about 2^-40 at best "
                   "(exp at order 30: 1.15e-12)",
                   rq->target_text);
    return 0;
}

static int check_fixed(pf_request *rq, const unsigned char *seen, char *err, size_t errlen)
{
    int c = first_of(seen, "rTRAPspUK");
    if (c)
        return bad(err, errlen, "--%s is not available with fixed-point types", long_name(c));
    if (!fx_func_find(rq->func))
        return bad(err, errlen, "no fixed-point %.200s (available: %s)", rq->func, fx_func_list());
    if (strcmp(rq->variant, "exact") && strcmp(rq->variant, "fast"))
        return bad(err, errlen, "unknown variant '%.200s' (use exact or fast)", rq->variant);
    if (rq->order > FX_MAX_SEARCH)
        return bad(err, errlen,
                   "--order %d: fixed-point orders go up to %d (the highest the order search tries; "
                   "higher ones only add fitting time)",
                   rq->order, FX_MAX_SEARCH);
    return 0;
}

static int check_noise(pf_request *rq, const unsigned char *seen, char *err, size_t errlen)
{
    int c = first_of(seen, "nmrTRAPUK");
    if (c)
        return bad(err, errlen, "--%s does not apply to noise (a fixed method: gradient noise within 1 LSB)",
                   long_name(c));
    if (seen['j'])
        return bad(err, errlen, "--json is not available for noise");
    if (seen['p'])
        return bad(err, errlen, "--prefix is for --scene");
    if (strcmp(rq->variant, "exact"))
        return bad(err, errlen, "noise has only the exact variant (within 1 LSB), not '%.200s'", rq->variant);
    if (!rq->type_s && !rq->out_type_s)
        return bad(err, errlen, "%s needs a fixed-point --type (float noise is pf_noise1f … pf_noise4f in libpfmath)",
                   rq->func);
    if (rq->in.is_float || rq->out.is_float)
        return bad(err, errlen,
                   "%s is generated for fixed-point types only; float noise is pf_noise1f … pf_noise4f in "
                   "libpfmath (pfnoise.h)",
                   rq->func);
    char t[64];
    if (!rq->out.is_signed) {
        pf_type_format(&rq->out, t, sizeof t);
        return bad(err, errlen,
                   "output %s is unsigned: gradient noise takes values in [-1, 1], half of them negative (they "
                   "would saturate to 0); use a signed output",
                   t);
    }
    pf_type_format(&rq->in, t, sizeof t);
    if (rq->in.exp <= 0)
        return bad(err, errlen,
                   "input %s has no fraction bits (exp <= 0): every input is a lattice point, where the noise is "
                   "identically 0",
                   t);
    if (rq->in.exp > 62)
        return bad(err, errlen, "input %s: exp > 62 is not supported (the fraction must fit a 64-bit word)", t);
    if (rq->name && !strcmp(rq->func, "noise") && strlen(rq->name) + 1 > PF_NAME_MAX)
        return bad(err, errlen, "bad --name: with --func noise the names are NAME1 .. NAME4, at most %d characters",
                   PF_NAME_MAX);
    /* --func noise --name log: its log2 is <math.h>'s */
    for (int d = 1; rq->name && !strcmp(rq->func, "noise") && d <= 4; d++) {
        char n[PF_NAME_MAX + 2];
        snprintf(n, sizeof n, "%s%d", rq->name, d);
        if (pf_check_name("--name (with --func noise, NAME1 .. NAME4)", n, err, errlen) != 0)
            return 2;
    }
    return 0;
}

/* the plot is SVG only: a name with another extension (x.png) would get
   SVG bytes under a name that promises something else */
static int plot_name_ok(const char *path)
{
    const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    const char *dot = strrchr(base, '.');
    return !dot || dot == base || !strcasecmp(dot, ".svg");
}

/* 1 when path is the regular file open as descriptor fd: a rename over it
   (output.h) leaves what was written to fd in the replaced file, lost */
static int is_fd_file(const char *path, int fd)
{
    struct stat a, b;
    return fstat(fd, &a) == 0 && S_ISREG(a.st_mode) && stat(path, &b) == 0 && a.st_dev == b.st_dev &&
           a.st_ino == b.st_ino;
}

/* -o and --plot: checked before the fit (output.h).  "-o -" is standard
   output, as no -o is (a file named '-' was written before 2026-12-07). */
static int check_outputs(pf_request *rq, char *err, size_t errlen)
{
    if (rq->output && !strcmp(rq->output, "-")) {
        if (rq->json)
            return bad(err, errlen, "-o - and --json both write to standard output: give -o a file name");
        rq->output = NULL;
    }
    if (rq->plot && !strcmp(rq->plot, "-"))
        return bad(err, errlen, "--plot -: give a file name (standard output carries the C)");
    if (rq->plot && !plot_name_ok(rq->plot))
        return bad(err, errlen, "--plot %.200s: the plot is SVG; give a name ending in .svg", rq->plot);
    if (rq->output && pf_out_check("-o", rq->output, err, errlen) != 0)
        return 2;
    if (rq->plot && pf_out_check("--plot", rq->plot, err, errlen) != 0)
        return 2;
    if (rq->output && rq->plot && pf_out_same(rq->output, rq->plot))
        return bad(err, errlen, "-o and --plot name the same file");
    /* "--json -o /dev/stdout > f" (or "-o f 2> f"): the JSON (the report)
       went to the file that the rename then replaced, exit 0 */
    const char *names[2] = {rq->output, rq->plot}, *opt[2] = {"-o", "--plot"};
    for (int i = 0; i < 2; i++) {
        if (names[i] && rq->json && is_fd_file(names[i], 1))
            return bad(err, errlen, "%s %.200s is the file standard output goes to, where --json writes", opt[i],
                       names[i]);
        if (names[i] && is_fd_file(names[i], 2))
            return bad(err, errlen, "%s %.200s is the file standard error goes to, where the report goes", opt[i],
                       names[i]);
    }
    return 0;
}

int pf_request_parse(int argc, char **argv, pf_request *rq, char *err, size_t errlen)
{
    memset(rq, 0, sizeof *rq);
    rq->variant = "exact";
    rq->sweep = 1;
    unsigned char seen[256] = {0};
    opterr = 0;
    optind = 0; /* GNU: a full re-initialisation */
    int c;
    while ((c = getopt_long(argc, argv, ":ho:", opts, NULL)) != -1) {
        if (c == ':')
            return bad(err, errlen, "option '%.200s' needs an argument", argv[optind - 1]);
        if (c == '?') {
            if (optopt && optopt < 256 && isprint(optopt))
                return bad(err, errlen, "unknown option '-%c' (see --help)", optopt);
            return bad(err, errlen, "unknown option '%.200s' (see --help)", argv[optind - 1]);
        }
        if (seen[c])
            return bad(err, errlen, "--%s given twice (each option at most once)", long_name(c));
        seen[c] = 1;
        if ((c == 'T' || c == 'R' || c == 'A') && seen['T'] + seen['R'] + seen['A'] > 1)
            return bad(err, errlen, "only one of --target, --max-rel-err, --max-abs-err");
        switch (c) {
        case 'f': rq->func = optarg; break;
        case 'v': rq->variant = optarg; break;
        case 'r': rq->reduction = optarg; break;
        case 't': rq->type_s = optarg; break;
        case 'O': rq->out_type_s = optarg; break;
        case 'N': rq->name = optarg; break;
        case 'o': rq->output = optarg; break;
        case 'P': rq->plot = optarg; break;
        case 'C': rq->scene = optarg; break;
        case 'p': rq->prefix = optarg; break;
        case 'j': rq->json = 1; break;
        case 'S': rq->sweep = 0; break;
        case 'h': rq->help = 1; break;
        case 'n': {
            char *end;
            errno = 0;
            long v = strtol(optarg, &end, 10);
            if (errno || !isdigit((unsigned char)optarg[0]) || *end || v < 1 || v > 30)
                return bad(err, errlen, "bad order '%.200s': expected an integer 1..30", optarg);
            rq->order = (int)v;
            break;
        }
        case 'm':
            if (strcmp(optarg, "lsq") && strcmp(optarg, "minimax"))
                return bad(err, errlen, "unknown method '%.200s' (available: minimax, lsq)", optarg);
            rq->method = optarg;
            break;
        case 's': {
            /* decimal or 0x hex, the whole argument (as pfsweep's and
               pfbench's numbers): no sign, no blank, no octal from a 0 */
            const char *d = optarg;
            int hex = d[0] == '0' && (d[1] == 'x' || d[1] == 'X');
            d += hex ? 2 : 0;
            char *end;
            errno = 0;
            unsigned long long v = isxdigit((unsigned char)*d) && (hex || isdigit((unsigned char)*d))
                                       ? strtoull(d, &end, hex ? 16 : 10)
                                       : (end = (char *)d, 0);
            if (errno || end == d || *end)
                return bad(err, errlen, "bad --seed '%.200s': expected an unsigned 64-bit integer (decimal or 0x hex)",
                           optarg);
            rq->seeded = 1;
            rq->seed = v;
            break;
        }
        case 'T': {
            pf_type t;
            char e[200];
            if (pf_type_parse(optarg, &t, e, sizeof e) != 0)
                return bad(err, errlen, "bad --target: %s", e);
            pf_type_format(&t, rq->target_text, sizeof rq->target_text);
            rq->target = t.is_float ? 0x1p-24 : 0.5 * pf_type_lsb(&t);
            rq->target_abs = !t.is_float;
            break;
        }
        case 'U':
            if (parse_ulp(optarg, &rq->max_ulp) != 0)
                return bad(err, errlen, "bad --max-ulp '%.200s': expected a finite number >= 0.5 (ULP), such as 1, "
                           "4 or 2^7", optarg);
            break;
        case 'K':
            if (strcmp(optarg, "all") && strcmp(optarg, "sample"))
                return bad(err, errlen, "bad --confirm '%.200s': all (exhaustive, the default) or sample", optarg);
            rq->confirm_sample = !strcmp(optarg, "sample");
            break;
        case 'R':
        case 'A':
            if (parse_bound(optarg, &rq->target) != 0)
                return bad(err, errlen, "bad error bound '%.200s': expected a number in (0, 1) such as 1e-4 or 2^-12",
                           optarg);
            rq->target_abs = c == 'A';
            snprintf(rq->target_text, sizeof rq->target_text, "%s %.60s",
                     c == 'A' ? "--max-abs-err" : "--max-rel-err", optarg);
            break;
        }
    }
    if (optind < argc)
        return bad(err, errlen, "unexpected argument '%.200s' (see --help)", argv[optind]);
    if (rq->help)
        return 0;
    if (rq->scene) {
        rq->mode = PF_MODE_SCENE;
        c = first_of(seen, "fvnrtOmNjSTRAPsUK");
        if (c)
            return bad(err, errlen, "--%s does not apply to --scene (usage: pfmathgen --scene FILE -o DIR "
                       "[--prefix P])", long_name(c));
        if (!rq->output)
            return bad(err, errlen, "usage: pfmathgen --scene FILE -o DIR [--prefix P]");
        if (!strcmp(rq->output, "-"))
            return bad(err, errlen, "-o -: --scene writes files into a directory; give its name");
        rq->command = pf_cli_command_line(argc, argv);
        return rq->command ? 0 : bad(err, errlen, "out of memory");
    }
    if (rq->prefix)
        return bad(err, errlen, "--prefix is for --scene");
    if (!rq->func)
        return bad(err, errlen, "--func is required (see --help)");
    if (rq->type_s && pf_parse_type("--type", rq->type_s, &rq->in, err, errlen) != 0)
        return 2;
    if (rq->out_type_s && pf_parse_type("--out-type", rq->out_type_s, &rq->out, err, errlen) != 0)
        return 2;
    /* a fixed-point output says nothing of the input's format: guessing
       it (the output's) picked a function of another argument range */
    if (!rq->type_s && rq->out_type_s && !rq->out.is_float)
        return bad(err, errlen, "--out-type %.100s without --type: give the input type too", rq->out_type_s);
    if (!rq->type_s)
        rq->in = rq->out_type_s ? rq->out : (pf_type){.is_float = 1};
    if (!rq->out_type_s)
        rq->out = rq->in;
    if (rq->name && pf_check_name("--name", rq->name, err, errlen) != 0)
        return 2;
    int rc;
    if (fx_noise_is(rq->func)) {
        rq->mode = PF_MODE_NOISE;
        rc = check_noise(rq, seen, err, errlen);
    } else if (!rq->in.is_float || !rq->out.is_float) {
        rq->mode = PF_MODE_FIXED;
        if (rq->in.is_float != rq->out.is_float) {
            char a[64], b[64];
            pf_type_format(&rq->in, a, sizeof a);
            pf_type_format(&rq->out, b, sizeof b);
            return bad(err, errlen,
                       "bad type pair %s -> %s: float and fixed point do not mix (both float, or both fixed)", a, b);
        }
        rc = check_fixed(rq, seen, err, errlen);
    } else {
        rq->mode = PF_MODE_FLOAT;
        rc = check_float(rq, seen, err, errlen);
    }
    if (rc)
        return rc;
    if (check_outputs(rq, err, errlen))
        return 2;
    rq->command = pf_cli_command_line(argc, argv);
    return rq->command ? 0 : bad(err, errlen, "out of memory");
}

void pf_request_free(pf_request *rq)
{
    free(rq->command);
    rq->command = NULL;
}
