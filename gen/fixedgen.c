/* pfmathgen for fixed-point types: option parsing, the checks that make a
 * bad type or pair a one-line error (exit 2, nothing written), and output.
 * The pipeline itself is gen/fixed_core.c. */
#include "cli.h"
#include "fixedgen.h"

#include "fixed_internal.h"
#include "fixedtype.h"

#include <ctype.h>
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const fx_func *const funcs[] = {&fx_func_sin, &fx_func_cos,  &fx_func_exp, &fx_func_exp2,
                                       &fx_func_log, &fx_func_log2, &fx_func_sqrt};
#define NFUNCS ((int)(sizeof funcs / sizeof funcs[0]))

const fx_func *fx_func_find(const char *name)
{
    for (int i = 0; i < NFUNCS; i++)
        if (!strcmp(funcs[i]->name, name))
            return funcs[i];
    return NULL;
}

const char *fx_func_list(void)
{
    return "sin, cos, exp, exp2, log, log2, sqrt, noise1, noise2, noise3, noise4, noise";
}

/* the --func argument, or NULL */
static const char *func_arg(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--func") && i + 1 < argc)
            return argv[i + 1];
        if (!strncmp(argv[i], "--func=", 7))
            return argv[i] + 7;
    }
    return NULL;
}

int pfmathgen_wants_fixed(int argc, char **argv)
{
    /* noise is generated for fixed-point types only: this front end also
       answers a float request for it (with a pointer to libpfmath) */
    if (fx_noise_is(func_arg(argc, argv)))
        return 1;
    for (int i = 1; i < argc; i++) {
        const char *v = NULL;
        if ((!strcmp(argv[i], "--type") || !strcmp(argv[i], "--out-type")) && i + 1 < argc)
            v = argv[i + 1];
        else if (!strncmp(argv[i], "--type=", 7))
            v = argv[i] + 7;
        else if (!strncmp(argv[i], "--out-type=", 11))
            v = argv[i] + 11;
        if (v && strcmp(v, "float"))
            return 1;
    }
    return 0;
}

static const char usage[] =
    "usage: pfmathgen --func NAME --type T [--out-type T2] [options]\n"
    "Fixed-point generation: integer-only C taking and returning the stored integers.\n"
    "  --func NAME         sin, cos, exp, exp2, log, log2, sqrt, or gradient noise:\n"
    "                      noise1, noise2, noise3, noise4 (one dimension) or noise (all four)\n"
    "  --type T            input type, e.g. 'fixed<15,12>', 'unsigned fixed<16,8>', 'ufixed<16,8>'\n"
    "                      (storage up to 32 bits)\n"
    "  --out-type T        output type (default: the input type)\n"
    "  --variant V         exact (default: below 1 LSB of the output for every input) or\n"
    "                      fast (within max(2^-10 relative, 4 LSB))\n"
    "  --order N           polynomial degree (default: the smallest within the variant's bound)\n"
    "  --method M          minimax (default for exact) or lsq (default for fast)\n"
    "  --name NAME         function name (default pf_<func>_<in>_<out>[_fast], see docs/fixed.md)\n"
    "  -o, --output FILE   write the C source to FILE (nothing is written on error)\n"
    "  --json              print the report as one JSON object on stdout instead of C\n"
    "  --no-sweep          do not compile and sweep the emitted code\n"
    "  --seed N            noise only: lattice from pf_noise_table_seed(N) (default: Perlin's\n"
    "                      permutation, the library's default table); noise takes exact only,\n"
    "                      no --order/--method, an input exp >= 1; --name S with --func noise\n"
    "                      names the four functions S1 .. S4\n"
    "  -h, --help          this text\n"
    "Exit status: 0 ok, 2 bad usage, bad type or pair, impossible request, 1 internal failure.\n";

const char *fx_usage_text(void) { return usage; }

/* the command line as a shell would re-run it (quoted where needed) */
/* A type option's value, or exit 2: malformed, or fixed with storage over
 * 32 bits (float passes, for the caller to judge). */
void fx_parse_type(const char *what, const char *s, pf_type *t)
{
    char e[200];
    if (pf_type_parse(s, t, e, sizeof e) != 0)
        pf_cli_die2("bad %s: %s", what, e);
    if (!t->is_float && t->storage_bits > 32) {
        char f[64];
        pf_type_format(t, f, sizeof f);
        pf_cli_die2("unsupported %s %s: fixed-point functions take storage of at most 32 bits", what, f);
    }
}

int pfmathgen_fixed_main(int argc, char **argv)
{
    static const struct option opts[] = {
        {"func", required_argument, 0, 'f'},     {"variant", required_argument, 0, 'v'},
        {"order", required_argument, 0, 'n'},    {"type", required_argument, 0, 't'},
        {"out-type", required_argument, 0, 'O'}, {"method", required_argument, 0, 'm'},
        {"name", required_argument, 0, 'N'},     {"output", required_argument, 0, 'o'},
        {"json", no_argument, 0, 'j'},           {"no-sweep", no_argument, 0, 'S'},
        {"help", no_argument, 0, 'h'},           {"reduction", required_argument, 0, 'X'},
        {"target", required_argument, 0, 'X'},   {"max-rel-err", required_argument, 0, 'X'},
        {"max-abs-err", required_argument, 0, 'X'}, {0, 0, 0, 0}};
    const char *func = NULL, *variant = "exact", *type_s = NULL, *out_s = NULL, *method = NULL, *name = NULL,
               *out = NULL;
    int order = 0, json = 0, sweep = 1;
    if (fx_noise_is(func_arg(argc, argv)))
        return fx_noise_main(argc, argv);
    opterr = 0;
    optind = 1;
    int c;
    while ((c = getopt_long(argc, argv, ":ho:", opts, NULL)) != -1) {
        switch (c) {
        case 'f': func = optarg; break;
        case 'v':
            if (strcmp(optarg, "exact") && strcmp(optarg, "fast"))
                pf_cli_die2("unknown variant '%s' (use exact or fast)%s", optarg, "");
            variant = optarg;
            break;
        case 'n': {
            char *end;
            errno = 0;
            long v = strtol(optarg, &end, 10);
            if (errno || end == optarg || *end || v < 1 || v > 30)
                pf_cli_die2("bad order '%s': expected an integer 1..30%s", optarg, "");
            order = (int)v;
            break;
        }
        case 't': type_s = optarg; break;
        case 'O': out_s = optarg; break;
        case 'm':
            if (strcmp(optarg, "lsq") && strcmp(optarg, "minimax"))
                pf_cli_die2("unknown method '%s' (available: minimax, lsq)%s", optarg, "");
            method = optarg;
            break;
        case 'N':
            if (!pf_cli_is_identifier(optarg))
                pf_cli_die2("bad --name '%s': not a C identifier%s", optarg, "");
            name = optarg;
            break;
        case 'o': out = optarg; break;
        case 'j': json = 1; break;
        case 'S': sweep = 0; break;
        case 'X': pf_cli_die2("--reduction, --target, --max-rel-err and --max-abs-err are not available with "
                       "fixed-point types%s%s", "", ""); break;
        case 'h': fputs(usage, stdout); return 0;
        case ':': pf_cli_die2("option '%s' needs an argument%s", argv[optind - 1], ""); break;
        default: pf_cli_die2("unknown option '%s' (see --help)%s", argv[optind - 1], ""); break;
        }
    }
    if (optind < argc)
        pf_cli_die2("unexpected argument '%s' (see --help)%s", argv[optind], "");
    if (!func)
        pf_cli_die2("--func is required (see --help)%s%s", "", "");
    pf_type in, ot;
    if (type_s)
        fx_parse_type("--type", type_s, &in);
    if (out_s)
        fx_parse_type("--out-type", out_s, &ot);
    if (!type_s)
        in = ot;
    if (!out_s)
        ot = in;
    if (in.is_float || ot.is_float) {
        char a[64], b[64];
        pf_type_format(&in, a, sizeof a);
        pf_type_format(&ot, b, sizeof b);
        pf_cli_die2("bad type pair %s -> %s: float and fixed point do not mix (both float, or both fixed)", a, b);
    }
    const fx_func *F = fx_func_find(func);
    if (!F)
        pf_cli_die2("no fixed-point %s (available: %s)", func, fx_func_list());
    fx_gen *G = calloc(1, sizeof *G);
    if (!G)
        return 1;
    G->fn = F;
    G->exact = !strcmp(variant, "exact");
    G->in = in;
    G->out = ot;
    pf_type_format(&in, G->in_text, sizeof G->in_text);
    pf_type_format(&ot, G->out_text, sizeof G->out_text);
    G->it = pf_type_ctype(&in);
    G->ot = pf_type_ctype(&ot);
    G->order_req = order;
    G->minimax = method ? !strcmp(method, "minimax") : -1;
    if (name)
        snprintf(G->name, sizeof G->name, "%s", name);
    else
        pf_fixed_default_name(F->name, &in, &ot, !G->exact, G->name, sizeof G->name);
    char *cmd = pf_cli_command_line(argc, argv);
    G->command = cmd;
    char err[800];
    int rc = fx_generate(G, sweep, err, sizeof err);
    if (rc == -1)
        pf_cli_die2("%s%s", err, "");
    if (rc != 0) {
        fprintf(stderr, "pfmathgen: %s\n", err);
        return 1;
    }
    if (G->swept) {
        /* the sweep checks the error model: a violation is a bug, not a result */
        const char *bad = NULL;
        char why[300];
        if (G->sw.mismatch)
            bad = "the scalar and array forms differ";
        else if (G->exact && !(G->sw.max_err < 1))
            bad = "the exact variant reaches 1 LSB";
        else if (!G->exact && G->sw.over_fast)
            bad = "the fast variant exceeds max(2^-10 relative, 4 LSB)";
        else if (G->sw.max_err > G->bound_lsb + 1e-6)
            bad = "the sweep exceeds the error bound";
        if (bad) {
            snprintf(why, sizeof why, "%s (max %.4f LSB at x = %lld, bound %.4f LSB)", bad, G->sw.max_err,
                     (long long)G->sw.worst_x, G->bound_lsb);
            fx_report_text(stderr, G);
            fprintf(stderr, "pfmathgen: internal failure: %s\n", why);
            return 1;
        }
    }
    size_t len;
    char *src = fx_emit(G, &len);
    if (json)
        fx_report_json(stdout, G);
    else
        fx_report_text(stderr, G);
    int ret = 0;
    if (out) {
        if (pf_cli_write_atomically(out, src, len) != 0) {
            fprintf(stderr, "pfmathgen: cannot write %s\n", out);
            ret = 1;
        }
    } else if (!json) {
        fwrite(src, 1, len, stdout);
    }
    free(src);
    free(cmd);
    free(G);
    return ret;
}
