/* pfsweep for fixed-point functions (--type/--out-type): error in LSBs of the
 * output type against ref/ (MPFR), max and mean, worst input, histogram.
 * Exhaustive for inputs of at most 16 bits; --all for 32-bit ones. */
#include "compile.h"
#include "pfcli.h"
#include "fixedgen.h"
#include "fixedtype.h"
#include "sweep_fixed.h"

#include <dlfcn.h>
#include <errno.h>
#include <getopt.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int pfsweep_fixed_main(int argc, char **argv);

static const char usage[] =
    "usage: pfsweep --func NAME --type T [--out-type T2] [--variant exact|fast]\n"
    "               [--lib [PATH] | --source FILE.c] [--name SYMBOL] [--all]\n"
    "               [--samples N] [--seed S] [--max-lsb B]\n"
    "Measures a fixed-point function's error in LSBs of the output type against\n"
    "MPFR: every input for input types of at most 16 bits; for 32-bit inputs every\n"
    "input within 2^16 of 0 and a seeded sample (or all 2^32 with --all).  The\n"
    "reference saturates to the output range; log(x <= 0) is the most negative\n"
    "output and sqrt(x < 0) is 0, as the generated functions define them.\n"
    "  --lib [PATH]    the function from libpfmath.so (default: next to pfsweep,\n"
    "                  or PREFIX/lib/libpfmath.so.0 for PREFIX/bin/pfsweep)\n"
    "  --source FILE   compile FILE.c with $CC (default cc) and sweep its function\n"
    "  --name SYMBOL   function symbol (default: the library's name, e.g. pf_sin_q12_q14)\n"
    "  --all           every input of a 32-bit type (OpenMP threads; minutes)\n"
    "  --samples N     size of the random sample, 0..2^32 (default 2^22)\n"
    "  --seed S        seed of the random sample, 0..2^64-1 (default 1)\n"
    "  --max-lsb B     exit with status 1 unless every error is below B LSB (B > 0)\n"
    "Numbers are decimal or 0x hex; each option may be given once.\n"
    "Exit status: 0 ok, 1 bound exceeded (--max-lsb; for --variant fast also the\n"
    "fast bound max(2^-10 relative, 4 LSB)), scalar and array forms disagreeing, or\n"
    "load failure, 2 bad usage.\n";

static void die2(const char *msg, const char *arg)
{
    pfcli_line("pfsweep", msg, arg); /* one line, whatever arg holds */
    exit(2);
}

static void parse(const char *what, const char *s, pf_type *t)
{
    char e[200];
    if (pf_type_parse(s, t, e, sizeof e) != 0) {
        char m[300];
        snprintf(m, sizeof m, "bad %s: %s", what, e);
        die2(m, NULL);
    }
    if (t->is_float || t->storage_bits > 32) {
        char m[400];
        snprintf(m, sizeof m, "%s %.200s: expected a fixed-point type of at most 32 bits", what, s);
        die2(m, NULL);
    }
}

int pfsweep_fixed_main(int argc, char **argv)
{
    static const struct option opts[] = {
        {"func", required_argument, 0, 'f'},    {"variant", required_argument, 0, 'v'},
        {"lib", optional_argument, 0, 'l'},     {"source", required_argument, 0, 's'},
        {"name", required_argument, 0, 'N'},    {"all", no_argument, 0, 'a'},
        {"samples", required_argument, 0, 'n'}, {"seed", required_argument, 0, 'S'},
        {"max-lsb", required_argument, 0, 'm'}, {"type", required_argument, 0, 't'},
        {"out-type", required_argument, 0, 'O'}, {"help", no_argument, 0, 'h'},
        {0, 0, 0, 0}};
    const char *func = NULL, *variant = "exact", *lib = NULL, *src = NULL, *name = NULL, *ts = NULL, *os = NULL;
    int all = 0, use_lib = 0;
    unsigned long long samples = 1ull << 22, seed = 1;
    double max_lsb = -1;
    unsigned char seen[256] = {0};
    opterr = 0;
    optind = 1;
    int c;
    while ((c = getopt_long(argc, argv, ":h", opts, NULL)) != -1) {
        if (c != ':' && c != '?' && pfcli_once(seen, c))
            die2("option given twice: --", pfcli_name(opts, c));
        switch (c) {
        case 'f': func = optarg; break;
        case 'v':
            if (strcmp(optarg, "exact") && strcmp(optarg, "fast"))
                die2("unknown variant ", optarg);
            variant = optarg;
            break;
        case 'l':
            use_lib = 1;
            lib = optarg;
            /* "--lib PATH" as well as "--lib=PATH" (an optional argument
               is otherwise only taken after '=') */
            if (!lib && optind < argc && argv[optind][0] != '-')
                lib = argv[optind++];
            if (lib && !*lib)
                die2("--lib: empty path (without a PATH: --lib alone)", NULL);
            break;
        case 's': src = optarg; break;
        case 'N':
            /* whole, or refused: sym[160] cut it, and the message then
               named a symbol that was not the one given */
            if (strlen(optarg) >= 160)
                die2("--name: a symbol of at most 159 characters, not ", optarg);
            name = optarg;
            break;
        case 'a': all = 1; break;
        case 'n':
            if (pfcli_u64(optarg, 0, 1ull << 32, &samples))
                die2("--samples must be a whole number in 0..2^32: ", optarg);
            break;
        case 'S':
            if (pfcli_u64(optarg, 0, ULLONG_MAX, &seed))
                die2("--seed must be a whole number in 0..2^64-1: ", optarg);
            break;
        case 'm':
            if (pfcli_real(optarg, 0, 1e300, &max_lsb) || !(max_lsb > 0))
                die2("--max-lsb must be a finite number > 0: ", optarg);
            break;
        case 't': ts = optarg; break;
        case 'O': os = optarg; break;
        case 'h': fputs(usage, stdout); return 0;
        case ':': die2("option needs an argument: ", argv[optind - 1]); break;
        default: die2("unknown option (see --help): ", argv[optind - 1]); break;
        }
    }
    if (optind < argc)
        die2("unexpected argument ", argv[optind]);
    if (!func)
        die2("--func is required (see --help)", NULL);
    int fid = pfref_lookup(func);
    if (fid != PF_SIN && fid != PF_COS && fid != PF_EXP && fid != PF_EXP2 && fid != PF_LOG && fid != PF_LOG2 &&
        fid != PF_SQRT)
        die2("no fixed-point function ", func);
    /* main() came here for an argument starting with --type, which may
       have been another option's value (--name --type): then no type was
       given, and in/out were read uninitialized */
    if (!ts && !os)
        die2("a fixed-point sweep needs --type (and --out-type); '--type' was another option's value", NULL);
    pf_type in, out;
    if (ts)
        parse("--type", ts, &in);
    if (os)
        parse("--out-type", os, &out);
    if (!ts)
        in = out;
    if (!os)
        out = in;
    /* an input of at most 16 bits, or --all, is swept whole: there is no
       sample, and --samples or --seed were accepted and had no effect */
    if ((in.storage_bits <= 16 || all) && (seen['n'] || seen['S']))
        die2(all ? "--samples and --seed are for the seeded sample, which --all replaces by every input"
                 : "--samples and --seed are for 32-bit inputs: every input of 8 or 16 bits is swept",
             NULL);
    if (use_lib && src)
        die2("--lib and --source exclude each other", NULL);
    if (!use_lib && !src)
        use_lib = 1;
    char sym[160], asym[176];
    if (name)
        snprintf(sym, sizeof sym, "%s", name);
    else
        pf_fixed_default_name(func, &in, &out, !strcmp(variant, "fast"), sym, sizeof sym);
    snprintf(asym, sizeof asym, "%s_array", sym);
    void *h;
    char err[512];
    if (use_lib) {
        char path[PATH_MAX];
        if (lib) {
            if (pfcli_lib_path(lib, path, sizeof path) != 0)
                die2("--lib: path too long: ", lib);
        } else {
            if (pfcli_default_lib(path, sizeof path) != 0)
                die2("cannot locate libpfmath.so; pass --lib PATH", NULL);
        }
        h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
        if (!h) {
            pfcli_line("pfsweep", dlerror(), NULL);
            return 1;
        }
    } else {
        h = pf_compile_load_file(src, err, sizeof err);
        if (!h) {
            pfcli_line("pfsweep", err, NULL);
            return 1;
        }
    }
    pf_fx_fn fn = {dlsym(h, sym), dlsym(h, asym), pf_type_to_fmt(&in), pf_type_to_fmt(&out)};
    if (!fn.scalar) {
        char m[PATH_MAX + 256];
        snprintf(m, sizeof m, "no function %s in %s", sym, src ? src : lib ? lib : "libpfmath.so");
        pfcli_line("pfsweep", m, NULL);
        return 1;
    }
    char ti[64], to[64], title[512];
    pf_type_format(&in, ti, sizeof ti);
    pf_type_format(&out, to, sizeof to);
    printf("pfsweep %s (%s, %s -> %s)\n", sym, func, ti, to);
    pf_fx_stats s;
    pf_fx_stats_init(&s);
    int64_t lo = pf_type_min_stored(&in), hi = pf_type_max_stored(&in);
    if (in.storage_bits <= 16 || all) {
        pf_fx_sweep_range(&s, (pf_func)fid, &fn, lo, hi, 1, in.storage_bits > 16 && isatty(2));
        snprintf(title, sizeof title, "every input (%llu)", (unsigned long long)(hi - lo + 1));
    } else {
        int64_t a = lo > -65536 ? lo : -65536, z = hi < 65536 ? hi : 65536;
        pf_fx_sweep_range(&s, (pf_func)fid, &fn, a, z, 1, 0);
        pf_fx_sweep_random(&s, (pf_func)fid, &fn, seed, samples);
        snprintf(title, sizeof title, "every input in [%lld, %lld], %llu seeded random ones (seed %llu), the ends",
                 (long long)a, (long long)z, samples, seed);
    }
    int fast = !strcmp(variant, "fast");
    pf_fx_stats_print(stdout, title, (pf_func)fid, fn.in, fn.out, &s, fast);
    int rc = 0;
    if (max_lsb > 0 && !(s.max_err < max_lsb)) {
        printf("FAIL: max error %.6f LSB is not below %g\n", s.max_err, max_lsb);
        rc = 1;
    }
    if (fast && s.over_fast) {
        printf("FAIL: %llu inputs beyond max(2^-10 relative, 4 LSB)\n", (unsigned long long)s.over_fast);
        rc = 1;
    }
    if (s.mismatch) {
        printf("FAIL: scalar and array forms differ on %llu inputs\n", (unsigned long long)s.mismatch);
        rc = 1;
    }
    return rc;
}
