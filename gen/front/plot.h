/* pfmathgen --plot: the relative error of the emitted polynomial over its
 * domain (the seed's Figure 4.16), drawn with gnuplot as SVG. */
#ifndef PF_PLOT_H
#define PF_PLOT_H

#include "generate.h"

/* Draws one or two results side by side into *svg (malloc'd, *len bytes);
 * the caller writes it (gen/front/output.h).  gnuplot gets its script, data
 * inline, on stdin and writes the SVG on stdout: no file name of the user's
 * reaches gnuplot or a shell.  Returns 0, or -1 with a reason. */
int pf_plot_svg(const pf_gen_result *const *r, int n, char **svg, size_t *len, char *err, size_t errlen);

#endif
