/* Plain port of Ken Perlin's reference "improved noise" (2002, Java), used
 * by the noise tests as an independent check and by pfnoise-bench as the
 * speed baseline.  Not part of the library. */
#ifndef NOISE_BASELINE_H
#define NOISE_BASELINE_H

#include <stdint.h>

/* Sets the permutation (p[i] and p[i+256] = perm[i]); default: Perlin's. */
void noise_baseline_set_perm(const uint8_t perm[256]);
double noise_baseline3(double x, double y, double z);
/* The same code in float, for a like-for-like speed comparison. */
float noise_baseline3f(float x, float y, float z);

#endif
