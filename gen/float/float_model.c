#include "float_model.h"

#include <math.h>

#define FM_POINTS 8192

/* One point: the running bound of fmaf Horner for p at r (see the header). */
static void fm_point(const fit_poly *p, int order, int parity, double r, int ncomp, double rel_r,
                     double *val, double *err)
{
    const double u = 0x1p-24, uc = 0x1p-44;
    int k0 = parity == FIT_PARITY_ODD ? 1 : 0, dk = parity == FIT_PARITY_NONE ? 1 : 2;
    double z = dk == 2 ? r * r : r;
    /* error of z: r's own relative error propagates (twice for r*r), and r*r rounds once */
    double dz = dk == 2 ? fabs(z) * (2 * rel_r + u) : fabs(z) * rel_r;
    int top = order;
    while ((top - k0) % dk)
        top--;
    int nsteps = (top - k0) / dk; /* Horner steps after the leading coefficient */
    double s = (double)p->c[top], e = 0;
    for (int k = top - dk, step = 1; k >= k0; k -= dk, step++) {
        double sn = s * z + (double)p->c[k];
        double uk = step > nsteps - ncomp ? uc : u;
        e = e * fabs(z) + fabs(s) * dz + uk * fabs(sn);
        s = sn;
    }
    if (parity == FIT_PARITY_ODD) {
        /* r * q(r^2): one more product, rounded (or kept double-float) */
        double v = r * s;
        e = e * fabs(r) + fabs(s * r) * rel_r + (ncomp > 0 ? uc : u) * fabs(v);
        s = v;
    }
    *val = s;
    *err = e;
}

pf_fm_bound pf_fm_horner(const fit_poly *p, int order, int parity, double a, double b, int ncomp,
                         double rel_r)
{
    pf_fm_bound out = {0, 0, a};
    for (int i = 0; i <= FM_POINTS; i++) {
        double r = a + (b - a) * i / FM_POINTS, v, e;
        fm_point(p, order, parity, r, ncomp, rel_r, &v, &e);
        if (e > out.abs_max)
            out.abs_max = e;
        if (v != 0 && e / fabs(v) > out.rel_max) {
            out.rel_max = e / fabs(v);
            out.at = r;
        }
    }
    return out;
}
