/* Scene-driven generation: a scene file lists what a set of shaders needs,
 * one function a line (function, variant, input type, output type); pfmathgen
 * --scene FILE -o DIR emits exactly those, each at the smallest order that
 * meets its output type, plus a header and a report.
 * Gradient noise is listed by dimension, fixed point only, variant
 * optional (exact is the only one): 'noise3 fixed<15,12> fixed<15,14>';
 * scene.h then declares OUT name(IN x, IN y, IN z) and
 * void name_array(const IN *x, const IN *y, const IN *z, OUT *out, size_t n). */
#ifndef PF_SCENE_H
#define PF_SCENE_H

int pfmathgen_scene_main(const char *scene, const char *outdir, const char *command);

#endif
