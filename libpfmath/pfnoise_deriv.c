/* Value and analytic gradient of the float noise, 1D to 4D.
 *
 * In a cell, n = s·Σ_c W_c (g_c·d_c) with d_c = t − c, W_c = Π_i w_i(c_i),
 * w_i(0) = 1 − f(t_i), w_i(1) = f(t_i), s the dimension's scale; so
 *   ∂n/∂t_i = s·Σ_c [ (∂W_c/∂t_i)(g_c·d_c) + W_c g_c,i ],
 * ∂w_i/∂t_i = ∓f'(t_i), f'(t) = 30 t²(t−1)².  This is a scalar routine that
 * sums corner by corner from the permutation (not from the evaluators' pair
 * tables' layout tricks), so its value is also an independent check of the
 * fast evaluators (equal up to float rounding). */
#include "pfnoise_impl.h"

#include <math.h>
#include <string.h>


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
    float p[3] = {x, y, z};
    return noise_d(t, 3, p, grad);
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
