/* Compensated sums for the energy ledgers of both engines. */
#ifndef WG_KSUM_H
#define WG_KSUM_H

#include <math.h>

typedef struct wg_ksum { double s, c; } wg_ksum;

/* Neumaier's compensated sum: value = s + c. */
static inline void wg_ksum_add(wg_ksum *k, double x)
{
  double t = k->s + x;
  if (fabs(k->s) >= fabs(x)) k->c += (k->s - t) + x;
  else k->c += (x - t) + k->s;
  k->s = t;
}

static inline double wg_ksum_value(const wg_ksum *k) { return k->s + k->c; }

#endif
