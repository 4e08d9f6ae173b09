/* pfbench: the peers — glibc's scalar functions, glibc's vector functions
 * (libmvec) and SLEEF — wrapped into the array form the harness times.
 *
 * The vector entry points are called directly (_ZGVdN8v_sinf is glibc's
 * AVX2 8-lane sinf, _ZGVeN16v_sinf its AVX-512 16-lane one; Sleef_sinf8_u10avx2
 * and friends are SLEEF's).  sleef.h declares its AVX functions only when the
 * including file is compiled with -mavx/-mavx512f, and libmvec has no header
 * at all, so they are declared here with the intrinsic vector types; each
 * wrapper is compiled for its ISA with a target attribute and only called
 * after __builtin_cpu_supports said yes, so the bench itself stays a
 * baseline x86-64 program. */
#include "pfbench.h"

#include <immintrin.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define AVX2 __attribute__((target("avx2,fma")))
#define AVX512 __attribute__((target("avx512f")))

/* Whole vectors straight from the arrays; the tail (n not a multiple of the
   width) goes through a padded copy so no lane reads past the end. */
#define WRAP1(NAME, SYM, ATTR, VT, W, LOAD, STORE)                                     \
    VT SYM(VT);                                                                         \
    ATTR static void NAME(const float *x, float *y, size_t n)                           \
    {                                                                                   \
        size_t i = 0;                                                                   \
        for (; i + W <= n; i += W)                                                      \
            STORE(y + i, SYM(LOAD(x + i)));                                             \
        if (i < n) {                                                                    \
            float tx[W], ty[W];                                                         \
            for (size_t k = 0; k < W; k++)                                              \
                tx[k] = x[i + k < n ? i + k : i];                                       \
            STORE(ty, SYM(LOAD(tx)));                                                   \
            memcpy(y + i, ty, (n - i) * sizeof *y);                                     \
        }                                                                               \
    }

#define WRAP2(NAME, SYM, ATTR, VT, W, LOAD, STORE)                                     \
    VT SYM(VT, VT);                                                                     \
    ATTR static void NAME(const float *y, const float *x, float *out, size_t n)         \
    {                                                                                   \
        size_t i = 0;                                                                   \
        for (; i + W <= n; i += W)                                                      \
            STORE(out + i, SYM(LOAD(y + i), LOAD(x + i)));                              \
        if (i < n) {                                                                    \
            float ty[W], tx[W], to[W];                                                  \
            for (size_t k = 0; k < W; k++) {                                            \
                ty[k] = y[i + k < n ? i + k : i];                                       \
                tx[k] = x[i + k < n ? i + k : i];                                       \
            }                                                                           \
            STORE(to, SYM(LOAD(ty), LOAD(tx)));                                         \
            memcpy(out + i, to, (n - i) * sizeof *out);                                 \
        }                                                                               \
    }

#define V8_1(NAME, SYM) WRAP1(NAME, SYM, AVX2, __m256, 8, _mm256_loadu_ps, _mm256_storeu_ps)
#define V16_1(NAME, SYM) WRAP1(NAME, SYM, AVX512, __m512, 16, _mm512_loadu_ps, _mm512_storeu_ps)
#define V8_2(NAME, SYM) WRAP2(NAME, SYM, AVX2, __m256, 8, _mm256_loadu_ps, _mm256_storeu_ps)
#define V16_2(NAME, SYM) WRAP2(NAME, SYM, AVX512, __m512, 16, _mm512_loadu_ps, _mm512_storeu_ps)

/* every peer of a one-argument function f that has SLEEF u10 and u35 */
#define PEERS1(fn)                                                                     \
    V8_1(mv8_##fn, _ZGVdN8v_##fn##f)                                                    \
    V16_1(mv16_##fn, _ZGVeN16v_##fn##f)                                                 \
    V8_1(s10x8_##fn, Sleef_##fn##f8_u10avx2)                                            \
    V16_1(s10x16_##fn, Sleef_##fn##f16_u10avx512f)                                      \
    V8_1(s35x8_##fn, Sleef_##fn##f8_u35avx2)                                            \
    V16_1(s35x16_##fn, Sleef_##fn##f16_u35avx512f)

PEERS1(sin)
PEERS1(cos)
PEERS1(tan)
PEERS1(asin)
PEERS1(acos)
PEERS1(atan)
PEERS1(exp2)
PEERS1(log)
PEERS1(log2)
/* SLEEF 3.5 has expf only as u10 */
V8_1(mv8_exp, _ZGVdN8v_expf)
V16_1(mv16_exp, _ZGVeN16v_expf)
V8_1(s10x8_exp, Sleef_expf8_u10avx2)
V16_1(s10x16_exp, Sleef_expf16_u10avx512f)
V8_2(mv8_atan2, _ZGVdN8vv_atan2f)
V16_2(mv16_atan2, _ZGVeN16vv_atan2f)
V8_2(s10x8_atan2, Sleef_atan2f8_u10avx2)
V16_2(s10x16_atan2, Sleef_atan2f16_u10avx512f)
V8_2(s35x8_atan2, Sleef_atan2f8_u35avx2)
V16_2(s35x16_atan2, Sleef_atan2f16_u35avx512f)
/* SLEEF's fast tier (3.5 has it for sinf, cosf and powf only): accurate to
   3500 ULP on a limited range only; the bench measures its error like every
   peer's, on the same inputs, whatever it is */
V8_1(sfx8_sin, Sleef_fastsinf8_u3500avx2)
V16_1(sfx16_sin, Sleef_fastsinf16_u3500avx512f)
V8_1(sfx8_cos, Sleef_fastcosf8_u3500avx2)
V16_1(sfx16_cos, Sleef_fastcosf16_u3500avx512f)

/* one row per function: glibc scalar, then the vector kinds in the order of
   kinds[] below; NULL = the peer library has no such function */
typedef struct {
    pf_func f;
    pf_fn1 g1;
    pf_fn2 g2;
    pfb_arr1 v1[6];
    pfb_arr2 v2[6];
    pfb_arr1 fast[2]; /* SLEEF's fast tier, AVX2 and AVX-512; NULL: none */
} peer_row;

#define ROW1(F, fn)                                                                    \
    {.f = F, .g1 = fn##f, .v1 = {mv8_##fn, mv16_##fn, s10x8_##fn, s10x16_##fn, s35x8_##fn, s35x16_##fn}}

static const peer_row rows[] = {
    {.f = PF_SIN, .g1 = sinf, .v1 = {mv8_sin, mv16_sin, s10x8_sin, s10x16_sin, s35x8_sin, s35x16_sin},
     .fast = {sfx8_sin, sfx16_sin}},
    {.f = PF_COS, .g1 = cosf, .v1 = {mv8_cos, mv16_cos, s10x8_cos, s10x16_cos, s35x8_cos, s35x16_cos},
     .fast = {sfx8_cos, sfx16_cos}},
    ROW1(PF_TAN, tan),
    ROW1(PF_ASIN, asin), ROW1(PF_ACOS, acos), ROW1(PF_ATAN, atan),
    {.f = PF_ATAN2, .g2 = atan2f,
     .v2 = {mv8_atan2, mv16_atan2, s10x8_atan2, s10x16_atan2, s35x8_atan2, s35x16_atan2}},
    {.f = PF_EXP, .g1 = expf, .v1 = {mv8_exp, mv16_exp, s10x8_exp, s10x16_exp, NULL, NULL}},
    ROW1(PF_EXP2, exp2), ROW1(PF_LOG, log),   ROW1(PF_LOG2, log2),
};

static const struct {
    const char *name, *isa;
    int fast, avx512;
} kinds[6] = {
    {"libmvec", "avx2", 0, 0},   {"libmvec", "avx512", 0, 1},
    {"sleef-u10", "avx2", 0, 0}, {"sleef-u10", "avx512", 0, 1},
    {"sleef-u35", "avx2", 1, 0}, {"sleef-u35", "avx512", 1, 1},
};

void pfb_peers(pf_func f, pfb_cand *c, int *n)
{
    const peer_row *r = NULL;
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++)
        if (rows[i].f == f)
            r = &rows[i];
    if (!r)
        return;
    __builtin_cpu_init();
    int has2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    int has512 = __builtin_cpu_supports("avx512f");

    pfb_cand *g = &c[(*n)++];
    memset(g, 0, sizeof *g);
    snprintf(g->name, sizeof g->name, "glibc");
    snprintf(g->isa, sizeof g->isa, "scalar");
    g->s1 = r->g1;
    g->s2 = r->g2;

    for (int k = 0; k < 6; k++) {
        pfb_cand *v = &c[(*n)++];
        memset(v, 0, sizeof *v);
        snprintf(v->name, sizeof v->name, "%s", kinds[k].name);
        snprintf(v->isa, sizeof v->isa, "%s", kinds[k].isa);
        v->fast = kinds[k].fast;
        int have = pfref_arity(f) == 2 ? r->v2[k] != NULL : r->v1[k] != NULL;
        if (!have)
            snprintf(v->absent, sizeof v->absent, "no %sf %s in %s", pfref_name(f),
                     kinds[k].fast ? "u35" : "u10", kinds[k].name[0] == 's' ? "SLEEF 3.5" : "libmvec");
        else if (kinds[k].avx512 ? !has512 : !has2)
            snprintf(v->absent, sizeof v->absent, "CPU lacks %s", kinds[k].avx512 ? "AVX-512F" : "AVX2+FMA");
        else {
            v->a1 = r->v1[k];
            v->a2 = r->v2[k];
        }
    }
    /* "sleef-fast": only where SLEEF has the function (sin, cos) */
    for (int k = 0; k < 2; k++) {
        if (!r->fast[k])
            continue;
        pfb_cand *v = &c[(*n)++];
        memset(v, 0, sizeof *v);
        snprintf(v->name, sizeof v->name, "sleef-fast");
        snprintf(v->isa, sizeof v->isa, "%s", k ? "avx512" : "avx2");
        v->fast = 1;
        if (k ? !has512 : !has2)
            snprintf(v->absent, sizeof v->absent, "CPU lacks %s", k ? "AVX-512F" : "AVX2+FMA");
        else
            v->a1 = r->fast[k];
    }
}
