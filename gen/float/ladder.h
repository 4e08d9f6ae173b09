/* The accuracy ladder (issue 13, item 2): pfmathgen --func F --max-ulp U.
 *
 * Emits NAME and NAME_array at the lowest cost whose error over every float
 * is at most U ULP.  The candidates are the function's specs (fast and
 * exact templates of its reduction) at every order; each gets a static cost
 * (gen/float/ladder.c says how it is counted) and they are tried cheapest first:
 *   1. fit (minimax; least squares where minimax fails) and predict the
 *      error: the spec's model (fit error and every rounding), or without a
 *      model 0.5 + (fit error + float Horner's rounding bound) 2^24 ULP;
 *      a prediction above U skips the candidate without compiling it;
 *   2. compile the emitted C and sweep a sample (the reduced range's every
 *      16th float, 2^20 seeded random floats, the directed list): above U,
 *      next candidate;
 *   3. confirm: every one of the 2^32 floats (atan2: the dense pair set of
 *      pfsweep --all, 2^28 seeded pairs and all special pairs), stopping at
 *      the first chunk above U.  Above U: next candidate.
 * The first candidate through 3 is written; its provenance records the bound,
 * the scheme and the confirming sweep's max ULP and worst input.  No
 * candidate: exit 2, "impossible target".
 *
 * Relative levels are ULP levels: U ULP bounds the relative error of every
 * normal result by U 2^-23 (an ulp of y is at most |y| 2^-23), so 2^-16
 * relative is --max-ulp 128 (2^7) and 2^-10 relative --max-ulp 8192 (2^13).
 * One measure, proved by the same sweep; stricter than the relative bound by
 * up to 2x at the bottom of a binade, and absolute (U 2^-149) for subnormal
 * results.
 *
 * confirm_sample (--confirm sample) drops step 3 and takes 2^22 random
 * floats in step 2 instead of 2^20: for the tests and quick ladders; the
 * provenance says "sampled, not exhaustive". */
#ifndef PF_LADDER_H
#define PF_LADDER_H

#include "generate.h"

#include <stdio.h>

/* base: the request as pfmathgen parsed it (func, reduction, method, name,
   command); log: one line per candidate tried.  Returns 0 (*res as
   pf_generate fills it), 2 (impossible target: err) or 1 (failure: err). */
int pf_ladder_generate(const pf_gen_req *base, double max_ulp, int confirm_sample, FILE *log,
                       pf_gen_result *res, char *err, size_t errlen);

#endif
