/* Supnorm of the approximation error of the emitted polynomial over D:
 * a dense grid in binary128 (g from MPFR), then golden-section refinement
 * around the largest peaks, since the extrema of a near-minimax error curve
 * are sharp and sit between grid points. */
#include "fit.h"
#include "linalg.h"

#include <stdlib.h>

#define GRID 4096
#define PEAKS 8

static fit_real err_at(const fit_problem *pb, const fit_poly *p, fit_real t, int *bad)
{
    fit_real g = fit_eval_target(pb, t);
    fit_real v = fit_eval_poly(p, t);
    if (pb->errkind == FIT_ABS)
        return la_fabs(v - g);
    if (g == 0) {
        if (v != 0)
            *bad = 1;
        return 0;
    }
    return la_fabs((v - g) / g);
}

void fit_measure(const fit_problem *pb, fit_poly *p)
{
    fit_real *e = malloc(sizeof(fit_real) * (GRID + 1));
    fit_real h = (pb->b - pb->a) / GRID;
    int bad = 0;
    for (int i = 0; i <= GRID; i++)
        e[i] = err_at(pb, p, i == GRID ? pb->b : pb->a + h * i, &bad);
    fit_real best = 0, best_t = pb->a;
    /* the PEAKS largest local maxima, each refined on its bracket */
    int used[PEAKS];
    for (int q = 0; q < PEAKS; q++) {
        int im = -1;
        for (int i = 0; i <= GRID; i++) {
            int ok = (i == 0 || e[i] >= e[i - 1]) && (i == GRID || e[i] >= e[i + 1]);
            for (int u = 0; u < q && ok; u++)
                if (used[u] == i)
                    ok = 0;
            if (ok && (im < 0 || e[i] > e[im]))
                im = i;
        }
        if (im < 0)
            break;
        used[q] = im;
        fit_real lo = im == 0 ? pb->a : pb->a + h * (im - 1);
        fit_real hi = im == GRID ? pb->b : pb->a + h * (im + 1);
        fit_real r = (fit_real)0.6180339887498948482045868343656381;
        fit_real x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo);
        fit_real f1 = err_at(pb, p, x1, &bad), f2 = err_at(pb, p, x2, &bad);
        for (int it = 0; it < 60; it++) {
            if (f1 > f2) {
                hi = x2; x2 = x1; f2 = f1;
                x1 = hi - r * (hi - lo);
                f1 = err_at(pb, p, x1, &bad);
            } else {
                lo = x1; x1 = x2; f1 = f2;
                x2 = lo + r * (hi - lo);
                f2 = err_at(pb, p, x2, &bad);
            }
        }
        fit_real cand[3] = {e[im], f1, f2};
        fit_real ct[3] = {im == GRID ? pb->b : pb->a + h * im, x1, x2};
        for (int c = 0; c < 3; c++)
            if (cand[c] > best) {
                best = cand[c];
                best_t = ct[c];
            }
    }
    free(e);
    p->max_err = bad ? __builtin_inf() : (double)best;
    p->max_err_at = (double)best_t;
}
