/* Bit-width analysis of fixed-point expressions (Olano, PixelFlow 4.3.3,
 * Figure 4.8): two passes over a tree of + - x nodes whose leaves have
 * known fixed types.
 *
 * Bottom-up keeps all precision: x adds sizes and exponents, + and - align
 * the exponents and grow one integer bit (pf_fmt_mul/add/sub in pffixed.h).
 *
 * Top-down trims every intermediate to what the destination can use.  The
 * seed only says "limits the types ... to only what is necessary for the
 * assignment" and shows one example; our reading of it:
 *  - the root takes the destination's lsb and integer bits, each only where
 *    they are smaller than the bottom-up ones (the assignment would round and
 *    saturate to them anyway); it is unsigned if either is;
 *  - an operand of + or - needs no lsb finer than its parent's;
 *  - an operand of x needs no lsb finer than parent lsb / 2^i, i the integer
 *    bits of the other operand (|other| <= 2^i, so dropping finer bits moves
 *    the product by under half a parent lsb) - the seed has no x example;
 *  - integer bits of inner nodes are never trimmed: our arithmetic
 *    saturates rather than wraps, so an inner overflow would corrupt an
 *    in-range result.  They are what the bottom-up pass needs, which is the
 *    seed's "no more than needed";
 *  - leaves (variables, constants) keep their declared types;
 *  - a format is never left with size < 1: it gets more integer bits rather
 *    than a coarser lsb (which would add a rounding);
 * With fixed<10,10> x,y; fixed<15,12> z,r; r = x*y + z this gives the
 * seed's fixed<20,20>, fixed<24,20> bottom-up and fixed<12,12>, fixed<15,12>
 * top-down.
 *
 * Two corners where a value does not fit its type and saturates, costing up
 * to one lsb instead of half: min*min (the seed's x rule, see pf_fmt_mul),
 * and trimming under round-to-nearest: a value within half a trimmed lsb
 * of 2^i rounds up to 2^i, one past the max.  (The seed's scheme is free of
 * the latter under truncation, which never rounds up; keeping the seed's
 * formats, we accept it: an extra integer bit per trimmed node would not
 * reproduce Figure 4.8.) */
#ifndef PF_BITWIDTH_H
#define PF_BITWIDTH_H

#include "fixedtype.h"

typedef enum { PF_BW_LEAF, PF_BW_ADD, PF_BW_SUB, PF_BW_MUL } pf_bw_op;

typedef struct pf_bw_node {
    pf_bw_op op;
    struct pf_bw_node *a, *b; /* operands, NULL for leaves */
    pf_type full;             /* after bottom-up: all available precision */
    pf_type type;             /* after top-down: the trimmed type (before: = full) */
} pf_bw_node;

/* Constructors.  An operator node owns its operands; if either is NULL (or
 * allocation fails) it frees the other and returns NULL, so a whole tree
 * can be built and checked once.  Leaves must be fixed types (float: NULL). */
pf_bw_node *pf_bw_leaf(pf_type t);
pf_bw_node *pf_bw_add(pf_bw_node *a, pf_bw_node *b);
pf_bw_node *pf_bw_sub(pf_bw_node *a, pf_bw_node *b);
pf_bw_node *pf_bw_mul(pf_bw_node *a, pf_bw_node *b);
void pf_bw_free(pf_bw_node *n);

/* Fill full (and type = full) everywhere.  0, or -1 if n is NULL. */
int pf_bw_bottom_up(pf_bw_node *n);

/* Bottom-up, then trim into dest (a fixed type).  0, or -1 if n is NULL or
 * dest is float. */
int pf_bw_top_down(pf_bw_node *n, pf_type dest);

/* Horner evaluation p(x) = c_0 + c_1 x + ... + c_n x^n:
 *     p_n = c_n;   m_k = p_{k+1} * x;   p_k = m_k + c_k    (k = n-1 .. 0)
 * analysed as the tree p_0 = (...(c_n*x + c_{n-1})*x ...)*x + c_0 into out.
 * steps[0..n] receive, for each k:
 *   p      type of p_k (p_n is c_n's own type; p_0 is the trimmed root,
 *          which the caller converts to out if it differs)
 *   m      type of m_k (unused for k = n)
 *   shift  p_{k+1}.exp + x.exp - p_k.exp (unused for k = n): the shift of
 *          pf_fx_horner / pf_mulshift*, which round p_{k+1}*x straight to
 *          p_k's lsb.  m_k's lsb is p_k's unless m_k is exact, so that is
 *          the tree's rounding of m_k, and adding c_k is exact once c_k is
 *          rounded to p_k's lsb.  So a code generator rounds coefficient k
 *          to p_k.exp when it emits it; analysing again with the rounded
 *          coefficient types gives the same lsbs (tested).
 * Returns 0, or -1 for n < 0, a float type, or no memory. */
typedef struct {
    pf_type p;
    pf_type m;
    int shift;
} pf_bw_step;

int pf_bw_horner(const pf_type *coef, int n, pf_type x, pf_type out, pf_bw_step *steps);

/* Horner under a word-size constraint (issue 14: fixed point in W-bit
 * lanes, W = 16).  The bottom-up rule above grows one integer bit per
 * addition, which a 16-bit word cannot afford; here each step's format comes
 * from a proven bound on the value itself, pmax[k] >= |p_k(x)| for x in
 * [0, 1] (the caller's proof, e.g. a sampled maximum plus a Lipschitz
 * margin), with the rounding errors of the earlier steps added.
 *
 * Every value is a signed W-bit word; x is in [0, 1) with W-1 fraction bits
 * (never 1, never negative).  Step k computes
 *     p_k = MULHRS(p_{k+1}, x_d) + c_k,   MULHRS(a, b) = round(a b / 2^(W-1))
 * (the rounding multiply-high, pmulhrsw for W = 16): the product's lsb is
 * p_{k+1}'s coarsened by d_k, so p_k.exp = p_{k+1}.exp - d_k, and c_k is
 * rounded to it.  The exponents are therefore non-increasing from the
 * leading coefficient to p_0; d_k > 0 only where p_k needs more integer
 * bits than p_{k+1} (the seed's top-down rule for x: an operand needs no lsb
 * finer than its parent's divided by the other operand's range).  x_d is
 * x rounded to W-1-d fraction bits, x_d = MULHRS(x, 2^(W-1-d)) (a multiply
 * rather than a shift: GCC then keeps the product in 16-bit lanes), which
 * costs |p_{k+1}| 2^(d-1) 2^-(W-1); x_d <= 1.
 * Error of the computed p_0 (rounded coefficients, exact x):
 *     e_n = 0,  e_k = e_{k+1} + pmax[k+1] 2^(d_k-1) 2^-(W-1) [d_k > 0] + 2^-(exp_k + 1)
 * (|x| <= 1 carries e_{k+1} over; half an lsb per rounding, ties up or to
 * even alike).  Each exp_k is the finest <= emax and <= exp_{k+1} with
 * (pmax[k] + e_k) 2^exp_k <= 2^(W-1) - 1, so no step overflows and
 * -2^(W-1) (whose square MULHRS cannot hold) never occurs.
 * kind is PF_BW_MULHRS for every step here; PF_BW_MULFULL names the full
 * W x W -> 2W product that reconstruction steps use where a kernel's error
 * model needs it (reported, not chosen, by this function).
 * Returns 0, or -1 (n < 0, W not in 8..32, or a value that cannot fit even
 * at exp -W). */
typedef enum { PF_BW_MULHRS = 1, PF_BW_MULH, PF_BW_MULFULL } pf_bw_mulkind;

typedef struct {
    int exp;       /* lsb exponent of p_k (value = stored 2^-exp) */
    int xdrop;     /* d_k: multiply by x rounded to W-1-d_k fraction bits (unused for k = n) */
    pf_bw_mulkind kind;
    double err;    /* e_k */
} pf_bw_wstep;

int pf_bw_horner_word(const double *pmax, int n, int W, int emax, pf_bw_wstep *steps, double *err);

#endif
