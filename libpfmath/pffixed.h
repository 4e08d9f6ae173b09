/* pffixed.h — fixed-point arithmetic for pfmath (header only, integer only).
 *
 * A fixed-point number is a stored integer v and a format
 *     fixed<size,exp>            value = v * 2^-exp
 * as in Pfman (Olano, PixelFlow, 4.1.1): `size` bits of magnitude plus a
 * sign bit when signed, so a signed fixed<15,0> is an int16_t.  Signed
 * stored values range over [-2^size, 2^size - 1] (two's complement: the
 * seed's fixed<10,10> holds -1 up to just under 1), unsigned ones over
 * [0, 2^size - 1].  exp may be negative or larger than size.
 *
 * C has no templates, so every operation takes (int64_t stored value,
 * pf_fmt) pairs and the caller names the output format; pf_fmt_mul & co.
 * give the seed's bit-width rules for choosing it.  Inputs are plain int64_t
 * values (they need not lie inside their format's range); every result is
 * computed exactly, rounded once and saturated to the output format.
 *
 *   formats   pf_fmt, pf_fmt_make, pf_fmt_max_stored/min_stored/storage_bits
 *   rules     pf_fmt_mul, pf_fmt_add, pf_fmt_sub (seed), pf_fmt_div, pf_fmt_sqrt
 *   convert   pf_fx_convert, pf_fx_from_double/float, pf_fx_to_double/float
 *   arith     pf_fx_add, pf_fx_sub, pf_fx_mul, pf_fx_div, pf_fx_sqrt
 *   kernels   pf_mulshift16/32/64, pf_fx_horner32, pf_fx_horner
 *
 * Rounding: to nearest, ties to even, everywhere (fixed->float too).
 * Chosen over ties-away-from-zero because it is unbiased (rounding errors
 * in a Horner chain do not drift one way) and it is the IEEE-754 and
 * MPFR_RNDN default, so the float conversions and the references use the
 * same rule.  Both are odd-symmetric; both cost about three operations more
 * per rounding than add-half-and-shift (ties towards +inf).
 *
 * Saturation: results outside the output range become its max or min.
 * NaN converts to 0 (it has no sign to saturate towards); +-inf saturate.
 * x / 0 gives max for x >= 0 (0/0 included, taken as +0/+0) and min for
 * x < 0: the sign of the infinite quotient.  sqrt of a negative gives 0
 * (NaN -> 0, as for conversions).
 *
 * Undefined behaviour: none for any int64_t inputs and valid formats
 * (1 <= size <= 63; formats are not checked).  Shifts of signed values are
 * done on unsigned types, floor shifts of negatives as ~(~x >> s), and every
 * shift count is checked.
 *
 * The exact generic operations need a 128-bit integer: unsigned __int128
 * where the compiler has it, otherwise a portable two-limb version (define
 * PF_FX_NO_INT128 to force it; the tests build both).  The hot primitives
 * the code generator emits (pf_mulshift16/32, pf_fx_horner32) use only
 * 32/64-bit integers.
 */
#ifndef PFFIXED_H
#define PFFIXED_H

#include <stdint.h>

typedef struct { int8_t is_signed; int8_t size; int16_t exp; } pf_fmt;

static inline pf_fmt pf_fmt_make(int is_signed, int size, int exp)
{
    pf_fmt f = { (int8_t)(is_signed != 0), (int8_t)size, (int16_t)exp };
    return f;
}

static inline int64_t pf_fmt_max_stored(pf_fmt f)
{
    return (int64_t)(((uint64_t)1 << f.size) - 1);
}

static inline int64_t pf_fmt_min_stored(pf_fmt f)
{
    return f.is_signed ? -pf_fmt_max_stored(f) - 1 : 0;
}

/* smallest of 8/16/32/64 bits holding size (+1 sign) bits */
static inline int pf_fmt_storage_bits(pf_fmt f)
{
    int need = f.size + (f.is_signed != 0);
    return need <= 8 ? 8 : need <= 16 ? 16 : need <= 32 ? 32 : 64;
}

/* ---------------------------------------------------------------------- */
/* Bit-width rules (Olano 4.3.3, bottom-up pass).  A result wider than 63   */
/* bits keeps its integer bits and drops fraction bits (exp lowered).       */

static inline pf_fmt pf__fmt_capped(int is_signed, int size, int exp)
{
    if (size > 63) {
        exp -= size - 63;
        size = 63;
    }
    if (exp > INT16_MAX)
        exp = INT16_MAX;
    if (exp < INT16_MIN)
        exp = INT16_MIN;
    return pf_fmt_make(is_signed, size, exp);
}

/* Multiplication adds sizes and exponents.  Exact except for min*min of two
 * signed operands (-2^sa * -2^sb = 2^(sa+sb), one past the max): the seed's
 * rule keeps fixed<10,10>*fixed<10,10> = fixed<20,20>, so that one product
 * saturates to max, an error of one lsb. */
static inline pf_fmt pf_fmt_mul(pf_fmt a, pf_fmt b)
{
    return pf__fmt_capped(a.is_signed || b.is_signed, a.size + b.size, a.exp + b.exp);
}

/* Addition aligns the exponents (keeps the finer lsb) and grows one integer
 * bit over the wider operand: |a + b| < 2^ia + 2^ib <= 2^(max(ia,ib)+1). */
static inline pf_fmt pf_fmt_add(pf_fmt a, pf_fmt b)
{
    int e = a.exp > b.exp ? a.exp : b.exp;
    int ia = a.size - a.exp, ib = b.size - b.exp;
    int i = (ia > ib ? ia : ib) + 1;
    return pf__fmt_capped(a.is_signed || b.is_signed, i + e, e);
}

/* Subtraction: as addition, but always signed (unsigned - unsigned can be
 * negative). */
static inline pf_fmt pf_fmt_sub(pf_fmt a, pf_fmt b)
{
    pf_fmt f = pf_fmt_add(a, b);
    f.is_signed = 1;
    return f;
}

/* Division (not in the seed; our rule, symmetric to multiplication): sizes
 * add; the range reaches max|a| / lsb(b) = 2^(sa-ea+eb) and the resolution
 * lsb(a) / max|b| = 2^-(ea+sb-eb), so exp = ea - eb + sb. */
static inline pf_fmt pf_fmt_div(pf_fmt a, pf_fmt b)
{
    return pf__fmt_capped(a.is_signed || b.is_signed, a.size + b.size, a.exp - b.exp + b.size);
}

/* Square root (not in the seed; our rule): unsigned, same size, integer bits
 * ceil(ia/2) since sqrt(x) < 2^(ia/2) for x < 2^ia. */
static inline pf_fmt pf_fmt_sqrt(pf_fmt a)
{
    int ia = a.size - a.exp;
    int ir = ia >= 0 ? (ia + 1) / 2 : -((-ia) / 2);
    return pf__fmt_capped(0, a.size, a.size - ir);
}

/* ---------------------------------------------------------------------- */
/* 64-bit helpers                                                           */

/* uint64_t -> int64_t, two's complement, without implementation-defined
 * conversion (compiles to nothing). */
static inline int64_t pf__u2i64(uint64_t u)
{
    return u <= (uint64_t)INT64_MAX ? (int64_t)u : -(int64_t)~u - 1;
}

static inline uint64_t pf__abs64(int64_t x)
{
    return x < 0 ? (uint64_t)0 - (uint64_t)x : (uint64_t)x;
}

static inline int pf__bitlen64(uint64_t x)
{
#if defined(__GNUC__)
    return x ? 64 - __builtin_clzll(x) : 0;
#else
    int n = 0;
    while (x) {
        n++;
        x >>= 1;
    }
    return n;
#endif
}

/* RNE(p / 2^s) for |p| <= 2^62 and 1 <= s <= 62.  Bias p by 2^63 so the
 * shift is of an unsigned value; adding half - 1 plus the lsb of the
 * truncated quotient rounds ties to even (the bias 2^(63-s) is even). */
static inline int64_t pf__rne_shr64(int64_t p, int s)
{
    uint64_t u = (uint64_t)p + ((uint64_t)1 << 63);
    u += ((uint64_t)1 << (s - 1)) - 1 + ((u >> s) & 1);
    return pf__u2i64((u >> s) - ((uint64_t)1 << (63 - s)));
}

/* Same for |p| <= 2^30, 1 <= s <= 30, in 32-bit arithmetic. */
static inline int32_t pf__rne_shr32(int32_t p, int s)
{
    uint32_t u = (uint32_t)p + ((uint32_t)1 << 31);
    u += ((uint32_t)1 << (s - 1)) - 1 + ((u >> s) & 1);
    u = (u >> s) - ((uint32_t)1 << (31 - s));
    return u <= (uint32_t)INT32_MAX ? (int32_t)u : -(int32_t)~u - 1;
}

static inline int32_t pf__sat32(int64_t x)
{
    return x > INT32_MAX ? INT32_MAX : x < INT32_MIN ? INT32_MIN : (int32_t)x;
}

static inline int16_t pf__sat16(int32_t x)
{
    return x > INT16_MAX ? INT16_MAX : x < INT16_MIN ? INT16_MIN : (int16_t)x;
}

/* ---------------------------------------------------------------------- */
/* Multiply-shift primitives: RNE(a * b * 2^-shift), saturated to the type. */
/* shift < 0 multiplies by 2^-shift exactly.  These are what generated      */
/* fixed-point polynomial code is made of.                                 */

/* a * b * 2^-shift as int64_t: exact product |p| <= 2^62, rounded once.
 * Left shifts clamp to +-2^40, beyond any int32 saturation threshold plus an
 * int32 addend, so callers that saturate to 32 bits see the right result. */
static inline int64_t pf__mulshift32_wide(int32_t a, int32_t b, int shift)
{
    int64_t p = (int64_t)a * b;
    if (shift > 0)
        return shift > 62 ? 0 : pf__rne_shr64(p, shift); /* |p| <= 2^62: < 1/2 lsb */
    if (shift < 0 && p != 0) {
        int ls = -shift;
        if (ls > 40 || pf__abs64(p) > ((uint64_t)1 << (40 - ls)))
            return p > 0 ? (int64_t)1 << 40 : -((int64_t)1 << 40);
        return p * ((int64_t)1 << ls);
    }
    return p;
}

static inline int32_t pf_mulshift32(int32_t a, int32_t b, int shift)
{
    return pf__sat32(pf__mulshift32_wide(a, b, shift));
}

static inline int16_t pf_mulshift16(int16_t a, int16_t b, int shift)
{
    int32_t p = (int32_t)a * (int32_t)b; /* |p| <= 2^30 */
    if (shift > 0)
        return pf__sat16(shift > 30 ? 0 : pf__rne_shr32(p, shift));
    if (shift < 0 && p != 0) {
        int ls = -shift;
        if (ls > 16 || (p > 0 ? p : -p) > ((int32_t)1 << (16 - ls)))
            return p > 0 ? INT16_MAX : INT16_MIN;
        p *= (int32_t)1 << ls;
    }
    return pf__sat16(p);
}

/* Horner on int32 stored values:
 *     p = c[n];  for k = n-1 .. 0:  p = sat32(RNE(p * x * 2^-shift[k]) + c[k])
 * c[k] at p_k's exponent.  Equals pf_fx_horner (below) with every step
 * format a signed fixed<31,e>: the product is not saturated, only each
 * partial sum, to int32_t. */
static inline int32_t pf_fx_horner32(int32_t x, const int32_t *c, const int8_t *shift, int n)
{
    int32_t p = c[n];
    for (int k = n - 1; k >= 0; k--)
        p = pf__sat32(pf__mulshift32_wide(p, x, shift[k]) + c[k]);
    return p;
}

/* ---------------------------------------------------------------------- */
/* 128-bit two's complement integers (internal).                            */

#if defined(__SIZEOF_INT128__) && !defined(PF_FX_NO_INT128)
#define PF_FX_INT128 1
__extension__ typedef unsigned __int128 pf__w;

static inline pf__w pf__w_u64(uint64_t x) { return x; }
static inline pf__w pf__w_i64(int64_t x) { return (pf__w)x; } /* sign-extends */
static inline pf__w pf__w_add(pf__w a, pf__w b) { return a + b; }
static inline pf__w pf__w_sub(pf__w a, pf__w b) { return a - b; }
static inline pf__w pf__w_neg(pf__w a) { return -a; }
static inline pf__w pf__w_not(pf__w a) { return ~a; }
static inline pf__w pf__w_shl(pf__w a, int s) { return a << s; } /* 0 <= s <= 127 */
static inline pf__w pf__w_shr(pf__w a, int s) { return a >> s; }
static inline pf__w pf__w_mask(pf__w a, int s) { return a & ((((pf__w)1) << s) - 1); }
static inline int pf__w_isneg(pf__w a) { return (int)(a >> 127); }
static inline int pf__w_eq(pf__w a, pf__w b) { return a == b; }
static inline int pf__w_ltu(pf__w a, pf__w b) { return a < b; }
static inline uint64_t pf__w_lo(pf__w a) { return (uint64_t)a; }
static inline pf__w pf__w_mulu(uint64_t a, uint64_t b) { return (pf__w)a * b; }
static inline pf__w pf__w_divu(pf__w n, uint64_t d, uint64_t *rem)
{
    *rem = (uint64_t)(n % d);
    return n / d;
}
#else
#define PF_FX_INT128 0
typedef struct { uint64_t hi, lo; } pf__w;

static inline pf__w pf__w_u64(uint64_t x) { pf__w r = { 0, x }; return r; }
static inline pf__w pf__w_i64(int64_t x)
{
    pf__w r = { x < 0 ? ~(uint64_t)0 : 0, (uint64_t)x };
    return r;
}
static inline pf__w pf__w_add(pf__w a, pf__w b)
{
    pf__w r;
    r.lo = a.lo + b.lo;
    r.hi = a.hi + b.hi + (r.lo < a.lo);
    return r;
}
static inline pf__w pf__w_sub(pf__w a, pf__w b)
{
    pf__w r;
    r.lo = a.lo - b.lo;
    r.hi = a.hi - b.hi - (a.lo < b.lo);
    return r;
}
static inline pf__w pf__w_neg(pf__w a) { return pf__w_sub(pf__w_u64(0), a); }
static inline pf__w pf__w_not(pf__w a) { pf__w r = { ~a.hi, ~a.lo }; return r; }
static inline pf__w pf__w_shl(pf__w a, int s)
{
    pf__w r;
    if (s == 0)
        return a;
    if (s < 64) {
        r.hi = a.hi << s | a.lo >> (64 - s);
        r.lo = a.lo << s;
    } else {
        r.hi = a.lo << (s - 64);
        r.lo = 0;
    }
    return r;
}
static inline pf__w pf__w_shr(pf__w a, int s)
{
    pf__w r;
    if (s == 0)
        return a;
    if (s < 64) {
        r.lo = a.lo >> s | a.hi << (64 - s);
        r.hi = a.hi >> s;
    } else {
        r.lo = a.hi >> (s - 64);
        r.hi = 0;
    }
    return r;
}
static inline pf__w pf__w_mask(pf__w a, int s)
{
    if (s < 64) {
        pf__w r = { 0, s ? a.lo & (~(uint64_t)0 >> (64 - s)) : 0 };
        return r;
    } else {
        pf__w r = { s > 64 ? a.hi & (~(uint64_t)0 >> (128 - s)) : 0, a.lo };
        return r;
    }
}
static inline int pf__w_isneg(pf__w a) { return (int)(a.hi >> 63); }
static inline int pf__w_eq(pf__w a, pf__w b) { return a.hi == b.hi && a.lo == b.lo; }
static inline int pf__w_ltu(pf__w a, pf__w b)
{
    return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo);
}
static inline uint64_t pf__w_lo(pf__w a) { return a.lo; }
/* 64x64 -> 128 from four 32x32 -> 64 partial products */
static inline pf__w pf__w_mulu(uint64_t a, uint64_t b)
{
    uint64_t a0 = (uint32_t)a, a1 = a >> 32, b0 = (uint32_t)b, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p10; /* < 3 * 2^32 */
    pf__w r;
    r.lo = (mid << 32) | (uint32_t)p00;
    r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    return r;
}
/* restoring division, one quotient bit per step; r < d throughout, and the
 * bit shifted out of r (carry) means 2r + bit >= 2^64 > d */
static inline pf__w pf__w_divu(pf__w n, uint64_t d, uint64_t *rem)
{
    pf__w q = { 0, 0 };
    uint64_t r = 0;
    for (int i = 127; i >= 0; i--) {
        uint64_t bit = i >= 64 ? (n.hi >> (i - 64)) & 1 : (n.lo >> i) & 1;
        uint64_t carry = r >> 63;
        r = (r << 1) | bit;
        if (carry || r >= d) {
            r -= d;
            if (i >= 64)
                q.hi |= (uint64_t)1 << (i - 64);
            else
                q.lo |= (uint64_t)1 << i;
        }
    }
    *rem = r;
    return q;
}
#endif

/* floor(a / 2^s) of a two's complement value, 0 <= s <= 127 */
static inline pf__w pf__w_sar(pf__w a, int s)
{
    return pf__w_isneg(a) ? pf__w_not(pf__w_shr(pf__w_not(a), s)) : pf__w_shr(a, s);
}

static inline int pf__w_lts(pf__w a, pf__w b)
{
    int na = pf__w_isneg(a), nb = pf__w_isneg(b);
    return na != nb ? na : pf__w_ltu(a, b);
}

static inline int64_t pf__w_toi64(pf__w a) { return pf__u2i64(pf__w_lo(a)); }

/* exact signed product, |a * b| <= 2^126 */
static inline pf__w pf__w_muls(int64_t a, int64_t b)
{
    pf__w p = pf__w_mulu(pf__abs64(a), pf__abs64(b));
    return (a < 0) != (b < 0) ? pf__w_neg(p) : p;
}

#define PF__W_CLAMP 70 /* see pf__w_shl_clamp */

/* t * 2^ls for ls >= 0, clamped to +-2^70.  Every format range lies inside
 * +-2^63 and the callers add at most ~2^64 more after this, so the clamp
 * keeps both the sign and the outcome of the final saturation. */
static inline pf__w pf__w_shl_clamp(pf__w t, int ls)
{
    int neg = pf__w_isneg(t);
    pf__w m = neg ? pf__w_neg(t) : t;
    pf__w big = pf__w_shl(pf__w_u64(1), PF__W_CLAMP);
    if (pf__w_eq(m, pf__w_u64(0)))
        return m;
    if (ls >= PF__W_CLAMP || pf__w_ltu(pf__w_shr(big, ls), m))
        return neg ? pf__w_neg(big) : big;
    return pf__w_shl(t, ls);
}

/* RNE((t + phi) * 2^-s) where phi = 0 if !sticky, else 0 < phi < 1 (the
 * floor-truncated part of an exact value; then s >= 1 is required).
 * Requires |t| <= 2^126, and |t| < 2^126 when sticky.  s <= 0 is an exact
 * multiplication (clamped, see above). */
static inline pf__w pf__w_round(pf__w t, int sticky, int s)
{
    if (s <= 0)
        return pf__w_shl_clamp(t, -s);
    if (s >= 127) /* |t + phi| <= 2^126: at most 1/2, and a tie goes to 0 */
        return pf__w_u64(0);
    pf__w q = pf__w_sar(t, s);
    pf__w rem = pf__w_mask(t, s);
    pf__w half = pf__w_shl(pf__w_u64(1), s - 1);
    int up;
    if (pf__w_ltu(half, rem))
        up = 1;
    else if (pf__w_eq(rem, half))
        up = sticky || (pf__w_lo(q) & 1);
    else
        up = 0;
    return up ? pf__w_add(q, pf__w_u64(1)) : q;
}

static inline int64_t pf__w_sat(pf__w t, pf_fmt f)
{
    int64_t hi = pf_fmt_max_stored(f), lo = pf_fmt_min_stored(f);
    if (pf__w_lts(pf__w_i64(hi), t))
        return hi;
    if (pf__w_lts(t, pf__w_i64(lo)))
        return lo;
    return pf__w_toi64(t);
}

/* ---------------------------------------------------------------------- */
/* Conversions                                                              */

static inline int64_t pf_fx_convert(int64_t v, pf_fmt from, pf_fmt to)
{
    return pf__w_sat(pf__w_round(pf__w_i64(v), 0, from.exp - to.exp), to);
}

/* x = m * 2^e exactly from the IEEE bits; then one rounding. */
static inline int64_t pf_fx_from_double(double x, pf_fmt to)
{
    union { double d; uint64_t u; } b = { x };
    int neg = (int)(b.u >> 63), be = (int)(b.u >> 52) & 0x7ff;
    uint64_t m = b.u & (((uint64_t)1 << 52) - 1);
    if (be == 0x7ff) {
        if (m)
            return 0; /* NaN */
        return neg ? pf_fmt_min_stored(to) : pf_fmt_max_stored(to);
    }
    if (be == 0)
        be = 1; /* subnormal */
    else
        m |= (uint64_t)1 << 52;
    pf__w t = pf__w_u64(m);
    if (neg)
        t = pf__w_neg(t);
    return pf__w_sat(pf__w_round(t, 0, 1075 - be - to.exp), to);
}

/* float -> double is exact, so this is a single rounding too */
static inline int64_t pf_fx_from_float(float x, pf_fmt to)
{
    return pf_fx_from_double((double)x, to);
}

/* Correctly rounded (RNE) IEEE bits of |v| * 2^-exp, sign excluded, for a
 * binary format with `prec` significand bits, lsb of the subnormals
 * 2^lsb_min and all-ones exponent field inf_field.  Overflow gives inf. */
static inline uint64_t pf__fx_ieee_bits(uint64_t m, int exp, int prec, int lsb_min, int inf_field)
{
    if (m == 0)
        return 0;
    int e = -exp; /* value = m * 2^e */
    int L = pf__bitlen64(m) + e - prec; /* lsb exponent of the result */
    if (L < lsb_min)
        L = lsb_min;
    /* L - e <= 0 means an exact left shift to < 2^prec; else one rounding */
    uint64_t q = pf__w_lo(pf__w_round(pf__w_u64(m), 0, L - e)); /* <= 2^prec */
    /* ((L - lsb_min) << (prec-1)) + q also encodes subnormals (q < 2^(prec-1))
     * and the carry of q = 2^prec into the exponent field */
    int64_t field = (int64_t)L - lsb_min + (int64_t)(q >> (prec - 1));
    if (field >= inf_field)
        return (uint64_t)inf_field << (prec - 1);
    return ((uint64_t)(L - lsb_min) << (prec - 1)) + q;
}

static inline double pf_fx_to_double(int64_t v, pf_fmt from)
{
    union { uint64_t u; double d; } b;
    b.u = pf__fx_ieee_bits(pf__abs64(v), from.exp, 53, -1074, 0x7ff) | (v < 0 ? (uint64_t)1 << 63 : 0);
    return b.d;
}

static inline float pf_fx_to_float(int64_t v, pf_fmt from)
{
    union { uint32_t u; float f; } b;
    b.u = (uint32_t)pf__fx_ieee_bits(pf__abs64(v), from.exp, 24, -149, 0xff) | (v < 0 ? (uint32_t)1 << 31 : 0);
    return b.f;
}

/* ---------------------------------------------------------------------- */
/* Arithmetic: exact result, one rounding (RNE), saturation to `out`.       */

static inline int64_t pf_fx_mul(int64_t a, pf_fmt fa, int64_t b, pf_fmt fb, pf_fmt out)
{
    return pf__w_sat(pf__w_round(pf__w_muls(a, b), 0, fa.exp + fb.exp - out.exp), out);
}

/* a*2^-ea + sign*b*2^-eb.  Work at exponent k = clamp(out.exp + 2, lo, hi)
 * (lo/hi: the coarser/finer operand exponent): the coarser operand is exact
 * there (shifted left, clamped), the finer one is floor-truncated with a
 * sticky bit.  Only one operand is inexact, so (sum, sticky) pins the exact
 * sum relative to the rounding point; when anything is truncated k is two
 * bits below out's lsb (one guard bit would do) for the round decision. */
static inline int64_t pf__fx_addsub(int64_t a, int ea, int64_t b, int eb, int negb, pf_fmt out)
{
    pf__w wa = pf__w_i64(a), wb = pf__w_i64(b);
    if (negb)
        wb = pf__w_neg(wb);
    if (ea > eb) { /* wa: coarse (smaller exp), wb: fine */
        pf__w t = wa;
        int e = ea;
        wa = wb;
        wb = t;
        ea = eb;
        eb = e;
    }
    int k = out.exp + 2;
    if (k < ea)
        k = ea;
    if (k > eb)
        k = eb;
    pf__w coarse = pf__w_shl_clamp(wa, k - ea);
    int f = eb - k;
    if (f > 100) /* |b| <= 2^63: floor is 0 or -1 from 64 on */
        f = 100;
    int sticky = !pf__w_eq(pf__w_mask(wb, f), pf__w_u64(0));
    pf__w fine = pf__w_sar(wb, f);
    return pf__w_sat(pf__w_round(pf__w_add(coarse, fine), sticky, k - out.exp), out);
}

static inline int64_t pf_fx_add(int64_t a, pf_fmt fa, int64_t b, pf_fmt fb, pf_fmt out)
{
    return pf__fx_addsub(a, fa.exp, b, fb.exp, 0, out);
}

static inline int64_t pf_fx_sub(int64_t a, pf_fmt fa, int64_t b, pf_fmt fb, pf_fmt out)
{
    return pf__fx_addsub(a, fa.exp, b, fb.exp, 1, out);
}

/* q = |a| * 2^s / |b| with s = eb - ea + eo, computed with one guard bit
 * (numerator |a| * 2^(s+1)) and a sticky remainder, then rounded.  When
 * bitlen(a) + s >= bitlen(b) + 64 the quotient is >= 2^63: saturate without
 * forming the numerator, which otherwise fits in 128 bits. */
static inline int64_t pf_fx_div(int64_t a, pf_fmt fa, int64_t b, pf_fmt fb, pf_fmt out)
{
    if (b == 0)
        return a >= 0 ? pf_fmt_max_stored(out) : pf_fmt_min_stored(out);
    if (a == 0)
        return 0;
    int neg = (a < 0) != (b < 0);
    uint64_t ma = pf__abs64(a), mb = pf__abs64(b);
    int s = fb.exp - fa.exp + out.exp;
    if (pf__bitlen64(ma) + s >= pf__bitlen64(mb) + 64)
        return neg ? pf_fmt_min_stored(out) : pf_fmt_max_stored(out);
    int g = s + 1;
    pf__w n = pf__w_u64(ma);
    if (g > 0)
        n = pf__w_shl(n, g); /* g <= 127 - bitlen(a) + 1 */
    uint64_t rem;
    pf__w q = pf__w_divu(n, mb, &rem); /* < 2^65 */
    pf__w r = pf__w_round(q, rem != 0, g >= 0 ? 1 : 1 - g);
    return pf__w_sat(neg ? pf__w_neg(r) : r, out);
}

/* floor(sqrt(y)), bit by bit: 64 compare steps of an exact square */
static inline uint64_t pf__w_isqrt(pf__w y)
{
    uint64_t r = 0;
    for (int i = 63; i >= 0; i--) {
        uint64_t c = r | (uint64_t)1 << i;
        if (!pf__w_ltu(y, pf__w_mulu(c, c)))
            r = c;
    }
    return r;
}

/* Correctly rounded square root.  With Y = 4 * a * 2^(2 eo - ea) the result
 * is RNE(sqrt(Y) / 2).  u = floor(sqrt(Y)) = floor(sqrt(floor(Y))); for even u
 * sqrt(Y)/2 < u/2 + 1/2 rounds down to u/2; for odd u it is a tie between
 * (u-1)/2 and (u+1)/2 exactly when sqrt(Y) = u (Y integral and a square),
 * otherwise it rounds up. */
static inline int64_t pf_fx_sqrt(int64_t a, pf_fmt fa, pf_fmt out)
{
    if (a <= 0)
        return 0;
    uint64_t ma = (uint64_t)a;
    int t = 2 * out.exp - fa.exp + 2;
    if (pf__bitlen64(ma) + t > 128) /* Y >= 2^128: result >= 2^63 */
        return pf_fmt_max_stored(out);
    pf__w y;
    int exact = 1;
    if (t >= 0) {
        y = pf__w_shl(pf__w_u64(ma), t);
    } else if (-t >= 64) {
        y = pf__w_u64(0);
        exact = 0;
    } else {
        y = pf__w_u64(ma >> -t);
        exact = (ma & ((((uint64_t)1) << -t) - 1)) == 0;
    }
    uint64_t u = pf__w_isqrt(y);
    exact = exact && pf__w_eq(pf__w_mulu(u, u), y);
    uint64_t r = u >> 1;
    if (u & 1)
        r += !exact || (r & 1);
    return r > (uint64_t)pf_fmt_max_stored(out) ? pf_fmt_max_stored(out) : (int64_t)r;
}

/* a * b * 2^-shift rounded (RNE), saturated to int64_t */
static inline int64_t pf_mulshift64(int64_t a, int64_t b, int shift)
{
    return pf__w_sat(pf__w_round(pf__w_muls(a, b), 0, shift), pf_fmt_make(1, 63, 0));
}

/* Horner with per-step formats (the exact reference for generated code):
 *     p = c[n]                      (format step[n])
 *     p = sat_step[k](RNE(p * x * 2^-shift[k]) + c[k])     k = n-1 .. 0
 * shift[k] = step[k+1].exp + x.exp - step[k].exp.  c[k] (k < n) is the
 * coefficient at exponent step[k].exp, any int64_t (not saturated to
 * step[k]).  One rounding per step, of the product; the product itself is
 * not saturated, only each partial sum.
 * This equals the tree p_k = p_{k+1}*x + c_k of pf_bw_horner evaluated op
 * by op with pf_fx_mul / pf_fx_add when c_k's lsb is no finer than p_k's
 * and no product saturates.  So round coefficients to step[k].exp once, when
 * generating code: a finer coefficient would need a second rounding, and
 * ties-to-even does not commute with adding an odd integer. */
static inline int64_t pf_fx_horner(int64_t x, const int64_t *c, const int8_t *shift,
                                   const pf_fmt *step, int n)
{
    int64_t p = c[n];
    for (int k = n - 1; k >= 0; k--)
        p = pf__w_sat(pf__w_add(pf__w_round(pf__w_muls(p, x), 0, shift[k]), pf__w_i64(c[k])), step[k]);
    return p;
}

#endif /* PFFIXED_H */
