/* The cosine shear field: bins, bin crossings and the exact quartic contact times (see
   shear.h for the model and the method).  No global state. */
#include "shear.h"

#include <float.h>
#include <gsl/gsl_poly.h>
#include <math.h>
#include <stdlib.h>

#define WG_TWO_PI 6.28318530717958647692528676655900577

/* A root bracket is accepted once it is at most this many ulps of tau wide. */
#define ROOT_BRACKET_ULPS 4.0
/* Iterations of the safeguarded Newton-bisection: every second one at least halves the
   bracket (see bracketed_root), and ~2100 halvings take any double bracket to a few ulps. */
#define ROOT_MAX_ITER 4400
/* Newton steps that polish a critical point from the closed-form cubic. */
#define POLISH_STEPS 3
/* Doublings of the search end beyond the last critical point (the exponent range). */
#define GROW_MAX 2100

int wg_shear_init(wg_shear *f, double fmax, int nbins, double lx, double t_on, double t_off,
                  int axis)
{
  f->fmax = fmax;
  f->nbins = nbins;
  f->lx = lx;
  f->width = lx / nbins;
  f->t_on = t_on;
  f->t_off = t_off;
  f->axis = axis;
  f->force = malloc(sizeof *f->force * (size_t)nbins);
  if (!f->force) return wg_error(WG_ENOMEM, "shear", "cannot allocate %d bins", nbins);
  for (int k = 0; k < nbins; k++) /* Eq. 2.20 at the bin's centre */
    f->force[k] = fmax * cos(WG_TWO_PI * (k + 0.5) / nbins);
  return WG_OK;
}

void wg_shear_free(wg_shear *f)
{
  free(f->force);
  f->force = NULL;
}

int wg_shear_bin_of(const wg_shear *f, double x)
{
  double u = fmod(x, f->lx);
  if (u < 0) u += f->lx;
  int b = (int)floor(u / f->width);
  return b < 0 ? 0 : b >= f->nbins ? f->nbins - 1 : b;
}

double wg_shear_bin_exit(const wg_shear *f, int bin, double x, double vx, int *dir)
{
  *dir = 0;
  if (vx == 0) return INFINITY;
  /* the image of the bin next to x (x may be a periodic image shifted by L_x) */
  double lower = bin * f->width;
  lower += f->lx * round((x - lower - 0.5 * f->width) / f->lx);
  double tau = vx > 0 ? (lower + f->width - x) / vx : (lower - x) / vx;
  *dir = vx > 0 ? 1 : -1;
  return tau > 0 ? tau : 0;
}

/* ---- relative motion of a pair -------------------------------------------------------- */

typedef struct pair_model {
  double dr[3], dv[3], da[3], s2;
  int dim;
} pair_model;

/* p = |d|^2 - sigma^2 and q = d.d' (= p'/2) at tau. */
static void eval(const pair_model *m, double tau, double *p, double *q)
{
  double dd = 0, dq = 0;
  for (int k = 0; k < m->dim; k++) {
    double d = m->dr[k] + tau * (m->dv[k] + 0.5 * tau * m->da[k]);
    double d1 = m->dv[k] + tau * m->da[k];
    dd += d * d;
    dq += d * d1;
  }
  *p = dd - m->s2;
  *q = dq;
}

/* q and q' = |d'|^2 + d.da at tau (for the critical points). */
static void eval_q(const pair_model *m, double tau, double *q, double *dq)
{
  double s = 0, s1 = 0;
  for (int k = 0; k < m->dim; k++) {
    double d = m->dr[k] + tau * (m->dv[k] + 0.5 * tau * m->da[k]);
    double d1 = m->dv[k] + tau * m->da[k];
    s += d * d1;
    s1 += d1 * d1 + d * m->da[k];
  }
  *q = s;
  *dq = s1;
}

static double dotn(const double *a, const double *b, int dim)
{
  double s = 0;
  for (int k = 0; k < dim; k++) s += a[k] * b[k];
  return s;
}

/* Real roots of q(tau) = A3 tau^3 + A2 tau^2 + A1 tau + A0, sorted, polished by Newton on q
   evaluated from d(tau); returns their number (at most 3). */
static int critical_points(const pair_model *m, double *out)
{
  double A3 = 0.5 * dotn(m->da, m->da, m->dim), A2 = 1.5 * dotn(m->dv, m->da, m->dim);
  double A1 = dotn(m->dv, m->dv, m->dim) + dotn(m->dr, m->da, m->dim);
  double A0 = dotn(m->dr, m->dv, m->dim);
  int n = 0;
  if (A3 > 0) {
    n = gsl_poly_solve_cubic(A2 / A3, A1 / A3, A0 / A3, &out[0], &out[1], &out[2]);
  } else if (A1 != 0) { /* da = 0: q is linear */
    out[0] = -A0 / A1;
    n = 1;
  }
  for (int k = 0; k < n; k++) {
    double x = out[k], q, dq;
    eval_q(m, x, &q, &dq);
    for (int it = 0; it < POLISH_STEPS && q != 0 && dq != 0; it++) {
      double y = x - q / dq, qy, dqy;
      eval_q(m, y, &qy, &dqy);
      if (!(fabs(qy) < fabs(q))) break;
      x = y; q = qy; dq = dqy;
    }
    out[k] = x;
  }
  /* polishing may reorder two nearly equal points */
  for (int a = 1; a < n; a++)
    for (int b = a; b > 0 && out[b] < out[b - 1]; b--) {
      double t = out[b]; out[b] = out[b - 1]; out[b - 1] = t;
    }
  return n;
}

static inline int before(double p, int dir) { return dir < 0 ? p > 0 : p < 0; }

/* The crossing in [lo, hi], where p(lo) is before it and p(hi) is not: safeguarded
   Newton-bisection (Press et al.'s rtsafe).  A Newton step is taken only if it lands inside
   the bracket and shrinks faster than bisection would; otherwise the bracket is halved.
   Returns the end of the final bracket that is not before the crossing (p there has
   crossed: a contact is reported touching or by round-off overlapping, never short). */
static double bracketed_root(const pair_model *m, int dir, double lo, double hi, double plo,
                             double qlo)
{
  double x = lo, px = plo, qx = qlo;
  double step_old = hi - lo, step = step_old;
  for (int it = 0; it < ROOT_MAX_ITER; it++) {
    if (hi - lo <= ROOT_BRACKET_ULPS * DBL_EPSILON * fmax(fabs(hi), DBL_MIN)) break;
    double dp = 2 * qx;
    double newton = dp != 0 ? x - px / dp : NAN;
    if (!(newton > lo && newton < hi) || fabs(2 * px) > fabs(step_old * dp)) {
      step_old = step;
      step = 0.5 * (hi - lo);
      x = lo + step;
    } else {
      step_old = step;
      step = fabs(newton - x);
      x = newton;
    }
    eval(m, x, &px, &qx);
    if (px == 0) return x;
    if (before(px, dir)) lo = x;
    else hi = x;
  }
  return hi;
}

int wg_shear_pair_root(const double *dr, const double *dv, const double *da, int dim,
                       double sigma, int dir, double tau_max, double *tau)
{
  pair_model m = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, sigma * sigma, dim};
  for (int k = 0; k < dim; k++) {
    m.dr[k] = dr[k];
    m.dv[k] = dv[k];
    m.da[k] = da[k];
  }
  double crit[3];
  int nc = critical_points(&m, crit);
  double a = 0, pa, qa;
  eval(&m, 0, &pa, &qa);
  /* pieces [a, b] between consecutive critical points in (0, tau_max), then [last, end] */
  for (int k = 0; k <= nc; k++) {
    double b;
    if (k < nc) {
      if (!(crit[k] > a)) continue;
      b = crit[k] < tau_max ? crit[k] : tau_max;
    } else {
      b = tau_max;
    }
    double pb, qb;
    if (isinf(b)) {
      /* beyond the last critical point p is monotonic: grow the end until it has crossed */
      if (!before(pa, dir)) return 0;
      double h = fmax(1.0, fabs(a));
      int grown = 0;
      for (int g = 0; g < GROW_MAX; g++, h *= 2) {
        b = a + h;
        eval(&m, b, &pb, &qb);
        if (!before(pb, dir) || isinf(b)) { grown = 1; break; }
        if (dir < 0 ? !(qb < 0) : !(qb > 0)) return 0; /* moving away from zero for good */
      }
      if (!grown || isinf(b) || before(pb, dir)) return 0;
    } else {
      eval(&m, b, &pb, &qb);
    }
    if (before(pa, dir) && !before(pb, dir)) {
      *tau = bracketed_root(&m, dir, a, b, pa, qa);
      return 1;
    }
    if (b >= tau_max) return 0;
    a = b;
    pa = pb;
    qa = qb;
  }
  return 0;
}

double wg_shear_pair_speed_time(const double *dr, const double *dv, const double *da, int dim,
                                double level)
{
  /* q(tau) - level is a cubic; its crossings are found as those of p in pieces between the
     zeros of q' (a quadratic) */
  double A3 = 0.5 * dotn(da, da, dim), A2 = 1.5 * dotn(dv, da, dim);
  double A1 = dotn(dv, dv, dim) + dotn(dr, da, dim), A0 = dotn(dr, dv, dim) - level;
  if (A0 >= 0) return 0;
  double c[3];
  int n = 0;
  if (A3 > 0) n = gsl_poly_solve_quadratic(3 * A3, 2 * A2, A1, &c[0], &c[1]);
  else if (A2 != 0) { c[0] = -A1 / (2 * A2); n = 1; }
  double a = 0;
  double fa = A0;
  for (int k = 0; k <= n; k++) {
    double b = k < n ? c[k] : INFINITY;
    if (k < n && !(b > a)) continue;
    double fb;
    if (isinf(b)) {
      double h = fmax(1.0, a);
      int g;
      for (g = 0; g < GROW_MAX; g++, h *= 2) {
        b = a + h;
        fb = ((A3 * b + A2) * b + A1) * b + A0;
        if (fb >= 0) break;
      }
      if (g == GROW_MAX) return INFINITY;
    } else {
      fb = ((A3 * b + A2) * b + A1) * b + A0;
    }
    if (fa < 0 && fb >= 0) {
      double lo = a, hi = b;
      for (int it = 0; it < ROOT_MAX_ITER && hi - lo > ROOT_BRACKET_ULPS * DBL_EPSILON * hi; it++) {
        double x = lo + 0.5 * (hi - lo);
        if (((A3 * x + A2) * x + A1) * x + A0 < 0) lo = x;
        else hi = x;
      }
      return hi;
    }
    a = b;
    fa = fb;
  }
  return INFINITY;
}

/* ---- cell crossings under a constant acceleration ----------------------------------------- */

/* First tau >= tau_now at which x(tau) = r + v tau + acc tau^2 / 2 crosses a level dz above
   r in direction dir (+1 upwards, -1 downwards).  A crossing computed just behind tau_now
   (round-off) is taken now when the acceleration drives the particle that way; otherwise
   the particle has turned and will not cross.  INFINITY if never. */
static double cross_time(double dz, double v, double acc, int dir, double tau_now)
{
  double tau;
  if (acc == 0) {
    if (v * dir <= 0) return INFINITY;
    tau = dz / v;
    return tau > tau_now ? tau : tau_now;
  }
  double disc = v * v + 2 * acc * dz;
  if (disc < 0) {
    if (acc * dir < 0) return INFINITY;
    disc = 0;
  }
  double sq = sqrt(disc);
  /* the root with x' = dir * sq, in the form without cancellation */
  tau = v * dir > 0 ? 2 * dz / (v + dir * sq) : (dir * sq - v) / acc;
  if (tau >= tau_now) return tau;
  return acc * dir > 0 ? tau_now : INFINITY;
}

double wg_shear_cell_exit_time(const wg_cells *c, long cell, const double *r, const double *v,
                               const double *acc, double tau_now, int skip_axis, int skip_dir,
                               int *axis, int *dir)
{
  int ix[3];
  long rest = cell;
  for (int a = 0; a < 3; a++) {
    ix[a] = (int)(rest % c->nc[a]);
    rest /= c->nc[a];
  }
  double best = INFINITY;
  *axis = 0;
  *dir = 0;
  for (int a = 0; a < c->dim; a++) {
    double lower = c->lo[a] + ix[a] * c->w[a];
    double upper = lower + c->w[a];
    int has_lower = (c->periodic[a] || ix[a] > 0) && !(a == skip_axis && skip_dir == -1);
    int has_upper = (c->periodic[a] || ix[a] < c->nc[a] - 1) && !(a == skip_axis && skip_dir == 1);
    double t_up = has_upper ? cross_time(upper - r[a], v[a], acc[a], 1, tau_now) : INFINITY;
    double t_down = has_lower ? cross_time(lower - r[a], v[a], acc[a], -1, tau_now) : INFINITY;
    if (t_up < best) { best = t_up; *axis = a; *dir = 1; }
    if (t_down < best) { best = t_down; *axis = a; *dir = -1; }
  }
  return best;
}
