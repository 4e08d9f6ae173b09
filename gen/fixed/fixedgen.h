/* Fixed-point generation: pfmathgen with a fixed<size,exp> --type or
 * --out-type runs pf_run_fixed (gen/front/request.h) on its checked request. */
#ifndef PF_FIXEDGEN_H
#define PF_FIXEDGEN_H

#include "fixedtype.h"

#include <stddef.h>

/* Default names: pf_<func>_<in>_<out>[_fast], or pf_<func>_<t>[_fast] when
 * both types are the same, where a type's tag is q<exp> (signed) or
 * uq<exp> (unsigned) when it fills its storage, else q<size>_<exp> /
 * uq<size>_<exp>, and a negative exp is written m<|exp|>:
 *   sin  fixed<15,12> -> fixed<15,14>          pf_sin_q12_q14
 *   exp  fixed<15,11> -> unsigned fixed<16,8>  pf_exp_q11_uq8
 *   log  fixed<31,16> -> fixed<31,16>          pf_log_q16
 *   sin  fixed<10,8>  -> fixed<15,14>          pf_sin_q10_8_q14 */
void pf_fixed_type_tag(const pf_type *t, char *buf, size_t n);
void pf_fixed_default_name(const char *func, const pf_type *in, const pf_type *out, int fast, char *buf,
                           size_t n);

#endif
