/* Issue 11: pfmathgen under the mistakes and odd names of a new user.  One
 * test per numbered item (11 and 12 are in test_cli.c); each was reproduced
 * on the code before the fix and fails there.  Every run happens in its own
 * scratch directory, without a shell (tests/tu_exec.h). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "compile.h"
#include "testutil.h"
#include "tu_exec.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>

static tu_run_result R;
static char scratch[64];

static void new_scratch(void)
{
    snprintf(scratch, sizeof scratch, "/tmp/pfhostile.XXXXXX");
    assert_non_null(mkdtemp(scratch));
}

static void put(const char *rel, const char *data, size_t n)
{
    char p[1300];
    snprintf(p, sizeof p, "%s/%s", scratch, rel);
    FILE *f = fopen(p, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, n, f), n);
    fclose(f);
}

static void puts_file(const char *rel, const char *text) { put(rel, text, strlen(text)); }

static char *get(const char *rel)
{
    char p[1300];
    snprintf(p, sizeof p, "%s/%s", scratch, rel);
    return tu_slurp(p, NULL);
}

static int exists(const char *rel)
{
    char p[1300];
    struct stat sb;
    snprintf(p, sizeof p, "%s/%s", scratch, rel);
    return lstat(p, &sb) == 0;
}

static mode_t kind(const char *rel)
{
    char p[1300];
    struct stat sb;
    snprintf(p, sizeof p, "%s/%s", scratch, rel);
    return lstat(p, &sb) == 0 ? (sb.st_mode & S_IFMT) : 0;
}

static int count_c(const char *rel)
{
    char p[1300];
    snprintf(p, sizeof p, "%s/%s", scratch, rel);
    DIR *d = opendir(p);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d));) {
        size_t l = strlen(e->d_name);
        n += l > 2 && !strcmp(e->d_name + l - 2, ".c");
    }
    if (d)
        closedir(d);
    return n;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* pfmathgen ARGS... in the scratch directory */
#define GEN(...) tu_runv_in(scratch, "pfmathgen", (const char *const[]){__VA_ARGS__, NULL}, &R)

static void expect2(void)
{
    print_message("  -> %d: %s", R.status, R.err);
    assert_int_equal(R.status, 2);
    assert_int_equal(tu_count_lines(R.err), 1);
    assert_non_null(strstr(R.err, "pfmathgen: "));
}

/* a cheap scene: an 8-bit sqrt (milliseconds to fit and sweep) */
static const char *cheap_scene = "sqrt exact ufixed<8,8> ufixed<8,8>\n";

/* item 1: --scene -o DIR never deletes DIR or anything in it; a regular
 * file named DIR is an error and stays as it was */
static void test_item1_scene_keeps_dir(void **st)
{
    (void)st;
    new_scratch();
    puts_file("s.scene", cheap_scene);
    char p[600];
    snprintf(p, sizeof p, "%s/out", scratch);
    assert_int_equal(mkdir(p, 0777), 0);
    puts_file("out/mine.txt", "the user's file\n");
    GEN("--scene", "s.scene", "-o", "out");
    assert_int_equal(R.status, 0);
    char *m = get("out/mine.txt");
    assert_non_null(m);
    assert_string_equal(m, "the user's file\n");
    free(m);
    assert_int_equal(count_c("out"), 1);
    assert_true(exists("out/scene.h") && exists("out/report.txt"));
    /* a scene that fails after its first entry was generated: DIR unchanged */
    char *before = get("out/s_sqrt_u8_8_u8_8.c");
    puts_file("out/s_sqrt_u8_8_u8_8.c", "user edit\n");
    puts_file("bad.scene", "sqrt exact ufixed<8,8> ufixed<8,8>\nsin exact fixed<15,12> ufixed<16,14>\n");
    GEN("--scene", "bad.scene", "-o", "out");
    expect2();
    char *after = get("out/s_sqrt_u8_8_u8_8.c");
    assert_string_equal(after, "user edit\n");
    m = get("out/mine.txt");
    assert_string_equal(m, "the user's file\n");
    free(m);
    free(before);
    free(after);
    /* a regular file named DIR */
    puts_file("plain", "precious\n");
    GEN("--scene", "s.scene", "-o", "plain");
    expect2();
    assert_int_equal(kind("plain"), S_IFREG);
    m = get("plain");
    assert_string_equal(m, "precious\n");
    free(m);
    tu_rm_tree(scratch);
}

/* item 2: the README's own "-o out/": a trailing slash is the same dir,
 * new or existing */
static void test_item2_trailing_slash(void **st)
{
    (void)st;
    new_scratch();
    puts_file("s.scene", cheap_scene);
    GEN("--scene", "s.scene", "-o", "out/");
    assert_int_equal(R.status, 0);
    assert_int_equal(count_c("out"), 1);
    GEN("--scene", "s.scene", "-o", "out//");
    assert_int_equal(R.status, 0);
    assert_int_equal(count_c("out"), 1);
    /* nothing else was created beside it (no out.tmp.PID) */
    DIR *d = opendir(scratch);
    int n = 0;
    for (struct dirent *e; (e = readdir(d));)
        n += e->d_name[0] != '.';
    closedir(d);
    assert_int_equal(n, 2); /* s.scene, out */
    tu_rm_tree(scratch);
}

/* item 3: a symlink is written through, a FIFO is written and stays one, a
 * directory is refused before the fit */
static void test_item3_links_and_fifos(void **st)
{
    (void)st;
    new_scratch();
    puts_file("target.c", "old\n");
    char p[600], q[600];
    snprintf(p, sizeof p, "%s/link.c", scratch);
    assert_int_equal(symlink("target.c", p), 0);
    GEN("--func", "log", "--variant", "fast", "--no-sweep", "-o", "link.c");
    assert_int_equal(R.status, 0);
    assert_int_equal(kind("link.c"), S_IFLNK);
    char *t = get("target.c");
    assert_non_null(strstr(t, "Generated by pfmathgen"));
    free(t);
    /* a dangling link: its target is created */
    snprintf(p, sizeof p, "%s/dangling.c", scratch);
    assert_int_equal(symlink("sub/new.c", p), 0);
    snprintf(q, sizeof q, "%s/sub", scratch);
    assert_int_equal(mkdir(q, 0777), 0);
    GEN("--func", "log", "--variant", "fast", "--no-sweep", "-o", "dangling.c");
    assert_int_equal(R.status, 0);
    assert_int_equal(kind("dangling.c"), S_IFLNK);
    assert_int_equal(kind("sub/new.c"), S_IFREG);
    /* a FIFO: opened and written, never replaced */
    snprintf(p, sizeof p, "%s/fifo.c", scratch);
    assert_int_equal(mkfifo(p, 0600), 0);
    int rd = open(p, O_RDONLY | O_NONBLOCK);
    assert_true(rd >= 0);
    GEN("--func", "log", "--variant", "fast", "--no-sweep", "-o", "fifo.c");
    assert_int_equal(R.status, 0);
    assert_int_equal(kind("fifo.c"), S_IFIFO);
    static char buf[1 << 16];
    ssize_t n = read(rd, buf, sizeof buf - 1);
    close(rd);
    assert_true(n > 0);
    buf[n] = 0;
    assert_non_null(strstr(buf, "Generated by pfmathgen"));
    /* a directory */
    GEN("--func", "log", "-o", "sub");
    expect2();
    assert_int_equal(kind("sub"), S_IFDIR);
    tu_rm_tree(scratch);
}

static int have_gnuplot(void)
{
    const char *v[] = {"gnuplot", "--version", NULL};
    tu_execvp_in(NULL, v, &R);
    return R.status == 0;
}

/* item 4: names with quotes are names, for the shell and for gnuplot */
static void test_item4_no_injection(void **st)
{
    (void)st;
    new_scratch();
    puts_file("s.scene", cheap_scene);
    const char *qdir = "q'; touch X; '";
    char p[600];
    snprintf(p, sizeof p, "%s/%s", scratch, qdir);
    assert_int_equal(mkdir(p, 0777), 0);
    GEN("--scene", "s.scene", "-o", qdir);
    assert_int_equal(R.status, 0);
    assert_false(exists("X"));
    snprintf(p, sizeof p, "%s/scene.h", qdir);
    assert_true(exists(p));
    GEN("--func", "log", "--variant", "fast", "--no-sweep", "-o", "a'; touch Z; 'b.c");
    assert_int_equal(R.status, 0);
    assert_false(exists("Z"));
    assert_true(exists("a'; touch Z; 'b.c"));
    if (have_gnuplot()) {
        const char *svg = "x'; system 'touch Y'; print '.svg";
        GEN("--func", "log", "--variant", "fast", "--no-sweep", "--plot", svg, "-o", "p.c");
        assert_int_equal(R.status, 0);
        assert_false(exists("Y"));
        char *s = get(svg);
        assert_non_null(s);
        assert_non_null(strstr(s, "</svg>"));
        free(s);
    } else {
        print_message("  (no gnuplot: the --plot half is skipped)\n");
    }
    tu_rm_tree(scratch);
}

/* item 5: scene lines of any length, true line numbers, no NUL bytes */
static void test_item5_long_lines(void **st)
{
    (void)st;
    new_scratch();
    static char line[4096];
    /* a comment whose tail, past byte 511, reads as an entry */
    snprintf(line, sizeof line, "#%600s%s\n%s", "", "sqrt fast ufixed<8,8> ufixed<8,8>", cheap_scene);
    puts_file("a.scene", line);
    GEN("--scene", "a.scene", "-o", "a");
    assert_int_equal(R.status, 0);
    assert_int_equal(count_c("a"), 1);
    assert_false(exists("a/a_sqrt_fast_u8_8_u8_8.c"));
    /* one entry spread over a long line */
    snprintf(line, sizeof line, "sqrt exact%700sufixed<8,8>%700sufixed<8,8>   # %1000s\n", "", "", "");
    puts_file("b.scene", line);
    GEN("--scene", "b.scene", "-o", "b");
    assert_int_equal(R.status, 0);
    assert_int_equal(count_c("b"), 1);
    /* the error's line number counts lines, not 511-byte pieces */
    snprintf(line, sizeof line, "# %2000s\n\nfrob exact float float\n", "");
    puts_file("c.scene", line);
    GEN("--scene", "c.scene", "-o", "c");
    expect2();
    assert_non_null(strstr(R.err, "c.scene:3:"));
    assert_false(exists("c"));
    /* a NUL byte, even in a comment */
    static const char nul[] = "sqrt exact ufixed<8,8> ufixed<8,8>\n# a\0b\n";
    put("d.scene", nul, sizeof nul - 1);
    GEN("--scene", "d.scene", "-o", "d");
    expect2();
    assert_non_null(strstr(R.err, "d.scene:2:"));
    assert_non_null(strstr(R.err, "NUL"));
    assert_false(exists("d"));
    tu_rm_tree(scratch);
}

/* item 9: impossible requests answer at once */
static void test_item9_fast_refusals(void **st)
{
    (void)st;
    new_scratch();
    const char *const cases[][8] = {
        {"--func", "exp", "--max-rel-err", "1e-30", NULL},
        {"--func", "log", "--max-abs-err", "2^-60", NULL},
        {"--func", "log", "--target", "fixed<31,60>", NULL},
        {"--func", "sin", "--type", "fixed<15,12>", "--order", "30", NULL},
        {"--func", "sin", "--type", "fixed<15,12>", "--order", "25", NULL},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double t0 = now();
        tu_runv_in(scratch, "pfmathgen", cases[i], &R);
        double dt = now() - t0;
        print_message("  %s %s %s: %.2f s", cases[i][1], cases[i][2], cases[i][3], dt);
        expect2();
        assert_true(dt < 3.0);
    }
    tu_rm_tree(scratch);
}

/* item 10: a bad output is found before the fit, with a clear message, and
 * nothing is left behind */
static void test_item10_outputs_first(void **st)
{
    (void)st;
    new_scratch();
    GEN("--func", "log", "-o", "/nonexistent/d/f.c");
    expect2(); /* one line: no report, so no fit */
    assert_non_null(strstr(R.err, "does not exist"));
    GEN("--func", "log", "--plot", "/nonexistent/e.svg");
    expect2();
    assert_null(strstr(R.err, "gnuplot"));
    assert_non_null(strstr(R.err, "/nonexistent"));
    GEN("--func", "log", "--plot", "e.svg", "-o", "/bad/x.c");
    expect2();
    assert_false(exists("e.svg"));
    char p[600];
    snprintf(p, sizeof p, "%s/dir", scratch);
    assert_int_equal(mkdir(p, 0777), 0);
    GEN("--func", "log", "--plot", "e.svg", "-o", "dir");
    expect2();
    assert_false(exists("e.svg"));
    tu_rm_tree(scratch);
}

/* item 13: scene.h works from C++ and float scene functions do not take
 * libpfmath's names: a C++ program links a scene and libpfmath together */
static void test_item13_scene_links_with_libpfmath(void **st)
{
    (void)st;
    new_scratch();
    puts_file("ripple.scene", "sin fast float float\n");
    GEN("--scene", "ripple.scene", "-o", "out");
    assert_int_equal(R.status, 0);
    char *h = get("out/scene.h");
    assert_non_null(strstr(h, "extern \"C\""));
    assert_non_null(strstr(h, "float ripple_sinf_fast(float x);"));
    assert_null(strstr(h, " pf_"));
    free(h);
    /* --prefix: a chosen prefix; never empty or pf_ alone */
    puts_file("s.scene", cheap_scene);
    GEN("--scene", "s.scene", "-o", "p", "--prefix", "my_");
    assert_int_equal(R.status, 0);
    assert_true(exists("p/my_sqrt_u8_8_u8_8.c"));
    const char *badp[] = {"", "pf_", "a b", "9x", "__x", "x'"};
    for (size_t i = 0; i < sizeof badp / sizeof badp[0]; i++) {
        GEN("--scene", "s.scene", "-o", "q", "--prefix", badp[i]);
        expect2();
        assert_false(exists("q"));
    }
    puts_file("main.cpp", "#include \"scene.h\"\n#include \"pfmath.h\"\n#include <cstdio>\n"
                          "int main() { std::printf(\"%d\\n\", ripple_sinf_fast(0.5f) == pf_sinf_fast(0.5f)); }\n");
    char lib[PATH_MAX], inc[PATH_MAX + 8], src[PATH_MAX];
    tu_prog_path("libpfmath.a", lib, sizeof lib);
    assert_non_null(realpath("libpfmath", src));
    snprintf(inc, sizeof inc, "-I%s", src);
    const char *v[] = {"g++", "-Iout", inc, "-c", "main.cpp", "-o", "main.o", NULL};
    tu_execvp_in(scratch, v, &R);
    if (R.status == 127) {
        print_message("  (no g++: skipped)\n");
        tu_rm_tree(scratch);
        return;
    }
    print_message("%s", R.err);
    assert_int_equal(R.status, 0);
    const char *c[] = {"cc", "-std=c17", "-O2", "-c", "out/ripple_sinf_fast.c", "-o", "s.o", NULL};
    tu_execvp_in(scratch, c, &R);
    assert_int_equal(R.status, 0);
    /* the ASan tree's libpfmath.a needs the sanitizers' run time */
    const char *san = strstr(lib, "/asan/") ? "-fsanitize=address,undefined" : "-lm";
    const char *l[] = {"g++", "main.o", "s.o", lib, "-lm", san, "-o", "prog", NULL};
    tu_execvp_in(scratch, l, &R);
    print_message("%s", R.err);
    assert_int_equal(R.status, 0);
    char prog[600];
    snprintf(prog, sizeof prog, "%s/prog", scratch);
    const char *r[] = {prog, NULL};
    tu_execvp_in(scratch, r, &R);
    assert_int_equal(R.status, 0);
    tu_rm_tree(scratch);
}

/* -o and --plot naming one file by two spellings (./a.c and a.c, a symlink
 * to it, a hard link): refused before the fit, as the same spelling is;
 * otherwise the plot's rename replaced the C and the run said 0 */
static void test_same_file_two_names(void **st)
{
    (void)st;
    new_scratch();
    char p[600], q[600];
    snprintf(p, sizeof p, "%s/sub", scratch);
    assert_int_equal(mkdir(p, 0777), 0);
    GEN("--func", "log", "--variant", "fast", "--no-sweep", "-o", "./same.c", "--plot", "same.c");
    expect2();
    assert_false(exists("same.c"));
    GEN("--func", "log", "--variant", "fast", "--no-sweep", "-o", "sub/../same.c", "--plot", "same.c");
    expect2();
    assert_false(exists("same.c"));
    puts_file("real.c", "the user's file\n");
    snprintf(p, sizeof p, "%s/link.c", scratch);
    assert_int_equal(symlink("real.c", p), 0);
    GEN("--func", "log", "--variant", "fast", "--no-sweep", "-o", "link.c", "--plot", "real.c");
    expect2();
    snprintf(p, sizeof p, "%s/real.c", scratch);
    snprintf(q, sizeof q, "%s/hard.c", scratch);
    assert_int_equal(link(p, q), 0);
    GEN("--func", "log", "--variant", "fast", "--no-sweep", "-o", "hard.c", "--plot", "real.c");
    expect2();
    char *m = get("real.c");
    assert_string_equal(m, "the user's file\n");
    free(m);
    /* two different files are still fine */
    GEN("--func", "log", "--variant", "fast", "--no-sweep", "-o", "./a.c", "--plot", "sub/a.svg");
    assert_int_equal(R.status, 0);
    m = get("a.c");
    assert_non_null(strstr(m, "Generated by pfmathgen"));
    free(m);
    tu_rm_tree(scratch);
}

/* a scene file named pf.scene: its default prefix would be pf_, the one
 * --prefix refuses (libpfmath's own names: pf_sinf_fast would be emitted
 * twice at link time); refused with a pointer to --prefix */
static void test_scene_default_prefix_pf(void **st)
{
    (void)st;
    new_scratch();
    puts_file("pf.scene", "sin fast float float\n");
    GEN("--scene", "pf.scene", "-o", "out");
    expect2();
    assert_non_null(strstr(R.err, "--prefix"));
    assert_false(exists("out"));
    puts_file("pf.x.scene", "sin fast float float\n");
    GEN("--scene", "pf.x.scene", "-o", "out");
    expect2();
    assert_false(exists("out"));
    /* another name, or an explicit prefix, works */
    GEN("--scene", "pf.scene", "-o", "out", "--prefix", "pfs_");
    assert_int_equal(R.status, 0);
    assert_true(exists("out/pfs_sinf_fast.c"));
    tu_rm_tree(scratch);
}

/* the scene file inside DIR under an output's name (report.txt, scene.h):
 * the run replaced the user's scene with its report, exit 0 */
static void test_scene_file_not_replaced(void **st)
{
    (void)st;
    new_scratch();
    char p[600];
    snprintf(p, sizeof p, "%s/out", scratch);
    assert_int_equal(mkdir(p, 0777), 0);
    puts_file("out/report.txt", cheap_scene);
    GEN("--scene", "out/report.txt", "-o", "out");
    expect2();
    puts_file("out/scene.h", cheap_scene);
    GEN("--scene", "out/scene.h", "-o", "out/");
    expect2();
    /* a link to it in DIR is the same file */
    puts_file("my.scene", cheap_scene);
    snprintf(p, sizeof p, "%s/out/report.txt", scratch);
    assert_int_equal(unlink(p), 0);
    assert_int_equal(symlink("../my.scene", p), 0);
    GEN("--scene", "my.scene", "-o", "out");
    expect2();
    char *m = get("out/scene.h");
    assert_string_equal(m, cheap_scene);
    free(m);
    m = get("my.scene");
    assert_string_equal(m, cheap_scene);
    free(m);
    assert_int_equal(count_c("out"), 0);
    tu_rm_tree(scratch);
}

/* pfmathgen ARGS in the scratch directory as a user without root's
 * override (root: as nobody, 65534), so that a file's write permission
 * counts as it does for everyone else; status, or -1 */
static int gen_unprivileged(const char *const *args)
{
    char path[PATH_MAX];
    tu_prog_path("pfmathgen", path, sizeof path);
    if (getuid() == 0) {
        /* nobody may not reach the build tree (a clone under a 0700
           directory, as mktemp -d makes): run a copy from the scratch
           directory, which it can (exec failed with 127 there); one copy
           per scratch directory */
        char copy[PATH_MAX];
        snprintf(copy, sizeof copy, "%s/pfmathgen-copy", scratch);
        if (access(copy, X_OK) != 0) {
            size_t n = 0;
            char *bin = tu_slurp(path, &n);
            assert_non_null(bin);
            put("pfmathgen-copy", bin, n);
            free(bin);
            assert_int_equal(chmod(copy, 0755), 0);
        }
        snprintf(path, sizeof path, "%s", copy);
    }
    const char *v[16] = {path};
    for (int i = 0; args[i] && i < 14; i++)
        v[i + 1] = args[i];
    pid_t pid = fork();
    if (pid == 0) {
        int dn = open("/dev/null", O_RDWR);
        if (dn >= 0) {
            dup2(dn, 0);
            dup2(dn, 1);
            dup2(dn, 2);
        }
        if (chdir(scratch) != 0)
            _exit(126);
        if (getuid() == 0 && (setgid(65534) != 0 || setuid(65534) != 0))
            _exit(126);
        execv(path, (char *const *)v);
        _exit(127);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* A read-only file as -o (or in a scene's DIR) is refused as a shell's
 * "> file" or cp would refuse it; the rename beside it replaced it (the
 * directory's write permission is all a rename needs). */
static void test_read_only_target(void **st)
{
    (void)st;
    new_scratch();
    assert_int_equal(chmod(scratch, 0777), 0);
    puts_file("ro.c", "the user's read-only file\n");
    char p[600];
    snprintf(p, sizeof p, "%s/ro.c", scratch);
    assert_int_equal(chmod(p, 0444), 0);
    const char *const a[] = {"--func", "log", "--variant", "fast", "--no-sweep", "-o", "ro.c", NULL};
    assert_int_equal(gen_unprivileged(a), 2);
    char *m = get("ro.c");
    assert_string_equal(m, "the user's read-only file\n");
    free(m);
    /* a scene: DIR holds a read-only output of the same name */
    puts_file("s.scene", cheap_scene);
    snprintf(p, sizeof p, "%s/out", scratch);
    assert_int_equal(mkdir(p, 0777), 0);
    assert_int_equal(chmod(p, 0777), 0);
    puts_file("out/report.txt", "kept\n");
    snprintf(p, sizeof p, "%s/out/report.txt", scratch);
    assert_int_equal(chmod(p, 0444), 0);
    const char *const b[] = {"--scene", "s.scene", "-o", "out", NULL};
    assert_int_equal(gen_unprivileged(b), 2);
    m = get("out/report.txt");
    assert_string_equal(m, "kept\n");
    free(m);
    assert_int_equal(count_c("out"), 0);
    /* a writable one is replaced as before */
    puts_file("rw.c", "old\n");
    snprintf(p, sizeof p, "%s/rw.c", scratch);
    assert_int_equal(chmod(p, 0666), 0);
    const char *const c[] = {"--func", "log", "--variant", "fast", "--no-sweep", "-o", "rw.c", NULL};
    assert_int_equal(gen_unprivileged(c), 0);
    m = get("rw.c");
    assert_non_null(strstr(m, "Generated by pfmathgen"));
    free(m);
    tu_rm_tree(scratch);
}

/* --json -o /dev/stdout > f: the JSON went to f, then the rename replaced
 * f with the C, exit 0, the JSON gone; -o f 2> f the same with the report.
 * (tu_execvp_in's standard output and error are regular files.) */
static void test_output_is_std_stream(void **st)
{
    (void)st;
    new_scratch();
    GEN("--func", "log", "--variant", "fast", "--no-sweep", "--json", "-o", "/dev/stdout");
    expect2();
    assert_non_null(strstr(R.err, "standard output"));
    GEN("--func", "log", "--variant", "fast", "--no-sweep", "-o", "/dev/stderr");
    expect2();
    assert_non_null(strstr(R.err, "standard error"));
    tu_rm_tree(scratch);
}

/* Another user's writable file in a sticky directory (as in /tmp): the
 * check passed it, and the rename failed with EPERM after the fit (exit
 * 1).  Now refused before it, the file as it was.  (Root only: the file
 * must be another user's than the one pfmathgen runs as.) */
static void test_sticky_dir(void **st)
{
    (void)st;
    if (getuid() != 0) {
        print_message("  (not root: skipped)\n");
        return;
    }
    new_scratch();
    assert_int_equal(chmod(scratch, 01777), 0);
    puts_file("other.c", "root's file\n");
    char p[600];
    snprintf(p, sizeof p, "%s/other.c", scratch);
    assert_int_equal(chmod(p, 0666), 0);
    const char *const a[] = {"--func", "log", "--variant", "fast", "--no-sweep", "-o", "other.c", NULL};
    assert_int_equal(gen_unprivileged(a), 2);
    char *m = get("other.c");
    assert_string_equal(m, "root's file\n");
    free(m);
    /* its own new file there is written as before */
    const char *const b[] = {"--func", "log", "--variant", "fast", "--no-sweep", "-o", "mine.c", NULL};
    assert_int_equal(gen_unprivileged(b), 0);
    assert_int_equal(gen_unprivileged(b), 0); /* and replaced: its own */
    m = get("mine.c");
    assert_non_null(strstr(m, "Generated by pfmathgen"));
    free(m);
    tu_rm_tree(scratch);
}

/* scene files as editors save them: a UTF-8 byte order mark, CRLF line
 * ends, tabs, no final newline; the mark made the first function unknown,
 * with a message showing the (invisible) mark before its name */
static void test_scene_editor_files(void **st)
{
    (void)st;
    new_scratch();
    puts_file("bom.scene", "\xef\xbb\xbfsqrt exact ufixed<8,8> ufixed<8,8>\r\nsqrt\tfast\tufixed<8,8>\tufixed<8,8>");
    GEN("--scene", "bom.scene", "-o", "out");
    print_message("  -> %d: %s", R.status, R.err);
    assert_int_equal(R.status, 0);
    assert_int_equal(count_c("out"), 2);
    /* only at the start of the file */
    puts_file("mid.scene", "sqrt exact ufixed<8,8> ufixed<8,8>\n\xef\xbb\xbfsqrt fast ufixed<8,8> ufixed<8,8>\n");
    GEN("--scene", "mid.scene", "-o", "out2");
    expect2();
    assert_non_null(strstr(R.err, "mid.scene:2:"));
    tu_rm_tree(scratch);
}

/* cc -std=c17 -Wall -Werror -fsyntax-only REL in the scratch directory:
 * the status (127: no cc) */
static int syntax_ok(const char *rel)
{
    const char *v[] = {"cc", "-std=c17", "-Wall", "-Werror", "-fsyntax-only", rel, NULL};
    tu_execvp_in(scratch, v, &R);
    print_message("  cc %s -> %d %s", rel, R.status, R.err);
    return R.status;
}

/* A file name is recorded in the C's comments (Regenerate:, scene.h's
 * first line).  "*", a backslash (or ??/), a newline, "/" is no "*" "/"
 * there, but lines are spliced before comments end: the comment ended,
 * the rest of the name was compiled, and the C did not build (with
 * --no-sweep exit 0; a chosen name could put code in it). */
static void test_names_in_comments(void **st)
{
    (void)st;
    new_scratch();
    const char *dirs[] = {"d*\\\n", "e*?\?/\n", "f/\\\n"};
    char p[600], o[1300];
    for (size_t i = 0; i < sizeof dirs / sizeof dirs[0]; i++) {
        /* every directory on the way ("e*??" holds "\n") */
        snprintf(p, sizeof p, "%s/%s", scratch, dirs[i]);
        for (char *s = p + strlen(scratch) + 1;; s++)
            if (*s == '/' || !*s) {
                char c = *s;
                *s = 0;
                assert_true(mkdir(p, 0777) == 0 || errno == EEXIST);
                if (!(*s = c))
                    break;
            }
        snprintf(o, sizeof o, "%s/*x.c", dirs[i]);
        GEN("--func", "log", "--variant", "fast", "--no-sweep", "-o", o);
        assert_int_equal(R.status, 0);
        if (syntax_ok(o) == 127) {
            print_message("  (no cc: skipped)\n");
            tu_rm_tree(scratch);
            return;
        }
        assert_int_equal(R.status, 0);
        /* the scene file's own name, and the fixed-point generator's comment */
        snprintf(o, sizeof o, "%s/s.scene", dirs[i]);
        puts_file(o, cheap_scene);
        snprintf(p, sizeof p, "%sout", dirs[i]);
        GEN("--scene", o, "-o", p, "--prefix", "s_");
        assert_int_equal(R.status, 0);
        snprintf(o, sizeof o, "%s/scene.h", p);
        assert_int_equal(syntax_ok(o), 0);
        snprintf(o, sizeof o, "%s/s_sqrt_u8_8_u8_8.c", p);
        assert_int_equal(syntax_ok(o), 0);
    }
    tu_rm_tree(scratch);
}

/* A scene's DIR/NAME.c that is a directory (or read-only, or the scene
 * file) is known from the scene's line: exit 2 before any fit, as for
 * scene.h and report.txt; it was exit 1 after all of them. */
static void test_scene_entry_file_first(void **st)
{
    (void)st;
    new_scratch();
    puts_file("s.scene", cheap_scene);
    char p[600];
    snprintf(p, sizeof p, "%s/out", scratch);
    assert_int_equal(mkdir(p, 0777), 0);
    snprintf(p, sizeof p, "%s/out/s_sqrt_u8_8_u8_8.c", scratch);
    assert_int_equal(mkdir(p, 0777), 0);
    GEN("--scene", "s.scene", "-o", "out");
    expect2();
    assert_non_null(strstr(R.err, "is a directory"));
    assert_int_equal(kind("out/s_sqrt_u8_8_u8_8.c"), S_IFDIR);
    assert_false(exists("out/scene.h"));
    tu_rm_tree(scratch);
}

/* --plot /dev/full -o a.c: the plot fails (ENOSPC) and the run says 1, and
 * a.c keeps what it held: it was renamed into place first.  A device is
 * written before any rename (pf_out_commit_all). */
static void test_device_fails_first(void **st)
{
    (void)st;
    if (!have_gnuplot() || access("/dev/full", W_OK) != 0) {
        print_message("  (no gnuplot or /dev/full: skipped)\n");
        return;
    }
    new_scratch();
    puts_file("a.c", "the user's a.c\n");
    GEN("--func", "log", "--variant", "fast", "--no-sweep", "--plot", "/dev/full", "-o", "a.c");
    print_message("  -> %d: %s", R.status, R.err);
    assert_int_equal(R.status, 1);
    assert_non_null(strstr(R.err, "/dev/full"));
    char *m = get("a.c");
    assert_string_equal(m, "the user's a.c\n");
    free(m);
    /* the same through a link in a scene's DIR: nothing renamed there */
    puts_file("s.scene", cheap_scene);
    char p[600];
    snprintf(p, sizeof p, "%s/out", scratch);
    assert_int_equal(mkdir(p, 0777), 0);
    puts_file("out/scene.h", "the user's scene.h\n");
    snprintf(p, sizeof p, "%s/out/report.txt", scratch);
    assert_int_equal(symlink("/dev/full", p), 0);
    GEN("--scene", "s.scene", "-o", "out");
    print_message("  -> %d: %s", R.status, R.err);
    assert_int_equal(R.status, 1);
    m = get("out/scene.h");
    assert_string_equal(m, "the user's scene.h\n");
    free(m);
    assert_int_equal(count_c("out"), 0);
    tu_rm_tree(scratch);
}

/* pfmathgen -o /dev/stdout | less: /proc/self/fd/1 of a pipe reads
 * "pipe:[N]", which the link-by-link resolution took as a name and
 * failed on after the fit (exit 1, "No such file or directory"); a shell's
 * "> /dev/stdout" writes the pipe. */
static void test_dev_stdout_pipe(void **st)
{
    (void)st;
    new_scratch();
    char prog[PATH_MAX];
    tu_prog_path("pfmathgen", prog, sizeof prog);
    int fd[2];
    assert_int_equal(pipe(fd), 0);
    pid_t pid = fork();
    if (pid == 0) {
        int dn = open("/dev/null", O_WRONLY);
        dup2(fd[1], 1);
        dup2(dn, 2);
        close(fd[0]);
        execl(prog, prog, "--func", "log", "--variant", "fast", "--no-sweep", "-o", "/dev/stdout", (char *)NULL);
        _exit(127);
    }
    close(fd[1]);
    static char buf[1 << 17];
    size_t n = 0;
    for (ssize_t k; n < sizeof buf - 1 && (k = read(fd[0], buf + n, sizeof buf - 1 - n)) > 0;)
        n += (size_t)k;
    buf[n] = 0;
    close(fd[0]);
    int stt = 0;
    assert_int_equal(waitpid(pid, &stt, 0), pid);
    print_message("  -> %d, %zu bytes\n", WIFEXITED(stt) ? WEXITSTATUS(stt) : -1, n);
    assert_true(WIFEXITED(stt));
    assert_int_equal(WEXITSTATUS(stt), 0);
    assert_non_null(strstr(buf, "Generated by pfmathgen"));
    tu_rm_tree(scratch);
}

/* -o NAME of 255 bytes (NAME_MAX) is a name "> NAME" writes; the temporary
 * ".NAME.XXXXXX" beside it was 263, so the run failed (exit 1) after the
 * whole fit.  One byte more is refused before it (exit 2). */
static void test_longest_name(void **st)
{
    (void)st;
    new_scratch();
    char name[300];
    memset(name, 'n', 253);
    strcpy(name + 253, ".c");
    GEN("--func", "log", "--variant", "fast", "--no-sweep", "-o", name);
    print_message("  -> %d: %.80s", R.status, R.err + (strlen(R.err) > 80 ? strlen(R.err) - 80 : 0));
    assert_int_equal(R.status, 0);
    char *c = get(name);
    assert_non_null(c);
    assert_non_null(strstr(c, "Generated by pfmathgen"));
    free(c);
    strcpy(name + 253, "n.c");
    GEN("--func", "log", "--variant", "fast", "--no-sweep", "-o", name);
    expect2();
    /* nothing but the one file was left */
    DIR *d = opendir(scratch);
    int n = 0;
    for (struct dirent *e; (e = readdir(d));)
        n += strcmp(e->d_name, ".") && strcmp(e->d_name, "..");
    closedir(d);
    assert_int_equal(n, 1);
    tu_rm_tree(scratch);
}

/* open file descriptors of this process */
static int open_fds(void)
{
    DIR *d = opendir("/proc/self/fd");
    assert_non_null(d);
    int n = 0;
    for (struct dirent *e; (e = readdir(d));)
        n += e->d_name[0] != '.';
    closedir(d);
    return n;
}

/* pf_compile_load (gen/front/compile.c) when the source cannot be
   written (a file size limit stands in for a full /tmp): NULL and one
   message, and the stream closed all the same (before the fix a short
   fwrite skipped the fclose, and each such call kept a descriptor open) */
static void test_compile_load_short_write(void **st)
{
    (void)st;
    int fds = open_fds();
    struct rlimit old;
    assert_int_equal(getrlimit(RLIMIT_FSIZE, &old), 0);
    void (*prev)(int) = signal(SIGXFSZ, SIG_IGN);
    struct rlimit lim = old;
    lim.rlim_cur = 4096;
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &lim), 0);
    size_t len = 1 << 16;
    char *src = malloc(len);
    assert_non_null(src);
    memset(src, ' ', len);
    char err[256] = "";
    void *h = pf_compile_load(src, len, err, sizeof err);
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &old), 0);
    signal(SIGXFSZ, prev);
    free(src);
    assert_null(h);
    print_message("pf_compile_load under a 4 kB file size limit: %s; open descriptors %d -> %d\n", err, fds,
                  open_fds());
    assert_non_null(strstr(err, "cannot write"));
    assert_int_equal(open_fds(), fds);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_item1_scene_keeps_dir),
        cmocka_unit_test(test_item2_trailing_slash),
        cmocka_unit_test(test_item3_links_and_fifos),
        cmocka_unit_test(test_item4_no_injection),
        cmocka_unit_test(test_item5_long_lines),
        cmocka_unit_test(test_item9_fast_refusals),
        cmocka_unit_test(test_item10_outputs_first),
        cmocka_unit_test(test_item13_scene_links_with_libpfmath),
        cmocka_unit_test(test_same_file_two_names),
        cmocka_unit_test(test_scene_default_prefix_pf),
        cmocka_unit_test(test_scene_file_not_replaced),
        cmocka_unit_test(test_read_only_target),
        cmocka_unit_test(test_scene_editor_files),
        cmocka_unit_test(test_names_in_comments),
        cmocka_unit_test(test_longest_name),
        cmocka_unit_test(test_scene_entry_file_first),
        cmocka_unit_test(test_device_fails_first),
        cmocka_unit_test(test_dev_stdout_pipe),
        cmocka_unit_test(test_sticky_dir),
        cmocka_unit_test(test_output_is_std_stream),
        cmocka_unit_test(test_compile_load_short_write),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
