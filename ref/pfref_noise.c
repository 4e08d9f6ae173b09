/* Exact gradient noise at dyadic points (see pfref_noise.h for why it is
 * exact and independent of the evaluators). */
#include "pfref_noise.h"

#include <math.h>

mpfr_prec_t pfref_noise_prec(int n, int exp)
{
    /* f(t) has 5·exp + 5 bits, a weight n of them, a dot exp + 5: the
       corner terms and their sum (all multiples of 2^-(5n+1)·exp, below 2^4)
       fit with room to spare */
    return (mpfr_prec_t)((5 * n + 2) * (exp + 6) + 64);
}

/* The gradient of hash h, dimension n, as small integers; the noise adds
 * g·d scaled by 1/4 (1D) or 2/3 (4D).  From the definitions in
 * libpfmath/pfnoise_table.c's comment, not from its code tables. */
static void gradient(int n, int h, int g[4])
{
    g[0] = g[1] = g[2] = g[3] = 0;
    switch (n) {
    case 1:
        g[0] = (h & 8) ? -(1 + (h & 7)) : 1 + (h & 7); /* Gustavson's ±1…±8 */
        break;
    case 2: /* (±1,±1) for h&7 < 4, then (±1,0), (0,±1); bit 0 (then 1) the signs */
        h &= 7;
        if (h < 4) {
            g[0] = (h & 1) ? -1 : 1;
            g[1] = (h & 2) ? -1 : 1;
        } else {
            g[h < 6 ? 0 : 1] = (h & 1) ? -1 : 1;
        }
        break;
    case 3: { /* Perlin's grad(): u = h<8 ? x : y, v = h<4 ? y : h==12||h==14 ? x : z */
        h &= 15;
        int u = h < 8 ? 0 : 1, v = h < 4 ? 1 : (h == 12 || h == 14) ? 0 : 2;
        g[u] += (h & 1) ? -1 : 1;
        g[v] += (h & 2) ? -1 : 1;
        break;
    }
    default: { /* component h>>3 is 0, the other three ±1 from bits 0,1,2 in order */
        h &= 31;
        int zero = h >> 3, bit = 0;
        for (int i = 0; i < 4; i++)
            if (i != zero)
                g[i] = (h >> bit++) & 1 ? -1 : 1;
        break;
    }
    }
}

void pfref_noise_mpfr(mpfr_t r, int n, const pf_noise_table *t, const int64_t *q, int exp)
{
    mpfr_prec_t P = pfref_noise_prec(n, exp);
    mpfr_t tt[4], f[4], w, dot, term, tmp;
    int cell[4];
    for (int i = 0; i < n; i++) {
        /* floor(q / 2^exp) and the remainder in [0, 2^exp), by C's
           truncating division (exact, no shifts of negative numbers) */
        int64_t one = (int64_t)1 << exp;
        int64_t fl = q[i] / one, rem = q[i] - fl * one;
        if (rem < 0) {
            rem += one;
            fl -= 1;
        }
        cell[i] = (int)(((fl % 256) + 256) % 256);
        mpfr_inits2(P, tt[i], f[i], (mpfr_ptr)0);
        mpfr_set_uj_2exp(tt[i], (uintmax_t)rem, -exp, MPFR_RNDN); /* exact */
        /* f = t³ (6t² − 15t + 10), exact at P bits */
        mpfr_mul_ui(f[i], tt[i], 6, MPFR_RNDN);
        mpfr_sub_ui(f[i], f[i], 15, MPFR_RNDN);
        mpfr_mul(f[i], f[i], tt[i], MPFR_RNDN);
        mpfr_add_ui(f[i], f[i], 10, MPFR_RNDN);
        for (int k = 0; k < 3; k++)
            mpfr_mul(f[i], f[i], tt[i], MPFR_RNDN);
    }
    mpfr_inits2(P, w, dot, term, tmp, (mpfr_ptr)0);
    mpfr_set_prec(r, P);
    mpfr_set_zero(r, 1);
    for (int c = 0; c < (1 << n); c++) {
        int h = 0;
        mpfr_set_ui(w, 1, MPFR_RNDN);
        for (int i = 0; i < n; i++) {
            int ci = (c >> i) & 1;
            h = t->perm[(h + cell[i] + ci) & 255];
            if (ci)
                mpfr_mul(w, w, f[i], MPFR_RNDN);
            else {
                mpfr_ui_sub(tmp, 1, f[i], MPFR_RNDN);
                mpfr_mul(w, w, tmp, MPFR_RNDN);
            }
        }
        int g[4];
        gradient(n, h, g);
        mpfr_set_zero(dot, 1);
        for (int i = 0; i < n; i++) {
            mpfr_sub_ui(tmp, tt[i], (c >> i) & 1, MPFR_RNDN); /* d = t − c */
            mpfr_mul_si(tmp, tmp, g[i], MPFR_RNDN);
            mpfr_add(dot, dot, tmp, MPFR_RNDN);
        }
        mpfr_mul(term, w, dot, MPFR_RNDN);
        mpfr_add(r, r, term, MPFR_RNDN);
    }
    if (n == 1)
        mpfr_div_2ui(r, r, 2, MPFR_RNDN);
    if (n == 4) {
        mpfr_mul_ui(r, r, 2, MPFR_RNDN);
        mpfr_div_ui(r, r, 3, MPFR_RNDN);
    }
    for (int i = 0; i < n; i++)
        mpfr_clears(tt[i], f[i], (mpfr_ptr)0);
    mpfr_clears(w, dot, term, tmp, (mpfr_ptr)0);
}

double pfref_noise(int n, const pf_noise_table *t, const int64_t *q, int exp)
{
    mpfr_t r;
    mpfr_init2(r, 64);
    pfref_noise_mpfr(r, n, t, q, exp);
    double d = mpfr_get_d(r, MPFR_RNDN);
    mpfr_clear(r);
    return d;
}

/* noise·2^oexp clamped to [lo, hi], at the noise's precision (+ 64 bits
   for the bounds) */
static void scaled_clamped(mpfr_t r, int n, const pf_noise_table *t, const int64_t *q, int exp, int oexp,
                           int64_t lo, int64_t hi)
{
    pfref_noise_mpfr(r, n, t, q, exp);
    mpfr_mul_2si(r, r, oexp, MPFR_RNDN); /* exact */
    mpfr_t b;
    mpfr_init2(b, 64);
    mpfr_set_sj(b, lo, MPFR_RNDN);
    if (mpfr_less_p(r, b))
        mpfr_set(r, b, MPFR_RNDN);
    mpfr_set_sj(b, hi, MPFR_RNDN);
    if (mpfr_greater_p(r, b))
        mpfr_set(r, b, MPFR_RNDN);
    mpfr_clear(b);
}

int64_t pfref_noise_round(int n, const pf_noise_table *t, const int64_t *q, int exp, int oexp, int64_t lo,
                          int64_t hi)
{
    mpfr_t r;
    mpfr_init2(r, 64);
    scaled_clamped(r, n, t, q, exp, oexp, lo, hi);
    mpfr_rint(r, r, MPFR_RNDN); /* ties to even */
    int64_t v = (int64_t)mpfr_get_sj(r, MPFR_RNDN);
    mpfr_clear(r);
    return v;
}

double pfref_noise_err_lsb(int n, const pf_noise_table *t, const int64_t *q, int exp, int64_t got, int oexp,
                           int64_t lo, int64_t hi)
{
    mpfr_t r;
    mpfr_init2(r, 64);
    scaled_clamped(r, n, t, q, exp, oexp, lo, hi);
    mpfr_t g;
    mpfr_init2(g, 64);
    mpfr_set_sj(g, got, MPFR_RNDN);
    mpfr_sub(r, r, g, MPFR_RNDN); /* exact enough: r's precision spans 2^64 down to its lsb */
    mpfr_clear(g);
    double e = fabs(mpfr_get_d(r, MPFR_RNDN));
    mpfr_clear(r);
    return e;
}
