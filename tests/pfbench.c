/* pfbench: speed against error for every pfmath function and its peers
 * (glibc scalar, glibc's libmvec, SLEEF u10/u35), same inputs, same run.
 * See --help and docs/bench.md. */
#include "pfbench.h"
#include "pfbench_fixed.h"
#include "pfbench_ladder.h"
#include "pfcli.h"
#include "pfcli_out.h"

#include <errno.h>
#include <getopt.h>
#include <gnu/libc-version.h>
#include <limits.h>
#include <math.h>
#include <sleef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static const char usage[] =
    "usage: pfbench [--lib PATH] [--out DIR] [--func f,g,...] [--reps N] [--samples N]\n"
    "               [--seed S] [--ms T] [--ladder PATH] [--list]\n"
    "Times every pfmath function found in libpfmath.so (exact, fast; scalar and\n"
    "each array clone) beside glibc's scalar function, libmvec and SLEEF u10/u35\n"
    "(AVX2, AVX-512 where the CPU has it) on the same inputs, and measures every\n"
    "candidate's ULP error against MPFR on a seeded sample of the same domain.\n"
    "  --lib PATH    libpfmath.so (default: next to pfbench)\n"
    "  --out DIR     where bench.md and bench.csv go (default: pfbench's directory)\n"
    "  --func LIST   only these functions (default: all)\n"
    "  --reps N      timed repetitions per candidate, >= 11 (default 15)\n"
    "  --samples N   error sample size, >= 2^16 (default 2^20)\n"
    "  --seed S      seed of the sample, 0..2^64-1 (default 1)\n"
    "  --ms T        target length of one timed repetition in ms (default 4)\n"
    "  --ladder PATH the accuracy ladder's library (make ladder: build/libpfladder.so):\n"
    "                rows pfmath-L<U> for its levels, in the Pareto checks\n"
    "  --list        print the domains and the candidates found, then exit\n"
    "Numbers are decimal or 0x hex; each option may be given once.  bench.md and\n"
    "bench.csv are replaced only at the end of a complete run.\n"
    "Exit status: 0 ok, 1 load or write failure, 2 bad usage.\n";

#define NTIME (1u << 16) /* elements per timed pass (issue 7) */

/* Timing uses this thread's CPU time, not the wall clock: on a shared
   machine the wall clock also counts the time other processes held the
   core, which says nothing about the code (it still sees their cache
   pollution, hence min and max beside the median). */
static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double wall(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static float asfloat(uint32_t u) { float f; memcpy(&f, &u, 4); return f; }
static uint32_t asuint(float f) { uint32_t u; memcpy(&u, &f, 4); return u; }

static void die2(const char *msg, const char *arg)
{
    pfcli_line("pfbench", msg, arg); /* one line, whatever arg holds */
    exit(2);
}

/* ---- timing ---- */

static void run(const pfb_cand *c, const float *x, const float *x2, float *y, size_t n)
{
    if (c->a1)
        c->a1(x, y, n);
    else if (c->a2)
        c->a2(x, x2, y, n);
    else if (c->s1)
        pfb_loop1(c->s1, x, y, n);
    else
        pfb_loop2(c->s2, x, x2, y, n);
}

static volatile uint32_t zero_v = 0;
static volatile float sink_v;

/* Latency: each input is x[i] with the previous result's bits ANDed with a
   zero the compiler cannot see, so every call waits for the one before it.
   Costs one and, one xor and two register moves per call: see "chain
   overhead" in the report, measured the same way on an empty function. */
static void chain(const pfb_cand *c, const float *x, const float *x2, size_t n)
{
    uint32_t zero = zero_v;
    float y = 0;
    if (c->s1) {
        for (size_t i = 0; i < n; i++)
            y = c->s1(asfloat(asuint(x[i]) ^ (asuint(y) & zero)));
    } else {
        for (size_t i = 0; i < n; i++)
            y = c->s2(asfloat(asuint(x[i]) ^ (asuint(y) & zero)), x2[i]);
    }
    sink_v = y;
}

__attribute__((noinline)) static float empty_fn(float x)
{
    __asm__ volatile("" : "+x"(x));
    return x;
}

typedef struct {
    pfb_cand c;
    pf_sweep_stats err;
    int have_err;
    int differs_from_scalar;  /* ours: array form's bits != scalar form's */
    int passes_t, passes_l;
    double *thr, *lat;        /* per repetition, ns */
    double thr_med, thr_min, thr_max, lat_med, lat_min, lat_max;
    int pareto;
} row;

static int passes_for(double t_one, double target)
{
    double p = target / (t_one > 1e-7 ? t_one : 1e-7);
    return p < 1 ? 1 : p > 1e6 ? 1000000 : (int)ceil(p);
}

/* ---- report helpers ---- */

static const char *fmt_ns(double v, char *b)
{
    if (!isfinite(v))
        snprintf(b, 24, "—");
    else if (v < 10)
        snprintf(b, 24, "%.2f", v);
    else if (v < 100)
        snprintf(b, 24, "%.1f", v);
    else
        snprintf(b, 24, "%.0f", v);
    return b;
}

static const char *fmt_ulp(double v, char *b)
{
    if (isnan(v))
        snprintf(b, 24, "—");
    else if (isinf(v))
        snprintf(b, 24, "inf");
    else if (v < 100)
        snprintf(b, 24, "%.3f", v);
    else
        snprintf(b, 24, "%.3g", v);
    return b;
}

static void cpu_name(char *out, size_t n)
{
    snprintf(out, n, "unknown CPU");
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (!f)
        return;
    char line[512];
    while (fgets(line, sizeof line, f)) {
        if (strncmp(line, "model name", 10) == 0) {
            char *p = strchr(line, ':');
            if (p) {
                p++;
                while (*p == ' ' || *p == '\t')
                    p++;
                p[strcspn(p, "\n")] = 0;
                snprintf(out, n, "%s", p);
            }
            break;
        }
    }
    fclose(f);
}

/* label for the plot: "pfmath avx512", "sleef-u35 avx2", "glibc" */
static void label(const pfb_cand *c, char *b, size_t n)
{
    if (strcmp(c->name, "glibc") == 0)
        snprintf(b, n, "glibc");
    else
        snprintf(b, n, "%s %s", c->name, c->isa);
}

static const row *find(const row *r, int n, const char *name, const char *isa)
{
    for (int i = 0; i < n; i++)
        if (!r[i].c.absent[0] && strcmp(r[i].c.name, name) == 0 && strcmp(r[i].c.isa, isa) == 0)
            return &r[i];
    return NULL;
}

/* goals of issue 7, one line each; counts misses */
typedef struct {
    FILE *md;
    int pass, miss, na;
    char misses[8192];
} goals;

static void goal_line(goals *g, const char *fn, const char *dom, const char *isa, const char *what,
                      double measured, double want, const char *unit, int higher_is_better,
                      const char *na_reason)
{
    char m[64];
    const char *verdict;
    if (na_reason) {
        snprintf(m, sizeof m, "—");
        verdict = na_reason;
        g->na++;
    } else {
        pfb_goal_fmt(m, sizeof m, measured, want, unit);
        int ok = higher_is_better ? measured >= want : measured <= want;
        verdict = ok ? "pass" : "**MISS**";
        if (ok)
            g->pass++;
        else {
            g->miss++;
            size_t l = strlen(g->misses);
            snprintf(g->misses + l, sizeof g->misses - l, "- %s %s %s: %s — measured %s, goal %s %.2f%s\n",
                     fn, dom, isa, what, m, higher_is_better ? ">=" : "<=", want, unit);
        }
    }
    fprintf(g->md, "| %s | %s | %s | %s | %s%.2f%s | %s | %s |\n", fn, dom, isa, what,
            higher_is_better ? ">= " : "<= ", want, unit, m, verdict);
}

static void goals_for(goals *g, pf_func f, const pfb_domain *d, const row *r, int n)
{
    const char *fn = pfref_name(f);
    const row *ex_s = find(r, n, "pfmath", "scalar");
    if (ex_s && ex_s->have_err)
        goal_line(g, fn, d->tag, "all", "exact: max ULP (sample)", ex_s->err.max_ulp, 1.0, "", 0, NULL);
    /* issue 12: the scalar exact form at least as fast as glibc's (throughput) */
    const row *gl = find(r, n, "glibc", "scalar");
    if (ex_s)
        goal_line(g, fn, d->tag, "scalar", "exact scalar vs glibc (speed ratio)",
                  gl ? gl->thr_med / ex_s->thr_med : NAN, 1.0, "x", 1, gl ? NULL : "n/a (no glibc function)");
    /* the same from each candidate's fastest repetition, for information: on
       a shared machine a scalar candidate's repetitions can split between two
       speed levels, and the medians then compare a slow level with a fast
       one (asin, 2026-12-08: medians 0.98x, fastest repetitions 1.29x) */
    if (ex_s && gl) {
        char m[64];
        pfb_goal_fmt(m, sizeof m, gl->thr_min / ex_s->thr_min, 1.0, "x");
        fprintf(g->md, "| %s | %s | scalar | exact scalar vs glibc, fastest repetitions (speed ratio) | — | %s | "
                       "information |\n",
                fn, d->tag, m);
    }
    int short_poly = f == PF_EXP || f == PF_EXP2 || f == PF_LOG || f == PF_LOG2 || f == PF_SIN ||
                     f == PF_COS;
    const char *isas[] = {"avx512", "avx2", "sse2", "dispatch"};
    for (int k = 0; k < 4; k++) {
        const row *ex = find(r, n, "pfmath", isas[k]), *fa = find(r, n, "pfmath-fast", isas[k]);
        /* the dispatched form runs the widest clone: compare with the widest peer */
        const char *peer_isa = k < 3 ? isas[k] : find(r, n, "sleef-u10", "avx512") ? "avx512" : "avx2";
        const row *u10 = find(r, n, "sleef-u10", peer_isa), *u35 = find(r, n, "sleef-u35", peer_isa);
        if (!ex && !fa)
            continue;
        if (ex && k != 2) {
            char what[96];
            snprintf(what, sizeof what, "exact vs SLEEF u10 (speed ratio)");
            goal_line(g, fn, d->tag, isas[k], what, u10 ? u10->thr_med / ex->thr_med : NAN,
                      short_poly ? 1.5 : 1.0, "x", 1, u10 ? NULL : "n/a (no SLEEF u10 here)");
        }
        if (fa)
            goal_line(g, fn, d->tag, isas[k], "fast vs exact (speed ratio)",
                      ex ? ex->thr_med / fa->thr_med : NAN, 1.5, "x", 1,
                      ex ? NULL : "n/a (no exact variant)");
        if (fa && k != 2) {
            const row *p = u35 ? u35 : u10;
            goal_line(g, fn, d->tag, isas[k],
                      u35 ? "fast vs SLEEF u35 (speed ratio)" : "fast vs SLEEF u10 (SLEEF has no u35)",
                      p ? p->thr_med / fa->thr_med : NAN, 1.0, "x", 1, p ? NULL : "n/a (no SLEEF here)");
        }
    }
}

/* 1 when name is one of the comma-separated functions in only (or only is NULL) */
static int selected(const char *only, const char *name)
{
    if (!only)
        return 1;
    size_t n = strlen(name);
    for (const char *p = only; *p;) {
        size_t k = strcspn(p, ",");
        if (k == n && strncmp(p, name, n) == 0)
            return 1;
        p += k;
        if (*p)
            p++;
    }
    return 0;
}

/* ---- fixed point ---- */

static void bench_fixed(FILE *md, FILE *csv, int reps, double target, uint64_t seed, const char *only)
{
    int nr;
    const pfb_fixed_row *fr = pfb_fixed_rows(&nr);
    int shown = 0;
    fprintf(md, "\n## Fixed point\n\n");
    for (int i = 0; i < nr; i++) {
        const pfb_fixed_row *r = &fr[i];
        if (!selected(only, pfref_name(r->f)))
            continue;
        void *s = pfb_fixed_scalar(r), *a = pfb_fixed_array(r);
        if (!s && !a)
            continue;
        if (!shown++)
            fprintf(md, "| function | in → out | form | ns/elem median [min, max] | latency ns | max LSB | mean LSB |\n"
                        "|---|---|---|---|---|---|---|\n");
        size_t w = pfb_fx_width(r->in_st) > pfb_fx_width(r->out_st) ? pfb_fx_width(r->in_st)
                                                                      : pfb_fx_width(r->out_st);
        void *in = calloc(1u << 20, w), *out = calloc(1u << 20, w);
        size_t n = pfb_fx_inputs(r, seed, in, 1u << 20);
        double mx = NAN, mean = NAN;
        int64_t worst = 0;
        void *forms[2] = {s, a};
        for (int k = 0; k < 2; k++) {
            if (!forms[k])
                continue;
            int bad = k ? pfb_fx_array(r, forms[k], in, out, n) : pfb_fx_loop(r, forms[k], in, out, n);
            if (bad) {
                fprintf(md, "| %s | %s → %s | %s | unsupported storage pair | | | |\n", pfref_name(r->f),
                        r->in_type, r->out_type, k ? "array" : "scalar");
                continue;
            }
            pfb_fx_err(r, in, out, n, &mx, &mean, &worst);
            size_t nt = n < NTIME ? n : NTIME;
            double t0 = now();
            if (k)
                pfb_fx_array(r, forms[k], in, out, nt);
            else
                pfb_fx_loop(r, forms[k], in, out, nt);
            int passes = passes_for(now() - t0, target);
            double *tv = calloc((size_t)reps, sizeof *tv), *lv = calloc((size_t)reps, sizeof *lv);
            int64_t sink = 0;
            for (int rep = 0; rep < reps; rep++) {
                t0 = now();
                for (int p = 0; p < passes; p++) {
                    if (k)
                        pfb_fx_array(r, forms[k], in, out, nt);
                    else
                        pfb_fx_loop(r, forms[k], in, out, nt);
                }
                tv[rep] = (now() - t0) * 1e9 / ((double)passes * (double)nt);
                if (!k) {
                    t0 = now();
                    for (int p = 0; p < passes; p++)
                        pfb_fx_chain(r, forms[k], in, nt, &sink);
                    lv[rep] = (now() - t0) * 1e9 / ((double)passes * (double)nt);
                }
            }
            double tm, tmin, tmax, lm = NAN, lmin = NAN, lmax = NAN;
            pfb_median(tv, reps, &tm, &tmin, &tmax);
            if (!k)
                pfb_median(lv, reps, &lm, &lmin, &lmax);
            char b1[24], b2[24], b3[24], b4[24], b5[24], b6[24];
            fprintf(md, "| %s | %s → %s | %s | %s [%s, %s] | %s | %s | %s |\n", pfref_name(r->f), r->in_type,
                    r->out_type, k ? "array" : "scalar", fmt_ns(tm, b1), fmt_ns(tmin, b2), fmt_ns(tmax, b3),
                    fmt_ns(lm, b4), fmt_ulp(mx, b5), fmt_ulp(mean, b6));
            fprintf(csv, "%s,\"%s->%s\",%s,pfmath-fixed,%s,1,0,ok,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.6g,%.6g,,%lld,,0,%s %s,lsb\n",
                    pfref_name(r->f), r->in_type, r->out_type, r->sym, k ? "array" : "scalar", tm, tmin,
                    tmax, lm, lmin, lmax, mx, mean, (long long)worst, r->sym, k ? "array" : "scalar");
            free(tv);
            free(lv);
        }
        free(in);
        free(out);
    }
    if (!shown)
        fprintf(md, "No fixed-point functions in this libpfmath.so yet (issue 5); their rows appear here "
                    "when the symbols exist (names in tests/pfbench_ours.c, `fixed_rows`).\n");
}

/* ---- main ---- */

int main(int argc, char **argv)
{
    pfcli_check_stdout("pfbench"); /* --list and --help on a full disk: exit 1 */
    static const struct option opts[] = {
        {"lib", required_argument, 0, 'l'},     {"out", required_argument, 0, 'o'},
        {"func", required_argument, 0, 'f'},    {"reps", required_argument, 0, 'r'},
        {"samples", required_argument, 0, 'n'}, {"seed", required_argument, 0, 'S'},
        {"ms", required_argument, 0, 'm'},      {"list", no_argument, 0, 'L'},
        {"help", no_argument, 0, 'h'},          {"ladder", required_argument, 0, 'D'},
        {0, 0, 0, 0}};
    const char *lib = NULL, *outdir = NULL, *only = NULL, *ladder = NULL;
    char libarg[PATH_MAX + 2], ladarg[PATH_MAX + 2];
    long reps = 15;
    unsigned long long samples = 1ull << 20, seed = 1, ureps;
    double target_ms = 4;
    int list = 0;
    unsigned char seen[256] = {0};
    opterr = 0;
    int ch;
    while ((ch = getopt_long(argc, argv, ":h", opts, NULL)) != -1) {
        if (ch != ':' && ch != '?' && pfcli_once(seen, ch))
            die2("option given twice: --", pfcli_name(opts, ch));
        switch (ch) {
        case 'l':
            if (pfcli_lib_path(optarg, libarg, sizeof libarg) != 0)
                die2("--lib: empty or too long a path: ", optarg);
            lib = libarg;
            break;
        case 'o': outdir = optarg; break;
        case 'f': only = optarg; break;
        case 'r':
            if (pfcli_u64(optarg, 11, 1001, &ureps))
                die2("--reps must be a whole number in 11..1001: ", optarg);
            reps = (long)ureps;
            break;
        case 'n':
            if (pfcli_u64(optarg, NTIME, 1ull << 28, &samples))
                die2("--samples must be a whole number in 2^16..2^28: ", optarg);
            break;
        case 'S':
            if (pfcli_u64(optarg, 0, ULLONG_MAX, &seed))
                die2("--seed must be a whole number in 0..2^64-1: ", optarg);
            break;
        case 'm':
            if (pfcli_real(optarg, 0, 1000, &target_ms) || !(target_ms > 0))
                die2("--ms must be a number in (0, 1000]: ", optarg);
            break;
        case 'L': list = 1; break;
        case 'D':
            if (pfcli_lib_path(optarg, ladarg, sizeof ladarg) != 0)
                die2("--ladder: empty or too long a path: ", optarg);
            ladder = ladarg;
            break;
        case 'h': fputs(usage, stdout); return 0;
        case ':': die2("option needs an argument: ", argv[optind - 1]); break;
        default: die2("unknown option (see --help): ", argv[optind - 1]); break;
        }
    }
    if (optind < argc)
        die2("unexpected argument ", argv[optind]);
    /* --list times and writes nothing: these were accepted and ignored */
    for (const char *c = "ornSm"; list && *c; c++)
        if (seen[(unsigned char)*c])
            die2("--list takes only --lib, --func and --ladder, not --", pfcli_name(opts, *c));
    int nd;
    const pfb_domain *doms = pfb_domains(&nd);
    if (only) {
        /* every name in the list must be a function this bench has rows
           for: an empty list or name would otherwise bench nothing */
        int nfr;
        const pfb_fixed_row *fr = pfb_fixed_rows(&nfr);
        const char *p = only;
        do {
            size_t k = strcspn(p, ",");
            char name[64];
            if (k == 0)
                die2("--func: empty function name in the list: ", only);
            if (k >= sizeof name)
                die2("--func: unknown function in the list: ", only);
            memcpy(name, p, k);
            name[k] = 0;
            int id = pfref_lookup(name), known = 0;
            for (int i = 0; id >= 0 && i < nd && !known; i++)
                known = (int)doms[i].f == id;
            for (int i = 0; id >= 0 && i < nfr && !known; i++)
                known = (int)fr[i].f == id;
            if (!known)
                die2("--func: unknown function: ", name);
            p += k;
        } while (*p++);
    }
    char self[PATH_MAX], libpath[PATH_MAX + 32], dir[PATH_MAX];
    ssize_t k = readlink("/proc/self/exe", self, sizeof self - 1);
    self[k > 0 ? k : 0] = 0;
    snprintf(dir, sizeof dir, "%s", self);
    char *slash = strrchr(dir, '/');
    if (slash)
        *slash = 0;
    if (!lib) {
        snprintf(libpath, sizeof libpath, "%s/libpfmath.so", dir);
        lib = libpath;
    }
    if (!outdir)
        outdir = dir;
    char err[512];
    struct stat osb;
    if (!list && (stat(outdir, &osb) != 0 || !S_ISDIR(osb.st_mode) || access(outdir, W_OK | X_OK) != 0))
        die2("--out is not a writable directory: ", outdir);
    if (pfb_ours_open(lib, err, sizeof err)) {
        pfcli_line("pfbench", err, NULL);
        return 1;
    }
    if (ladder && pfb_ladder_open(ladder, err, sizeof err)) {
        pfcli_line("pfbench", "--ladder: ", err);
        return 1;
    }

    if (list) {
        for (int i = 0; i < nd; i++) {
            const pfb_domain *d = &doms[i];
            if (!selected(only, pfref_name(d->f)))
                continue; /* --list --func log listed every function */
            pfb_cand c[PFB_MAX_CANDS];
            int n = 0;
            pfb_ours(d->f, c, &n);
            pfb_ladder(d->f, c, &n);
            pfb_peers(d->f, c, &n);
            printf("%s %s (%s):", pfref_name(d->f), d->tag, d->desc);
            for (int j = 0; j < n; j++)
                printf(" %s/%s%s", c[j].name, c[j].isa, c[j].absent[0] ? "(absent)" : "");
            printf("\n");
        }
        return 0;
    }

    char mdpath[PATH_MAX + 16], csvpath[PATH_MAX + 16];
    snprintf(mdpath, sizeof mdpath, "%s/bench.md", outdir);
    snprintf(csvpath, sizeof csvpath, "%s/bench.csv", outdir);
    /* both names checked before the run; nothing is written before its end */
    pfcli_out omd, ocsv;
    if (pfcli_out_open(&omd, mdpath, err, sizeof err) != 0) {
        pfcli_line("pfbench", err, NULL);
        return 1;
    }
    if (pfcli_out_open(&ocsv, csvpath, err, sizeof err) != 0) {
        pfcli_out_abort(&omd);
        pfcli_line("pfbench", err, NULL);
        return 1;
    }
    FILE *md = omd.f, *csv = ocsv.f;
    double t_start = wall();
    double target = target_ms * 1e-3;

    /* spin up the clock before anything is timed */
    {
        double t0 = now();
        volatile double acc = 0;
        while (now() - t0 < 0.3)
            acc = acc + 1;
    }
    /* chain overhead: an empty function in the latency harness */
    double overhead;
    {
        static float xs[NTIME];
        for (size_t i = 0; i < NTIME; i++)
            xs[i] = (float)i;
        pfb_cand e;
        memset(&e, 0, sizeof e);
        e.s1 = empty_fn;
        double v[15], mn, mx;
        for (int r = 0; r < 15; r++) {
            double t0 = now();
            for (int p = 0; p < 20; p++)
                chain(&e, xs, NULL, NTIME);
            v[r] = (now() - t0) * 1e9 / (20.0 * NTIME);
        }
        pfb_median(v, 15, &overhead, &mn, &mx);
    }
    /* call floor: the same empty function in the scalar rows' throughput
       loop (pfb_loop1, one indirect call an element), the part of a scalar
       row's time that is the call rather than the function */
    double call_floor;
    {
        static float xs[NTIME], ys[NTIME];
        for (size_t i = 0; i < NTIME; i++)
            xs[i] = (float)i;
        double v[15], mn, mx;
        for (int r = 0; r < 15; r++) {
            double t0 = now();
            for (int p = 0; p < 20; p++)
                pfb_loop1(empty_fn, xs, ys, NTIME);
            v[r] = (now() - t0) * 1e9 / (20.0 * NTIME);
        }
        pfb_median(v, 15, &call_floor, &mn, &mx);
    }

    char cpu[256], date[64];
    cpu_name(cpu, sizeof cpu);
    time_t tt = time(NULL);
    strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", gmtime(&tt));
    __builtin_cpu_init();
    fprintf(md, "# pfbench: speed against error\n\n");
    fprintf(md, "- CPU: %s (AVX2+FMA: %s, AVX-512F: %s), %ld online\n", cpu,
            __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") ? "yes" : "no",
            __builtin_cpu_supports("avx512f") ? "yes" : "no", sysconf(_SC_NPROCESSORS_ONLN));
    fprintf(md, "- date: %s; glibc %s; SLEEF %d.%d.%d; bench compiled by GCC %s\n", date,
            gnu_get_libc_version(), SLEEF_VERSION_MAJOR, SLEEF_VERSION_MINOR, SLEEF_VERSION_PATCHLEVEL,
            __VERSION__);
    fprintf(md, "- library: `%s`; per-ISA clones of the array forms %s\n", lib,
            pfb_ours_have_clones() ? "found (each timed separately)"
                                   : "not found (stripped?): array rows are the dispatched form");
    fprintf(md, "- throughput: ns per element over %u inputs of the domain, median of %ld repetitions "
                "[min, max] of ~%.0f ms each, interleaved across candidates, after a warm-up\n",
            NTIME, reps, target_ms);
    fprintf(md, "- latency: ns per call in a dependent chain (scalar forms only), including the chain's "
                "own overhead of %.2f ns (an empty function measured the same way)\n", overhead);
    fprintf(md, "- scalar throughput includes the call: an empty function (in pfbench itself) through "
                "the same loop takes %.2f ns per element\n", call_floor);
    fprintf(md, "- error: max and mean ULP against MPFR (ref/, pfref_ulp_err_raw, as pfsweep) on %llu "
                "seeded inputs of the same domain (seed %llu; the timing inputs are its first %u); "
                "CR = correctly rounded share; exhaustive figures for pfmath: `make sweep`\n",
            samples, seed, NTIME);
    fprintf(md, "- ratios are the trustworthy numbers (same run, interleaved); absolute ns move with the "
                "machine's load and clock\n");
    fprintf(csv, "func,domain,domain_desc,candidate,isa,ours,fast,status,thr_med,thr_min,thr_max,"
                 "lat_med,lat_min,lat_max,max_ulp,mean_ulp,cr_pct,worst_x,worst_x2,pareto,label,unit\n");

    float *X = malloc(samples * sizeof *X), *X2 = malloc(samples * sizeof *X2);
    float *Y = malloc(samples * sizeof *Y), *YS[2] = {malloc(samples * sizeof *Y), malloc(samples * sizeof *Y)};
    float *YL = malloc(samples * sizeof *Y);
    if (!X || !X2 || !Y || !YS[0] || !YS[1] || !YL)
        die2("out of memory", NULL);

    static goals g;
    char *goal_text = NULL;
    size_t goal_len = 0;
    g.md = open_memstream(&goal_text, &goal_len);
    if (!g.md)
        die2("out of memory", NULL);
    /* issue 13's Pareto checks, collected per domain, written after the goals */
    char *par_text = NULL;
    size_t par_len = 0;
    int par_pass = 0, par_miss = 0;
    FILE *par = open_memstream(&par_text, &par_len);
    char *lad_text = NULL;
    size_t lad_len = 0;
    FILE *lad = open_memstream(&lad_text, &lad_len);
    if (!par || !lad)
        die2("out of memory", NULL);

    for (int di = 0; di < nd; di++) {
        const pfb_domain *d = &doms[di];
        const char *fn = pfref_name(d->f);
        if (!selected(only, fn))
            continue;
        double t_dom = wall();
        pfb_cand cands[PFB_MAX_CANDS];
        int nc = 0;
        pfb_ours(d->f, cands, &nc);
        pfb_ladder(d->f, cands, &nc);
        pfb_peers(d->f, cands, &nc);
        row *r = calloc((size_t)nc, sizeof *r);
        for (int i = 0; i < nc; i++) {
            r[i].c = cands[i];
            r[i].thr = calloc((size_t)reps, sizeof(double));
            r[i].lat = calloc((size_t)reps, sizeof(double));
            r[i].thr_med = r[i].thr_min = r[i].thr_max = NAN;
            r[i].lat_med = r[i].lat_min = r[i].lat_max = NAN;
        }
        int two = pfref_arity(d->f) == 2;
        pfb_sample(d, seed, X, X2, samples);

        /* errors: every candidate on the whole sample, through the form
           that is timed (this is also the warm-up) */
        for (int i = 0; i < nc; i++) {
            pfb_cand *c = &r[i].c;
            if (c->absent[0])
                continue;
            run(c, X, X2, Y, samples);
            pf_sweep_init(&r[i].err);
            pfb_err_arrays(&r[i].err, d->f, X, two ? X2 : NULL, Y, samples);
            r[i].have_err = 1;
            if (c->ours == PFB_OURS_LADDER) {
                /* a ladder row against its own scalar form */
                void *sc = pfb_ladder_scalar(d->f, c);
                pf_fn1 s1 = NULL;
                pf_fn2 s2 = NULL;
                if (two)
                    *(void **)&s2 = sc;
                else
                    *(void **)&s1 = sc;
                if (sc && two)
                    pfb_loop2(s2, X, X2, YL, samples);
                else if (sc)
                    pfb_loop1(s1, X, YL, samples);
                r[i].differs_from_scalar = !sc || memcmp(YL, Y, samples * sizeof *Y) != 0;
            } else if (c->ours && strcmp(c->isa, "scalar") == 0)
                memcpy(YS[c->fast], Y, samples * sizeof *Y);
            else if (c->ours)
                r[i].differs_from_scalar = memcmp(YS[c->fast], Y, samples * sizeof *Y) != 0;
        }
        /* calibration: passes per repetition */
        for (int i = 0; i < nc; i++) {
            pfb_cand *c = &r[i].c;
            if (c->absent[0])
                continue;
            double t0 = now();
            run(c, X, X2, Y, NTIME);
            r[i].passes_t = passes_for(now() - t0, target);
            if (c->s1 || c->s2) {
                t0 = now();
                chain(c, X, X2, NTIME);
                r[i].passes_l = passes_for(now() - t0, target);
            }
        }
        /* repetitions, interleaved so that load changes hit every candidate */
        for (int rep = 0; rep < reps; rep++) {
            for (int i = 0; i < nc; i++) {
                pfb_cand *c = &r[i].c;
                if (c->absent[0])
                    continue;
                double t0 = now();
                for (int p = 0; p < r[i].passes_t; p++)
                    run(c, X, X2, Y, NTIME);
                r[i].thr[rep] = (now() - t0) * 1e9 / ((double)r[i].passes_t * NTIME);
                if (r[i].passes_l) {
                    t0 = now();
                    for (int p = 0; p < r[i].passes_l; p++)
                        chain(c, X, X2, NTIME);
                    r[i].lat[rep] = (now() - t0) * 1e9 / ((double)r[i].passes_l * NTIME);
                }
            }
        }
        double *tv = malloc((size_t)nc * sizeof *tv), *ev = malloc((size_t)nc * sizeof *ev);
        int *on = malloc((size_t)nc * sizeof *on);
        for (int i = 0; i < nc; i++) {
            if (!r[i].c.absent[0]) {
                pfb_median(r[i].thr, (int)reps, &r[i].thr_med, &r[i].thr_min, &r[i].thr_max);
                if (r[i].passes_l)
                    pfb_median(r[i].lat, (int)reps, &r[i].lat_med, &r[i].lat_min, &r[i].lat_max);
            }
            tv[i] = r[i].thr_med;
            ev[i] = r[i].have_err ? r[i].err.max_ulp : NAN;
        }
        pfb_pareto(tv, ev, nc, on);
        const row *glibc = find(r, nc, "glibc", "scalar");

        fprintf(md, "\n## %s on %s\n\n", fn, d->desc);
        fprintf(md, "| candidate | ISA | ns/elem median [min, max] | speed vs glibc | latency ns median [min, max] "
                    "| max ULP | mean ULP | CR %% | worst input | Pareto |\n"
                    "|---|---|---|---|---|---|---|---|---|---|\n");
        for (int i = 0; i < nc; i++) {
            const row *q = &r[i];
            char lab[64];
            label(&q->c, lab, sizeof lab);
            if (q->c.absent[0]) {
                fprintf(md, "| %s | %s | absent (%s) | | | | | | | |\n", q->c.name, q->c.isa, q->c.absent);
                fprintf(csv, "%s,%s,\"%s\",%s,%s,%d,%d,absent: %s,,,,,,,,,,,,0,%s,ulp\n", fn, d->tag, d->desc,
                        q->c.name, q->c.isa, q->c.ours, q->c.fast, q->c.absent, lab);
                continue;
            }
            char a[24], b[24], c2[24], l1[24], l2[24], l3[24], e1[24], e2[24], ratio[32], worst[64];
            if (glibc)
                snprintf(ratio, sizeof ratio, "%.2fx", glibc->thr_med / q->thr_med);
            else
                snprintf(ratio, sizeof ratio, "—");
            if (two)
                snprintf(worst, sizeof worst, "(%a, %a)", (double)q->err.worst_x, (double)q->err.worst_x2);
            else
                snprintf(worst, sizeof worst, "%a", (double)q->err.worst_x);
            char lat[80];
            if (q->passes_l)
                snprintf(lat, sizeof lat, "%s [%s, %s]", fmt_ns(q->lat_med, l1), fmt_ns(q->lat_min, l2),
                         fmt_ns(q->lat_max, l3));
            else
                snprintf(lat, sizeof lat, "—");
            fprintf(md, "| %s%s | %s | %s [%s, %s] | %s | %s | %s | %s | %.2f | %s | %s |\n", q->c.name,
                    q->differs_from_scalar ? " (≠ scalar bits!)" : "", q->c.isa, fmt_ns(q->thr_med, a),
                    fmt_ns(q->thr_min, b), fmt_ns(q->thr_max, c2), ratio, lat, fmt_ulp(q->err.max_ulp, e1),
                    fmt_ulp(pf_sweep_mean(&q->err), e2), pf_sweep_cr_percent(&q->err), worst,
                    on[i] ? "yes" : "");
            fprintf(csv, "%s,%s,\"%s\",%s,%s,%d,%d,ok,%.5g,%.5g,%.5g,", fn, d->tag, d->desc, q->c.name,
                    q->c.isa, q->c.ours, q->c.fast, q->thr_med, q->thr_min, q->thr_max);
            if (q->passes_l)
                fprintf(csv, "%.5g,%.5g,%.5g,", q->lat_med, q->lat_min, q->lat_max);
            else
                fprintf(csv, ",,,");
            fprintf(csv, "%.6g,%.6g,%.4f,%a,%a,%d,%s,ulp\n", q->err.max_ulp, pf_sweep_mean(&q->err),
                    pf_sweep_cr_percent(&q->err), (double)q->err.worst_x, two ? (double)q->err.worst_x2 : 0.0,
                    on[i], lab);
        }
        goals_for(&g, d->f, d, r, nc);
        {
            pfb_point pts[PFB_MAX_CANDS];
            for (int i = 0; i < nc; i++)
                pts[i] = (pfb_point){r[i].c.name, r[i].c.isa, r[i].c.ours, r[i].c.absent[0] ? NAN : r[i].thr_med,
                                     r[i].have_err ? r[i].err.max_ulp : NAN};
            pfb_pareto_checks(par, fn, d->tag, pts, nc, &par_pass, &par_miss);
            pfb_ladder_table(lad, fn, d->tag, pts, nc);
        }
        fprintf(stderr, "pfbench: %-5s %-4s %2d candidates, %.1f s\n", fn, d->tag, nc, wall() - t_dom);
        for (int i = 0; i < nc; i++) {
            free(r[i].thr);
            free(r[i].lat);
        }
        free(r);
        free(tv);
        free(ev);
        free(on);
    }

    bench_fixed(md, csv, (int)reps, target, seed, only);

    /* goals: the lines collected above, then the list of misses */
    fprintf(md, "\n## Goals of issues 7 and 12 (same run, same ISA; array forms, and the scalar exact form "
                "against glibc; ratio = peer ns / pfmath ns)\n\n");
    fprintf(md, "| function | domain | ISA | goal | target | measured | verdict |\n|---|---|---|---|---|---|---|\n");
    fclose(g.md);
    fputs(goal_text, md);
    free(goal_text);
    fprintf(md, "\n%d goals met, %d missed, %d not applicable here.\n", g.pass, g.miss, g.na);
    if (g.miss)
        fprintf(md, "\nMissed:\n\n%s", g.misses);
    fprintf(md, "\n## Pareto checks of issue 13 (same run, same ISA)\n\n"
                "For each vector peer point (time t, max error e): the fastest pfmath point (exact, fast%s) "
                "with max error <= e; pass when its time <= t.  Ratio = peer ns / pfmath ns.\n\n"
                "| function | domain | ISA | peer | peer point | fastest pfmath point as accurate | ratio | "
                "verdict |\n|---|---|---|---|---|---|---|---|\n",
            ladder ? ", ladder levels" : "; no --ladder given");
    fclose(par);
    fputs(par_text, md);
    free(par_text);
    fprintf(md, "\n%d Pareto checks pass, %d MISS.\n", par_pass, par_miss);
    fprintf(md, "\n## Accuracy ladder (issue 13): each level beside the vector peer nearest in max error\n\n"
                "Levels pfmath-L<U>: pfmathgen --max-ulp U (make ladder), U ULP over every float; 128 and "
                "8192 ULP are the relative levels 2^-16 and 2^-10.  Ratio = peer ns / level ns.\n\n"
                "| function | domain | ISA | level | ns/elem | max ULP (sample) | nearest peer | peer ns | peer "
                "max ULP | ratio |\n|---|---|---|---|---|---|---|---|---|---|\n");
    fclose(lad);
    fputs(lad_text, md);
    free(lad_text);
    fprintf(md, "\nTotal bench time %.0f s.\n", wall() - t_start);
    if (pfcli_out_commit(&omd, err, sizeof err) != 0) {
        pfcli_out_abort(&ocsv);
        pfcli_line("pfbench", err, NULL);
        return 1;
    }
    if (pfcli_out_commit(&ocsv, err, sizeof err) != 0) {
        pfcli_line("pfbench", err, NULL);
        return 1;
    }
    fprintf(stderr, "pfbench: wrote %s and %s (%.0f s); %d goals met, %d missed\n", mdpath, csvpath,
            wall() - t_start, g.pass, g.miss);
    free(X);
    free(X2);
    free(Y);
    free(YS[0]);
    free(YS[1]);
    free(YL);
    return 0;
}
