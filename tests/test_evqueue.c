/* The event queue (sim/ed/evqueue.c, a tournament tree of fan-out 8) against a brute-force scan:
   after every update the top must be the particle of the earliest time, the lowest index
   among equal times (the order of events, and so every trajectory, depends on it).  Sizes
   around the powers of the fan-out, times drawn from few values so that ties abound, and
   infinite times (particles with no event). */
#include <math.h>
#include <stdlib.h>

#include "evqueue.h"
#include "tharness.h"

static unsigned long long rng_state = 88172645463325252ULL;
static unsigned long long xorshift(void)
{
  rng_state ^= rng_state << 13;
  rng_state ^= rng_state >> 7;
  rng_state ^= rng_state << 17;
  return rng_state;
}

static double draw_time(void)
{
  unsigned long long r = xorshift();
  if (r % 17 == 0) return INFINITY;
  return (double)(r % 50); /* few distinct values: many ties */
}

static long brute_top(const double *key, long n)
{
  long best = 0;
  for (long i = 1; i < n; i++)
    if (key[i] < key[best]) best = i;
  return best;
}

int main(void)
{
  const long sizes[] = {1, 2, 7, 8, 9, 63, 64, 65, 511, 512, 513, 4097};
  for (int k = 0; k < (int)(sizeof sizes / sizeof *sizes); k++) {
    long n = sizes[k];
    double *key = malloc(sizeof *key * (size_t)n);
    for (long i = 0; i < n; i++) key[i] = draw_time();
    wg_evqueue q;
    TH_CHECK(wg_evqueue_alloc(&q, n, key) == WG_OK, "n = %ld: allocated (%d levels)", n, q.levels);
    wg_evqueue_build(&q);
    int bad = 0, built_ok = wg_evqueue_top(&q) == brute_top(key, n);
    long updates = 20 * n + 200;
    for (long u = 0; u < updates; u++) {
      /* like the engine: mostly the top particle moves on, sometimes any other */
      long i = u % 3 ? wg_evqueue_top(&q) : (long)(xorshift() % (unsigned long long)n);
      key[i] = u % 3 ? key[i] + (double)(xorshift() % 4) : draw_time();
      wg_evqueue_update(&q, i);
      if (wg_evqueue_top(&q) != brute_top(key, n)) bad++;
    }
    TH_CHECK(built_ok && bad == 0,
             "n = %ld: top = earliest time, lowest index on ties, after the build and %ld updates "
             "(%d wrong)", n, updates, bad);
    wg_evqueue_free(&q);
    free(key);
  }
  return th_summary();
}
