/* Number types of pfmath: float, and the fixed-point family fixed<size,exp>
 * of Pfman (Olano, PixelFlow, 4.1.1).
 *
 *   [signed] fixed<size,exp>     size magnitude bits + a sign bit
 *   unsigned fixed<size,exp>     size bits, no sign bit (also ufixed<size,exp>)
 *   float                        IEEE binary32
 *
 * value = stored * 2^-exp.  Signed is the default; a signed fixed<15,0>
 * takes 16 bits.  Storage is the smallest of (u)int8/16/32/64_t holding the
 * bits.  Parsing limits: 1 <= size <= 63, -256 <= exp <= 256 (so lsb, max
 * and min are normal doubles).  The arithmetic lives in libpfmath/pffixed.h;
 * pf_type_to_fmt gives its format descriptor. */
#ifndef PF_FIXEDTYPE_H
#define PF_FIXEDTYPE_H

#include <stddef.h>
#include <stdint.h>

#include "pffixed.h"

#define PF_TYPE_SIZE_MAX 63
#define PF_TYPE_EXP_MAX 256

typedef struct {
    int is_float;
    int is_signed;
    int size;
    int exp;
    int storage_bits;
} pf_type;

/* 0 on success; on error -1 and a one-line message (no newline) in
 * err[errlen] (err may be NULL), e.g.
 *   "malformed fixed type 'fixed<15>': expected fixed<size,exp>"
 *   "fixed<70,3>: size must be 1..63".
 * Accepts surrounding and inner blanks: "fixed < 15 , 12 >".  Keywords are
 * case-sensitive, and "signed"/"unsigned" must be separated from "fixed". */
int pf_type_parse(const char *s, pf_type *t, char *err, size_t errlen);

/* canonical spelling: "fixed<15,12>", "unsigned fixed<16,8>", "float" */
void pf_type_format(const pf_type *t, char *buf, size_t n);

/* "int16_t", "uint32_t", ..., "float" */
const char *pf_type_ctype(const pf_type *t);

/* 2^-exp; 0 for float (no fixed lsb) */
double pf_type_lsb(const pf_type *t);

/* representable range as doubles, (2^size - 1) * 2^-exp correctly rounded
 * (size > 53 rounds up to 2^size * 2^-exp); +-FLT_MAX for float */
double pf_type_max(const pf_type *t);
double pf_type_min(const pf_type *t);

/* stored-value range; 0 for float */
int64_t pf_type_max_stored(const pf_type *t);
int64_t pf_type_min_stored(const pf_type *t);

/* a fixed type with storage_bits filled in (no range check) */
pf_type pf_type_fixed(int is_signed, int size, int exp);
pf_type pf_type_float(void);

/* between pf_type and libpfmath's pf_fmt (fixed types only) */
pf_fmt pf_type_to_fmt(const pf_type *t);
pf_type pf_type_from_fmt(pf_fmt f);

#endif
