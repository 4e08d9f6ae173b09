/* Directed special values (tests/special/NAME.txt), run against every variant
 * of every function the library has: exact (pf_<f>f) and fast (pf_<f>f_fast). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "testutil.h"

#include <dirent.h>
#include <dlfcn.h>
#include <math.h>
#include <stdint.h>

static void *lib;

static float asf(uint32_t u) { float f; memcpy(&f, &u, 4); return f; }
static uint32_t asu(float f) { uint32_t u; memcpy(&u, &f, 4); return u; }

static int run_file(const char *path, int *checked)
{
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char line[512];
    int bad = 0, ln = 0;
    while (fgets(line, sizeof line, f)) {
        ln++;
        char *h = strchr(line, '#');
        if (h)
            *h = 0;
        char fn[32];
        unsigned a, b, c;
        int n = sscanf(line, "%31s %x %x %x", fn, &a, &b, &c);
        if (n < 3)
            continue;
        int binary = n == 4;
        uint32_t want = binary ? c : b;
        for (int v = 0; v < 2; v++) {
            char sym[64];
            snprintf(sym, sizeof sym, "pf_%sf%s", fn, v ? "_fast" : "");
            void *p = dlsym(lib, sym);
            if (!p) {
                print_message("%s:%d: %s missing from libpfmath\n", path, ln, sym);
                bad++;
                continue;
            }
            float got;
            if (binary) {
                float (*f2)(float, float);
                *(void **)&f2 = p;
                got = f2(asf(a), asf(b));
            } else {
                float (*f1)(float);
                *(void **)&f1 = p;
                got = f1(asf(a));
            }
            int ok = isnan(asf(want)) ? isnan(got) : asu(got) == want;
            if (!ok) {
                print_message("%s:%d: %s(0x%08x%s) = 0x%08x, want 0x%08x\n", path, ln, sym, a,
                              binary ? ", ..." : "", asu(got), want);
                bad++;
            }
            (*checked)++;
        }
    }
    fclose(f);
    return bad;
}

static void test_special_tables(void **st)
{
    (void)st;
    char dir[4096];
    tu_prog_path("../../tests/special", dir, sizeof dir);
    DIR *d = opendir(dir);
    if (!d) {
        tu_prog_path("../tests/special", dir, sizeof dir);
        d = opendir(dir);
    }
    if (!d) {
        snprintf(dir, sizeof dir, "tests/special");
        d = opendir(dir);
    }
    assert_non_null(d);
    struct dirent *e;
    int bad = 0, checked = 0;
    while ((e = readdir(d))) {
        size_t l = strlen(e->d_name);
        if (l < 5 || strcmp(e->d_name + l - 4, ".txt"))
            continue;
        char p[8192];
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        bad += run_file(p, &checked);
    }
    closedir(d);
    print_message("%d special cases checked, %d wrong\n", checked, bad);
    assert_true(checked > 0);
    assert_int_equal(bad, 0);
}

static int setup(void **st)
{
    (void)st;
    char p[4096];
    tu_prog_path("libpfmath.so", p, sizeof p);
    lib = dlopen(p, RTLD_NOW);
    return lib ? 0 : -1;
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_special_tables)};
    return cmocka_run_group_tests(tests, setup, NULL);
}
