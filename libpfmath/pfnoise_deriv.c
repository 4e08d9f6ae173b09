/* Value and analytic gradient of the float noise, 1D to 4D.
 *
 * In a cell, n = s·Σ_c W_c (g_c·d_c) with d_c = t − c, W_c = Π_i w_i(c_i),
 * w_i(0) = 1 − f(t_i), w_i(1) = f(t_i), s the dimension's scale; so
 *   ∂n/∂t_i = s·Σ_c [ (∂W_c/∂t_i)(g_c·d_c) + W_c g_c,i ],
 * ∂w_i/∂t_i = ∓f'(t_i), f'(t) = 30 t²(t−1)².  This is a scalar routine that
 * sums corner by corner from the permutation (not from the evaluators' pair
 * tables' layout tricks), so its value is also an independent check of the
 * fast evaluators (equal up to float rounding). */
#include <math.h>
#include <string.h>

#if defined(__GNUC__) && !defined(__clang__)
/* floorf inline (SSE4.1 roundss or GCC's SSE2 sequence) instead of a call */
#pragma GCC optimize("no-trapping-math")
#endif
#include "pfnoise_impl.h"


static float fade(float t)
{
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

/* Gradient of hash-index i (the last-level table index) for dimension n,
 * decoded from the dimension's code table. */
static void gradient(const pf_noise_table *t, int n, uint32_t i, float g[4])
{
    if (n == 1) {
        g[0] = (float)((int)(t->g1[i] & 31u) - 8);
        return;
    }
    const uint32_t *tab = n == 2 ? t->g2 : n == 3 ? t->g3 : t->g4;
    uint32_t code = tab[i] & 0xffffu;
    for (int k = 0; k < n; k++)
        g[k] = (float)((int)((code >> (2 * k)) & 3u) - 1);
}

static float noise_d(const pf_noise_table *t, int n, const float *p, float *grad)
{
    static const float scale[5] = {0.0f, 0.25f, 1.0f, 1.0f, 2.0f / 3.0f};
    if (!t) /* NULL = the default table, as everywhere */
        t = &pf_noise_default_;
    float d0[4], f[4], df[4];
    uint32_t L[4];
    for (int i = 0; i < n; i++) {
        float fl = floorf(p[i]);
        d0[i] = p[i] - fl;
        /* floor mod 256 as in the evaluators (exact for |x| < 2^22). */
        float m = fl + 12582912.0f;
        uint32_t u;
        memcpy(&u, &m, sizeof u);
        L[i] = u & 255u;
        f[i] = fade(d0[i]);
        df[i] = 30.0f * d0[i] * d0[i] * (d0[i] - 1.0f) * (d0[i] - 1.0f);
    }
    float val = 0.0f, gr[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int c = 0; c < (1 << n); c++) {
        /* Perlin's nesting p[p[p[X]+Y]+Z]; the final index selects the code. */
        uint32_t idx = L[0] + (uint32_t)(c & 1);
        for (int i = 1; i < n; i++)
            idx = (t->hash[idx] & 0xffffu) + L[i] + (uint32_t)((c >> i) & 1);
        float g[4], w[4], dot = 0.0f, W = 1.0f;
        gradient(t, n, idx, g);
        for (int i = 0; i < n; i++) {
            int o = (c >> i) & 1;
            dot += g[i] * (d0[i] - (float)o);
            w[i] = o ? f[i] : 1.0f - f[i];
            W *= w[i];
        }
        val += W * dot;
        for (int i = 0; i < n; i++) {
            float rest = 1.0f;
            for (int j = 0; j < n; j++)
                if (j != i)
                    rest *= w[j];
            float dw = ((c >> i) & 1) ? df[i] : -df[i];
            gr[i] += dw * rest * dot + W * g[i];
        }
    }
    for (int i = 0; i < n; i++)
        grad[i] = scale[n] * gr[i];
    return scale[n] * val;
}

/* 3D, unrolled for one cell (the loop above costs ~5x as much).  With
 * n_ijk the corner values g·(d − (i,j,k)) and the trilinear coefficients
 * k0..k7 of the blend, n = k0 + k1 u + k2 v + k3 w + k4 uv + k5 vw + k6 wu
 * + k7 uvw in the fades u, v, w of the offsets, so
 *   ∂n/∂x = G_x + u'(x)·(k1 + k4 v + k6 w + k7 vw)      (and cyclically)
 * where G is the same blend of the corner gradients g (∂n_ijk/∂x = g_x).
 * Equal to the generic routine and to pf_noise3f up to float rounding. */
static float noise3_d(const pf_noise_table *t, float x, float y, float z, float grad[3])
{
    float xf = floorf(x), yf = floorf(y), zf = floorf(z);
    float x0 = x - xf, y0 = y - yf, z0 = z - zf;
    uint32_t L[3];
    const float fl[3] = {xf, yf, zf};
    for (int i = 0; i < 3; i++) { /* floor mod 256 as in the evaluators */
        float m = fl[i] + 12582912.0f;
        uint32_t u;
        memcpy(&u, &m, sizeof u);
        L[i] = u & 255u;
    }
    uint32_t P = t->hash[L[0]];
    uint32_t A = (P & 0xffffu) + L[1], B = (P >> 16) + L[1];
    uint32_t PA = t->hash[A], PB = t->hash[B];
    /* pair codes of the (x, y) corners 00 01 10 11; z = 0 low, z = 1 high */
    const uint32_t c[4] = {t->g3[(PA & 0xffffu) + L[2]], t->g3[(PA >> 16) + L[2]],
                           t->g3[(PB & 0xffffu) + L[2]], t->g3[(PB >> 16) + L[2]]};
    /* corner q = 4i + 2j + k: code half k of c[2i + j]; plain scalars (an
     * array here was filled by vector stores and read back lane by lane,
     * a store-forwarding stall per read) */
#define CORNER(q)                                                                          \
    uint32_t h##q = c[(q) >> 1] >> (16 * ((q)&1));                                         \
    float gx##q = (float)((int)(h##q & 3u) - 1), gy##q = (float)((int)((h##q >> 2) & 3u) - 1), \
          gz##q = (float)((int)((h##q >> 4) & 3u) - 1);                                    \
    float n##q = gx##q * (x0 - (float)((q) >> 2)) + gy##q * (y0 - (float)(((q) >> 1) & 1)) + \
                 gz##q * (z0 - (float)((q)&1));
    CORNER(0) CORNER(1) CORNER(2) CORNER(3) CORNER(4) CORNER(5) CORNER(6) CORNER(7)
#undef CORNER
    float u = fade(x0), v = fade(y0), w = fade(z0);
    float du = 30.0f * x0 * x0 * (x0 - 1.0f) * (x0 - 1.0f),
          dv = 30.0f * y0 * y0 * (y0 - 1.0f) * (y0 - 1.0f),
          dw = 30.0f * z0 * z0 * (z0 - 1.0f) * (z0 - 1.0f);
#define TRI(a, k)                                                                          \
    float k##0 = a##0, k##1 = a##4 - a##0, k##2 = a##2 - a##0, k##3 = a##1 - a##0,          \
          k##4 = a##0 - a##4 - a##2 + a##6, k##5 = a##0 - a##2 - a##1 + a##3,              \
          k##6 = a##0 - a##4 - a##1 + a##5,                                                 \
          k##7 = -a##0 + a##4 + a##2 - a##6 + a##1 - a##5 - a##3 + a##7;
#define BLEND(k)                                                                           \
    (k##0 + u * k##1 + v * k##2 + w * k##3 + u * v * k##4 + v * w * k##5 + w * u * k##6 +   \
     u * v * w * k##7)
    TRI(n, k)
    TRI(gx, a)
    TRI(gy, b)
    TRI(gz, e)
    grad[0] = BLEND(a) + du * (k1 + k4 * v + k6 * w + k7 * v * w);
    grad[1] = BLEND(b) + dv * (k2 + k5 * w + k4 * u + k7 * w * u);
    grad[2] = BLEND(e) + dw * (k3 + k6 * u + k5 * v + k7 * u * v);
    return BLEND(k);
#undef TRI
#undef BLEND
}

float pf_noise1f_d_t(const pf_noise_table *t, float x, float *dx)
{
    return noise_d(t, 1, &x, dx);
}

float pf_noise2f_d_t(const pf_noise_table *t, float x, float y, float grad[2])
{
    float p[2] = {x, y};
    return noise_d(t, 2, p, grad);
}

float pf_noise3f_d_t(const pf_noise_table *t, float x, float y, float z, float grad[3])
{
    return noise3_d(t ? t : &pf_noise_default_, x, y, z, grad);
}

float pf_noise4f_d_t(const pf_noise_table *t, float x, float y, float z, float w,
                     float grad[4])
{
    float p[4] = {x, y, z, w};
    return noise_d(t, 4, p, grad);
}

float pf_noise1f_d(float x, float *dx)
{
    return noise_d(&pf_noise_default_, 1, &x, dx);
}

float pf_noise2f_d(float x, float y, float grad[2])
{
    return pf_noise2f_d_t(&pf_noise_default_, x, y, grad);
}

float pf_noise3f_d(float x, float y, float z, float grad[3])
{
    return pf_noise3f_d_t(&pf_noise_default_, x, y, z, grad);
}

float pf_noise4f_d(float x, float y, float z, float w, float grad[4])
{
    return pf_noise4f_d_t(&pf_noise_default_, x, y, z, w, grad);
}
