/* Fuzz of pfmathgen's front end and scene parser (issue 11): a few thousand
 * random option sequences and random or malformed scene files (long lines,
 * NUL bytes, quotes, spaces, odd names, CRLF), each run without a shell in
 * its own scratch directory.  Every run must end with status 0 or 2 (no
 * crash, no internal failure), exactly one line on stderr for 2, and leave
 * everything outside its scratch directory as it was (a canary directory
 * beside it is compared after every run).  The sequences are seeded: a
 * failure prints the command to replay.  Most sequences fail validation;
 * the few valid ones are cheap (orders <= 6, 8-bit fixed types, mostly
 * --no-sweep). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "testutil.h"
#include "tu_exec.h"

#include <dirent.h>
#include <stdint.h>
#include <sys/stat.h>

static uint64_t rs = 0x9e3779b97f4a7c15ull;
static uint64_t rnd(void)
{
    uint64_t z = (rs += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}
#define PICK(a) (a)[rnd() % (sizeof(a) / sizeof((a)[0]))]

static char root[64], canary_state[4096];
static tu_run_result R;

/* names and sizes under root/canary, and root's own entries: the state that
 * no run may change */
static void state(char *buf, size_t n)
{
    buf[0] = 0;
    char p[200];
    snprintf(p, sizeof p, "%s/canary", root);
    DIR *d = opendir(p);
    assert_non_null(d);
    for (struct dirent *e; (e = readdir(d));) {
        char q[600];
        struct stat sb;
        if (!strcmp(e->d_name, ".."))
            continue;
        snprintf(q, sizeof q, "%s/%s", p, e->d_name);
        if (lstat(q, &sb) == 0)
            snprintf(buf + strlen(buf), n - strlen(buf), "%s:%lld:%lld ", e->d_name, (long long)sb.st_size,
                     (long long)sb.st_mtime);
    }
    closedir(d);
    d = opendir(root);
    for (struct dirent *e; (e = readdir(d));)
        if (strcmp(e->d_name, "run") && strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            snprintf(buf + strlen(buf), n - strlen(buf), "[%s] ", e->d_name);
    closedir(d);
}

static void setup_root(void)
{
    snprintf(root, sizeof root, "/tmp/pffuzz.XXXXXX");
    assert_non_null(mkdtemp(root));
    char p[200];
    snprintf(p, sizeof p, "%s/canary", root);
    assert_int_equal(mkdir(p, 0777), 0);
    snprintf(p, sizeof p, "%s/canary/keep.c", root);
    FILE *f = fopen(p, "w");
    fputs("keep\n", f);
    fclose(f);
    state(canary_state, sizeof canary_state);
}

/* a fresh run directory with a regular file "file", a directory "dir" and a
 * scene "s.scene" */
static void new_run(char *dir, size_t n)
{
    snprintf(dir, n, "%s/run", root);
    tu_rm_tree(dir);
    assert_int_equal(mkdir(dir, 0777), 0);
    char p[300];
    snprintf(p, sizeof p, "%s/dir", dir);
    assert_int_equal(mkdir(p, 0777), 0);
    snprintf(p, sizeof p, "%s/file", dir);
    FILE *f = fopen(p, "w");
    fputs("precious\n", f);
    fclose(f);
    snprintf(p, sizeof p, "%s/s.scene", dir);
    f = fopen(p, "w");
    fputs("sqrt exact ufixed<8,8> ufixed<8,8>\n", f);
    fclose(f);
}

static void check_run(const char *const *argv, int argc, int scene_run)
{
    char now[4096];
    state(now, sizeof now);
    int ok = (R.status == 0 || (R.status == 2 && tu_count_lines(R.err) == 1)) && !strcmp(now, canary_state);
    if (!ok) {
        print_message("replay (seed state %llu): pfmathgen", (unsigned long long)rs);
        for (int i = 0; i < argc; i++)
            print_message(" '%s'", argv[i]);
        print_message("\n  status %d, stderr:\n%s\n  outside state: %s\n  want: %s\n", R.status, R.err, now,
                      canary_state);
    }
    (void)scene_run;
    assert_true(ok);
}

static const char *const opts[] = {"--func", "--variant", "--order", "--reduction", "--type",
                                   "--out-type", "--method", "--name", "-o", "--output",
                                   "--json", "--no-sweep", "--plot", "--target", "--max-rel-err",
                                   "--max-abs-err", "--seed", "--scene", "--prefix", "--help",
                                   "--bogus", "-x", "", "--func=log", "--order=", "-"};
static const char *const funcs[] = {"log", "log2", "exp", "exp2", "sin", "cos", "tan", "asin", "atan2",
                                    "sqrt", "noise1", "noise3", "noise", "noise5", "", "lo g", "'", "sin'",
                                    "LOG", "log\n", "\xff\xfe"};
static const char *const values[] = {
    "exact", "fast", "both", "quick", "1", "3", "5", "6", "0", "31", "-1", "1e3", "99999999999999999999",
    " 5", "seed", "balanced", "float", "double", "fixed<15,12>", "ufixed<8,8>", "unsigned fixed<8,8>",
    "fixed<7,5>", "fixed<40,3>", "fixed<15", "fixed<15,-3>", "fixed<8,0>", "minimax", "lsq", "remez",
    "int", "_Bool", "my_f", "a b", "x'y", "9x", "caf\xc3\xa9", "f.c", "a b.c", "q'; touch X; '.c", "dir",
    "dir/", "file", "nonexist/x.c", ".", "o\nq.c", "e.svg", "x'; system 'touch Y'; print '.svg", "1e-30",
    "2^-80", "2^-12", "1e-4", "0.5", "abc", "nan", "inf", "0x10", "s.scene", "missing.scene", "out", "out/",
    "pre_", "9p", "--func", "-o", "'", "\"", "\\", "$(touch Z)", "`touch Z`", "*/", "%s%n"};

static char longname[200], longval[5000];

static const char *value(void)
{
    switch (rnd() % 16) {
    case 0: return PICK(funcs);
    case 1: return longname; /* over the --name limit */
    case 2: return rnd() % 4 ? PICK(values) : longval;
    default: return PICK(values);
    }
}

static void test_option_sequences(void **st)
{
    (void)st;
    char path[PATH_MAX];
    tu_prog_path("pfmathgen", path, sizeof path);
    int runs = strstr(path, "/asan/") ? 400 : 1500; /* ASan: slower starts, same kinds of input */
    memset(longname, 'n', sizeof longname - 1);
    memset(longval, 'v', sizeof longval - 1);
    int n0 = 0, n2 = 0;
    for (int it = 0; it < runs; it++) {
        char dir[200];
        new_run(dir, sizeof dir);
        const char *argv[24];
        int argc = 0;
        int k = 1 + (int)(rnd() % 8);
        /* mostly a function first: what a user writes */
        if (rnd() % 4) {
            argv[argc++] = "--func";
            argv[argc++] = PICK(funcs);
        }
        for (int j = 0; j < k && argc < 18; j++) {
            argv[argc++] = PICK(opts);
            if (rnd() % 8)
                argv[argc++] = value();
        }
        /* keep valid requests cheap: most runs skip the sweep */
        if (rnd() % 8)
            argv[argc++] = "--no-sweep";
        argv[argc] = NULL;
        tu_runv_in(dir, "pfmathgen", argv, &R);
        check_run(argv, argc, 0);
        n0 += R.status == 0;
        n2 += R.status == 2;
    }
    print_message("  %d option sequences: %d exit 0, %d exit 2\n", runs, n0, n2);
}

/* random scene text */
static size_t scene_text(char *buf, size_t cap)
{
    static const char *const lines[] = {
        "sqrt exact ufixed<8,8> ufixed<8,8>", "sqrt fast ufixed<8,8> ufixed<8,8>", "# a comment",
        "   ", "sin exact float", "frob exact float float", "sin' exact float float",
        "s\"in exact float float", "sin exact fixed<15,12 fixed<15,14>", "sin exact float float extra",
        "noise fixed<15,12> fixed<15,14>", "noise3 fast fixed<15,12> fixed<15,14>", "noise2 float float",
        "sqrt exactly ufixed<8,8> ufixed<8,8>", "sqrt exact fixed<40,8> fixed<40,8>", "exact", "#",
        "sqrt exact ufixed<8,8> ufixed<8,8> # trailing", "tan exact fixed<15,12> fixed<15,14>",
        "sqrt\texact\tufixed<8,8>\tufixed<8,8>", "sqrt exact ufixed<8,8> ufixed<8,8>\r"};
    size_t n = 0;
    int nl = (int)(rnd() % 6);
    for (int i = 0; i < nl && n + 6000 < cap; i++) {
        switch (rnd() % 8) {
        case 0: { /* a long line: spaces or junk, maybe then an entry */
            size_t len = 400 + rnd() % 4000;
            char c = rnd() % 2 ? ' ' : 'x';
            if (rnd() % 2)
                buf[n++] = '#';
            memset(buf + n, c, len);
            n += len;
            if (rnd() % 2)
                n += (size_t)sprintf(buf + n, "%s", lines[0]);
            break;
        }
        case 1: { /* random bytes, NUL included */
            size_t len = 1 + rnd() % 80;
            for (size_t j = 0; j < len; j++)
                buf[n++] = (char)(rnd() % 256);
            break;
        }
        default: n += (size_t)sprintf(buf + n, "%s", PICK(lines)); break;
        }
        if (rnd() % 10 == 0)
            buf[n++] = 0; /* a NUL byte */
        buf[n++] = '\n';
    }
    return n;
}

static void test_scene_files(void **st)
{
    (void)st;
    char path[PATH_MAX];
    tu_prog_path("pfmathgen", path, sizeof path);
    int runs = strstr(path, "/asan/") ? 150 : 500;
    static const char *const names[] = {"s.scene", "a b.scene", "q'x.scene", "9.scene", ".scene", "x.y.scene",
                                        "caf\xc3\xa9.scene", "-.scene"};
    static const char *const outs[] = {"out", "out/", "o u t", "q'; touch X; '", "file", "nonexist/sub", "dir",
                                       "dir/", ".", "o\nut", ""};
    static char buf[1 << 16];
    int n0 = 0, n2 = 0;
    for (int it = 0; it < runs; it++) {
        char dir[200], p[600];
        new_run(dir, sizeof dir);
        const char *name = PICK(names);
        size_t len = scene_text(buf, sizeof buf);
        snprintf(p, sizeof p, "%s/%s", dir, name);
        FILE *f = fopen(p, "wb");
        assert_non_null(f);
        fwrite(buf, 1, len, f);
        fclose(f);
        const char *argv[8] = {"--scene", name, "-o", PICK(outs), NULL};
        int argc = 4;
        if (rnd() % 4 == 0) {
            argv[argc++] = "--prefix";
            argv[argc++] = rnd() % 2 ? PICK(values) : "p_";
        }
        argv[argc] = NULL;
        tu_runv_in(dir, "pfmathgen", argv, &R);
        check_run(argv, argc, 1);
        /* the regular file "file" is never replaced */
        snprintf(p, sizeof p, "%s/file", dir);
        char *c = tu_slurp(p, NULL);
        assert_non_null(c);
        assert_string_equal(c, "precious\n");
        free(c);
        n0 += R.status == 0;
        n2 += R.status == 2;
    }
    print_message("  %d scene files: %d exit 0, %d exit 2\n", runs, n0, n2);
}

static int teardown(void **st)
{
    (void)st;
    tu_rm_tree(root);
    return 0;
}

static int setup(void **st)
{
    (void)st;
    setup_root();
    return 0;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_option_sequences),
        cmocka_unit_test(test_scene_files),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
