/* Internal to libpfmath's noise files (not installed): the default table
 * and the vectorisation attributes every array form uses.  Each file keeps
 * its own `#pragma GCC optimize` (the float ones also turn off FMA
 * contraction), placed before this header. */
#ifndef PF_NOISE_IMPL_H
#define PF_NOISE_IMPL_H

#include "pfnoise.h"

#if defined(__GNUC__) && !defined(__clang__)
#define PF_IVDEP _Pragma("GCC ivdep")
#else
#define PF_IVDEP
#endif
/* runtime dispatch: the widest vectors the CPU has, any x86-64 */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define PF_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define PF_CLONES
#endif
#define PF_INLINE static inline __attribute__((always_inline))

extern pf_noise_table pf_noise_default_ __attribute__((visibility("hidden")));

#endif
