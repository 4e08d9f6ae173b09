/* Cross-checks against Sollya, the independent oracle: for each function at
 * the order the library uses, pfmathgen's minimax (float coefficients, same
 * domain and constraints) must be within 1.1x of Sollya's fpminimax with
 * single-precision coefficients; and the order `--target float` picks (the
 * smallest whose emitted polynomial is within 2^-24 relative) must equal
 * Sollya's guessdegree for relative error 2^-24.  Sollya runs by fork/exec
 * (no shell).  Skipped, with a message, without sollya. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "tu_exec.h"

#include <fcntl.h>
#include <math.h>
#include <sys/stat.h>

/* What Sollya is asked: f(x) on the domain pfmathgen reports, as
 *   p = q + sum a_k x^k over `monomials`, with q the constrained part
 * (our value/slope constraints at 0 are exactly such a q). */
typedef struct {
    const char *func;      /* pfmathgen --func */
    const char *args;      /* extra pfmathgen arguments */
    const char *f;         /* Sollya expression in x */
    const char *q;         /* constrained part */
    int first, step;       /* free monomials: first, first+step, ... <= order */
    const char *gd_g;      /* guessdegree: the q that p = x^shift q(...) approximates */
    int gd_shift;          /* order = guessdegree + shift (q = x * ...) */
} sollya_case;

/* guessdegree(f, I, eps, w) bounds ||p w - f|| (Sollya's help text).  The
 * relative error of q against g is q/g - 1 = q (1/g) - 1, so the relative
 * question is guessdegree(1, I, eps, 1/g); guessdegree(g, I, eps, 1/g) would
 * bound q/g - g instead. */

static const sollya_case cases[] = {
    {"log", "", "log(1+x)", "x", 2, 1, "log(1+x)/x", 1},
    {"log", "--reduction seed", "log(1+x)", "x", 2, 1, "log(1+x)/x", 1},
    {"log2", "", "log(1+x)", "x", 2, 1, "log(1+x)/x", 1},
    {"exp", "", "exp(x)", "1+x", 2, 1, "exp(x)", 0},
    {"exp2", "", "2^x", "1", 1, 1, "2^x", 0},
    /* odd fits p = x q(x^2): guessdegree on q(u) = f(sqrt u)/sqrt u over
       [0, b^2] (gd_shift -1 marks it: order = 2 gd + 1) */
    {"sin", "", "sin(x)", "x", 3, 2, "sin(sqrt(x))/sqrt(x)", -1},
    {"cos", "", "sin(x)", "x", 3, 2, "sin(sqrt(x))/sqrt(x)", -1},
    {"tan", "", "tan(x)", "x", 3, 2, "tan(sqrt(x))/sqrt(x)", -1},
    {"asin", "", "asin(x)", "x", 3, 2, "asin(sqrt(x))/sqrt(x)", -1},
    {"acos", "", "asin(x)", "x", 3, 2, "asin(sqrt(x))/sqrt(x)", -1},
    {"atan", "", "atan(x)", "x", 3, 2, "atan(sqrt(x))/sqrt(x)", -1},
    {"atan2", "", "atan(x)", "x", 3, 2, "atan(sqrt(x))/sqrt(x)", -1},
};

/* sollya on PATH, its full name in path */
static int find_sollya(char *path, size_t n)
{
    const char *p = getenv("PATH");
    if (!p)
        p = "/usr/bin:/bin";
    while (*p) {
        size_t k = strcspn(p, ":");
        snprintf(path, n, "%.*s/sollya", (int)k, p);
        if (k && access(path, X_OK) == 0)
            return 1;
        p += k + (p[k] == ':');
    }
    return 0;
}

static int have_sollya(void)
{
    char path[PATH_MAX];
    return find_sollya(path, sizeof path);
}

static double json_num(const char *s, const char *key)
{
    char k[64];
    snprintf(k, sizeof k, "\"%s\": ", key);
    const char *p = strstr(s, k);
    assert_non_null(p);
    return strtod(p + strlen(k), NULL);
}

static void json_domain(const char *s, char *a, char *b)
{
    const char *p = strstr(s, "\"domain\": [\"");
    assert_non_null(p);
    assert_int_equal(sscanf(p, "\"domain\": [\"%63[^\"]\", \"%63[^\"]\"]", a, b), 2);
}

static double run_sollya(const char *script, char *out2, size_t n2)
{
    char path[] = "/tmp/pfsollya.XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    assert_true(write(fd, script, strlen(script)) == (ssize_t)strlen(script));
    close(fd);
    char sollya[PATH_MAX], outp[] = "/tmp/pfsollya-out.XXXXXX";
    assert_true(find_sollya(sollya, sizeof sollya));
    int ofd = mkstemp(outp);
    assert_true(ofd >= 0);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        int nul = open("/dev/null", O_RDWR);
        if (nul < 0 || dup2(nul, 0) < 0 || dup2(ofd, 1) < 0 || dup2(nul, 2) < 0)
            _exit(127);
        execl(sollya, "sollya", "--warnonstderr", path, (char *)NULL);
        _exit(127);
    }
    int wst;
    waitpid(pid, &wst, 0);
    close(ofd);
    FILE *p = fopen(outp, "r");
    assert_non_null(p);
    char line[4096], last[4096] = "", prev[4096] = "";
    while (fgets(line, sizeof line, p)) {
        snprintf(prev, sizeof prev, "%s", last);
        snprintf(last, sizeof last, "%s", line);
    }
    fclose(p);
    unlink(outp);
    unlink(path);
    if (out2)
        snprintf(out2, n2, "%s", prev);
    return strtod(last, NULL);
}

static tu_run_result R;

static void test_minimax_vs_fpminimax(void **st)
{
    (void)st;
    if (!have_sollya()) {
        print_message("sollya is not installed: skipping the Sollya cross-check\n");
        skip();
    }
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const sollya_case *c = &cases[i];
        char args[256];
        snprintf(args, sizeof args, "--func %s %s --order %d --no-sweep --json", c->func, c->args,
                 strcmp(c->args, "") ? 10 : 0);
        if (!strcmp(c->args, ""))
            snprintf(args, sizeof args, "--func %s --no-sweep --json", c->func);
        tu_runs("pfmathgen", args, &R);
        assert_int_equal(R.status, 0);
        double ours = json_num(R.out, "max_rel_error"), lsq = json_num(R.out, "lsq_max_rel_error");
        int order = (int)json_num(R.out, "order");
        char a[64], b[64], mono[256] = "", script[2048];
        json_domain(R.out, a, b);
        for (int k = c->first; k <= order; k += c->step) {
            char t[16];
            snprintf(t, sizeof t, "%s%d", mono[0] ? "," : "", k);
            strcat(mono, t);
        }
        /* f(0) = 0 at a left endpoint 0: the relative error is measured from
           2^-40 on (it is continuous there; Sollya would evaluate 0/0) */
        const char *a0 = strtod(a, NULL) == 0 ? "2^-40" : a;
        snprintf(script, sizeof script,
                 "prec = 200; display = decimal;\n"
                 "f = %s; q = %s;\n"
                 "p = fpminimax(f, [|%s|], [|single...|], [%s;%s], relative, floating, q);\n"
                 "print(dirtyinfnorm(p/f - 1, [%s;%s]));\n",
                 c->f, c->q, mono, a0, b, a0, b);
        double sol = run_sollya(script, NULL, 0);
        print_message("%-6s %-16s order %2d: minimax %.4e  lsq %.4e  sollya fpminimax %.4e  ratio %.3f\n",
                      c->func, c->args, order, ours, lsq, sol, ours / sol);
        assert_true(sol > 0);
        assert_true(ours <= 1.1 * sol);
    }
}

static void test_target_float_vs_guessdegree(void **st)
{
    (void)st;
    if (!have_sollya()) {
        print_message("sollya is not installed: skipping the Sollya cross-check\n");
        skip();
    }
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const sollya_case *c = &cases[i];
        char args[256];
        if (strcmp(c->args, ""))
            continue;
        snprintf(args, sizeof args, "--func %s --no-sweep --json --target float", c->func);
        tu_runs("pfmathgen", args, &R);
        assert_int_equal(R.status, 0);
        int order = (int)json_num(R.out, "order");
        assert_true(json_num(R.out, "max_rel_error") <= 0x1p-24);
        char a[64], b[64], script[2048], line[4096];
        json_domain(R.out, a, b);
        /* relative error 2^-24: guessdegree(1, I, eps, 1/g) (see above) */
        if (c->gd_shift < 0)
            snprintf(script, sizeof script,
                     "prec = 200;\ng = %s;\nd = guessdegree(1, [2^-40;(%s)^2], 2^-24, 1/g);\nprint(inf(d));\n",
                     c->gd_g, b);
        else
            snprintf(script, sizeof script,
                     "prec = 200;\ng = %s;\nd = guessdegree(1, [%s;%s], 2^-24, 1/g);\nprint(inf(d));\n", c->gd_g,
                     a, b);
        double g = run_sollya(script, line, sizeof line);
        int gd = c->gd_shift < 0 ? 2 * (int)g + 1 : (int)g + c->gd_shift;
        print_message("%-6s --target float: order %d, Sollya guessdegree %d\n", c->func, order, gd);
        assert_true(gd > 0);
        assert_int_equal(order, gd);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_minimax_vs_fpminimax),
        cmocka_unit_test(test_target_float_vs_guessdegree),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
