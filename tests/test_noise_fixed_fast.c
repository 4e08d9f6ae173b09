/* pfnoise fast fixed point (pfnoise_fixed_fast.c): the fade against f over
 * all 2^16 fractions (error δ, range, symmetry, exact 0 at t = 0) and the
 * proven bound recomputed from δ; the result against an independent double
 * evaluation of the noise (3D: the plain port of Perlin's reference code,
 * tests/noise_baseline.c; 2D: the double evaluation below, written from the
 * documented hashing and gradient set) over 2^22 random points per
 * dimension plus cell edges and lattice points, within the bound; agreement
 * with the float and the exact fixed forms; array == scalar; zeros at
 * lattice points; period 256; golden hashes pinning the bits (this test
 * runs in the -O2 and in the -O1 sanitizer builds against the same
 * constants). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "noise_baseline.h"
#include "pfnoise.h"

/* Library-internal: G = f(t) - 1/2 in Q18 for the fraction of x. */
int32_t pf__noise_fast_fade_g18(int32_t x);

/* δ used by the bound in pfnoise_fixed_fast.c, in LSB of Q0.15. */
#define FADE_DELTA 0.245

static int quick;

static uint64_t rng_state = 0x452821e638d01377u;
static uint64_t rnd(void)
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

static double fade(double t)
{
    return t * t * t * (t * (t * 6 - 15) + 10);
}

static void test_fade(void **state)
{
    (void)state;
    double worst = 0;
    int32_t lo = 0, hi = 0;
    for (int32_t t = 0; t < 65536; t++) {
        int32_t g = pf__noise_fast_fade_g18(t);
        /* only the fraction matters */
        assert_int_equal(g, pf__noise_fast_fade_g18(t + 65536 * 1000));
        assert_int_equal(g, pf__noise_fast_fade_g18(t - 65536 * 3));
        lo = g < lo ? g : lo;
        hi = g > hi ? g : hi;
        double tt = t / 65536.0;
        worst = fmax(worst, fabs(g / 262144.0 - (fade(tt) - 0.5)));
        /* f(1 - t) = 1 - f(t), exactly: the evaluation uses |t - 1/2| */
        if (t > 0)
            assert_int_equal(g, -pf__noise_fast_fade_g18(65536 - t));
    }
    double delta = worst * 32768;
    printf("# fast fade: max |G - (f - 1/2)| = %.4f LSB of Q0.15 (2^%.2f), G in [%d, %d]\n",
           delta, log2(worst), lo, hi);
    /* lerp weights F = 1/2 + G/2^18 in [0, 1]; the lerp's int32 products
     * need |G| <= 2^17 */
    assert_true(lo >= -131072 && hi <= 131072);
    /* F = 0 at t = 0: zero at lattice points */
    assert_int_equal(pf__noise_fast_fade_g18(0), -131072);
    assert_true(delta <= FADE_DELTA);
    /* the bounds of pfnoise_fixed_fast.c with this δ, in LSB (with δ = d
     * LSB = d·2^-15, a term kδ² is k·d²/2^15 LSB) */
    double d = FADE_DELTA;
    double b2 = 0.75 + 4 * d + 2 * d * d / 32768, b3 = 1.0 + 9 * d + 6 * d * d / 32768;
    printf("# bounds: 2D %.3f LSB, 3D %.3f LSB\n", b2, b3);
    assert_true(b2 <= PF_NOISE2_FAST_ERR);
    assert_true(b3 <= PF_NOISE3_FAST_ERR);
}

/* Independent double evaluation of the 2D noise: hash p[(p[X] + Y) mod 256],
 * gradient by h & 7 from (1,1), (-1,1), (1,-1), (-1,-1), (1,0), (-1,0),
 * (0,1), (0,-1) (docs/noise.md, pfnoise_table.c). */
static const uint8_t *ref_perm;
static double grad2(int h, double x, double y)
{
    static const int g[8][2] = {{1, 1}, {-1, 1}, {1, -1}, {-1, -1},
                                {1, 0}, {-1, 0}, {0, 1},  {0, -1}};
    return g[h & 7][0] * x + g[h & 7][1] * y;
}

static double ref2(double x, double y)
{
    const uint8_t *p = ref_perm;
    double fx = floor(x), fy = floor(y);
    int X = (int)((int64_t)fx & 255), Y = (int)((int64_t)fy & 255);
    x -= fx;
    y -= fy;
    int h00 = p[(p[X] + Y) & 255], h01 = p[(p[X] + Y + 1) & 255];
    int h10 = p[(p[(X + 1) & 255] + Y) & 255], h11 = p[(p[(X + 1) & 255] + Y + 1) & 255];
    double u = fade(x), v = fade(y);
    double a = grad2(h00, x, y) + u * (grad2(h10, x - 1, y) - grad2(h00, x, y));
    double b = grad2(h01, x, y - 1) + u * (grad2(h11, x - 1, y - 1) - grad2(h01, x, y - 1));
    return a + v * (b - a);
}

/* |r - clamp(2^15·n)| in LSB, n from the double reference. */
static double err_lsb(int dim, int16_t r, const int32_t *q)
{
    double n = dim == 2 ? ref2(q[0] / 65536.0, q[1] / 65536.0)
                        : noise_baseline3(q[0] / 65536.0, q[1] / 65536.0, q[2] / 65536.0);
    double e = fmin(32767, fmax(-32768, n * 32768));
    return fabs(r - e);
}

enum { BLK = 4096 };
static int32_t bx[BLK], by[BLK], bz[BLK];
static int16_t bo[BLK];

static double check_block(int dim, int len)
{
    double worst = 0;
    if (dim == 2)
        pf_noise2_q15_fast_array(NULL, bo, bx, by, (size_t)len);
    else
        pf_noise3_q15_fast_array(NULL, bo, bx, by, bz, (size_t)len);
    for (int i = 0; i < len; i++) {
        int32_t q[3] = {bx[i], by[i], bz[i]};
        worst = fmax(worst, err_lsb(dim, bo[i], q));
    }
    return worst;
}

/* Fractions on and next to cell edges and at the centre. */
static const int32_t edge_frac[] = {0, 1, 2, 3, 32767, 32768, 32769, 65533, 65534, 65535};
enum { NEDGE = sizeof edge_frac / sizeof *edge_frac };

static void test_accuracy(void **state)
{
    (void)state;
    ref_perm = pf_noise_perlin_perm;
    noise_baseline_set_perm(NULL);
    long n_pts = quick ? 1L << 16 : 1L << 22;
    for (int dim = 2; dim <= 3; dim++) {
        double bound = dim == 2 ? PF_NOISE2_FAST_ERR : PF_NOISE3_FAST_ERR;
        double w_rand = 0, w_edge = 0, w_lat = 0;
        for (long done = 0; done < n_pts; done += BLK) {
            for (int i = 0; i < BLK; i++) {
                bx[i] = (int32_t)(uint32_t)rnd();
                by[i] = (int32_t)(uint32_t)rnd();
                bz[i] = (int32_t)(uint32_t)rnd();
            }
            w_rand = fmax(w_rand, check_block(dim, BLK));
        }
        /* every combination of edge fractions, in random cells */
        int len = 0, combos = dim == 2 ? NEDGE * NEDGE : NEDGE * NEDGE * NEDGE;
        for (int rep = 0; rep < (quick ? 4 : 64); rep++) {
            for (int c = 0; c < combos; c++) {
                int32_t *dst[3] = {bx, by, bz};
                int cc = c;
                for (int k = 0; k < 3; k++) {
                    uint32_t cell = (uint32_t)rnd() & 0xffff0000u;
                    dst[k][len] = (int32_t)(cell | (uint32_t)edge_frac[cc % NEDGE]);
                    cc /= NEDGE;
                }
                if (++len == BLK) {
                    w_edge = fmax(w_edge, check_block(dim, len));
                    len = 0;
                }
            }
        }
        w_edge = fmax(w_edge, check_block(dim, len));
        /* lattice points: exactly 0 */
        for (int i = 0; i < BLK; i++) {
            bx[i] = (int32_t)((uint32_t)rnd() & 0xffff0000u);
            by[i] = (int32_t)((uint32_t)rnd() & 0xffff0000u);
            bz[i] = (int32_t)((uint32_t)rnd() & 0xffff0000u);
        }
        w_lat = check_block(dim, BLK);
        for (int i = 0; i < BLK; i++)
            assert_int_equal(bo[i], 0);
        printf("# %dD fast: max |r - 2^15 n| = %.3f LSB random (%ld points), %.3f edges, %.3f "
               "lattice; proven bound %.2f\n",
               dim, w_rand, n_pts, w_edge, w_lat, bound);
        assert_true(w_rand <= bound);
        assert_true(w_edge <= bound);
    }
}

/* Against the float noise and the exact fixed form: within the bound plus
 * their own error (float: < 3e-6 = 0.1 LSB, checked by test_noise_fixed;
 * exact: 1 LSB). */
static float fl(int dim, const int32_t *q)
{
    float p[3];
    for (int k = 0; k < dim; k++) /* low 24 bits: exact in float, period 256 */
        p[k] = (float)((int32_t)((uint32_t)q[k] << 8) >> 8) / 65536.0f;
    return dim == 2 ? pf_noise2f(p[0], p[1]) : pf_noise3f(p[0], p[1], p[2]);
}

static void test_agrees_with_float_and_exact(void **state)
{
    (void)state;
    int n_pts = quick ? 1 << 14 : 1 << 20;
    for (int dim = 2; dim <= 3; dim++) {
        double bound = dim == 2 ? PF_NOISE2_FAST_ERR : PF_NOISE3_FAST_ERR;
        double wf = 0;
        int wq = 0;
        for (int i = 0; i < n_pts; i++) {
            int32_t q[3];
            for (int k = 0; k < 3; k++)
                q[k] = (int32_t)(uint32_t)rnd();
            int16_t r = dim == 2 ? pf_noise2_q15_fast(q[0], q[1])
                                 : pf_noise3_q15_fast(q[0], q[1], q[2]);
            int16_t x = dim == 2 ? pf_noise2_q15(q[0], q[1]) : pf_noise3_q15(q[0], q[1], q[2]);
            double f = fmin(32767, fmax(-32768, (double)fl(dim, q) * 32768));
            wf = fmax(wf, fabs(r - f));
            wq = abs(r - x) > wq ? abs(r - x) : wq;
        }
        printf("# %dD fast: max |r - float·2^15| = %.3f LSB, max |r - exact q15| = %d LSB\n", dim,
               wf, wq);
        assert_true(wf <= bound + 0.1);
        assert_true(wq <= bound + 1);
    }
}

static void test_array_equals_scalar(void **state)
{
    (void)state;
    enum { LEN = 777 };
    static int32_t x[LEN], y[LEN], z[LEN];
    static int16_t o[LEN];
    for (int i = 0; i < LEN; i++) {
        x[i] = (int32_t)(uint32_t)rnd();
        y[i] = (int32_t)(uint32_t)rnd();
        z[i] = (int32_t)(uint32_t)rnd();
    }
    /* odd lengths exercise the vector loops' tails */
    for (int len = LEN; len > 0; len = len * 3 / 5) {
        pf_noise2_q15_fast_array(NULL, o, x, y, (size_t)len);
        for (int i = 0; i < len; i++)
            assert_int_equal(o[i], pf_noise2_q15_fast(x[i], y[i]));
        pf_noise3_q15_fast_array(pf_noise_default_table(), o, x, y, z, (size_t)len);
        for (int i = 0; i < len; i++)
            assert_int_equal(o[i], pf_noise3_q15_fast(x[i], y[i], z[i]));
    }
    /* in place (out aliases nothing here: int16 out, int32 in) and n = 0 */
    pf_noise3_q15_fast_array(NULL, o, x, y, z, 0);
    /* a seeded table: against the double references with its permutation */
    pf_noise_table t;
    pf_noise_table_seed(&t, 11);
    ref_perm = t.perm;
    noise_baseline_set_perm(t.perm);
    double w2 = 0, w3 = 0;
    pf_noise2_q15_fast_array(&t, o, x, y, LEN);
    for (int i = 0; i < LEN; i++) {
        int32_t q[3] = {x[i], y[i], z[i]};
        w2 = fmax(w2, err_lsb(2, o[i], q));
    }
    pf_noise3_q15_fast_array(&t, o, x, y, z, LEN);
    for (int i = 0; i < LEN; i++) {
        int32_t q[3] = {x[i], y[i], z[i]};
        w3 = fmax(w3, err_lsb(3, o[i], q));
    }
    noise_baseline_set_perm(NULL);
    ref_perm = pf_noise_perlin_perm;
    printf("# seeded table: max error %.3f (2D), %.3f (3D) LSB\n", w2, w3);
    assert_true(w2 <= PF_NOISE2_FAST_ERR);
    assert_true(w3 <= PF_NOISE3_FAST_ERR);
}

static void test_lattice_and_period(void **state)
{
    (void)state;
    for (int i = 0; i < 20000; i++) {
        int32_t q[3], r[3];
        for (int k = 0; k < 3; k++)
            q[k] = (int32_t)((uint32_t)rnd() & 0xffff0000u);
        assert_int_equal(pf_noise2_q15_fast(q[0], q[1]), 0);
        assert_int_equal(pf_noise3_q15_fast(q[0], q[1], q[2]), 0);
        for (int k = 0; k < 3; k++)
            q[k] = (int32_t)(uint32_t)rnd();
        memcpy(r, q, sizeof r);
        int ax = (int)(rnd() % 3); /* + 256k, wrapping like the hardware */
        r[ax] = (int32_t)((uint32_t)r[ax] + (uint32_t)((rnd() % 64) << 24));
        assert_int_equal(pf_noise3_q15_fast(q[0], q[1], q[2]),
                         pf_noise3_q15_fast(r[0], r[1], r[2]));
        if (ax < 2)
            assert_int_equal(pf_noise2_q15_fast(q[0], q[1]), pf_noise2_q15_fast(r[0], r[1]));
    }
}

/* FNV-1a over the results on a fixed scatter of 4096 points per dimension
 * covering the whole int32 input range.  The constants pin the bit
 * patterns: they may change only with a deliberate change of the algorithm
 * (then the accuracy tests above must still pass). */
static uint64_t fnv(uint64_t h, uint32_t v)
{
    for (int b = 0; b < 2; b++) {
        h ^= (v >> (8 * b)) & 0xff;
        h *= 0x100000001b3u;
    }
    return h;
}

static void test_golden_hashes(void **state)
{
    (void)state;
    static const uint64_t golden[4] = {0, 0, 0x398078b45f3b2ebfu, 0x58e60c2be792d017u};
    int ok = 1;
    for (int dim = 2; dim <= 3; dim++) {
        uint64_t h = 0xcbf29ce484222325u;
        for (uint32_t i = 0; i < 4096; i++) {
            int32_t q[3];
            for (int k = 0; k < 3; k++)
                q[k] = (int32_t)(i * 2654435761u ^ ((uint32_t)k * 0x9e3779b9u + (i << 7)));
            int16_t r = dim == 2 ? pf_noise2_q15_fast(q[0], q[1])
                                 : pf_noise3_q15_fast(q[0], q[1], q[2]);
            h = fnv(h, (uint16_t)r);
        }
        printf("# %dD fast golden hash 0x%016llxu\n", dim, (unsigned long long)h);
        ok &= h == golden[dim];
    }
    assert_true(ok);
}

int main(void)
{
    quick = getenv("PF_QUICK") != NULL;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fade),
        cmocka_unit_test(test_accuracy),
        cmocka_unit_test(test_agrees_with_float_and_exact),
        cmocka_unit_test(test_array_equals_scalar),
        cmocka_unit_test(test_lattice_and_period),
        cmocka_unit_test(test_golden_hashes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
