/* pfmathgen --plot: the relative error of the emitted polynomial over its
 * domain (the seed's Figure 4.16), drawn with gnuplot as SVG. */
#ifndef PF_PLOT_H
#define PF_PLOT_H

#include "generate.h"

/* Plots one or two results side by side.  Returns 0, or -1 with a reason. */
int pf_plot_error(const char *svg, const pf_gen_result *const *r, int n, char *err, size_t errlen);

#endif
