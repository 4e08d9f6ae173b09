#include "plot.h"

#include "subproc.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define NPTS 2000

static void script(FILE *g, const pf_gen_result *const *r, int n)
{
    fprintf(g, "set terminal svg size %d,420 dynamic font 'sans,11'\nset output\n", 560 * n);
    /* the data as datablocks (gnuplot >= 5.0): no data files */
    for (int i = 0; i < n; i++) {
        fprintf(g, "$E%d << EOD\n", i);
        const fit_problem *pb = &r[i]->pb;
        for (int k = 0; k <= NPTS; k++) {
            fit_real t = pb->a + (pb->b - pb->a) * k / NPTS;
            fit_real y = fit_eval_target(pb, t), p = fit_eval_poly(&r[i]->poly, t);
            double e = pb->errkind == FIT_REL ? (y == 0 ? 0 : (double)((p - y) / y)) : (double)(p - y);
            fprintf(g, "%.17g %.6e\n", (double)t, e);
        }
        fprintf(g, "EOD\n");
    }
    if (n > 1)
        fprintf(g, "set multiplot layout 1,%d\n", n);
    for (int i = 0; i < n; i++) {
        /* every string below comes from the function table, not the user */
        const pf_spec *s = r[i]->spec;
        fprintf(g, "set title \"%s %s: order %d, max |%s error| %.3g\"\n", s->func, s->variant, r[i]->order,
                r[i]->pb.errkind == FIT_REL ? "rel" : "abs", r[i]->poly.max_err);
        fprintf(g, "set xlabel \"t (%s)\"\nset ylabel \"%s error of the emitted polynomial\"\n",
                s->target_text, r[i]->pb.errkind == FIT_REL ? "relative" : "absolute");
        fprintf(g, "set grid\nset format y '%%.1e'\nunset key\n");
        fprintf(g, "plot $E%d using 1:2 with lines lw 1.5 lc rgb '#1f5fa8'\n", i);
    }
    if (n > 1)
        fprintf(g, "unset multiplot\n");
}

/* the whole of f from its start, malloc'd and NUL-terminated */
static char *slurp(FILE *f, size_t *len)
{
    fflush(f);
    long n = ftell(f);
    if (n < 0 || fseek(f, 0, SEEK_SET) != 0)
        return NULL;
    char *s = malloc((size_t)n + 1);
    size_t got = s ? fread(s, 1, (size_t)n, f) : 0;
    if (s)
        s[got] = 0;
    *len = got;
    return s;
}

int pf_plot_svg(const pf_gen_result *const *r, int n, char **svg, size_t *len, char *err, size_t errlen)
{
    *svg = NULL;
    *len = 0;
    /* unnamed temporary files: stdin, stdout and stderr of gnuplot */
    FILE *in = tmpfile(), *out = tmpfile(), *log = tmpfile();
    int rc = -1;
    if (!in || !out || !log) {
        snprintf(err, errlen, "cannot create a temporary file for gnuplot");
        goto done;
    }
    script(in, r, n);
    if (fflush(in) != 0 || fseek(in, 0, SEEK_SET) != 0) {
        snprintf(err, errlen, "cannot write gnuplot's script");
        goto done;
    }
    char *argv[] = {"gnuplot", NULL};
    int st = pf_spawn(argv, fileno(in), fileno(out), fileno(log));
    fseek(log, 0, SEEK_END);
    size_t ln;
    char *msg = slurp(log, &ln);
    if (msg) {
        /* gnuplot's first non-blank line */
        char *p = msg + strspn(msg, " \t\r\n");
        p[strcspn(p, "\r\n")] = 0;
        if (st == 127 && !*p)
            snprintf(err, errlen, "cannot run gnuplot (is gnuplot-nox installed?)");
        else if (st != 0)
            snprintf(err, errlen, "gnuplot failed%s%s", *p ? ": " : "", p);
        free(msg);
    }
    if (st != 0) {
        if (!msg)
            snprintf(err, errlen, "gnuplot failed");
        goto done;
    }
    fseek(out, 0, SEEK_END);
    *svg = slurp(out, len);
    if (!*svg || !strstr(*svg, "</svg>")) {
        snprintf(err, errlen, "gnuplot wrote no SVG");
        free(*svg);
        *svg = NULL;
        goto done;
    }
    rc = 0;
done:
    if (in)
        fclose(in);
    if (out)
        fclose(out);
    if (log)
        fclose(log);
    return rc;
}
