#include "extrema.h"

#include <math.h>
#include <stdlib.h>

long wg_turning_points(const double *x, long n, double swing, long *idx, int *kind)
{
  long m = 0, best = -1, lo = -1, hi = -1;
  int dir = 0; /* 0: not yet known, +1 looking for a maximum, -1 for a minimum */
  for (long i = 0; i < n; i++) {
    if (!isfinite(x[i])) continue;
    if (dir == 0) {
      if (lo < 0 || x[i] < x[lo]) lo = i;
      if (hi < 0 || x[i] > x[hi]) hi = i;
      if (x[i] >= x[lo] + swing) dir = +1, best = i;
      else if (x[i] <= x[hi] - swing) dir = -1, best = i;
      continue;
    }
    if (dir > 0) {
      if (x[i] > x[best]) best = i;
      else if (x[i] <= x[best] - swing) idx[m] = best, kind[m++] = +1, dir = -1, best = i;
    } else {
      if (x[i] < x[best]) best = i;
      else if (x[i] >= x[best] + swing) idx[m] = best, kind[m++] = -1, dir = +1, best = i;
    }
  }
  return m;
}

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

double wg_auto_swing(const double *x, long n, double frac, double floor)
{
  double *v = malloc(sizeof(double) * (n ? n : 1)), s = floor;
  long m = 0;
  if (!v) return s;
  for (long i = 0; i < n; i++)
    if (isfinite(x[i])) v[m++] = x[i];
  if (m >= 10) {
    qsort(v, (size_t)m, sizeof(double), cmp_double);
    s = fmax(s, frac * (v[(9 * m) / 10] - v[m / 10]));
  }
  free(v);
  return s;
}
