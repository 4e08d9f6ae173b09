/* Bit-identical whatever the flags: every 16-bit function of the library's
 * fixed-point set (libpfmath/generated/pf_fx_*.c) is compiled here with
 * several flag sets, from -O0 to -O3 -march=native (vectorized, the widest
 * SIMD the machine has) and -ffast-math, and the full output table of its
 * scalar and array forms is hashed: all builds and both forms must agree
 * (the array form called on pieces of varied lengths, so that the ends of
 * its vector loops run too: the whole table alone, 2^16 values, is a
 * multiple of every block), and called in place (y == x) as well.
 * The -O0 table is also swept against MPFR (exact: below 1 LSB; fast: its
 * bound), so every build is within bound.  The one golden hash is derived,
 * not recorded: the exact sqrt's table must hash like the table of
 * pffixed.h's correctly rounded pf_fx_sqrt.  "-U__GNUC__" builds the plain-C
 * fallbacks of the 16-bit lane helpers (other compilers' path).
 * test_lanes16: the functions emitted in 16-bit lanes really run in them:
 * built with gcc -O3 -march=x86-64-v3, their array loop holds at least one
 * vpmulhrsw per pf_fx_mulhrs of the source (GCC finds the rounding
 * multiply-high only under the conditions fx_tail16.c.in describes); built
 * with -march=x86-64-v4 (the AVX-512 loop, bw = 1), at least one on zmm
 * registers (32 lanes) per pf_fx_mulhrs; a register-table kernel (sin/cos
 * with vpermw lookups) is checked in its AVX-512BW intrinsics loop instead. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "funcset.h"
#include "pffixed.h"
#include "sweep_fixed.h"
#include "tu_exec.h"

#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

typedef struct {
    const char *stem; /* pf_<stem>: libpfmath/generated/pf_fx_<stem>.c */
    pf_func f;
    pf_fmt in, out;
} hfn;

/* the PF_FIXED rows of libpfmath/functions.def whose input is 16-bit (their
   whole table is 2^16 values); 32-bit inputs expand to nothing */
#define HASH_ROW_i16(n, id, isg, isz, ie, osg, osz, oe) {#n, id, PF_FS_FMT(isg, isz, ie), PF_FS_FMT(osg, osz, oe)},
#define HASH_ROW_u16 HASH_ROW_i16
#define HASH_ROW_i32(n, id, isg, isz, ie, osg, osz, oe)
#define HASH_ROW_u32 HASH_ROW_i32
static const hfn fns[] = {
#define PF_FIXED(n, f, id, ist, isg, isz, ie, ost, osg, osz, oe, lsb, lo, hi)                                  \
    HASH_ROW_##ist(n, id, isg, isz, ie, osg, osz, oe)
#include "functions.def"
};
#define NFNS ((int)(sizeof fns / sizeof fns[0]))

/* compiler ("" = $CC or cc) and flags; clang's rows run when it is installed */
static const char *const flagsets[][2] = {
    {"", "-O0"}, {"", "-O1 -fno-inline"}, {"", "-O2 -ffast-math"}, {"", "-Os -fno-tree-vectorize"},
    {"", "-O3 -march=native"}, {"clang", "-O0"}, {"clang", "-O3 -march=native -ffast-math"},
    {"", "-O2 -U__GNUC__"}, {"", "-O2 -DPF_FX_TEST_AVX2"}, /* the AVX2 loops of the table kernels */
};
#define NFLAGS ((int)(sizeof flagsets / sizeof flagsets[0]))

static char root[PATH_MAX];

/* the repository: the current directory, or above the test program */
static int find_root(void)
{
    struct stat sb;
    if (stat("libpfmath/generated", &sb) == 0) {
        snprintf(root, sizeof root, ".");
        return 0;
    }
    char self[PATH_MAX];
    ssize_t k = readlink("/proc/self/exe", self, sizeof self - 1);
    if (k <= 0)
        return -1;
    self[k] = 0;
    for (int up = 0; up < 6; up++) {
        char *s = strrchr(self, '/');
        if (!s)
            return -1;
        *s = 0;
        char p[PATH_MAX + 32];
        snprintf(p, sizeof p, "%s/libpfmath/generated", self);
        if (stat(p, &sb) == 0) {
            snprintf(root, sizeof root, "%s", self);
            return 0;
        }
    }
    return -1;
}

static uint64_t fnv(uint64_t h, int64_t v)
{
    uint32_t u = (uint32_t)v;
    for (int i = 0; i < 4; i++) {
        h ^= (u >> (8 * i)) & 0xff;
        h *= 0x100000001b3ull;
    }
    return h;
}

static void *build(const char *src, const char *compiler, const char *flags, const char *so)
{
    tu_argv *a = calloc(1, sizeof *a);
    tu_run_result *r = malloc(sizeof *r);
    assert_non_null(a);
    assert_non_null(r);
    if (*compiler)
        tu_argv_add(a, compiler);
    else
        tu_argv_cc(a);
    tu_argv_words(a, "-std=c17 -Wall -Wextra -Werror");
    tu_argv_words(a, flags);
    tu_argv_words(a, "-fPIC -shared -o");
    tu_argv_add(a, so);
    tu_argv_add(a, src);
    tu_execvp_in(NULL, a->v, r);
    int st = r->status;
    if (st != 0)
        print_message("failed (exit %d): %s %s %s\n%s%s", st, a->v[0], flags, src, r->out, r->err);
    free(a);
    free(r);
    if (st != 0)
        return NULL;
    void *h = dlopen(so, RTLD_NOW | RTLD_LOCAL);
    unlink(so);
    return h;
}

/* hash of the scalar form's and the array form's full tables; the array
   form is called on pieces of the table whose lengths run through the ends
   of its loops (blocks of 16 or 32 lanes, pairs and fours of them, the one
   block and the scalar elements left over), then once on the rest */
static void tables(const pf_fx_fn *fn, int64_t *ys, int64_t *ya, uint64_t *hs, uint64_t *ha, uint64_t *hp)
{
    static const int64_t piece[] = {1, 15, 16, 17, 31, 32, 33, 47, 48, 63, 64, 65, 79, 95, 96, 97, 127, 129, 1000};
    int64_t lo = pf_fmt_min_stored(fn->in), hi = pf_fmt_max_stored(fn->in), n = hi - lo + 1;
    int64_t *x = malloc(sizeof(int64_t) * (size_t)n);
    for (int64_t i = 0; i < n; i++) {
        x[i] = lo + i;
        ys[i] = pf_fx_call_scalar(fn, x[i]);
    }
    int64_t at = 0;
    for (size_t k = 0; k < sizeof piece / sizeof piece[0] && at + piece[k] <= n; k++) {
        pf_fx_call_array(fn, x + at, ya + at, (size_t)piece[k]);
        at += piece[k];
    }
    pf_fx_call_array(fn, x + at, ya + at, (size_t)(n - at));
    *hs = *ha = *hp = 0xcbf29ce484222325ull;
    for (int64_t i = 0; i < n; i++) {
        *hs = fnv(*hs, ys[i]);
        *ha = fnv(*ha, ya[i]);
    }
    /* and in place (y == x, as pfmath_fixed.h allows), in pieces of the
       same lengths (at most 256 a call: pf_fx_call_array_inplace's buffer) */
    at = 0;
    for (size_t k = 0; at < n; k = (k + 1) % (sizeof piece / sizeof piece[0])) {
        int64_t m = piece[k] < 256 ? piece[k] : 256;
        m = m < n - at ? m : n - at;
        if (!pf_fx_call_array_inplace(fn, x + at, ya + at, (size_t)m))
            break;
        at += m;
    }
    for (int64_t i = 0; i < n; i++)
        *hp = fnv(*hp, ya[i]);
    free(x);
}

static void test_flags(void **st)
{
    (void)st;
    assert_int_equal(find_root(), 0);
    tu_run_result *cr = malloc(sizeof *cr);
    assert_non_null(cr);
    tu_runl_cmd(cr, "clang", "--version", NULL); /* output kept from the log */
    int have_clang = cr->status == 0;
    free(cr);
    if (!have_clang)
        print_message("clang not found: gcc builds only\n");
    char dir[] = "/tmp/pf-fxhash-XXXXXX";
    assert_non_null(mkdtemp(dir));
    int bad = 0;
    for (int i = 0; i < NFNS; i++) {
        for (int fast = 0; fast <= 1; fast++) {
            const hfn *F = &fns[i];
            char src[PATH_MAX + 64], so[96], sym[96], asym[112];
            snprintf(src, sizeof src, "%s/libpfmath/generated/pf_fx_%s%s.c", root, F->stem, fast ? "_fast" : "");
            snprintf(sym, sizeof sym, "pf_%s%s", F->stem, fast ? "_fast" : "");
            snprintf(asym, sizeof asym, "%s_array", sym);
            uint64_t h0 = 0;
            int64_t n = pf_fmt_max_stored(F->in) - pf_fmt_min_stored(F->in) + 1;
            int64_t *ys = malloc(sizeof(int64_t) * (size_t)n), *ya = malloc(sizeof(int64_t) * (size_t)n);
            for (int k = 0; k < NFLAGS; k++) {
                if (*flagsets[k][0] && !have_clang)
                    continue;
#if defined(__SANITIZE_ADDRESS__)
                /* the sanitized copy of this test compiles the same code:
                   only the two ends of the flag range */
                if (k != 0 && k != 4)
                    continue;
#endif
                snprintf(so, sizeof so, "%s/f%d.so", dir, k);
                void *h = build(src, flagsets[k][0], flagsets[k][1], so);
                assert_non_null(h);
                pf_fx_fn fn = {dlsym(h, sym), dlsym(h, asym), F->in, F->out};
                assert_non_null(fn.scalar);
                assert_non_null(fn.array);
                uint64_t hs, ha, hp;
                tables(&fn, ys, ya, &hs, &ha, &hp);
                char fl[80];
                snprintf(fl, sizeof fl, "%s%s%s", flagsets[k][0], *flagsets[k][0] ? " " : "", flagsets[k][1]);
                print_message("%-24s %-36s scalar %016llx array %016llx\n", sym, fl, (unsigned long long)hs,
                              (unsigned long long)ha);
                if (k == 0) {
                    h0 = hs;
                    /* within bound (so every build with the same hash is too) */
                    pf_fx_stats s;
                    pf_fx_stats_init(&s);
                    for (int64_t j = 0; j < n; j++)
                        pf_fx_stats_add(&s, F->f, F->in, F->out, pf_fmt_min_stored(F->in) + j, ys[j]);
                    if (fast ? s.over_fast != 0 : !(s.max_err < 1)) {
                        print_message("FAILED: %s -O0 max %.4f LSB\n", sym, s.max_err);
                        bad++;
                    }
                    if (F->f == PF_SQRT && !fast) {
                        uint64_t hr = 0xcbf29ce484222325ull;
                        for (int64_t j = 0; j < n; j++)
                            hr = fnv(hr, pf_fx_sqrt(pf_fmt_min_stored(F->in) + j, F->in, F->out));
                        print_message("%-24s %-36s scalar %016llx\n", sym, "pffixed.h pf_fx_sqrt", (unsigned long long)hr);
                        if (hr != hs) {
                            print_message("FAILED: %s is not the correctly rounded table\n", sym);
                            bad++;
                        }
                    }
                }
                if (hs != h0 || ha != h0) {
                    print_message("FAILED: %s with %s differs from -O0\n", sym, fl);
                    bad++;
                }
                if (hp != h0) {
                    print_message("FAILED: %s_array with %s in place (y == x) differs: %016llx\n", sym, fl,
                                  (unsigned long long)hp);
                    bad++;
                }
                dlclose(h);
            }
            free(ys);
            free(ya);
        }
    }
    rmdir(dir);
    assert_int_equal(bad, 0);
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *b = malloc((size_t)n + 1);
    if (b && fread(b, 1, (size_t)n, f) != (size_t)n) {
        free(b);
        b = NULL;
    }
    if (b)
        b[n] = 0;
    fclose(f);
    return b;
}

static int count(const char *a, const char *end, const char *needle)
{
    int c = 0;
    size_t l = strlen(needle);
    for (const char *p = strstr(a, needle); p && p < end; p = strstr(p + l, needle))
        c++;
    return c;
}

/* lines between a and end holding both needles (an instruction and an operand) */
static int count_line(const char *a, const char *end, const char *insn, const char *reg)
{
    int c = 0;
    for (const char *p = strstr(a, insn); p && p < end; p = strstr(p + 1, insn)) {
        const char *nl = strchr(p, '\n');
        size_t len = nl ? (size_t)(nl - p) : strlen(p);
        const char *r = strstr(p, reg);
        if (r && (size_t)(r - p) < len)
            c++;
    }
    return c;
}

/* the compiler's assembly of src (flags ending in "-S -o") as dir/f.s, read
   back; as receives the path */
static char *asm_of(const char *dir, const char *flags, const char *src, char *as, size_t asz)
{
    snprintf(as, asz, "%s/f.s", dir);
    tu_argv *av = calloc(1, sizeof *av);
    tu_run_result *r = malloc(sizeof *r);
    assert_non_null(av);
    assert_non_null(r);
    tu_argv_cc(av);
    tu_argv_words(av, flags);
    tu_argv_add(av, as);
    tu_argv_add(av, src);
    tu_execvp_in(NULL, av->v, r);
    if (r->status != 0)
        print_message("%s -S %s: exit %d\n%s%s", av->v[0], src, r->status, r->out, r->err);
    assert_int_equal(r->status, 0);
    free(av);
    free(r);
    char *a = slurp(as);
    assert_non_null(a);
    return a;
}

static void test_lanes16(void **st)
{
    (void)st;
#if defined(__x86_64__)
    assert_int_equal(find_root(), 0);
    char dir[] = "/tmp/pf-fxlanes-XXXXXX";
    assert_non_null(mkdtemp(dir));
    int bad = 0, n16 = 0;
    for (int i = 0; i < NFNS; i++)
        for (int fast = 0; fast <= 1; fast++) {
            char src[PATH_MAX + 64], as[PATH_MAX], sym[112];
            snprintf(src, sizeof src, "%s/libpfmath/generated/pf_fx_%s%s.c", root, fns[i].stem, fast ? "_fast" : "");
            char *c = slurp(src);
            assert_non_null(c);
            const char *body = strstr(c, "_inline(");
            int calls = body ? count(body, body + strlen(body), "pf_fx_mulhrs(") : 0;
            /* the table kernels (exp/exp2: fixed_exp.c, fixed_exp16f.c) have no
               multiply-high to count: their AVX-512BW loop (intrinsics, built
               without -march as the library is) must hold one zmm vpermw or
               vpermi2w/vpermt2w per lookup of the source */
            int looks = count(c, c + strlen(c), "_mm512_permutexvar_epi16(") +
                        count(c, c + strlen(c), "_mm512_permutex2var_epi16(");
            if (strstr(c, "16-bit lanes") && !calls && looks) {
                n16++;
                char *a = asm_of(dir, "-std=c17 -O3 -S -o", src, as, sizeof as);
                snprintf(sym, sizeof sym, "pf_%s%s_array_bw:", fns[i].stem, fast ? "_fast" : "");
                const char *f = strstr(a, sym), *e = f ? strstr(f, ".size") : NULL;
                int got = f && e ? count_line(f, e, "vpermw", "%zmm") + count_line(f, e, "vpermi2w", "%zmm") +
                                     count_line(f, e, "vpermt2w", "%zmm")
                                 : 0;
                print_message("%-28s %d table lookups in the source, %d zmm vpermw/vpermi2w/vpermt2w in the AVX-512 loop\n", sym, looks,
                              got);
                if (got < looks) {
                    print_message("FAILED: %s does not look up its tables in zmm registers\n", sym);
                    bad++;
                }
                unlink(as);
                free(a);
            }
            if (!strstr(c, "16-bit lanes") || !calls) {
                free(c);
                continue;
            }
            n16++;
            /* a register-table kernel (exact sin/cos, kind 4: vpermw/vpermi2w) runs
               its AVX-512BW loop by intrinsics, which the library's baseline
               build dispatches to: that loop (-O3, no -march) must hold one
               zmm vpmulhrsw per pf_fx_mulhrs; its plain-C form (other
               clones, -march builds) loads the tables as 32-bit gathers */
            int tab = strstr(c, "_mm512_permutex") != NULL; /* vpermw, vpermi2w */
            for (int v4 = tab; v4 <= 1; v4++) {
                char *a = asm_of(dir, tab  ? "-std=c17 -O3 -S -o"
                                      : v4 ? "-std=c17 -O3 -march=x86-64-v4 -S -o"
                                           : "-std=c17 -O3 -march=x86-64-v3 -S -o",
                                 src, as, sizeof as);
                snprintf(sym, sizeof sym, "pf_%s%s_array%s:", fns[i].stem, fast ? "_fast" : "", tab ? "_bw" : "");
                const char *f = strstr(a, sym), *e = f ? strstr(f, ".size") : NULL;
                int got = f && e ? (v4 ? count_line(f, e, "vpmulhrsw", "%zmm") : count(f, e, "vpmulhrsw")) : 0;
                print_message("%-28s %d pf_fx_mulhrs in the source, %d vpmulhrsw%s in the array loop (x86-64-%s)\n",
                              sym, calls, got, v4 ? " on zmm" : "", tab ? "v4 intrinsics" : v4 ? "v4" : "v3");
                if (got < calls) {
                    print_message("FAILED: %s does not run in 16-bit lanes\n", sym);
                    bad++;
                }
                unlink(as);
                free(a);
            }
            free(c);
        }
    rmdir(dir);
    assert_int_equal(bad, 0);
    assert_true(n16 >= 7); /* every fast 16-bit function at least */
#else
    skip();
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_flags),
        cmocka_unit_test(test_lanes16),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
