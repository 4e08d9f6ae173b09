/* pfmath_fixed.h — the library's fixed-point functions (integer only).
 *
 * Each function takes and returns stored integers: for fixed<size,exp> the
 * value is stored * 2^-exp (signed types carry a sign bit on top of size,
 * so fixed<15,12> is an int16_t holding x * 4096).  Every one is generated
 * by pfmathgen (libpfmath/generated/pf_fx_*.c, whose header records the
 * command, the polynomial, its formats, the error bound and the sweep) and
 * swept exhaustively against MPFR: all 2^16 inputs of the 16-bit functions
 * in `make test`, all 2^32 of the Q16.16 ones in `make sweep`.
 *
 *   pf_<f>_<in>_<out>        exact: below 1 LSB of the output for every input
 *   pf_<f>_<in>_<out>_fast   fast: within max(2^-10 |f(x)|, 4 LSB), cheaper
 *   ..._array(x, y, n)       y[i] = f(x[i]); vectorizes (16-bit I/O: 16-bit
 *                            lanes, with AVX-512 and AVX2 loops of their own);
 *                            y may be x (in place), no other overlap
 * Type tags: q<e> is a signed type filling its storage with exponent e
 * (q12 = fixed<15,12>, q16 = fixed<31,16>), uq<e> the unsigned one
 * (uq8 = unsigned fixed<16,8>); one tag when input and output types agree.
 *
 * Saturation (defined, not errors): results beyond the output range give
 * its max or min (exp above ln 256 in uq8 gives 65535, i.e. 255.996);
 * log and log2 of x <= 0 give the most negative output; sqrt of x < 0
 * gives 0.  Results are bit-identical whatever the compiler and flags.
 * See docs/fixed.md for the error and speed tables. */
#ifndef PFMATH_FIXED_H
#define PFMATH_FIXED_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* one block per PF_FIXED row of functions.def (tests/test_funcset checks) */

/* sin: fixed<15,12> -> fixed<15,14> */
int16_t pf_sin_q12_q14(int16_t x);
void pf_sin_q12_q14_array(const int16_t *x, int16_t *y, size_t n);
int16_t pf_sin_q12_q14_fast(int16_t x);
void pf_sin_q12_q14_fast_array(const int16_t *x, int16_t *y, size_t n);

/* cos: fixed<15,12> -> fixed<15,14> */
int16_t pf_cos_q12_q14(int16_t x);
void pf_cos_q12_q14_array(const int16_t *x, int16_t *y, size_t n);
int16_t pf_cos_q12_q14_fast(int16_t x);
void pf_cos_q12_q14_fast_array(const int16_t *x, int16_t *y, size_t n);

/* exp: fixed<15,11> -> unsigned fixed<16,8> */
uint16_t pf_exp_q11_uq8(int16_t x);
void pf_exp_q11_uq8_array(const int16_t *x, uint16_t *y, size_t n);
uint16_t pf_exp_q11_uq8_fast(int16_t x);
void pf_exp_q11_uq8_fast_array(const int16_t *x, uint16_t *y, size_t n);

/* exp2: fixed<15,11> -> unsigned fixed<16,8> */
uint16_t pf_exp2_q11_uq8(int16_t x);
void pf_exp2_q11_uq8_array(const int16_t *x, uint16_t *y, size_t n);
uint16_t pf_exp2_q11_uq8_fast(int16_t x);
void pf_exp2_q11_uq8_fast_array(const int16_t *x, uint16_t *y, size_t n);

/* log: unsigned fixed<16,8> -> fixed<15,11> */
int16_t pf_log_uq8_q11(uint16_t x);
void pf_log_uq8_q11_array(const uint16_t *x, int16_t *y, size_t n);
int16_t pf_log_uq8_q11_fast(uint16_t x);
void pf_log_uq8_q11_fast_array(const uint16_t *x, int16_t *y, size_t n);

/* log2: unsigned fixed<16,8> -> fixed<15,11> */
int16_t pf_log2_uq8_q11(uint16_t x);
void pf_log2_uq8_q11_array(const uint16_t *x, int16_t *y, size_t n);
int16_t pf_log2_uq8_q11_fast(uint16_t x);
void pf_log2_uq8_q11_fast_array(const uint16_t *x, int16_t *y, size_t n);

/* sqrt: unsigned fixed<16,8> -> unsigned fixed<16,12> */
uint16_t pf_sqrt_uq8_uq12(uint16_t x);
void pf_sqrt_uq8_uq12_array(const uint16_t *x, uint16_t *y, size_t n);
uint16_t pf_sqrt_uq8_uq12_fast(uint16_t x);
void pf_sqrt_uq8_uq12_fast_array(const uint16_t *x, uint16_t *y, size_t n);

/* sin: fixed<31,16> -> fixed<31,16> */
int32_t pf_sin_q16(int32_t x);
void pf_sin_q16_array(const int32_t *x, int32_t *y, size_t n);
int32_t pf_sin_q16_fast(int32_t x);
void pf_sin_q16_fast_array(const int32_t *x, int32_t *y, size_t n);

/* cos: fixed<31,16> -> fixed<31,16> */
int32_t pf_cos_q16(int32_t x);
void pf_cos_q16_array(const int32_t *x, int32_t *y, size_t n);
int32_t pf_cos_q16_fast(int32_t x);
void pf_cos_q16_fast_array(const int32_t *x, int32_t *y, size_t n);

/* exp: fixed<31,16> -> fixed<31,16> */
int32_t pf_exp_q16(int32_t x);
void pf_exp_q16_array(const int32_t *x, int32_t *y, size_t n);
int32_t pf_exp_q16_fast(int32_t x);
void pf_exp_q16_fast_array(const int32_t *x, int32_t *y, size_t n);

/* exp2: fixed<31,16> -> fixed<31,16> */
int32_t pf_exp2_q16(int32_t x);
void pf_exp2_q16_array(const int32_t *x, int32_t *y, size_t n);
int32_t pf_exp2_q16_fast(int32_t x);
void pf_exp2_q16_fast_array(const int32_t *x, int32_t *y, size_t n);

/* log: fixed<31,16> -> fixed<31,16> */
int32_t pf_log_q16(int32_t x);
void pf_log_q16_array(const int32_t *x, int32_t *y, size_t n);
int32_t pf_log_q16_fast(int32_t x);
void pf_log_q16_fast_array(const int32_t *x, int32_t *y, size_t n);

/* log2: fixed<31,16> -> fixed<31,16> */
int32_t pf_log2_q16(int32_t x);
void pf_log2_q16_array(const int32_t *x, int32_t *y, size_t n);
int32_t pf_log2_q16_fast(int32_t x);
void pf_log2_q16_fast_array(const int32_t *x, int32_t *y, size_t n);

/* sqrt: fixed<31,16> -> fixed<31,16> */
int32_t pf_sqrt_q16(int32_t x);
void pf_sqrt_q16_array(const int32_t *x, int32_t *y, size_t n);
int32_t pf_sqrt_q16_fast(int32_t x);
void pf_sqrt_q16_fast_array(const int32_t *x, int32_t *y, size_t n);

#ifdef __cplusplus
}
#endif

#endif
