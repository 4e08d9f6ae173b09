/* pfbench: issue 13's Pareto checks (pfbench_ladder.h).  A peer point (t, e)
 * is covered when a pfmath point of the same ISA has error <= e and time <=
 * t; the ratio shown is t over the time of the fastest pfmath point with
 * error <= e, so >= 1 is a pass and below 1 says how much faster pfmath's
 * nearest-accuracy point must get. */
#include "pfbench_ladder.h"

#include <math.h>
#include <string.h>

static int vector_peer(const pfb_point *p)
{
    return !p->ours && (!strcmp(p->isa, "avx2") || !strcmp(p->isa, "avx512")) && isfinite(p->t) &&
           isfinite(p->e);
}

void pfb_pareto_checks(FILE *md, const char *fn, const char *dom, const pfb_point *p, int n, int *pass,
                       int *miss)
{
    for (int i = 0; i < n; i++) {
        if (!vector_peer(&p[i]))
            continue;
        int best = -1;
        for (int j = 0; j < n; j++)
            if (p[j].ours && !strcmp(p[j].isa, p[i].isa) && isfinite(p[j].t) && p[j].e <= p[i].e &&
                (best < 0 || p[j].t < p[best].t))
                best = j;
        if (best < 0) {
            (*miss)++;
            fprintf(md, "| %s | %s | %s | %s | %.3g ns, %.3g ULP | none as accurate | — | **MISS** |\n", fn, dom,
                    p[i].isa, p[i].name, p[i].t, p[i].e);
            continue;
        }
        double ratio = p[i].t / p[best].t;
        int ok = p[best].t <= p[i].t;
        ok ? (*pass)++ : (*miss)++;
        fprintf(md, "| %s | %s | %s | %s | %.3g ns, %.3g ULP | %s: %.3g ns, %.3g ULP | %.2fx | %s |\n", fn, dom,
                p[i].isa, p[i].name, p[i].t, p[i].e, p[best].name, p[best].t, p[best].e, ratio,
                ok ? "pass" : "**MISS**");
    }
}

void pfb_ladder_table(FILE *md, const char *fn, const char *dom, const pfb_point *p, int n)
{
    for (int i = 0; i < n; i++) {
        if (p[i].ours != PFB_OURS_LADDER || !isfinite(p[i].t) || !isfinite(p[i].e))
            continue;
        int near = -1;
        double dist = INFINITY;
        for (int j = 0; j < n; j++) {
            if (!vector_peer(&p[j]) || strcmp(p[j].isa, p[i].isa))
                continue;
            /* log distance; errors of 0 count as 2^-10 ULP */
            double d = fabs(log2(fmax(p[j].e, 0x1p-10)) - log2(fmax(p[i].e, 0x1p-10)));
            if (d < dist)
                dist = d, near = j;
        }
        if (near < 0) {
            fprintf(md, "| %s | %s | %s | %s | %.3g | %.3g | — | | | |\n", fn, dom, p[i].isa, p[i].name, p[i].t,
                    p[i].e);
            continue;
        }
        fprintf(md, "| %s | %s | %s | %s | %.3g | %.3g | %s | %.3g | %.3g | %.2fx |\n", fn, dom, p[i].isa,
                p[i].name, p[i].t, p[i].e, p[near].name, p[near].t, p[near].e, p[near].t / p[i].t);
    }
}
