#include "nlist.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Room per list to start with: a sphere's centre-to-centre neighbours within 1.3 d in the
   densest packing (12); lists grow when a denser or more polydisperse state needs more. */
enum { CAP_2D = 8, CAP_3D = 16 };
/* The region is left a hair before its nominal edge, so that round-off in the exit time can
   never carry a particle beyond what the lists allow. */
#define REACH_MARGIN 1e-9

int wg_nlist_alloc(wg_nlist *l, int dim, long n, double shell)
{
  memset(l, 0, sizeof *l);
  l->dim = dim;
  l->cap = dim == 2 ? CAP_2D : CAP_3D;
  l->shell = shell;
  l->reach = 0.5 * shell * (1 - REACH_MARGIN);
  size_t un = (size_t)(n ? n : 1);
  l->centre = calloc(3 * un, sizeof *l->centre);
  l->nb = calloc(un * (size_t)l->cap, sizeof *l->nb);
  l->nn = calloc(un, sizeof *l->nn);
  if (!l->centre || !l->nb || !l->nn) {
    wg_nlist_free(l);
    return wg_error(WG_ENOMEM, "engine", "no memory for the neighbour lists of %ld particles", n);
  }
  return WG_OK;
}

void wg_nlist_free(wg_nlist *l)
{
  free(l->centre);
  free(l->nb);
  free(l->nn);
  memset(l, 0, sizeof *l);
}

size_t wg_nlist_bytes(const wg_nlist *l, long n)
{
  return (size_t)n * (3 * sizeof *l->centre + (size_t)l->cap * sizeof *l->nb + sizeof *l->nn);
}

void wg_nlist_clear(wg_nlist *l, long n)
{
  memset(l->nn, 0, (size_t)n * sizeof *l->nn);
}

/* Twice the room per list, the lists copied row by row. */
static int grow(wg_nlist *l, long n)
{
  int cap = 2 * l->cap;
  if (cap > UINT16_MAX)
    return wg_error(WG_ERANGE, "engine", "a neighbour list would hold more than %d particles: "
                    "the shell is far too wide for this density", UINT16_MAX);
  int32_t *nb = calloc((size_t)n * (size_t)cap, sizeof *nb);
  if (!nb) return wg_error(WG_ENOMEM, "engine", "no memory for neighbour lists of %d", cap);
  for (long i = 0; i < n; i++)
    memcpy(nb + (size_t)i * cap, l->nb + (size_t)i * l->cap, l->nn[i] * sizeof *nb);
  free(l->nb);
  l->nb = nb;
  l->cap = cap;
  return WG_OK;
}

int wg_nlist_link(wg_nlist *l, long n, long i, long j)
{
  if (l->nn[i] == l->cap || l->nn[j] == l->cap) {
    int st = grow(l, n);
    if (st != WG_OK) return st;
  }
  l->nb[(size_t)i * l->cap + l->nn[i]++] = (int32_t)j;
  l->nb[(size_t)j * l->cap + l->nn[j]++] = (int32_t)i;
  return WG_OK;
}

void wg_nlist_unlink_all(wg_nlist *l, long i)
{
  const int32_t *mine = l->nb + (size_t)i * l->cap;
  for (int k = 0; k < l->nn[i]; k++) {
    long j = mine[k];
    int32_t *theirs = l->nb + (size_t)j * l->cap;
    int m = l->nn[j];
    for (int q = 0; q < m; q++)
      if (theirs[q] == i) {
        theirs[q] = theirs[m - 1]; /* order within a list does not matter: ties go by slot */
        l->nn[j]--;
        break;
      }
  }
  l->nn[i] = 0;
}

/* First time at which |d + v tau| reaches rho (d inside): the positive root of the quadratic,
   in the form without cancellation. */
static double ball_exit(const double *d, const double *v, int axes, int skip, double rho)
{
  double a = 0, b = 0, c = -rho * rho;
  for (int k = 0; k < axes; k++) {
    if (k == skip) continue;
    a += v[k] * v[k];
    b += d[k] * v[k];
    c += d[k] * d[k];
  }
  if (c >= 0) return 0;
  if (a == 0) return INFINITY;
  double disc = sqrt(b * b - a * c);
  return b > 0 ? -c / (b + disc) : (disc - b) / a;
}

double wg_nlist_exit_time(const wg_nlist *l, long i, const double *r, const double *v, double g,
                          double tau_now)
{
  int dim = l->dim, up = dim - 1;
  double d[3] = {0, 0, 0};
  for (int k = 0; k < dim; k++) d[k] = r[k] - l->centre[3 * i + k];
  double tau;
  if (g == 0) {
    tau = ball_exit(d, v, dim, -1, l->reach);
  } else {
    /* the cylinder of radius and half-height rho: its corners are reach from the centre */
    double rho = l->reach * M_SQRT1_2;
    tau = ball_exit(d, v, dim, up, rho);
    double z = d[up], w = v[up];
    if (fabs(z) >= rho) return tau_now;
    double top = w * w - 2 * g * (rho - z); /* reaches z = rho while rising? */
    double tz;
    if (top >= 0 && w > 0) {
      tz = 2 * (rho - z) / (w + sqrt(top));
    } else { /* falls to z = -rho: the positive root, without cancellation */
      double e = sqrt(w * w + 2 * g * (rho + z));
      tz = w > 0 ? (w + e) / g : 2 * (rho + z) / (e - w);
    }
    if (tz < tau) tau = tz;
  }
  return tau > tau_now ? tau : tau_now;
}
