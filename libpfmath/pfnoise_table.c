/* Permutation tables and gradient sets for pfnoise.
 *
 * Gradient sets (h is the 8-bit lattice hash):
 *   1D  g = ±(1 + (h & 7)), minus when h & 8 (Gustavson); value scaled by 1/4.
 *   2D  the 8 vectors (±1,±1), (±1,0), (0,±1), by h & 7.
 *   3D  Perlin's 12 edge vectors (±1,±1,0)… padded to 16, by h & 15, exactly
 *       as his grad() (derived below from his expression, not retyped).
 *   4D  the 32 vectors with one zero and three ±1, by h & 31; value scaled
 *       by 2/3.
 *
 * Range argument.  In a cell, with t ∈ [0,1)^N the position in the cell,
 * n(t) = Σ_c W_c(t) g_c·(t − c), W_c = Π_i (c_i ? f(t_i) : 1 − f(t_i)) >= 0,
 * Σ_c W_c = 1.  For any choice of gradients, n(t) <= B(t) =
 * Σ_c W_c(t) max_g g·(t − c), and max_g g·d is: 1D 8|d| (·1/4), 2D
 * |d1|+|d2|, 3D the sum of the two largest |d_i|, 4D the sum of the three
 * largest (·2/3).  The sets are symmetric under g -> -g, so |n| <= sup B.
 *   1D/2D: B separates into Σ_i h(t_i), h(t) = (1−f(t))t + f(t)(1−t), whose
 *   max is h(1/2) = 1/2, so sup B = 1 (1D: 8·1/2·1/4), attained at the cell
 *   centre when every gradient points to the centre.
 *   3D: sup B = 1.036354 at t ≈ (0.5, 0.4815, 0.3553) and permutations.
 *   4D: sup B = 1.536582·2/3 = 1.024388 at t ≈ (0.4816, 0.4919, 0.5, 0.3564).
 * tests/test_noise.c recomputes sup B from the code tables below (grid
 * search over [0,1/2]^N, B being symmetric under t_i -> 1 − t_i, then
 * coordinate ascent) and checks PF_NOISEn_MAX lies within 2e-4 above it;
 * it also checks that 2^22 random points stay inside.  Whether a given
 * permutation realises the worst gradient combination is luck (in 4D the 16
 * corners practically never do: 0.76 is the largest value seen); the bound
 * holds for all of them.
 */
#include "pfnoise.h"

#include <string.h>

const uint8_t pf_noise_perlin_perm[256] = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225,
    140, 36,  103, 30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148,
    247, 120, 234, 75,  0,   26,  197, 62,  94,  252, 219, 203, 117, 35,  11,  32,
    57,  177, 33,  88,  237, 149, 56,  87,  174, 20,  125, 136, 171, 168, 68,  175,
    74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231, 83,  111, 229, 122,
    60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143, 54,
    65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169,
    200, 196, 135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,
    52,  217, 226, 250, 124, 123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212,
    207, 206, 59,  227, 47,  16,  58,  17,  182, 189, 28,  42,  223, 183, 170, 213,
    119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101, 155, 167, 43,  172, 9,
    129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185, 112, 104,
    218, 246, 97,  228, 251, 34,  242, 193, 238, 210, 144, 12,  191, 179, 162, 241,
    81,  51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,  181, 199, 106, 157,
    184, 84,  204, 176, 115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,
    222, 114, 67,  29,  24,  72,  243, 141, 128, 195, 78,  66,  215, 61,  156, 180,
};

/* Perlin's grad(), used only to derive the 3D code table. */
static int perlin_grad(int h, int x, int y, int z)
{
    h &= 15;
    int u = h < 8 ? x : y;
    int v = h < 4 ? y : (h == 12 || h == 14) ? x : z;
    return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

/* Codes hold k = g + 1 ∈ {0,1,2} per component in 2-bit fields at bits 0, 2,
 * 4, 6 (1D: k = g + 8 in bits 0..4), so that the evaluators get g·d as
 * k·d − d without branches; the second corner of a pair sits 16 bits up. */
static uint32_t code1(int h)
{
    int g = 1 + (h & 7);
    if (h & 8)
        g = -g;
    return (uint32_t)(g + 8);
}

static uint32_t code2(int h)
{
    static const int8_t g[8][2] = {{1, 1}, {-1, 1}, {1, -1}, {-1, -1},
                                   {1, 0}, {-1, 0}, {0, 1},  {0, -1}};
    h &= 7;
    return (uint32_t)(g[h][0] + 1) | (uint32_t)(g[h][1] + 1) << 2;
}

static uint32_t code3(int h)
{
    int gx = perlin_grad(h, 1, 0, 0), gy = perlin_grad(h, 0, 1, 0),
        gz = perlin_grad(h, 0, 0, 1);
    return (uint32_t)(gx + 1) | (uint32_t)(gy + 1) << 2 | (uint32_t)(gz + 1) << 4;
}

static uint32_t code4(int h)
{
    h &= 31;
    int zero = h >> 3, bit = 0;
    uint32_t c = 0;
    for (int i = 0; i < 4; i++) {
        int g = 0;
        if (i != zero)
            g = (h >> bit++) & 1 ? -1 : 1;
        c |= (uint32_t)(g + 1) << (2 * i);
    }
    return c;
}

static void build(pf_noise_table *t, const uint8_t perm[256])
{
    memcpy(t->perm, perm, 256);
    for (int i = 0; i < 512; i++) {
        int a = perm[i & 255], b = perm[(i + 1) & 255];
        t->hash[i] = (uint32_t)a | (uint32_t)b << 16;
        t->g1[i] = code1(a) | code1(b) << 16;
        t->g2[i] = code2(a) | code2(b) << 16;
        t->g3[i] = code3(a) | code3(b) << 16;
        t->g4[i] = code4(a) | code4(b) << 16;
    }
}

int pf_noise_table_init(pf_noise_table *t, const uint8_t perm[256])
{
    uint8_t seen[256] = {0};
    for (int i = 0; i < 256; i++) {
        if (seen[perm[i]])
            return -1;
        seen[perm[i]] = 1;
    }
    build(t, perm);
    return 0;
}

static uint64_t splitmix64(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

void pf_noise_table_seed(pf_noise_table *t, uint64_t seed)
{
    uint8_t p[256];
    for (int i = 0; i < 256; i++)
        p[i] = (uint8_t)i;
    uint64_t s = seed;
    for (int i = 255; i > 0; i--) {
        /* Unbiased draw in [0, i] by rejection. */
        uint64_t lim = UINT64_MAX - UINT64_MAX % (uint64_t)(i + 1), r;
        do
            r = splitmix64(&s);
        while (r >= lim);
        int j = (int)(r % (uint64_t)(i + 1));
        uint8_t tmp = p[i];
        p[i] = p[j];
        p[j] = tmp;
    }
    build(t, p);
}

/* The default table is data, not code run at load time: a constructor that
 * filled it ran too late for callers that are themselves constructors or
 * C++ global initialisers (issue 11, item 6).  The build compiles this file
 * with -DPF_NOISE_TABLEGEN into build/pfnoise-tablegen, which writes the
 * table's initialiser from the same build() as user tables
 * ($(BUILD)/include/pfnoise_default.inc, mk/noise.mk): one definition of
 * the codes, no hand-typed copy, and tests/test_noise.c checks the result
 * against pf_noise_table_init(pf_noise_perlin_perm).  Being const, it lives
 * in read-only data at a link-time address (no pointer to load). */
#ifdef PF_NOISE_TABLEGEN
#include <stdio.h>

static void row(const char *name, const uint32_t *v, int n)
{
    printf("    .%s = {", name);
    for (int i = 0; i < n; i++)
        printf("%s0x%08x,", i % 8 ? " " : "\n        ", (unsigned)v[i]);
    printf("\n    },\n");
}

int main(int argc, char **argv)
{
    /* a build tool without options: anything given is a mistake, not ignored */
    if (argc == 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
        puts("usage: pfnoise-tablegen > pfnoise_default.inc\n"
             "Prints the default noise tables as C (a build step of libpfmath); no options.");
        return 0;
    }
    if (argc > 1) {
        fputs("pfnoise-tablegen: takes no arguments (see --help)\n", stderr);
        return 2;
    }
    static pf_noise_table t;
    build(&t, pf_noise_perlin_perm);
    printf("/* Generated by build/pfnoise-tablegen (libpfmath/pfnoise_table.c built\n"
           " * with -DPF_NOISE_TABLEGEN): pf_noise_default_, the noise lookup tables\n"
           " * for Perlin's permutation pf_noise_perlin_perm, through the same\n"
           " * build() as pf_noise_table_init().  Do not edit. */\n");
    row("hash", t.hash, 512);
    row("g1", t.g1, 512);
    row("g2", t.g2, 512);
    row("g3", t.g3, 512);
    row("g4", t.g4, 512);
    printf("    .perm = {");
    for (int i = 0; i < 256; i++)
        printf("%s%u,", i % 16 ? " " : "\n        ", (unsigned)t.perm[i]);
    printf("\n    },\n");
    return fflush(stdout) != 0 || ferror(stdout) ? 1 : 0;
}
#else
#include "pfnoise_impl.h"

/* Library-internal (not in pfnoise.h, hidden in the shared library);
 * 64-byte aligned so that a point's hash pairs share cache lines alike. */
__attribute__((visibility("hidden"), aligned(64))) const pf_noise_table pf_noise_default_ = {
#include "pfnoise_default.inc"
};

const pf_noise_table *pf_noise_default_table(void)
{
    return &pf_noise_default_;
}
#endif
