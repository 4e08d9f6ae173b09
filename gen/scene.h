/* Scene-driven generation: a scene file lists what a set of shaders needs,
 * one function a line (function, variant, input type, output type); pfmathgen
 * --scene FILE -o DIR emits exactly those, each at the smallest order that
 * meets its output type, plus a header and a report. */
#ifndef PF_SCENE_H
#define PF_SCENE_H

int pfmathgen_scene_main(const char *scene, const char *outdir, const char *command);

#endif
