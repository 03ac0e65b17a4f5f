/* A counter-based random number: a pure function of (seed, counters), so a number drawn for
   the k-th kick of particle id is the same whatever the event order, the storage order or a
   checkpoint in between (GSL's generators are streams whose state would have to follow the
   run).  The mixing is SplitMix64's finaliser (Steele, Lea & Flood, OOPSLA 2014), applied
   after each counter; the output passes through GSL's inverse normal CDF for Gaussians. */
#ifndef WG_COUNTER_RNG_H
#define WG_COUNTER_RNG_H

#include <stdint.h>

static inline uint64_t wg_mix64(uint64_t z)
{
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/* Uniform in the open interval (0, 1): 53 bits, never 0 or 1. */
static inline double wg_counter_uniform(uint64_t seed, uint64_t a, uint64_t b, uint64_t c)
{
  const uint64_t golden = 0x9e3779b97f4a7c15ULL;
  uint64_t z = wg_mix64(seed + golden);
  z = wg_mix64(z ^ (a + golden));
  z = wg_mix64(z ^ (b + 2 * golden));
  z = wg_mix64(z ^ (c + 3 * golden));
  return ((double)(z >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

#endif
