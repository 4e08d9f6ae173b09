/* pfsweep's and pfbench's command lines (issue 11, item 8): a bad number,
 * NaN bound, empty or unknown function or repeated option is exit 2 with one
 * line on stderr, before any work; a refused pfbench leaves bench.md and
 * bench.csv as they were, a complete one replaces them at the end.  The programs run by fork/exec (no shell), each
 * with a time limit: a value that wraps (--samples -1 = 2^64-1) would hang. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "testutil.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <time.h>

#define LIMIT_S 30

static char scratch[] = "/tmp/pf-tools-cli.XXXXXX";

typedef struct {
    int status; /* exit status; -1 killed (time limit) or crashed */
    char out[4096], err[4096];
} run_result;

static void slurp_into(const char *path, char *buf, size_t n)
{
    FILE *f = fopen(path, "r");
    size_t k = f ? fread(buf, 1, n - 1, f) : 0;
    buf[k] = 0;
    if (f)
        fclose(f);
}

/* set: the next run's standard output is /dev/full (ENOSPC on every
   write); run() clears it, so a failed test leaves no later run there */
static int run_to_full;

/* argv[0] is the program's name under the build directory */
static void run(const char *const *argv, run_result *r)
{
    char path[PATH_MAX], o[PATH_MAX], e[PATH_MAX];
    tu_prog_path(argv[0], path, sizeof path);
    snprintf(o, sizeof o, "%s/stdout", scratch);
    snprintf(e, sizeof e, "%s/stderr", scratch);
    int full = run_to_full;
    run_to_full = 0;
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        int fo = open(full ? "/dev/full" : o, O_WRONLY | O_CREAT | O_TRUNC, 0644),
            fe = open(e, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fo < 0 || fe < 0 || dup2(fo, 1) < 0 || dup2(fe, 2) < 0)
            _exit(127);
        execv(path, (char *const *)argv);
        _exit(127);
    }
    int st = 0;
    struct timespec t0, t;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (;;) {
        pid_t w = waitpid(pid, &st, WNOHANG);
        if (w == pid)
            break;
        clock_gettime(CLOCK_MONOTONIC, &t);
        if (t.tv_sec - t0.tv_sec > LIMIT_S) {
            kill(pid, SIGKILL);
            waitpid(pid, &st, 0);
            st = -1;
            break;
        }
        struct timespec nap = {0, 20 * 1000 * 1000};
        nanosleep(&nap, NULL);
    }
    r->status = st != -1 && WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    slurp_into(o, r->out, sizeof r->out);
    slurp_into(e, r->err, sizeof r->err);
}

static void expect_refused(const char *const *argv, const char *prog)
{
    run_result r;
    run(argv, &r);
    char line[512] = "";
    for (int i = 0; argv[i]; i++) {
        size_t l = strlen(line);
        snprintf(line + l, sizeof line - l, "%s'%s'", i ? " " : "", argv[i]);
    }
    print_message("%s -> %d: %s", line, r.status, r.err);
    assert_int_equal(r.status, 2);
    assert_int_equal(tu_count_lines(r.err), 1);
    char pre[32];
    snprintf(pre, sizeof pre, "%s: ", prog);
    assert_int_equal(strncmp(r.err, pre, strlen(pre)), 0);
    assert_string_equal(r.out, "");
}

#define REFUSE(prog, ...)                                                                          \
    do {                                                                                           \
        const char *const a_[] = {prog, __VA_ARGS__, NULL};                                        \
        expect_refused(a_, prog);                                                                  \
    } while (0)

static void test_pfsweep_numbers(void **st)
{
    (void)st;
    REFUSE("pfsweep", "--func", "log", "--samples", "-1");
    REFUSE("pfsweep", "--func", "log", "--samples", "18446744073709551616");
    REFUSE("pfsweep", "--func", "log", "--samples", "99999999999");
    REFUSE("pfsweep", "--func", "log", "--samples", "");
    REFUSE("pfsweep", "--func", "log", "--samples", "12abc");
    REFUSE("pfsweep", "--func", "log", "--samples", " 12");
    REFUSE("pfsweep", "--func", "log", "--seed", "abc");
    REFUSE("pfsweep", "--func", "log", "--seed", "-5");
    REFUSE("pfsweep", "--func", "log", "--seed", "");
    REFUSE("pfsweep", "--func", "log", "--seed", "0x");
    REFUSE("pfsweep", "--func", "atan2", "--all", "--pairs", "-1");
    REFUSE("pfsweep", "--func", "atan2", "--all", "--pairs", "0");
    REFUSE("pfsweep", "--func", "log", "--max-ulp", "nan");
    REFUSE("pfsweep", "--func", "log", "--max-ulp", "-1");
    REFUSE("pfsweep", "--func", "log", "--max-ulp", "inf");
    REFUSE("pfsweep", "--func", "log", "--max-ulp", "1e999");
    REFUSE("pfsweep", "--func", "log", "--max-ulp", "1ulp");
}

static void test_pfsweep_names_and_repeats(void **st)
{
    (void)st;
    REFUSE("pfsweep", "--func", "");
    REFUSE("pfsweep", "--func", "logg");
    REFUSE("pfsweep", "--func", "log", "--func", "sin");
    REFUSE("pfsweep", "--func", "log", "--samples", "5", "--samples=6");
    REFUSE("pfsweep", "--func", "log", "--max-ulp", "1", "--max-ulp", "2");
    REFUSE("pfsweep", "--func", "log", "--variant", "fast", "--variant", "exact");
    /* the fixed-point front end */
    REFUSE("pfsweep", "--func", "sin", "--type", "fixed<15,12>", "--samples", "-1");
    REFUSE("pfsweep", "--func", "sin", "--type", "fixed<15,12>", "--seed", "abc");
    REFUSE("pfsweep", "--func", "sin", "--type", "fixed<15,12>", "--max-lsb", "nan");
    REFUSE("pfsweep", "--func", "sin", "--type", "fixed<15,12>", "--max-lsb", "0");
    REFUSE("pfsweep", "--func", "sin", "--type", "fixed<15,12>", "--type", "fixed<15,13>");
    REFUSE("pfsweep", "--func", "sin", "--func", "cos", "--type", "fixed<15,12>");
    /* options that had no effect: --samples and --seed where no sample is
       drawn (--all of a one-argument function; a 16-bit fixed input) */
    REFUSE("pfsweep", "--func", "log", "--all", "--samples", "5");
    REFUSE("pfsweep", "--func", "log", "--all", "--seed", "3");
    REFUSE("pfsweep", "--func", "sin", "--type", "fixed<15,12>", "--out-type", "fixed<15,14>", "--samples", "5");
    REFUSE("pfsweep", "--func", "sin", "--type", "fixed<15,12>", "--out-type", "fixed<15,14>", "--seed", "3");
    /* "--type" as another option's value sent the run to the fixed-point
       sweep with no type (read uninitialized) */
    REFUSE("pfsweep", "--func", "sin", "--name", "--type");
    REFUSE("pfsweep", "--func", "sin", "--source", "--type");
    /* a --name longer than the symbol buffer was cut (exit 1, "no function"
       with another name than the one given) */
    static char longname[200];
    memset(longname, 'a', sizeof longname - 1);
    REFUSE("pfsweep", "--func", "log", "--name", longname);
    REFUSE("pfsweep", "--func", "sin", "--type", "fixed<15,12>", "--name", longname);
}

/* A newline in a value made the message two lines (pfmathgen's, and
 * pfcli_refuse's, print control characters as '?'); the load failures
 * (exit 1) that name the user's file too. */
static void test_one_line_messages(void **st)
{
    (void)st;
    REFUSE("pfsweep", "--func", "no\nsuch");
    REFUSE("pfsweep", "--func", "log", "--variant", "a\nb");
    REFUSE("pfsweep", "--func", "log", "--seed", "1\n");
    REFUSE("pfsweep", "--func", "log", "--bo\ngus");
    REFUSE("pfsweep", "--func", "sin", "--type", "fixed<15,\n>");
    REFUSE("pfsweep", "--func", "sin", "--type", "fixed<15,12>", "--out-type", "fixed<40,\n1>");
    REFUSE("pfsweep", "--func", "no\nsuch", "--type", "fixed<15,12>");
    REFUSE("pfbench", "--func", "no\nsuch");
    REFUSE("pfbench", "--out", "/nonexistent\n/x");
    const char *const l1[] = {"pfsweep", "--func", "log", "--lib", "/nonexistent\nx.so", NULL};
    const char *const l2[] = {"pfsweep", "--func", "log", "--source", "/nonexistent\nx.c", NULL};
    const char *const l3[] = {"pfsweep", "--func", "sin", "--type", "fixed<15,12>", "--lib", "/nonexistent\nx.so", NULL};
    const char *const *l[] = {l1, l2, l3};
    for (size_t i = 0; i < sizeof l / sizeof l[0]; i++) {
        run_result r;
        run(l[i], &r);
        print_message("%s -> %d: %s", l[i][4], r.status, r.err);
        assert_int_equal(r.status, 1);
        assert_int_equal(tu_count_lines(r.err), 1);
    }
}

/* Standard output on a full disk: the results (pfsweep), --list or --help
 * were lost and the status said 0; now 1, with one line saying so. */
static void test_stdout_full(void **st)
{
    (void)st;
    if (access("/dev/full", W_OK) != 0)
        skip();
    const char *const a1[] = {"pfsweep", "--func", "log", "--samples", "16", NULL};
    const char *const a2[] = {"pfsweep", "--func", "sin", "--type", "fixed<15,12>", "--out-type", "fixed<15,14>",
                              NULL};
    const char *const a3[] = {"pfsweep", "--help", NULL};
    char lib[PATH_MAX];
    tu_prog_path("libpfmath.so", lib, sizeof lib);
    const char *const a4[] = {"pfbench", "--list", "--lib", lib, "--func", "log", NULL};
    const char *const a5[] = {"pfbench", "--help", NULL};
    const char *const a6[] = {"pfmathgen", "--help", NULL};
    const char *const *a[] = {a1, a2, a3, a4, a5, a6};
    for (size_t i = 0; i < sizeof a / sizeof a[0]; i++) {
        run_result r;
        run_to_full = 1;
        run(a[i], &r);
        print_message("%s %s > /dev/full -> %d: %s", a[i][0], a[i][1], r.status, r.err);
        assert_int_equal(r.status, 1);
        assert_int_equal(tu_count_lines(r.err), 1);
        assert_non_null(strstr(r.err, "standard output"));
    }
}

/* pfbench --list --func log listed every function; --out, --reps,
 * --samples, --seed, --ms with --list were accepted and did nothing */
static void test_pfbench_list(void **st)
{
    (void)st;
    char lib[PATH_MAX];
    tu_prog_path("libpfmath.so", lib, sizeof lib);
    const char *const a[] = {"pfbench", "--list", "--lib", lib, "--func", "log,exp", NULL};
    run_result r;
    run(a, &r);
    print_message("pfbench --list --func log,exp -> %d:\n%s", r.status, r.out);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "log "));
    assert_non_null(strstr(r.out, "exp "));
    assert_null(strstr(r.out, "sin "));
    assert_null(strstr(r.out, "log2 "));
    REFUSE("pfbench", "--list", "--lib", lib, "--out", scratch);
    REFUSE("pfbench", "--list", "--lib", lib, "--reps", "11");
    REFUSE("pfbench", "--list", "--lib", lib, "--samples", "65536");
    REFUSE("pfbench", "--list", "--lib", lib, "--seed", "1");
    REFUSE("pfbench", "--list", "--lib", lib, "--ms", "1");
}

/* bench.md and bench.csv as they were before a refused run */
static void check_outputs_kept(const char *dir)
{
    char p[PATH_MAX];
    snprintf(p, sizeof p, "%s/bench.md", dir);
    char *s = tu_slurp(p, NULL);
    assert_non_null(s);
    assert_string_equal(s, "an earlier bench\n");
    free(s);
    snprintf(p, sizeof p, "%s/bench.csv", dir);
    struct stat sb;
    assert_int_not_equal(stat(p, &sb), 0);
}

static void test_pfbench(void **st)
{
    (void)st;
    char dir[PATH_MAX], md[PATH_MAX + 16], lib[PATH_MAX];
    snprintf(dir, sizeof dir, "%s/out", scratch);
    assert_int_equal(mkdir(dir, 0755), 0);
    snprintf(md, sizeof md, "%s/bench.md", dir);
    FILE *f = fopen(md, "w");
    assert_non_null(f);
    fputs("an earlier bench\n", f);
    fclose(f);
    tu_prog_path("libpfmath.so", lib, sizeof lib);
#define BENCH(...) REFUSE("pfbench", "--lib", lib, "--out", dir, __VA_ARGS__)
    BENCH("--func", "");
    BENCH("--func", ",");
    BENCH("--func", "log,,exp");
    BENCH("--func", "log,");
    BENCH("--func", "nosuch");
    BENCH("--func", "log", "--func", "exp");
    BENCH("--seed", "abc");
    BENCH("--seed", "-1");
    BENCH("--samples", "-1");
    BENCH("--samples", "1000");
    BENCH("--reps", "1e3");
    BENCH("--reps", "12x");
    BENCH("--ms", "nan");
    BENCH("--ms", "0");
    BENCH("--list", "--list");
    BENCH("--ladder", "");
    REFUSE("pfbench", "--lib", "", "--out", dir, "--func", "sqrt");
    check_outputs_kept(dir);
    REFUSE("pfbench", "--lib", lib, "--out", "/nonexistent/pf-tools-cli", "--func", "log");
    REFUSE("pfbench", "--lib", lib, "--out", md, "--func", "log");
    check_outputs_kept(dir);
    /* nothing else appeared in the output directory (no temporaries) */
    int n = 0;
    DIR *d = opendir(dir);
    assert_non_null(d);
    for (struct dirent *de; (de = readdir(d));)
        n += de->d_name[0] != '.';
    closedir(d);
    assert_int_equal(n, 1);
}

/* A complete run replaces the outputs at the end: bench.md, a symlink here,
 * is written through (the link stays, its target gets the report), and no
 * temporary is left behind.  The cheapest run: the fixed-point sqrt rows. */
static void test_pfbench_writes(void **st)
{
    (void)st;
    char dir[PATH_MAX], md[PATH_MAX + 16], real[PATH_MAX + 16], lib[PATH_MAX];
    snprintf(dir, sizeof dir, "%s/out2", scratch);
    assert_int_equal(mkdir(dir, 0755), 0);
    snprintf(md, sizeof md, "%s/bench.md", dir);
    snprintf(real, sizeof real, "%s/real.md", dir);
    FILE *f = fopen(real, "w");
    assert_non_null(f);
    fputs("an earlier bench\n", f);
    fclose(f);
    assert_int_equal(symlink("real.md", md), 0);
    tu_prog_path("libpfmath.so", lib, sizeof lib);
    const char *const argv[] = {"pfbench", "--lib", lib, "--out", dir, "--func", "sqrt", "--reps", "11",
                                "--ms", "0.1", "--samples", "65536", NULL};
    run_result r;
    run(argv, &r);
    print_message("pfbench --func sqrt -> %d: %s", r.status, r.err);
    assert_int_equal(r.status, 0);
    struct stat sb;
    assert_int_equal(lstat(md, &sb), 0);
    assert_true(S_ISLNK(sb.st_mode));
    char *s = tu_slurp(real, NULL);
    assert_non_null(s);
    assert_non_null(strstr(s, "# pfbench"));
    assert_non_null(strstr(s, "sqrt"));
    free(s);
    int n = 0;
    DIR *d = opendir(dir);
    assert_non_null(d);
    for (struct dirent *de; (de = readdir(d));)
        n += de->d_name[0] != '.';
    closedir(d);
    assert_int_equal(n, 3); /* bench.md (link), real.md, bench.csv */
    /* a dangling link is written through as pfmathgen's -o is (new.md
       created, the link kept); pfbench refused it, realpath failing */
    assert_int_equal(unlink(md), 0);
    assert_int_equal(symlink("new.md", md), 0);
    run(argv, &r);
    print_message("pfbench, bench.md -> new.md (absent) -> %d: %s", r.status, r.err);
    assert_int_equal(r.status, 0);
    assert_int_equal(lstat(md, &sb), 0);
    assert_true(S_ISLNK(sb.st_mode));
    snprintf(real, sizeof real, "%s/new.md", dir);
    s = tu_slurp(real, NULL);
    assert_non_null(s);
    assert_non_null(strstr(s, "# pfbench"));
    free(s);
}

/* the build's table printer takes no arguments: one given is refused, not
 * ignored (it printed the tables whatever it was given) */
static void test_pfnoise_tablegen(void **st)
{
    (void)st;
    REFUSE("pfnoise-tablegen", "--seed");
    REFUSE("pfnoise-tablegen", "42");
    REFUSE("pfnoise-tablegen", "--help", "x");
    const char *const help[] = {"pfnoise-tablegen", "--help", NULL};
    run_result r;
    run(help, &r);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "usage: pfnoise-tablegen"));
}

/* pfnoise-demo [DIR] (README: make noise-pictures): an option is not a
 * directory name.  Before, "pfnoise-demo --help" created a directory
 * "--help" with five pictures in it, any other option did the same, a
 * regular file as DIR gave five error lines, and a second argument was
 * ignored. */
static void test_pfnoise_demo(void **st)
{
    (void)st;
    const char *const help[] = {"pfnoise-demo", "--help", NULL};
    run_result r;
    run(help, &r);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "usage: pfnoise-demo"));
    struct stat sb;
    assert_int_not_equal(lstat("--help", &sb), 0);
    char plain[PATH_MAX], dir[PATH_MAX];
    snprintf(plain, sizeof plain, "%s/plain", scratch);
    FILE *f = fopen(plain, "w");
    assert_non_null(f);
    fputs("precious\n", f);
    fclose(f);
    snprintf(dir, sizeof dir, "%s/pics", scratch);
    REFUSE("pfnoise-demo", "-h2");
    REFUSE("pfnoise-demo", "--frobnicate");
    REFUSE("pfnoise-demo", "");
    REFUSE("pfnoise-demo", dir, dir);
    REFUSE("pfnoise-demo", plain);
    char *s = tu_slurp(plain, NULL);
    assert_string_equal(s, "precious\n");
    free(s);
    assert_int_not_equal(lstat("-h2", &sb), 0);
    assert_int_not_equal(lstat("--frobnicate", &sb), 0);
    assert_int_not_equal(lstat(dir, &sb), 0);
    /* a run: DIR created, a symlinked picture written through (the link
       stays), nothing else left in DIR */
    assert_int_equal(mkdir(dir, 0755), 0);
    char link[PATH_MAX + 16], real[PATH_MAX + 16];
    snprintf(link, sizeof link, "%s/noise2d.png", dir);
    snprintf(real, sizeof real, "%s/real.png", dir);
    f = fopen(real, "w");
    assert_non_null(f);
    fputs("old\n", f);
    fclose(f);
    assert_int_equal(symlink("real.png", link), 0);
    const char *const go[] = {"pfnoise-demo", dir, NULL};
    run(go, &r);
    print_message("pfnoise-demo DIR -> %d: %s", r.status, r.err);
    assert_int_equal(r.status, 0);
    assert_int_equal(lstat(link, &sb), 0);
    assert_true(S_ISLNK(sb.st_mode));
    size_t n = 0;
    s = tu_slurp(real, &n);
    assert_non_null(s);
    assert_true(n > 8 && !memcmp(s, "\x89PNG", 4));
    free(s);
    int k = 0;
    DIR *d = opendir(dir);
    assert_non_null(d);
    for (struct dirent *de; (de = readdir(d));)
        k += de->d_name[0] != '.';
    closedir(d);
    assert_int_equal(k, 6); /* five pictures, real.png */
    const char *pics[] = {"noise2d.png", "noise3d_fixed.png", "fbm2d.png", "plane_unfiltered.png",
                          "plane_filtered.png", "real.png", NULL};
    for (int i = 0; pics[i]; i++) {
        char p[PATH_MAX + 32];
        snprintf(p, sizeof p, "%s/%s", dir, pics[i]);
        unlink(p);
    }
    rmdir(dir);
    unlink(plain);
}

/* --lib and --ladder name files: an empty PATH was dlopen(""), the program
 * itself (pfsweep: "no function" exit 1; pfbench: a run with no pfmath rows
 * or no ladder rows, exit 0), and a PATH without '/' searched the system's
 * library path instead of the current directory.  pfsweep's fixed-point
 * help shows "--lib [PATH]", but "--lib PATH" was "unexpected argument";
 * --pairs outside atan2 --all was silently ignored. */
static void test_lib_paths(void **st)
{
    (void)st;
    REFUSE("pfsweep", "--func", "log", "--lib=");
    REFUSE("pfsweep", "--func", "sin", "--type", "fixed<15,12>", "--lib=");
    REFUSE("pfsweep", "--func", "log", "--pairs", "5");
    REFUSE("pfsweep", "--func", "atan2", "--pairs", "5");
    char lib[PATH_MAX], dir[PATH_MAX], cwd[PATH_MAX];
    tu_prog_path("libpfmath.so", lib, sizeof lib);
    snprintf(dir, sizeof dir, "%s", lib);
    *strrchr(dir, '/') = 0;
    run_result r;
    /* "--lib PATH" as the fixed-point help writes it */
    const char *const a[] = {"pfsweep", "--func", "sin", "--type", "fixed<15,12>", "--out-type", "fixed<15,14>",
                             "--lib", lib, NULL}; /* (--samples: no sample for 16 bits, refused) */
    run(a, &r);
    print_message("pfsweep ... --lib PATH -> %d: %s", r.status, r.err);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "pf_sin_q12_q14"));
    /* a bare file name is the file in the current directory */
    assert_non_null(getcwd(cwd, sizeof cwd));
    assert_int_equal(chdir(dir), 0);
    const char *const b[] = {"pfsweep", "--func", "sin", "--type", "fixed<15,12>", "--out-type", "fixed<15,14>",
                             "--lib=libpfmath.so", NULL};
    run(b, &r);
    assert_int_equal(chdir(cwd), 0);
    print_message("pfsweep ... --lib=libpfmath.so (in its directory) -> %d: %s", r.status, r.err);
    assert_int_equal(r.status, 0);
    assert_non_null(strstr(r.out, "pf_sin_q12_q14"));
}

/* The bench programs' one optional argument: atoi/atof took "--help" as 0
 * (bench_trig then timed inputs in [-0, 0]; the others ran their whole
 * bench), "12x" as 12, "-5" as 1, "nan" as a range; fastsweep_atrig's
 * --pairs -1 was 2^64-1 pairs (hours) and "--help" an unknown function. */
static void test_bench_programs(void **st)
{
    (void)st;
    const char *progs[] = {"bench_trig", "bench_atrig", "bench_exp", "bench_fixed", "pfnoise-bench",
                           "fastsweep_atrig"};
    for (size_t i = 0; i < sizeof progs / sizeof progs[0]; i++) {
        const char *const h[] = {progs[i], "--help", NULL};
        run_result r;
        run(h, &r);
        print_message("%s --help -> %d", progs[i], r.status);
        assert_int_equal(r.status, 0);
        assert_non_null(strstr(r.out, "usage: "));
        REFUSE(progs[i], "12x");
        REFUSE(progs[i], "--frobnicate");
        REFUSE(progs[i], "-5");
        REFUSE(progs[i], "");
    }
    const char *counts[] = {"bench_atrig", "bench_exp", "bench_fixed", "pfnoise-bench"};
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++) {
        REFUSE(counts[i], "0");
        REFUSE(counts[i], "1", "2");
        REFUSE(counts[i], "99999999999999999999");
    }
    REFUSE("bench_trig", "0");
    REFUSE("bench_trig", "nan");
    REFUSE("bench_trig", "inf");
    REFUSE("bench_trig", "1", "2");
    REFUSE("bench_exp", "--fast-bound", "x");
    REFUSE("bench_exp", "--fast-bound", "0");
    REFUSE("fastsweep_atrig", "--pairs", "-1");
    REFUSE("fastsweep_atrig", "--pairs");
    REFUSE("fastsweep_atrig", "atan2", "--pairs", "5", "--pairs", "6");
    REFUSE("fastsweep_atrig", "sin");
}

static int setup(void **st)
{
    (void)st;
    return mkdtemp(scratch) ? 0 : -1;
}

static int teardown(void **st)
{
    (void)st;
    /* only what this test made: two capture files, out/ and its bench.md */
    char p[PATH_MAX + 32];
    const char *files[] = {"stdout", "stderr", "out/bench.md", "out2/bench.md", "out2/real.md", "out2/bench.csv", NULL};
    for (int i = 0; files[i]; i++) {
        snprintf(p, sizeof p, "%s/%s", scratch, files[i]);
        unlink(p);
    }
    snprintf(p, sizeof p, "%s/out", scratch);
    rmdir(p);
    snprintf(p, sizeof p, "%s/out2", scratch);
    rmdir(p);
    rmdir(scratch);
    return 0;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pfsweep_numbers),
        cmocka_unit_test(test_pfsweep_names_and_repeats),
        cmocka_unit_test(test_one_line_messages),
        cmocka_unit_test(test_stdout_full),
        cmocka_unit_test(test_pfbench_list),
        cmocka_unit_test(test_pfbench),
        cmocka_unit_test(test_pfbench_writes),
        cmocka_unit_test(test_pfnoise_demo),
        cmocka_unit_test(test_pfnoise_tablegen),
        cmocka_unit_test(test_lib_paths),
        cmocka_unit_test(test_bench_programs),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
