#include "plot.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define NPTS 2000

int pf_plot_error(const char *svg, const pf_gen_result *const *r, int n, char *err, size_t errlen)
{
    char dir[] = "/tmp/pfplot.XXXXXX";
    if (!mkdtemp(dir)) {
        snprintf(err, errlen, "cannot create a temporary directory");
        return -1;
    }
    char dat[2][64], gp[64];
    for (int i = 0; i < n; i++) {
        snprintf(dat[i], sizeof dat[i], "%s/e%d.dat", dir, i);
        FILE *f = fopen(dat[i], "w");
        if (!f) {
            snprintf(err, errlen, "cannot write %s", dat[i]);
            return -1;
        }
        const fit_problem *pb = &r[i]->pb;
        for (int k = 0; k <= NPTS; k++) {
            fit_real t = pb->a + (pb->b - pb->a) * k / NPTS;
            fit_real g = fit_eval_target(pb, t), p = fit_eval_poly(&r[i]->poly, t);
            double e = pb->errkind == FIT_REL ? (g == 0 ? 0 : (double)((p - g) / g)) : (double)(p - g);
            fprintf(f, "%.17g %.6e\n", (double)t, e);
        }
        fclose(f);
    }
    snprintf(gp, sizeof gp, "%s/plot.gp", dir);
    FILE *g = fopen(gp, "w");
    if (!g) {
        snprintf(err, errlen, "cannot write %s", gp);
        return -1;
    }
    fprintf(g, "set terminal svg size %d,420 dynamic font 'sans,11'\nset output '%s'\n", 560 * n, svg);
    if (n > 1)
        fprintf(g, "set multiplot layout 1,%d\n", n);
    for (int i = 0; i < n; i++) {
        const pf_spec *s = r[i]->spec;
        fprintf(g, "set title \"%s %s: order %d, max |%s error| %.3g\"\n", s->func, s->variant, r[i]->order,
                r[i]->pb.errkind == FIT_REL ? "rel" : "abs", r[i]->poly.max_err);
        fprintf(g, "set xlabel \"t (%s)\"\nset ylabel \"%s error of the emitted polynomial\"\n",
                s->target_text, r[i]->pb.errkind == FIT_REL ? "relative" : "absolute");
        fprintf(g, "set grid\nset format y '%%.1e'\nunset key\n");
        fprintf(g, "plot '%s' using 1:2 with lines lw 1.5 lc rgb '#1f5fa8'\n", dat[i]);
    }
    if (n > 1)
        fprintf(g, "unset multiplot\n");
    fclose(g);
    char cmd[256];
    snprintf(cmd, sizeof cmd, "gnuplot '%s' 2>'%s/gp.log'", gp, dir);
    int rc = system(cmd);
    char log[300] = "";
    snprintf(cmd, sizeof cmd, "%s/gp.log", dir);
    FILE *l = fopen(cmd, "r");
    if (l) {
        if (!fgets(log, sizeof log, l))
            log[0] = 0;
        fclose(l);
    }
    log[strcspn(log, "\n")] = 0;
    unlink(cmd);
    for (int i = 0; i < n; i++)
        unlink(dat[i]);
    unlink(gp);
    rmdir(dir);
    if (rc != 0) {
        snprintf(err, errlen, "gnuplot failed%s%s (is gnuplot-nox installed?)", log[0] ? ": " : "", log);
        unlink(svg);
        return -1;
    }
    return 0;
}
