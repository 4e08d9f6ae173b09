/* pfsweep: ULP error of a float function against the MPFR references.
 * See --help. */
#include "compile.h"
#include "pfcli.h"
#include "sweep.h"

#include <dlfcn.h>
#include <errno.h>
#include <getopt.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char usage[] =
    "usage: pfsweep --func NAME [--variant exact|fast] [--lib[=PATH] | --source FILE.c]\n"
    "               [--name SYMBOL] [--all] [--samples N] [--seed S] [--max-ulp B]\n"
    "Measures the ULP error of a float function against correctly rounded MPFR\n"
    "references: every float in the function's reduced domain, a seeded\n"
    "full-range sample, and a directed list of special and hard inputs.\n"
    "  --lib[=PATH]    the function from libpfmath.so (default: next to pfsweep,\n"
    "                  or PREFIX/lib/libpfmath.so.0 for PREFIX/bin/pfsweep)\n"
    "  --source FILE   compile FILE.c with $CC (default cc) and sweep its function\n"
    "  --name SYMBOL   function symbol (default pf_<func>f or pf_<func>f_fast)\n"
    "  --all           every one of the 2^32 floats instead (OpenMP threads);\n"
    "                  atan2: a dense seeded sample of --pairs pairs and every\n"
    "                  pair of special values (tests/pfsweep_pairs.c)\n"
    "  --pairs N       atan2 with --all: random pairs, 1..2^32 (default 2^28)\n"
    "  --samples N     size of the random sample, 0..2^32 (default 2^22)\n"
    "  --seed S        seed of the random sample, 0..2^64-1 (default 1)\n"
    "  --max-ulp B     exit with status 1 when the max error exceeds B ULP (B >= 0)\n"
    "Numbers are decimal or 0x hex; each option may be given once.\n"
    "Exit status: 0 ok, 1 bound exceeded or load failure, 2 bad usage.\n";

static void die2(const char *msg, const char *arg)
{
    pfcli_line("pfsweep", msg, arg); /* one line, whatever arg holds */
    exit(2);
}

int pfsweep_fixed_main(int argc, char **argv); /* tests/pfsweep_fixed.c */
int pfsweep_pairs(pf_sweep_stats *s, pf_func f, pf_fn2 fn, uint64_t seed, uint64_t n); /* tests/pfsweep_pairs.c */

int main(int argc, char **argv)
{
    pfcli_check_stdout("pfsweep"); /* the results are its output: > /dev/full is exit 1 */
    for (int i = 1; i < argc; i++)
        if (!strncmp(argv[i], "--type", 6) || !strncmp(argv[i], "--out-type", 10))
            return pfsweep_fixed_main(argc, argv);
    static const struct option opts[] = {
        {"func", required_argument, 0, 'f'},   {"variant", required_argument, 0, 'v'},
        {"lib", optional_argument, 0, 'l'},    {"source", required_argument, 0, 's'},
        {"name", required_argument, 0, 'N'},   {"all", no_argument, 0, 'a'},
        {"samples", required_argument, 0, 'n'}, {"seed", required_argument, 0, 'S'},
        {"max-ulp", required_argument, 0, 'm'}, {"help", no_argument, 0, 'h'},
        {"pairs", required_argument, 0, 'P'},
        {0, 0, 0, 0}};
    const char *func = NULL, *variant = "exact", *lib = NULL, *src = NULL, *name = NULL;
    int all = 0, use_lib = 0;
    unsigned long long samples = 1ull << 22, seed = 1, pairs = 1ull << 28;
    double max_ulp = -1;
    unsigned char seen[256] = {0};
    opterr = 0;
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
        case 'P':
            if (pfcli_u64(optarg, 1, 1ull << 32, &pairs))
                die2("--pairs must be a whole number in 1..2^32: ", optarg);
            break;
        case 'm':
            if (pfcli_real(optarg, 0, 1e300, &max_ulp))
                die2("--max-ulp must be a finite number >= 0: ", optarg);
            break;
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
    if (fid < 0 || fid == PF_SQRT)
        die2("unknown function ", func);
    if (use_lib && src)
        die2("--lib and --source exclude each other", NULL);
    if (seen['P'] && !(all && pfref_arity((pf_func)fid) == 2))
        die2("--pairs is for atan2 with --all (see --help)", NULL);
    /* --all of a one-argument function sweeps every float and draws no
       sample: --samples and --seed were accepted and had no effect */
    if (all && pfref_arity((pf_func)fid) == 1 && (seen['n'] || seen['S']))
        die2("--samples and --seed are for the seeded sample, which --all replaces by every float (see --help)", NULL);
    if (!use_lib && !src)
        use_lib = 1;
    char sym[160];
    if (name)
        snprintf(sym, sizeof sym, "%s", name);
    else
        snprintf(sym, sizeof sym, "pf_%sf%s", func, strcmp(variant, "fast") ? "" : "_fast");
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
    void *p = dlsym(h, sym);
    if (!p) {
        char m[PATH_MAX + 256];
        snprintf(m, sizeof m, "no function %s in %s", sym, src ? src : lib ? lib : "libpfmath.so");
        pfcli_line("pfsweep", m, NULL);
        return 1;
    }
    pf_fn1 f1 = NULL;
    pf_fn2 f2 = NULL;
    if (pfref_arity((pf_func)fid) == 2)
        *(void **)&f2 = p;
    else
        *(void **)&f1 = p;
    pf_sweep_stats tot;
    pf_sweep_init(&tot);
    printf("pfsweep %s (%s)\n", sym, func);
    if (all && !f2) {
        pf_sweep_stats s;
        pf_sweep_init(&s);
        pf_sweep_bits(&s, (pf_func)fid, f1, f2, 0, 0xffffffffu, isatty(2));
        pf_sweep_print(stdout, "every float (2^32)", (pf_func)fid, &s);
        pf_sweep_merge(&tot, &s);
    } else {
        pf_sweep_stats s;
        if (!f2) {
            uint32_t lo, hi;
            pf_sweep_reduced_range((pf_func)fid, &lo, &hi);
            pf_sweep_init(&s);
            pf_sweep_bits(&s, (pf_func)fid, f1, f2, lo, hi, isatty(2));
            pf_sweep_print(stdout, "reduced domain (every float)", (pf_func)fid, &s);
            pf_sweep_merge(&tot, &s);
        }
        if (f2 && all) {
            pf_sweep_init(&s);
            int nsp = pfsweep_pairs(&s, (pf_func)fid, f2, seed, pairs);
            char title[128];
            snprintf(title, sizeof title, "dense seeded pairs (%llu) and all %d special pairs", pairs, nsp);
            pf_sweep_print(stdout, title, (pf_func)fid, &s);
            pf_sweep_merge(&tot, &s);
        }
        pf_sweep_init(&s);
        pf_sweep_random(&s, (pf_func)fid, f1, f2, seed, samples);
        pf_sweep_print(stdout, "seeded full-range sample", (pf_func)fid, &s);
        pf_sweep_merge(&tot, &s);
    }
    pf_sweep_stats d;
    pf_sweep_init(&d);
    pf_sweep_directed(&d, (pf_func)fid, f1, f2);
    pf_sweep_print(stdout, "directed special and hard inputs", (pf_func)fid, &d);
    pf_sweep_merge(&tot, &d);
    printf("TOTAL %s max_ulp=%.6f mean_ulp=%.6f cr=%.4f%% count=%llu worst=%a\n", sym, tot.max_ulp,
           pf_sweep_mean(&tot), pf_sweep_cr_percent(&tot), (unsigned long long)tot.count,
           (double)tot.worst_x);
    if (max_ulp >= 0 && !(tot.max_ulp <= max_ulp)) {
        printf("FAIL: max %.6f ULP exceeds the bound %.3f\n", tot.max_ulp, max_ulp);
        return 1;
    }
    return 0;
}
