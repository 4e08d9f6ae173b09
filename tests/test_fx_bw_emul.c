/* The AVX-512BW loops (<name>_array_bw) of the 16-bit functions, run on
 * any x86-64 through SIMDe: on a CPU without AVX-512 (this project's
 * machines and CI) the library's dispatch never takes them, so nothing
 * else would see a wrong one.
 *
 * mk/emul.mk turns every libpfmath/generated/ file that has an _array_bw
 * into build/emul/<file>.c (tests/emul.sed: the v4 functions' intrinsics
 * and types get SIMDe's names, its target attribute goes; the exported
 * names become pf_emu_<name>), appends an entry pf_emu_bw_<name>(x, y, n)
 * calling the static loop, compiles each alone (their static helpers share
 * names) with tests/simde_fill.h (SIMDe plus the intrinsics it lacks), and
 * lists them in build/emul/emul_list.h as PF_EMU(name, input, output),
 * parsed from the loop's signature: a new 16-bit function with such a loop
 * is tested without an edit here.
 *
 * Per function (one cmocka test each, named after it):
 *   - the transformed file's scalar form equals the library's (pf_<name>
 *     from libpfmath.a) on all 2^16 inputs (the transform left it alone);
 *   - the emulated _array_bw gives the scalar form's bits on all 2^16
 *     inputs; for a loop that uses vrsqrt14ps (the 16-bit sqrt) under each
 *     of the fill's in-spec approximations (nearest, truncated, high and
 *     low by nearly 2^-14), as the clones must be bit-identical on any CPU;
 *   - n = 0..100 and around multiples of 32 and 128 (the loops step by 32
 *     or 128, software pipelined, the tail in the scalar form), x and y
 *     each ending where an inaccessible page begins (a read or write past
 *     the end crashes the test; the start's alignment varies with n), a
 *     sentinel before y; and each length again in place (y == x, which
 *     pfmath_fixed.h allows).
 * Not in the sanitized tree (Makefile's ASAN_SAME): instrumenting SIMDe's
 * inlined lane loops costs about 25 s more CPU to compile, the guard pages
 * catch what ASan would here, and UBSan stops in SIMDe's own code (0.7.4's
 * simde_mm512_add_epi16 adds int16_t vectors, whose overflow it reports).
 * And the fills themselves (tests/simde_fill.h) and the SIMDe intrinsics
 * the loops lean on most, against the native AVX2 instruction on each
 * 256-bit half where one exists, else against Intel's definition, on edge
 * and random values: a wrong emulation fails there, not as a wrong loop.
 * The native checks skip on a CPU without AVX2 and FMA.  test_fixedgen_funcs
 * runs the loops of the other type pairs it emits the same way (through
 * tests/emul.sed and this build's precompiled header). */
#include "simde_fill.h" /* first: mk/emul.mk precompiles it */

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "pfmath_fixed.h"

#include <immintrin.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

int pf_emu_rsqrt14_mode = PF_EMU_RSQRT14_NEAR;
unsigned long pf_emu_rsqrt14_calls;

static const char *const rsqrt14_names[PF_EMU_RSQRT14_MODES] = {"nearest", "truncated", "high", "low"};

typedef void (*bw_fn)(const void *x, void *y, size_t n);
typedef uint16_t (*scalar_fn)(uint16_t x); /* stored bits in and out */

/* the emulated loop against the scalar form on all 2^16 inputs (mode: the
   vrsqrt14ps emulation in use, for the message); the number of mismatches
   (the first few printed) */
static long sweep_all(const char *name, bw_fn bw, const uint16_t *ref, int mode)
{
    static uint16_t in[65536], out[65536];
    for (int i = 0; i < 65536; i++)
        in[i] = (uint16_t)i;
    memset(out, 0, sizeof out);
    bw(in, out, 65536);
    char how[64] = "emulated";
    if (mode != PF_EMU_RSQRT14_NEAR)
        snprintf(how, sizeof how, "emulated, vrsqrt14ps %s", rsqrt14_names[mode]);
    long bad = 0;
    for (int i = 0; i < 65536; i++)
        if (out[i] != ref[i] && bad++ < 5)
            print_message("%s_array_bw (%s): x = %d (0x%04x): 0x%04x, scalar form 0x%04x\n", name, how, i, i, out[i],
                          ref[i]);
    if (bad)
        print_message("%s_array_bw (%s): %ld of 65536 inputs differ\n", name, how, bad);
    return bad;
}

/* a buffer of n words that ends where an inaccessible page begins: a read
   or write past its end is a SIGSEGV (a failed test) in any build; one
   word before it is kept for a sentinel.  Its start's alignment varies
   with n (the end is page aligned). */
typedef struct {
    uint16_t *p;
    void *map;
    size_t len;
} guarded;

static guarded guarded_words(size_t n)
{
    size_t pg = (size_t)sysconf(_SC_PAGESIZE), data = ((n + 1) * 2 + pg - 1) / pg * pg;
    guarded g = {NULL, mmap(NULL, data + pg, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0), data + pg};
    assert_true(g.map != MAP_FAILED);
    assert_int_equal(mprotect((char *)g.map + data, pg, PROT_NONE), 0);
    g.p = (uint16_t *)((char *)g.map + data) - n;
    return g;
}

/* a fault in a guarded run names its length, then goes to cmocka's handler
   (which fails the test and runs the next) */
static void (*segv_prev)(int);
static const char *segv_name;
static size_t segv_n;
static void on_segv(int sig)
{
    char m[160];
    int k = snprintf(m, sizeof m, "%s_array_bw (emulated): n = %zu reads or writes past the end of x or y\n", segv_name,
                     segv_n);
    if (write(STDOUT_FILENO, m, (size_t)k) < 0) { /* nothing more to do */
    }
    signal(SIGSEGV, segv_prev);
    if (segv_prev != SIG_DFL && segv_prev != SIG_IGN && segv_prev != SIG_ERR)
        segv_prev(sig);
    else
        raise(sig);
}

/* n elements, inputs p, p + 1, ... (mod 2^16), x and y each ending at a
   guard page; 0 when the output is the scalar form's and y[-1] is
   untouched, out of place and in place (verbose: print the first wrong
   element) */
static long run_len(const char *name, bw_fn bw, const uint16_t *ref, size_t n, size_t p, int verbose)
{
    const uint16_t sentinel = 0xa55a;
    guarded xg = guarded_words(n), yg = guarded_words(n);
    for (size_t i = 0; i < n; i++) {
        xg.p[i] = (uint16_t)(p + i);
        yg.p[i] = sentinel;
    }
    yg.p[-1] = sentinel;
    segv_name = name, segv_n = n;
    segv_prev = signal(SIGSEGV, on_segv);
    bw(xg.p, yg.p, n);
    signal(SIGSEGV, segv_prev);
    long bad = 0;
    for (size_t i = 0; i < n; i++)
        if (yg.p[i] != ref[(p + i) & 0xffff] && bad++ < verbose)
            print_message("%s_array_bw (emulated): n = %zu, element %zu (x = 0x%04zx): 0x%04x, scalar form 0x%04x\n",
                          name, n, i, (p + i) & 0xffff, yg.p[i], ref[(p + i) & 0xffff]);
    if (yg.p[-1] != sentinel) {
        if (verbose)
            print_message("%s_array_bw (emulated): n = %zu wrote y[-1]\n", name, n);
        bad++;
    }
    /* in place (y == x, as pfmath_fixed.h allows): the same bits */
    segv_prev = signal(SIGSEGV, on_segv);
    bw(xg.p, xg.p, n);
    signal(SIGSEGV, segv_prev);
    for (size_t i = 0; i < n; i++)
        if (xg.p[i] != ref[(p + i) & 0xffff] && bad++ < verbose)
            print_message("%s_array_bw (emulated) in place: n = %zu, element %zu (x = 0x%04zx): 0x%04x, scalar form 0x%04x\n",
                          name, n, i, (p + i) & 0xffff, xg.p[i], ref[(p + i) & 0xffff]);
    munmap(xg.map, xg.len);
    munmap(yg.map, yg.len);
    return bad;
}

static void check_bw(const char *name, bw_fn bw, scalar_fn emu_scalar, scalar_fn lib_scalar)
{
    static uint16_t ref[65536];
    long bad = 0;
    /* the reference: the transformed file's scalar form, which must be the library's */
    for (int i = 0; i < 65536; i++) {
        ref[i] = emu_scalar((uint16_t)i);
        uint16_t l = lib_scalar((uint16_t)i);
        if (ref[i] != l && bad++ < 5)
            print_message("%s (transformed file) x = 0x%04x: 0x%04x, libpfmath 0x%04x\n", name, i, ref[i], l);
    }
    /* every input; every vrsqrt14ps approximation if the loop uses it */
    pf_emu_rsqrt14_mode = PF_EMU_RSQRT14_NEAR;
    pf_emu_rsqrt14_calls = 0;
    bad += sweep_all(name, bw, ref, PF_EMU_RSQRT14_NEAR);
    int uses_rsqrt14 = pf_emu_rsqrt14_calls != 0;
    for (int m = 1; uses_rsqrt14 && m < PF_EMU_RSQRT14_MODES; m++) {
        pf_emu_rsqrt14_mode = m;
        bad += sweep_all(name, bw, ref, m);
    }
    pf_emu_rsqrt14_mode = PF_EMU_RSQRT14_NEAR;
    if (uses_rsqrt14)
        print_message("%s_array_bw: uses vrsqrt14ps, checked under its %d emulations\n", name, PF_EMU_RSQRT14_MODES);
    /* lengths and tails; the inputs start at a different place for each n */
    size_t lens[400];
    int nl = 0;
    for (size_t n = 0; n <= 100; n++)
        lens[nl++] = n;
    for (size_t k = 4; k <= 16; k++)
        for (size_t d = 0; d < 3; d++)
            lens[nl++] = 32 * k - 1 + d;
    const size_t more[] = {511, 512, 513, 639, 640, 641, 1000, 4095, 4096, 4097};
    for (size_t j = 0; j < sizeof more / sizeof more[0]; j++)
        lens[nl++] = more[j];
    int bad_lens = 0;
    for (int j = 0; j < nl; j++)
        if (run_len(name, bw, ref, lens[j], (lens[j] * 40503u + 12345u) & 0xffff, bad_lens < 5))
            bad_lens++;
    if (bad_lens)
        print_message("%s_array_bw (emulated): %d of %d lengths wrong\n", name, bad_lens, nl);
    assert_int_equal(bad + bad_lens, 0);
}

/* one test per function, from build/emul/emul_list.h */
#define PF_EMU(name, tin, tout)                                                                 \
    void pf_emu_bw_##name(const void *x, void *y, size_t n);                                    \
    tout pf_emu_##name(tin x);                                                                  \
    static uint16_t emu_##name(uint16_t x) { return (uint16_t)pf_emu_##name((tin)x); }          \
    static uint16_t lib_##name(uint16_t x) { return (uint16_t)pf_##name((tin)x); }              \
    static void pf_##name##_bw(void **st)                                                       \
    {                                                                                           \
        (void)st;                                                                               \
        check_bw("pf_" #name, pf_emu_bw_##name, emu_##name, lib_##name);                        \
    }
#include "emul_list.h"
#undef PF_EMU

/* ---- the emulation itself ---- */

static uint64_t rng = 0x9e3779b97f4a7c15u;
static uint64_t rnd(void) /* xorshift64* */
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return rng * 0x2545f4914f6cdd1du;
}

/* a word: an edge value (half the time) or random bits */
static uint16_t rnd16(void)
{
    static const uint16_t edge[] = {0, 1, 2, 0x7ffe, 0x7fff, 0x8000, 0x8001, 0xfffe, 0xffff, 0x4000, 0xc000, 0x00ff, 0xff00};
    uint64_t r = rnd();
    return (r & 1) ? edge[(r >> 1) % (sizeof edge / sizeof edge[0])] : (uint16_t)(r >> 20);
}

/* a float: special, near the int32 range's ends, small with halves, or random bits */
static float rndf(void)
{
    static const float edge[] = {0.0f, -0.0f, 0.5f, -0.5f, 1.5f, -1.5f, 2.5f, -2.5f, 0x1p31f, -0x1p31f,
                                 2147483520.0f, -2147483904.0f, 0x1p32f, -0x1p32f, 1e10f, -1e10f,
                                 INFINITY, -INFINITY, NAN, -NAN, 0x1p-149f, -0x1p-149f, 0x1.fffffep127f};
    uint64_t r = rnd();
    switch (r & 3) {
    case 0:
        return edge[(r >> 2) % (sizeof edge / sizeof edge[0])];
    case 1:
        return (float)((int64_t)(r >> 8) % 200001 - 100000) / 64.0f;
    default: {
        uint32_t u = (uint32_t)(r >> 16);
        float f;
        memcpy(&f, &u, 4);
        return f;
    }
    }
}

static pf_emu_v512 rndv(void)
{
    pf_emu_v512 v;
    for (int i = 0; i < 32; i++)
        v.u16[i] = rnd16();
    return v;
}

static pf_emu_v512 rndvf(void)
{
    pf_emu_v512 v;
    for (int i = 0; i < 16; i++)
        v.f32[i] = rndf();
    return v;
}

enum { TRIALS = 20000 };

static int same(const pf_emu_v512 *a, const pf_emu_v512 *b, const char *what, const pf_emu_v512 *x, const pf_emu_v512 *y)
{
    if (memcmp(a, b, 64) == 0)
        return 1;
    for (int i = 0; i < 32; i++)
        if (a->u16[i] != b->u16[i]) {
            print_message("%s: word %d: 0x%04x, expected 0x%04x (a word 0x%04x, b word 0x%04x)\n", what, i, a->u16[i],
                          b->u16[i], x ? x->u16[i] : 0, y ? y->u16[i] : 0);
            break;
        }
    return 0;
}

/* Intel's definitions, lane by lane, where AVX2 has no equal */

static void test_defined(void **st)
{
    (void)st;
    int bad = 0;
    for (int t = 0; t < TRIALS && bad < 10; t++) {
        pf_emu_v512 a = rndv(), b = rndv(), c = rndv(), e, r;
        uint32_t k = (uint32_t)rnd();
        /* counts of all sizes, mostly around 16 */
        pf_emu_v512 cnt = rndv();
        for (int i = 0; i < 32; i++)
            if (rnd() & 1)
                cnt.u16[i] = (uint16_t)(rnd() % 20);
        /* vpermw: index mod 32 */
        r = pf_emu_in(simde_mm512_permutexvar_epi16(pf_emu_out(b), pf_emu_out(a)));
        for (int i = 0; i < 32; i++)
            e.u16[i] = a.u16[b.u16[i] & 31];
        bad += !same(&r, &e, "simde_mm512_permutexvar_epi16", &b, &a);
        /* vpsrlvw, vpsllvw: counts >= 16 give 0 */
        r = pf_emu_in(simde_mm512_srlv_epi16(pf_emu_out(a), pf_emu_out(cnt)));
        for (int i = 0; i < 32; i++)
            e.u16[i] = cnt.u16[i] < 16 ? (uint16_t)(a.u16[i] >> cnt.u16[i]) : 0;
        bad += !same(&r, &e, "simde_mm512_srlv_epi16", &a, &cnt);
        r = pf_emu_in(simde_mm512_sllv_epi16(pf_emu_out(a), pf_emu_out(cnt)));
        for (int i = 0; i < 32; i++)
            e.u16[i] = cnt.u16[i] < 16 ? (uint16_t)(a.u16[i] << cnt.u16[i]) : 0;
        bad += !same(&r, &e, "simde_mm512_sllv_epi16", &a, &cnt);
        /* vpmovdw (fill): truncation */
        {
            simde__m256i h = simde_mm512_cvtepi32_epi16(pf_emu_out(a));
            uint16_t w[16];
            memcpy(w, &h, 32);
            for (int i = 0; i < 16; i++)
                if (w[i] != (uint16_t)a.u32[i]) {
                    print_message("cvtepi32_epi16 (fill): lane %d: 0x%04x of 0x%08x\n", i, w[i], a.u32[i]);
                    bad++;
                    break;
                }
        }
        /* vplzcntd (fill): __builtin_clz, 32 for 0 */
        {
            pf_emu_v512 z = a;
            for (int i = 0; i < 16; i++)
                z.u32[i] = (rnd() & 3) ? z.u32[i] >> (rnd() % 33 & 31) : 0;
            r = pf_emu_in(simde_mm512_lzcnt_epi32(pf_emu_out(z)));
            for (int i = 0; i < 16; i++)
                e.u32[i] = z.u32[i] ? (uint32_t)__builtin_clz(z.u32[i]) : 32u;
            bad += !same(&r, &e, "lzcnt_epi32 (fill)", &z, NULL);
        }
        /* vpmovw2m: the sign bits */
        {
            uint32_t m = simde_mm512_movepi16_mask(pf_emu_out(a)), em = 0;
            for (int i = 0; i < 32; i++)
                em |= (uint32_t)(a.u16[i] >> 15) << i;
            if (m != em) {
                print_message("simde_mm512_movepi16_mask: 0x%08x, expected 0x%08x\n", m, em);
                bad++;
            }
        }
        /* vpternlog: bit j of the result = bit (4 a_j + 2 b_j + c_j) of imm, for the loops' imm */
        r = pf_emu_in(simde_mm512_ternarylogic_epi32(pf_emu_out(a), pf_emu_out(b), pf_emu_out(c), 0x96));
        for (int i = 0; i < 32; i++)
            e.u16[i] = (uint16_t)(a.u16[i] ^ b.u16[i] ^ c.u16[i]); /* 0x96: odd parity */
        bad += !same(&r, &e, "simde_mm512_ternarylogic_epi32 (0x96)", &a, &b);
        r = pf_emu_in(simde_mm512_ternarylogic_epi64(pf_emu_out(a), pf_emu_out(b), pf_emu_out(c), 0xa8));
        for (int i = 0; i < 32; i++)
            e.u16[i] = (uint16_t)((a.u16[i] | b.u16[i]) & c.u16[i]); /* 0xa8: (a | b) & c */
        bad += !same(&r, &e, "simde_mm512_ternarylogic_epi64 (0xa8)", &a, &b);
        /* merge masks: vpsubw (fill), vpaddw, vmovdqu16 */
        r = pf_emu_in(simde_mm512_mask_sub_epi16(pf_emu_out(c), k, pf_emu_out(a), pf_emu_out(b)));
        for (int i = 0; i < 32; i++)
            e.u16[i] = (k >> i & 1) ? (uint16_t)(a.u16[i] - b.u16[i]) : c.u16[i];
        bad += !same(&r, &e, "mask_sub_epi16 (fill)", &a, &b);
        r = pf_emu_in(simde_mm512_mask_add_epi16(pf_emu_out(c), k, pf_emu_out(a), pf_emu_out(b)));
        for (int i = 0; i < 32; i++)
            e.u16[i] = (k >> i & 1) ? (uint16_t)(a.u16[i] + b.u16[i]) : c.u16[i];
        bad += !same(&r, &e, "simde_mm512_mask_add_epi16", &a, &b);
        r = pf_emu_in(simde_mm512_mask_mov_epi16(pf_emu_out(c), k, pf_emu_out(a)));
        for (int i = 0; i < 32; i++)
            e.u16[i] = (k >> i & 1) ? a.u16[i] : c.u16[i];
        bad += !same(&r, &e, "simde_mm512_mask_mov_epi16", &a, &c);
        /* the unsigned compares (fill) */
        {
            uint32_t gt = simde_mm512_cmpgt_epu16_mask(pf_emu_out(a), pf_emu_out(b));
            uint32_t lt = simde_mm512_cmplt_epu16_mask(pf_emu_out(a), pf_emu_out(b)), egt = 0, elt = 0;
            for (int i = 0; i < 32; i++) {
                egt |= (uint32_t)(a.u16[i] > b.u16[i]) << i;
                elt |= (uint32_t)(a.u16[i] < b.u16[i]) << i;
            }
            if (gt != egt || lt != elt) {
                print_message("cmpgt/cmplt_epu16_mask (fill): 0x%08x 0x%08x, expected 0x%08x 0x%08x\n", gt, lt, egt, elt);
                bad++;
            }
        }
        /* 256-bit halves: vinserti64x4 over a cast, vbroadcasti64x4 */
        {
            simde__m256i lo, hi;
            memcpy(&lo, &a, 32);
            memcpy(&hi, &b, 32);
            r = pf_emu_in(simde_mm512_inserti64x4(simde_mm512_castsi256_si512(lo), hi, 1));
            memcpy(&e, &a, 32);
            memcpy(e.u16 + 16, &b, 32);
            bad += !same(&r, &e, "simde_mm512_inserti64x4", &a, &b);
            r = pf_emu_in(simde_mm512_broadcast_i64x4(lo));
            memcpy(e.u16 + 16, &a, 32);
            bad += !same(&r, &e, "simde_mm512_broadcast_i64x4", &a, NULL);
        }
    }
    assert_int_equal(bad, 0);
}

/* vrsqrt14ps (fill): every mode within Intel's bound |r sqrt(a) - 1| < 2^-14
   on every argument the sqrt loops give it (Z = x 2^14, x < 2^16) and on
   random positive floats; HIGH and LOW use most of it (beyond 2^-15 on
   every argument); the special values */
static void test_rsqrt14(void **st)
{
    (void)st;
    int bad = 0;
    for (int m = 0; m < PF_EMU_RSQRT14_MODES; m++) {
        long double worst = 0, least = 1;
        for (int i = 0; i < 65536 + TRIALS; i++) {
            float a;
            if (i < 65536) {
                a = (float)(i + 1) * 0x1p14f; /* includes 2^30, where 1/sqrt is exact */
            } else {
                uint32_t u = (uint32_t)(rnd() >> 33) & 0x7f7fffffu; /* positive, finite */
                memcpy(&a, &u, 4);
                if (a == 0)
                    continue;
            }
            float r = pf_emu_rsqrt14_1(a, m);
            long double d = fabsl((long double)r * sqrtl((long double)a) - 1.0L);
            worst = d > worst ? d : worst;
            least = d < least ? d : least;
            if (!(d < 0x1p-14L) && bad++ < 5)
                print_message("rsqrt14 (fill, %s): a = %a: %a, relative error %Lg\n", rsqrt14_names[m], a, r, d);
        }
        print_message("rsqrt14 (fill, %s): relative error %.3Lg .. %.3Lg (of 2^-14 = %.3g)\n", rsqrt14_names[m], least,
                      worst, 0x1p-14);
        if ((m == PF_EMU_RSQRT14_HIGH || m == PF_EMU_RSQRT14_LOW) && !(least > 0x1p-15L)) {
            print_message("rsqrt14 (fill, %s): not adversarial (error %Lg somewhere)\n", rsqrt14_names[m], least);
            bad++;
        }
    }
    const float sp[] = {0.0f, -0.0f, INFINITY, -1.0f, -INFINITY, NAN};
    for (int m = 0; m < PF_EMU_RSQRT14_MODES; m++) {
        float r[6];
        for (int i = 0; i < 6; i++)
            r[i] = pf_emu_rsqrt14_1(sp[i], m);
        if (!(r[0] == INFINITY && r[1] == -INFINITY && r[2] == 0.0f && !signbit(r[2]) && isnan(r[3]) && isnan(r[4]) &&
              isnan(r[5]))) {
            print_message("rsqrt14 (fill, %s): special values wrong\n", rsqrt14_names[m]);
            bad++;
        }
    }
    assert_int_equal(bad, 0);
}

/* against the native AVX2 instruction on each 256-bit half */
#define AVX2 __attribute__((target("avx2,fma")))

typedef simde__m512i (*s2_fn)(simde__m512i, simde__m512i);
typedef __m256i (*n2_fn)(__m256i, __m256i);
typedef simde__m512 (*s2f_fn)(simde__m512, simde__m512);
typedef __m256 (*n2f_fn)(__m256, __m256);
typedef simde__m512 (*s3f_fn)(simde__m512, simde__m512, simde__m512);
typedef __m256 (*n3f_fn)(__m256, __m256, __m256);

#define PAIR(op)                                                                                \
    static simde__m512i s_##op(simde__m512i a, simde__m512i b) { return simde_mm512_##op(a, b); } \
    AVX2 static __m256i n_##op(__m256i a, __m256i b) { return _mm256_##op(a, b); }
/* the SIMDe intrinsics the loops use most, and the fill for vpmulhuw */
PAIR(mulhi_epu16)
PAIR(mulhrs_epi16)
PAIR(packus_epi32)
PAIR(adds_epu16)
PAIR(adds_epi16)
PAIR(avg_epu16)
PAIR(mullo_epi16)
PAIR(min_epu16)
PAIR(min_epi16)
PAIR(max_epi16)
PAIR(add_epi16)
PAIR(sub_epi16)
PAIR(unpacklo_epi16)
PAIR(unpackhi_epi16)
#undef PAIR
/* (names that differ between the two: and, xor) */
static simde__m512i s_and(simde__m512i a, simde__m512i b) { return simde_mm512_and_si512(a, b); }
AVX2 static __m256i n_and(__m256i a, __m256i b) { return _mm256_and_si256(a, b); }
static simde__m512i s_xor(simde__m512i a, simde__m512i b) { return simde_mm512_xor_si512(a, b); }
AVX2 static __m256i n_xor(__m256i a, __m256i b) { return _mm256_xor_si256(a, b); }
static simde__m512i s_abs(simde__m512i a, simde__m512i b) { (void)b; return simde_mm512_abs_epi16(a); }
AVX2 static __m256i n_abs(__m256i a, __m256i b) { (void)b; return _mm256_abs_epi16(a); }
/* shifts by an immediate: b's first word picks the count (0..15) */
#define SHIFT(op, nop)                                                                          \
    static simde__m512i s_##op(simde__m512i a, simde__m512i b)                                  \
    {                                                                                           \
        switch (pf_emu_in(b).u16[0] & 15) {                                                      \
        case 0: return simde_mm512_##op(a, 0);   case 1: return simde_mm512_##op(a, 1);         \
        case 2: return simde_mm512_##op(a, 2);   case 3: return simde_mm512_##op(a, 3);         \
        case 4: return simde_mm512_##op(a, 4);   case 5: return simde_mm512_##op(a, 5);         \
        case 6: return simde_mm512_##op(a, 6);   case 7: return simde_mm512_##op(a, 7);         \
        case 8: return simde_mm512_##op(a, 8);   case 9: return simde_mm512_##op(a, 9);         \
        case 10: return simde_mm512_##op(a, 10); case 11: return simde_mm512_##op(a, 11);       \
        case 12: return simde_mm512_##op(a, 12); case 13: return simde_mm512_##op(a, 13);       \
        case 14: return simde_mm512_##op(a, 14); default: return simde_mm512_##op(a, 15);       \
        }                                                                                       \
    }                                                                                           \
    AVX2 static __m256i n_##op(__m256i a, __m256i b)                                            \
    {                                                                                           \
        uint16_t c;                                                                             \
        memcpy(&c, &b, 2);                                                                      \
        return _mm256_##nop(a, _mm_cvtsi32_si128(c & 15)); /* the count from an xmm register */ \
    }
SHIFT(srli_epi16, srl_epi16)
SHIFT(slli_epi16, sll_epi16)
SHIFT(srai_epi16, sra_epi16)
#undef SHIFT

/* shift: the op is a shift whose count is b's first word (both halves get it) */
AVX2 static int check2x(const char *what, s2_fn s, n2_fn n, int shift)
{
    for (int t = 0; t < TRIALS; t++) {
        pf_emu_v512 a = rndv(), b = rndv(), r, e;
        if (shift)
            b.u16[16] = b.u16[0];
        r = pf_emu_in(s(pf_emu_out(a), pf_emu_out(b)));
        for (int h = 0; h < 2; h++) {
            __m256i x, y, z;
            memcpy(&x, a.u16 + 16 * h, 32);
            memcpy(&y, b.u16 + 16 * h, 32);
            z = n(x, y);
            memcpy(e.u16 + 16 * h, &z, 32);
        }
        if (!same(&r, &e, what, &a, &b))
            return 1;
    }
    return 0;
}
#define check2(what, s, n) check2x(what, s, n, 0)

#define S3F(op)                                                                                 \
    static simde__m512 s_##op(simde__m512 a, simde__m512 b, simde__m512 c) { return op##_512; } \
    AVX2 static __m256 n_##op(__m256 a, __m256 b, __m256 c) { return op##_256; }
#define sqrt_512 ((void)b, (void)c, simde_mm512_sqrt_ps(a))
#define sqrt_256 ((void)b, (void)c, _mm256_sqrt_ps(a))
#define min_512 ((void)c, simde_mm512_min_ps(a, b))
#define min_256 ((void)c, _mm256_min_ps(a, b))
#define mul_512 ((void)c, simde_mm512_mul_ps(a, b))
#define mul_256 ((void)c, _mm256_mul_ps(a, b))
#define sub_512 ((void)c, simde_mm512_sub_ps(a, b))
#define sub_256 ((void)c, _mm256_sub_ps(a, b))
#define fnmadd_512 simde_mm512_fnmadd_ps(a, b, c)
#define fnmadd_256 _mm256_fnmadd_ps(a, b, c)
/* SIMDe's own vfnmadd (the fill replaces it in the loops), for the report */
#undef simde_mm512_fnmadd_ps
#define simdefnmadd_512 simde_mm512_fnmadd_ps(a, b, c)
#define simdefnmadd_256 _mm256_fnmadd_ps(a, b, c)
S3F(sqrt)
S3F(min)
S3F(mul)
S3F(sub)
S3F(simdefnmadd)
#define simde_mm512_fnmadd_ps pf_emu_mm512_fnmadd_ps
S3F(fnmadd)

/* vcvttps2dq (fill), float in, int32 out, as a three-operand float op */
static simde__m512 s_cvtt(simde__m512 a, simde__m512 b, simde__m512 c)
{
    (void)b, (void)c;
    return simde_mm512_castsi512_ps(simde_mm512_cvttps_epi32(a));
}
AVX2 static __m256 n_cvtt(__m256 a, __m256 b, __m256 c)
{
    (void)b, (void)c;
    return _mm256_castsi256_ps(_mm256_cvttps_epi32(a));
}

/* the number of results that differ (as bits; any NaN equals any NaN) */
AVX2 static long check3f(const char *what, s3f_fn s, n3f_fn n, int quiet)
{
    long bad = 0;
    for (int t = 0; t < TRIALS; t++) {
        pf_emu_v512 a = rndvf(), b = rndvf(), c = rndvf(), r, e;
        if (t & 1) /* products near c: where fused and unfused differ */
            for (int i = 0; i < 16; i++)
                c.f32[i] = a.f32[i] * b.f32[i] * (1.0f + (float)(rnd() % 7) * 0x1p-23f);
        r = pf_emu_inf(s(pf_emu_outf(a), pf_emu_outf(b), pf_emu_outf(c)));
        for (int h = 0; h < 2; h++) {
            __m256 x, y, z, w;
            memcpy(&x, a.f32 + 8 * h, 32);
            memcpy(&y, b.f32 + 8 * h, 32);
            memcpy(&z, c.f32 + 8 * h, 32);
            w = n(x, y, z);
            memcpy(e.f32 + 8 * h, &w, 32);
        }
        for (int i = 0; i < 16; i++)
            if (r.u32[i] != e.u32[i] && !(isnan(r.f32[i]) && isnan(e.f32[i]) && s != s_cvtt) && bad++ < 3 && !quiet)
                print_message("%s: lane %d: %a %a %a gives %a (0x%08x), native %a (0x%08x)\n", what, i, a.f32[i],
                              b.f32[i], c.f32[i], r.f32[i], r.u32[i], e.f32[i], e.u32[i]);
    }
    return bad;
}

/* the unsigned word compares (fill) against vpmaxuw and vpcmpeqw */
AVX2 static int check_cmp(void)
{
    for (int t = 0; t < TRIALS; t++) {
        pf_emu_v512 a = rndv(), b = rndv();
        uint32_t gt = simde_mm512_cmpgt_epu16_mask(pf_emu_out(a), pf_emu_out(b));
        uint32_t lt = simde_mm512_cmplt_epu16_mask(pf_emu_out(a), pf_emu_out(b)), egt = 0, elt = 0;
        for (int h = 0; h < 2; h++) {
            __m256i x, y;
            memcpy(&x, a.u16 + 16 * h, 32);
            memcpy(&y, b.u16 + 16 * h, 32);
            __m256i m = _mm256_max_epu16(x, y);
            /* a > b iff max(a, b) != b; one mask bit per word from vpmovmskb's pairs */
            uint32_t g = ~(uint32_t)_mm256_movemask_epi8(_mm256_cmpeq_epi16(m, y));
            uint32_t l = ~(uint32_t)_mm256_movemask_epi8(_mm256_cmpeq_epi16(m, x));
            for (int i = 0; i < 16; i++) {
                egt |= (g >> (2 * i) & 1) << (16 * h + i);
                elt |= (l >> (2 * i) & 1) << (16 * h + i);
            }
        }
        if (gt != egt || lt != elt) {
            print_message("cmpgt/cmplt_epu16_mask (fill): 0x%08x 0x%08x, vpmaxuw/vpcmpeqw 0x%08x 0x%08x\n", gt, lt, egt,
                          elt);
            return 1;
        }
    }
    return 0;
}

/* vpmovdw (fill) against vpshufb (words 0, 2, 4, 6 of each 128-bit lane) and vpermq */
AVX2 static int check_cvtepi32_epi16(void)
{
    const __m256i sel = _mm256_setr_epi8(0, 1, 4, 5, 8, 9, 12, 13, -1, -1, -1, -1, -1, -1, -1, -1, 0, 1, 4, 5, 8, 9, 12,
                                         13, -1, -1, -1, -1, -1, -1, -1, -1);
    for (int t = 0; t < TRIALS; t++) {
        pf_emu_v512 a = rndv();
        simde__m256i r = simde_mm512_cvtepi32_epi16(pf_emu_out(a));
        uint64_t q[4];
        for (int h = 0; h < 2; h++) {
            __m256i x;
            memcpy(&x, a.u16 + 16 * h, 32);
            __m256i p = _mm256_permute4x64_epi64(_mm256_shuffle_epi8(x, sel), 0x08); /* qwords 0, 2 */
            memcpy(q + 2 * h, &p, 16);
        }
        if (memcmp(&r, q, 32) != 0) {
            print_message("cvtepi32_epi16 (fill) differs from vpshufb/vpermq\n");
            return 1;
        }
    }
    return 0;
}

static void test_native(void **st)
{
    (void)st;
    if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma"))
        skip();
    int bad = 0;
    bad += check2("mulhi_epu16 (fill)", s_mulhi_epu16, n_mulhi_epu16);
    bad += check2("simde_mm512_mulhrs_epi16", s_mulhrs_epi16, n_mulhrs_epi16);
    bad += check2("simde_mm512_packus_epi32", s_packus_epi32, n_packus_epi32);
    bad += check2("simde_mm512_adds_epu16", s_adds_epu16, n_adds_epu16);
    bad += check2("simde_mm512_adds_epi16", s_adds_epi16, n_adds_epi16);
    bad += check2("simde_mm512_avg_epu16", s_avg_epu16, n_avg_epu16);
    bad += check2("simde_mm512_mullo_epi16", s_mullo_epi16, n_mullo_epi16);
    bad += check2("simde_mm512_min_epu16", s_min_epu16, n_min_epu16);
    bad += check2("simde_mm512_min_epi16", s_min_epi16, n_min_epi16);
    bad += check2("simde_mm512_max_epi16", s_max_epi16, n_max_epi16);
    bad += check2("simde_mm512_add_epi16", s_add_epi16, n_add_epi16);
    bad += check2("simde_mm512_sub_epi16", s_sub_epi16, n_sub_epi16);
    bad += check2("simde_mm512_unpacklo_epi16", s_unpacklo_epi16, n_unpacklo_epi16);
    bad += check2("simde_mm512_unpackhi_epi16", s_unpackhi_epi16, n_unpackhi_epi16);
    bad += check2("simde_mm512_and_si512", s_and, n_and);
    bad += check2("simde_mm512_xor_si512", s_xor, n_xor);
    bad += check2("simde_mm512_abs_epi16", s_abs, n_abs);
    bad += check2x("simde_mm512_srli_epi16", s_srli_epi16, n_srli_epi16, 1);
    bad += check2x("simde_mm512_slli_epi16", s_slli_epi16, n_slli_epi16, 1);
    bad += check2x("simde_mm512_srai_epi16", s_srai_epi16, n_srai_epi16, 1);
    /* mulhrs at -32768 * -32768 (0x8000, the one overflow) and packus's clamps, explicitly */
    {
        simde__m512i m = simde_mm512_mulhrs_epi16(simde_mm512_set1_epi16(-32768), simde_mm512_set1_epi16(-32768));
        simde__m512i p = simde_mm512_packus_epi32(simde_mm512_set1_epi32(-5), simde_mm512_set1_epi32(70000));
        pf_emu_v512 mv = pf_emu_in(m), pv = pf_emu_in(p);
        if (mv.u16[0] != 0x8000 || mv.u16[31] != 0x8000 || pv.u16[0] != 0 || pv.u16[4] != 0xffff || pv.u16[31] != 0xffff) {
            print_message("simde_mm512_mulhrs_epi16(-32768, -32768) = 0x%04x, packus_epi32(-5, 70000) = 0x%04x 0x%04x\n",
                          mv.u16[0], pv.u16[0], pv.u16[4]);
            bad++;
        }
    }
    bad += check_cmp();
    bad += check_cvtepi32_epi16();
    bad += check3f("cvttps_epi32 (fill)", s_cvtt, n_cvtt, 0) != 0;
    bad += check3f("fnmadd_ps (fill)", s_fnmadd, n_fnmadd, 0) != 0;
    bad += check3f("simde_mm512_sqrt_ps", s_sqrt, n_sqrt, 0) != 0;
    bad += check3f("simde_mm512_min_ps", s_min, n_min, 0) != 0;
    bad += check3f("simde_mm512_mul_ps", s_mul, n_mul, 0) != 0;
    bad += check3f("simde_mm512_sub_ps", s_sub, n_sub, 0) != 0;
    /* not an error (the loops get the fill): SIMDe 0.7.4's own vfnmadd rounds twice */
    long u = check3f("SIMDe's own simde_mm512_fnmadd_ps", s_simdefnmadd, n_simdefnmadd, 1);
    print_message("SIMDe's own simde_mm512_fnmadd_ps differs from vfnmadd231ps in %ld of %d lanes "
                  "(unfused; tests/simde_fill.h replaces it)\n", u, 16 * TRIALS);
    assert_int_equal(bad, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_native),
        cmocka_unit_test(test_defined),
        cmocka_unit_test(test_rsqrt14),
#define PF_EMU(name, tin, tout) cmocka_unit_test(pf_##name##_bw),
#include "emul_list.h"
#undef PF_EMU
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
