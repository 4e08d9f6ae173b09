/* Scene-driven generation: a scene file lists what a set of shaders needs,
 * one function a line (function, variant, input type, output type); pfmathgen
 * --scene FILE -o DIR emits exactly those, each at the smallest order that
 * meets its output type, plus scene.h (with extern "C" guards) and
 * report.txt.  Lines may be of any length; '#' starts a comment; a NUL byte
 * is an error.
 * Names: a prefix (--prefix P, default the scene file's name up to its
 * first '.', then '_': brick.scene -> brick_) replaces libpfmath's "pf_", so
 * a program can link a scene and libpfmath together:
 *   float    P<func>f, P<func>f_fast                  brick_expf
 *   fixed    P<func>[_fast]_<in>_<out>, a type as      brick_sin_s15_12_s15_14
 *            s|u<size>_<exp> (m<|exp|> when negative)
 *   noise    P<noiseN>_<in>_<out>                      brick_noise3_s15_12_s15_14
 * Gradient noise is listed by dimension, fixed point only, variant
 * optional (exact is the only one): 'noise3 fixed<15,12> fixed<15,14>';
 * scene.h then declares OUT name(IN x, IN y, IN z) and
 * void name_array(const IN *x, const IN *y, const IN *z, OUT *out, size_t n).
 * DIR may exist: its files are replaced one by one (gen/front/output.h), only
 * after every entry was generated; nothing else in DIR is touched. */
#ifndef PF_SCENE_H
#define PF_SCENE_H

#include "request.h"

/* 0, 2 (bad scene, bad DIR, impossible entry: one line on stderr), 1 */
int pf_scene_run(const pf_request *rq);

#endif
