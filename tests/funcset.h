/* Helpers for reading libpfmath/functions.def (the function set, declared
 * once) in the tests and benches: a PF_FIXED row's storage tag and type
 * fields turned into a C type, a pf_fmt and pfmathgen's type spelling. */
#ifndef PF_FUNCSET_H
#define PF_FUNCSET_H

#include <stdint.h>

/* storage tag (i16 u16 i32 u32) -> C type */
#define PF_FS_CTYPE(st) PF_FS_CT_##st
#define PF_FS_CT_i16 int16_t
#define PF_FS_CT_u16 uint16_t
#define PF_FS_CT_i32 int32_t
#define PF_FS_CT_u32 uint32_t

/* storage tag -> bits of storage */
#define PF_FS_BITS(st) PF_FS_BITS_##st
#define PF_FS_BITS_i16 16
#define PF_FS_BITS_u16 16
#define PF_FS_BITS_i32 32
#define PF_FS_BITS_u32 32

/* (signed, size, exp) -> "fixed<size,exp>" or "ufixed<size,exp>", the
   spelling of mk/funcset.awk and the generated files' provenance */
#define PF_FS_TYPE(sg, size, e) PF_FS_TYPE_##sg(size, e)
#define PF_FS_TYPE_1(size, e) "fixed<" #size "," #e ">"
#define PF_FS_TYPE_0(size, e) "ufixed<" #size "," #e ">"

/* (signed, size, exp) -> pf_fmt initializer (ref/sweep_fixed.h) */
#define PF_FS_FMT(sg, size, e) {sg, size, e}

#endif
