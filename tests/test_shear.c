/* Tests of sim/ed/shear.c: the cosine shear field's bins and the exact quartic contact times of
   two particles with constant relative acceleration (thesis Sec. 2.4.4, footnote 6).

   Independent reference.  It shares no idea with the solver (no critical points, no cubic,
   no Newton): it evaluates p(t) = |d(t)|^2 - sigma^2 in long double and steps forward with
   the rigorous lower bound
       f(t + h) >= f(t) + f'(t) h - M h^2 / 2,   f = -dir p,   M >= |p''| on [0, T],
   taking the largest h for which that bound stays positive.  It can never step over a root,
   however grazing; in front of a root it converges to it from the left.

   Acceptance of a solver time ts against the reference tr:
     plain:        |ts - tr| <= 1e-12 * max(tr, 1);
     conditioned:  otherwise (or when only one of them finds a root), ts must be the exact
                   answer for a p perturbed by at most E (16 eps times the magnitude of the
                   terms of |d|^2 and sigma^2): tr(+E) - tol <= ts <= tr(-E) + tol, where
                   tr(+-E) is the reference's first time at which -dir p >= -+E... i.e. the
                   crossing of the levels p = +-E (a solver "no root" needs no crossing of
                   the far level).  Only nearly grazing pairs can need this clause; their
                   count is printed and must stay below 1 %. */
#include "tharness.h"
#include "ed.h"
#include "shear.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#define REF_MAX_STEPS 20000000L

typedef struct rng { uint64_t state; } rng;
static uint64_t rng_next(rng *r)
{
  uint64_t z = (r->state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
static double uniform(rng *r) { return (double)(rng_next(r) >> 11) * 0x1.0p-53; }
static double sym(rng *r) { return 2 * uniform(r) - 1; }

typedef struct pcase {
  double dr[3], dv[3], da[3], sigma;
  int dim, dir;
  double tmax;
} pcase;

/* ---- the long-double reference ------------------------------------------------------ */

static long double ref_p(const pcase *c, long double t, long double *dp)
{
  long double s = 0, q = 0;
  for (int k = 0; k < c->dim; k++) {
    long double d = (long double)c->dr[k] + (long double)c->dv[k] * t +
                    0.5L * (long double)c->da[k] * t * t;
    long double d1 = (long double)c->dv[k] + (long double)c->da[k] * t;
    s += d * d;
    q += d * d1;
  }
  *dp = 2 * q;
  return s - (long double)c->sigma * (long double)c->sigma;
}

static long double norml(const double *a, int dim)
{
  long double s = 0;
  for (int k = 0; k < dim; k++) s += (long double)a[k] * a[k];
  return sqrtl(s);
}

/* First t in (0, tmax] where p crosses `level` in direction dir, the crossing being from the
   side -dir (p - level has sign -dir before it); starts on the far side wait until p has
   come back.  Returns 1 and *t, or 0. */
static int ref_root(const pcase *c, long double level, long double *t_out)
{
  long double T = c->tmax;
  long double a = norml(c->da, c->dim), v = norml(c->dv, c->dim), r = norml(c->dr, c->dim);
  long double d1 = v + a * T, d0 = r + v * T + 0.5L * a * T * T;
  long double M = 2 * d1 * d1 + 2 * d0 * a;
  if (M <= 0) M = 1e-30L;
  long double t = 0, dp;
  int dir = c->dir;
  /* phase 1: if on the far side, leave it (step while the far side is certain) */
  long double f = -dir * (ref_p(c, t, &dp) - level);
  long steps = 0;
  while (f <= 0) { /* on or beyond the level: walk until strictly before it again */
    long double fp = -dir * dp;
    long double g = -f; /* g >= 0: distance on the far side */
    long double h = (-fp + sqrtl(fp * fp + 2 * M * g)) / M; /* g - fp h - M h^2/2 >= 0 */
    if (!(h > 1e-19L * (t > 1 ? t : 1))) h = 1e-19L * (t > 1 ? t : 1);
    t += h;
    if (t > T || ++steps > REF_MAX_STEPS) return 0;
    f = -dir * (ref_p(c, t, &dp) - level);
  }
  for (;;) {
    long double fp = -dir * dp;
    long double h = (fp + sqrtl(fp * fp + 2 * M * f)) / M;
    if (h < 1e-18L * (t > 1 ? t : 1)) {
      *t_out = t + h;
      return t <= T;
    }
    t += h;
    if (t > T || ++steps > REF_MAX_STEPS) return 0;
    f = -dir * (ref_p(c, t, &dp) - level);
    if (f <= 0) {
      *t_out = t;
      return 1;
    }
  }
}

static double error_bound(const pcase *c)
{
  double T = c->tmax;
  double d0 = (double)(norml(c->dr, c->dim) + norml(c->dv, c->dim) * T +
                       0.5 * norml(c->da, c->dim) * T * T);
  return 16 * DBL_EPSILON * (d0 * d0 + c->sigma * c->sigma);
}

typedef struct stats {
  long cases, plain, conditioned, failed, roots;
  double worst;
} stats;

static void judge(stats *st, const pcase *c, const char *what)
{
  double ts = NAN;
  int hs = wg_shear_pair_root(c->dr, c->dv, c->da, c->dim, c->sigma, c->dir, c->tmax, &ts);
  long double tr = 0;
  int hr = ref_root(c, 0, &tr);
  st->cases++;
  if (hs) st->roots++;
  if (hs && hr && fabs(ts - (double)tr) <= 1e-12 * fmax((double)tr, 1)) {
    st->plain++;
    double rel = fabs(ts - (double)tr) / fmax((double)tr, 1);
    if (rel > st->worst) st->worst = rel;
    return;
  }
  if (!hs && !hr) {
    st->plain++;
    return;
  }
  double E = error_bound(c);
  long double t_near = 0, t_far = 0;
  int h_near = ref_root(c, c->dir < 0 ? E : -E, &t_near); /* the level met first */
  int h_far = ref_root(c, c->dir < 0 ? -E : E, &t_far);
  double tol = 1e-12 * fmax(hs ? ts : 1, 1);
  int ok;
  if (hs) ok = h_near && ts >= (double)t_near - tol && (!h_far || ts <= (double)t_far + tol);
  else ok = !h_far;
  if (ok) {
    st->conditioned++;
    return;
  }
  st->failed++;
  if (st->failed <= 5)
    printf("# %s mismatch: solver %d %.17g, reference %d %.17Lg; dr (%.17g %.17g %.17g) dv "
           "(%.17g %.17g %.17g) da (%.17g %.17g %.17g) sigma %.17g dir %d\n",
           what, hs, ts, hr, tr, c->dr[0], c->dr[1], c->dr[2], c->dv[0], c->dv[1], c->dv[2],
           c->da[0], c->da[1], c->da[2], c->sigma, c->dir);
}

static void report(const char *what, const stats *st, double max_cond_fraction)
{
  TH_CHECK(st->failed == 0, "%s: %ld cases (%ld with a root): %ld plain, %ld conditioned, %ld "
           "failed; worst plain error %.2e", what, st->cases, st->roots, st->plain,
           st->conditioned, st->failed, st->worst);
  TH_CHECK(st->conditioned <= max_cond_fraction * st->cases,
           "%s: conditioned cases %ld <= %.0f %% of %ld", what, st->conditioned,
           100 * max_cond_fraction, st->cases);
}

static void random_unit(rng *g, int dim, double *u)
{
  double n2;
  do {
    n2 = 0;
    for (int k = 0; k < dim; k++) {
      u[k] = sym(g);
      n2 += u[k] * u[k];
    }
  } while (n2 > 1 || n2 < 1e-4);
  for (int k = 0; k < 3; k++) u[k] = k < dim ? u[k] / sqrt(n2) : 0;
}

/* Random approaching and separating pairs, both directions, the field's relative
   acceleration along axis 1 (as in the engine) or anywhere. */
static void test_random(void)
{
  rng g = {20260307};
  stats st = {0};
  for (int n = 0; n < 20000; n++) {
    pcase c = {{0}, {0}, {0}, 0, 2 + n % 2, n % 4 < 2 ? -1 : 1, 20};
    c.sigma = 0.9 + 0.2 * uniform(&g);
    double u[3];
    random_unit(&g, c.dim, u);
    double dist = c.dir < 0 ? c.sigma * (1 + 3 * uniform(&g)) : c.sigma * (1 - 0.06 * uniform(&g));
    for (int k = 0; k < c.dim; k++) c.dr[k] = dist * u[k];
    random_unit(&g, c.dim, u);
    double speed = 3 * uniform(&g);
    for (int k = 0; k < c.dim; k++) c.dv[k] = speed * u[k];
    if (n % 3 == 0) {
      random_unit(&g, c.dim, u);
      double acc = 2 * uniform(&g);
      for (int k = 0; k < c.dim; k++) c.da[k] = acc * u[k];
    } else {
      c.da[1] = 2 * sym(&g); /* the field: along axis 1 only */
    }
    judge(&st, &c, "random");
  }
  report("random pairs against the long-double reference", &st, 0.01);
  TH_CHECK(st.roots > 10000, "random: %ld of %ld cases have a crossing (the test sees roots)",
           st.roots, st.cases);
}

/* Grazing and near-double roots: the distance has a local minimum sigma (1 + delta) at t*
   (d(t*) . d'(t*) = 0, d(t*) along n), delta from -1e-6 to +1e-6 down to +-1e-15. */
static void test_grazing(void)
{
  rng g = {77};
  stats st = {0};
  const double deltas[] = {-1e-6, -1e-9, -1e-12, -1e-15, 0, 1e-15, 1e-12, 1e-9, 1e-6};
  long found_deep = 0, deep = 0, found_clear = 0;
  for (int n = 0; n < 4000; n++) {
    double delta = deltas[n % 9];
    pcase c = {{0}, {0}, {0}, 1.0 + 0.1 * uniform(&g), 2 + n % 2, -1, 20};
    double nrm[3], tan[3], D[3], V[3];
    random_unit(&g, c.dim, nrm);
    /* a tangent: any unit vector made orthogonal to n */
    random_unit(&g, c.dim, tan);
    double p = tan[0] * nrm[0] + tan[1] * nrm[1] + tan[2] * nrm[2];
    double tn = 0;
    for (int k = 0; k < 3; k++) { tan[k] -= p * nrm[k]; tn += tan[k] * tan[k]; }
    tn = sqrt(tn);
    if (tn < 1e-3) continue;
    double speed = 0.1 + 2 * uniform(&g), ts = 0.5 + 3 * uniform(&g);
    for (int k = 0; k < 3; k++) {
      D[k] = c.sigma * (1 + delta) * nrm[k];
      V[k] = speed * tan[k] / tn;
    }
    c.da[1] = 0.5 * sym(&g);
    /* keep the minimum a minimum: |V|^2 + D.da > 0 */
    if (speed * speed + D[1] * c.da[1] <= 0.05) c.da[1] = 0;
    for (int k = 0; k < c.dim; k++) {
      c.dr[k] = D[k] - V[k] * ts + 0.5 * c.da[k] * ts * ts;
      c.dv[k] = V[k] - c.da[k] * ts;
    }
    double tau;
    int h = wg_shear_pair_root(c.dr, c.dv, c.da, c.dim, c.sigma, -1, c.tmax, &tau);
    if (delta <= -1e-9) {
      deep++;
      if (h && tau < ts + 1e-6) found_deep++; /* at t* or, on a bent path, before */
      else if (deep - found_deep < 4) printf("# dip %g missed: h %d tau %.17g t* %.17g\n", delta, h, tau, ts);
    }
    if (delta >= 1e-9 && !(h && tau < ts + 1e-6)) found_clear++;
    judge(&st, &c, "grazing");
  }
  report("grazing and near-double roots against the reference", &st, 0.5);
  TH_CHECK(found_deep == deep, "grazing: dips of 1e-9 and deeper found by t* (%ld of %ld)",
           found_deep, deep);
  TH_CHECK(found_clear > 0, "grazing: near misses by 1e-9 and more pass by t* (%ld)", found_clear);
}

/* Same bin (da = 0): the quartic reduces to the engine's quadratic,
   t = c / (-b + sqrt(b^2 - a c)). */
static void test_same_bin(void)
{
  rng g = {5};
  long n_cmp = 0, bad = 0;
  double worst = 0;
  for (int n = 0; n < 5000; n++) {
    int dim = 2 + n % 2;
    double dr[3] = {0}, dv[3] = {0}, da[3] = {0}, u[3];
    random_unit(&g, dim, u);
    double dist = 1 + 3 * uniform(&g);
    for (int k = 0; k < dim; k++) dr[k] = dist * u[k];
    random_unit(&g, dim, u);
    for (int k = 0; k < dim; k++) dv[k] = 3 * uniform(&g) * u[k];
    double b = 0, a = 0, r2 = 0;
    for (int k = 0; k < dim; k++) { b += dr[k] * dv[k]; a += dv[k] * dv[k]; r2 += dr[k] * dr[k]; }
    double cc = r2 - 1, disc = b * b - a * cc;
    double tq = b < 0 && disc > 0 ? cc / (-b + sqrt(disc)) : INFINITY;
    double tau;
    int h = wg_shear_pair_root(dr, dv, da, dim, 1.0, -1, INFINITY, &tau);
    if (isinf(tq)) {
      if (h && disc < -1e-12) bad++;
      continue;
    }
    n_cmp++;
    double rel = h ? fabs(tau - tq) / fmax(tq, 1e-3) : INFINITY;
    if (rel > worst) worst = rel;
    if (!(rel <= 1e-13)) bad++;
  }
  TH_CHECK(bad == 0 && n_cmp > 300, "same bin: quartic solver = the quadratic formula to 1e-13 in %ld "
           "cases (worst %.2e, %ld bad)", n_cmp, worst, bad);
}

static void test_special(void)
{
  double tau = -1;
  /* head-on under a relative acceleration only: d = 2 - t^2/2 along x, contact at t = sqrt 2 */
  double dr[3] = {2, 0, 0}, dv[3] = {0, 0, 0}, da[3] = {-1, 0, 0};
  int h = wg_shear_pair_root(dr, dv, da, 2, 1.0, -1, INFINITY, &tau);
  TH_CHECK(h && fabs(tau - sqrt(2.0)) < 1e-15, "pair at rest pushed together: t = %.17g (sqrt 2)", tau);
  /* receding and pushed apart: never */
  double dv2[3] = {1, 0, 0}, da2[3] = {1, 0, 0};
  h = wg_shear_pair_root(dr, dv2, da2, 2, 1.0, -1, INFINITY, &tau);
  TH_CHECK(!h, "receding pair pushed apart: no contact (%d)", h);
  /* receding now but decelerated: turns round at t = 1, x = 2.5, back to 1 at t = 1 + sqrt 3 */
  double da3[3] = {-1, 0, 0};
  h = wg_shear_pair_root(dr, dv2, da3, 2, 1.0, -1, INFINITY, &tau);
  TH_CHECK(h && fabs(tau - (1 + sqrt(3.0))) < 1e-14, "receding pair turned round: t = %.17g", tau);
  /* tau_max cuts it */
  h = wg_shear_pair_root(dr, dv2, da3, 2, 1.0, -1, 2.0, &tau);
  TH_CHECK(!h, "tau_max before the contact: none (%d)", h);
  /* bonded pair at gap 0 inside a well of edge 1.1 drifting out under acceleration 0.2:
     1 + 0.1 t^2 = 1.1 at t = 1 */
  double br[3] = {1, 0, 0}, bv[3] = {0, 0, 0}, ba[3] = {0.2, 0, 0};
  h = wg_shear_pair_root(br, bv, ba, 2, 1.1, 1, INFINITY, &tau);
  TH_CHECK(h && fabs(tau - 1) < 1e-14, "bonded pair pulled to the edge: t = %.17g (1)", tau);
  /* a lateral pass: acceleration perpendicular bends the path into the partner */
  double lr[3] = {0, 2, 0}, lv[3] = {1, 0, 0}, la[3] = {0, -2, 0};
  /* d = (t, 2 - t^2): |d|^2 = 1 at t^4 - 3 t^2 + 3 = 0 -> no real root; a miss */
  h = wg_shear_pair_root(lr, lv, la, 2, 1.0, -1, INFINITY, &tau);
  TH_CHECK(!h, "bent path that misses (t^4 - 3t^2 + 3 > 0): none (%d)", h);
  /* speed time: d.d' = t - 1 for d = (1 + ...) ... dr = (1,0), dv = (-1,0), da = (1,0):
     d.d' = (1 - t + t^2/2)(t - 1) crosses 0.5 upwards where (1 - t + t^2/2)(t-1) = 0.5 */
  double sr[3] = {1, 0, 0}, sv[3] = {-1, 0, 0}, sa[3] = {1, 0, 0};
  double ts = wg_shear_pair_speed_time(sr, sv, sa, 2, 0.5);
  double q = (1 - ts + ts * ts / 2) * (ts - 1);
  TH_CHECK(fabs(q - 0.5) < 1e-13 && ts > 1, "speed time: d.d' = %.17g (0.5) at t = %.17g", q, ts);
}

static void test_bins(void)
{
  wg_shear f;
  int st = wg_shear_init(&f, 0.5, 20, 20.0, 0, INFINITY, 1);
  TH_CHECK(st == WG_OK && f.width == 1.0, "bins: 20 bins of width %g", f.width);
  double sum = 0;
  for (int k = 0; k < f.nbins; k++) sum += f.force[k];
  TH_CLOSE("bins: forces sum to zero (no net push)", sum, 0.0, 0, 1e-14);
  TH_CLOSE("bins: force of bin 0 = F cos(pi/20)", f.force[0], 0.5 * cos(M_PI / 20), 1e-15, 0);
  TH_CHECK(wg_shear_bin_of(&f, 3.5) == 3 && wg_shear_bin_of(&f, -0.5) == 19 &&
           wg_shear_bin_of(&f, 20.25) == 0, "bins: bin_of 3.5 -> %d, -0.5 -> %d, 20.25 -> %d",
           wg_shear_bin_of(&f, 3.5), wg_shear_bin_of(&f, -0.5), wg_shear_bin_of(&f, 20.25));
  int dir;
  double t = wg_shear_bin_exit(&f, 3, 3.25, 0.5, &dir);
  TH_CHECK(fabs(t - 1.5) < 1e-15 && dir == 1, "bins: exit up after %g (1.5), dir %d", t, dir);
  t = wg_shear_bin_exit(&f, 19, -0.75, -0.5, &dir); /* image of bin 19 below 0 */
  TH_CHECK(fabs(t - 0.5) < 1e-15 && dir == -1, "bins: exit of a wrapped image after %g (0.5)", t);
  TH_CHECK(wg_shear_bin_step(&f, 19, 1) == 0 && wg_shear_bin_step(&f, 0, -1) == 19,
           "bins: steps wrap around");
  TH_CHECK(wg_shear_active(&f, 0) && !wg_shear_active(NULL, 0), "field active from t_on");
  wg_shear_free(&f);
  wg_shear_init(&f, 1, 4, 8, 2, 5, 1);
  TH_CHECK(!wg_shear_active(&f, 1.99) && wg_shear_active(&f, 2) && !wg_shear_active(&f, 5),
           "field on at t_on = 2, off at t_off = 5");
  wg_shear_free(&f);
}

/* Cell exits under an acceleration along a lateral axis, against the brute force. */
static void test_cell_exit(void)
{
  wg_cells c = {0};
  double lo[3] = {0, 0, 0}, len[3] = {10, 10, 10};
  int per[3] = {1, 1, 0};
  wg_cells_alloc(&c, 3, lo, len, per, 1.25, 1);
  rng g = {9};
  long bad = 0;
  for (int n = 0; n < 2000; n++) {
    double r[3], v[3], acc[3] = {0, 2 * sym(&g), -1};
    for (int k = 0; k < 3; k++) {
      r[k] = 2.5 + 1.25 * uniform(&g); /* inside cell (2, 2, 2) */
      v[k] = 2 * sym(&g);
    }
    long cell = wg_cells_locate(&c, r);
    int axis, dir;
    double t = wg_shear_cell_exit_time(&c, cell, r, v, acc, 0, -1, 0, &axis, &dir);
    /* brute force: first step of 1e-5 at which the position leaves the cell */
    double tb = INFINITY;
    for (double s = 1e-5; s < 10; s += 1e-5) {
      double x[3];
      for (int k = 0; k < 3; k++) x[k] = r[k] + v[k] * s + 0.5 * acc[k] * s * s;
      if (wg_cells_locate(&c, x) != cell) { tb = s; break; }
    }
    if (!(t <= tb && t > tb - 1.01e-5)) {
      bad++;
      if (bad < 4) printf("# cell exit %.17g, brute force %.17g\n", t, tb);
    }
  }
  TH_CHECK(bad == 0, "cell exits under acceleration agree with a 1e-5 scan in 2000 cases (%ld bad)", bad);
  /* just entered rising through the lower face, against gravity: the particle turns round and
     must leave through that face again (wg_cells_exit_time with turn_back, the rule of scenes
     with resting grains; docs/engines.md, "Cell crossings under gravity") */
  long bad_g = 0;
  c.turn_back = 1;
  for (int n = 0; n < 500; n++) {
    double r[3], v[3], acc[3] = {0, 0, -1};
    for (int k = 0; k < 3; k++) {
      r[k] = 2.5 + 1.25 * (0.1 + 0.8 * uniform(&g));
      v[k] = 0.3 * sym(&g);
    }
    r[2] = 2.5; /* on the lower face of cell 2 along z, just come in */
    v[2] = 0.05 + 0.5 * uniform(&g);
    long cell = wg_cells_locate(&c, r);
    int axis, dir;
    double t = wg_cells_exit_time(&c, cell, r, v, 1.0, 0, 2, -1, &axis, &dir);
    double tb = INFINITY;
    for (double s = 1e-5; s < 20; s += 1e-5) {
      double x[3];
      for (int k = 0; k < 3; k++) x[k] = r[k] + v[k] * s + 0.5 * acc[k] * s * s;
      if (wg_cells_locate(&c, x) != cell) { tb = s; break; }
    }
    if (!(t <= tb && t > tb - 1.01e-5)) bad_g++;
  }
  TH_CHECK(bad_g == 0, "turn_back: a particle that came in rising leaves through the same face "
           "after its apex: 500 cases agree with the scan (%ld bad)", bad_g);
  wg_cells_free(&c);
}

/* ---- the field in the engine ----------------------------------------------------------- */

static int make_scene(wg_scene *sc, const char *const *keys)
{
  wg_scene_init(sc);
  for (int k = 0; keys[k]; k++)
    if (wg_scene_set_override(sc, keys[k]) != WG_OK) return WG_EINVAL;
  return wg_scene_finish(sc);
}

/* One particle flying along x through the bins: its momentum along y grows by exactly
   F_bin times the time spent in each bin, the field's work is its kinetic energy. */
static void test_single_particle(void)
{
  const char *keys[] = {"dim=3", "n=1", "lx=8", "ly=8", "height=8", "container=periodic",
                        "tg_init_abs=1", "seed=1", "t_end=10", "sigma_p=0", "shear_force=0.5",
                        NULL};
  wg_scene sc;
  TH_CHECK(make_scene(&sc, keys) == WG_OK && sc.shear_bins == 8, "single: scene with 8 bins (%d)",
           sc.shear_bins);
  double r[3] = {0.5, 4, 4}, v[3] = {1, 0, 0}, rad[1] = {0.5};
  wg_ed s;
  TH_CHECK(wg_ed_alloc_state(&s, &sc, 1, r, v, rad, NULL, 0) == WG_OK, "single: set up");
  TH_CHECK(wg_ed_advance(&s, 2.0) == WG_OK, "single: advanced to t = 2");
  /* x: 0.5 -> 2.5; bins 0 (0.5 of time), 1 (1), 2 (0.5) */
  const double *F = s.shear->force;
  double dt[3] = {0.5, 1, 0.5}, vy = 0, y = 4;
  for (int k = 0; k < 3; k++) {
    y += vy * dt[k] + 0.5 * F[k] * dt[k] * dt[k];
    vy += F[k] * dt[k];
  }
  double rr[3], vv[3];
  wg_ed_position_of(&s, 0, 2.0, rr, vv);
  TH_CLOSE("single: momentum along y = sum of F dt", vv[1], vy, 1e-14, 1e-15);
  TH_CLOSE("single: y on the piecewise parabola", rr[1], y, 1e-14, 0);
  TH_CHECK(fabs(vy) > 0.3, "single: a momentum that can be wrong (%g)", vy);
  TH_CLOSE("single: x unaffected", rr[0], 2.5, 1e-15, 0);
  TH_CHECK(s.counts.bin_crossings == 2, "single: 2 bin crossings (%llu)", s.counts.bin_crossings);
  TH_CLOSE("single: field work = kinetic energy gained", wg_ed_field_work(&s), 0.5 * vy * vy,
           1e-13, 1e-15);
  TH_CHECK(wg_ed_ledger_residual(&s) < 1e-14, "single: ledger residual %.2e",
           wg_ed_ledger_residual(&s));
  wg_ed_free(&s);
}

/* Shaken (3D) or free (2D periodic) wet inelastic runs under the field: the ledger closes;
   with the field switched on and off, nothing of it acts outside [t_on, t_off). */
static void ledger_case(const char *name, const char *const *keys, double t_end, double t_on,
                        double t_off)
{
  wg_scene sc;
  TH_CHECK(make_scene(&sc, keys) == WG_OK, "%s: scene accepted", name);
  wg_ed s;
  TH_CHECK(wg_ed_alloc(&s, &sc) == WG_OK, "%s: set up", name);
  double worst = 0, w_on = NAN, w_off = NAN;
  unsigned long long bins_off = 0;
  for (int k = 1; k <= 40; k++) {
    double t = t_end * k / 40;
    if (wg_ed_advance(&s, t) != WG_OK) {
      TH_CHECK(0, "%s: run failed at t = %g", name, s.now);
      break;
    }
    double r = wg_ed_ledger_residual(&s);
    if (r > worst) worst = r;
    if (t <= t_on) w_on = wg_ed_field_work(&s);
    if (t <= t_off) {
      w_off = wg_ed_field_work(&s);
      bins_off = s.counts.bin_crossings;
    }
  }
  TH_CHECK(s.counts.collisions > 10000 && s.counts.ruptures > 100 && s.counts.bin_crossings > 1000,
           "%s: collisions %llu, ruptures %llu, bin crossings %llu", name, s.counts.collisions,
           s.counts.ruptures, s.counts.bin_crossings);
  TH_CHECK(fabs(wg_ed_field_work(&s)) > 1, "%s: the field works (%.4g)", name, wg_ed_field_work(&s));
  TH_CHECK(worst < 1e-9, "%s: largest ledger residual %.3g < 1e-9", name, worst);
  if (t_on > 0) TH_CHECK(w_on == 0, "%s: no work before t_on = %g (%g)", name, t_on, w_on);
  if (t_off < t_end)
    TH_CHECK(wg_ed_field_work(&s) == w_off && s.counts.bin_crossings == bins_off,
             "%s: after t_off = %g no work (%.17g = %.17g) and no bin crossing (%llu = %llu)",
             name, t_off, wg_ed_field_work(&s), w_off, s.counts.bin_crossings, bins_off);
  wg_ed_free(&s);
}

static void test_ledger(void)
{
  const char *shake3d[] = {"dim=3", "n=800", "lx=14", "ly=14", "height=8", "s_crit=0.0625",
                           "e_cb_mgs=4", "eps=0.9", "eps_wall=0.95", "gamma=15", "estar=2",
                           "seed=6", "t_end=20", "shear_force=0.5", NULL};
  ledger_case("3D wet shaker, field on", shake3d, 20, 0, INFINITY);
  const char *free2d[] = {"dim=2", "n=400", "lx=40", "height=20", "container=periodic",
                          "s_crit=0.0711", "f_b=4", "eps=0.9", "tg_init=20", "seed=3", "t_end=40",
                          "shear_force=0.3", "shear_on=5", "shear_off=25", NULL};
  ledger_case("2D wet periodic, field on at 5, off at 25", free2d, 40, 5, 25);
}

/* Until the field is switched on the run is the run without a field, bit for bit. */
static void test_off_until_on(void)
{
  const char *with[] = {"dim=3", "n=400", "lx=12", "ly=12", "height=8", "s_crit=0.0625",
                        "e_cb_mgs=4", "eps=0.9", "gamma=30", "estar=2", "seed=2", "t_end=10",
                        "shear_force=1", "shear_on=3", NULL};
  wg_scene a, b;
  TH_CHECK(make_scene(&a, with) == WG_OK, "off until on: scene");
  b = a;
  b.shear_force = 0;
  wg_ed sa, sb;
  int ok = wg_ed_alloc(&sa, &a) == WG_OK && wg_ed_alloc(&sb, &b) == WG_OK &&
           wg_ed_advance(&sa, 3.0) == WG_OK && wg_ed_advance(&sb, 3.0) == WG_OK;
  long diff = 0;
  for (long id = 0; ok && id < sa.n; id++) {
    double ra[3], va[3], rb[3], vb[3];
    wg_ed_position_of(&sa, id, 3.0, ra, va);
    wg_ed_position_of(&sb, id, 3.0, rb, vb);
    for (int k = 0; k < 3; k++) diff += ra[k] != rb[k] || va[k] != vb[k];
  }
  TH_CHECK(ok && diff == 0 && sa.counts.collisions == sb.counts.collisions &&
           sa.counts.collisions > 1000,
           "off until on: at t_on = 3 identical to the run without field (%ld differences, "
           "%llu = %llu collisions)", diff, sa.counts.collisions, sb.counts.collisions);
  ok = ok && wg_ed_advance(&sa, 4.0) == WG_OK && wg_ed_advance(&sb, 4.0) == WG_OK;
  TH_CHECK(ok && sa.counts.bin_crossings > 100 && wg_ed_field_work(&sa) != 0,
           "off until on: then the field acts (%llu bin crossings)", sa.counts.bin_crossings);
  wg_ed_free(&sa);
  wg_ed_free(&sb);
}

static void test_scene_errors(void)
{
  wg_scene sc;
  const char *shaker2d[] = {"dim=2", "n=100", "lx=40", "height=9", "s_crit=0.07", "f_b=4",
                            "gamma=15", "estar=1", "seed=1", "t_end=1", "shear_force=1", NULL};
  TH_CHECK(make_scene(&sc, shaker2d) != WG_OK, "scene: a 2D shaker with a field is refused");
  const char *order[] = {"dim=3", "n=100", "lx=10", "ly=10", "height=8", "s_crit=0.07", "f_b=4",
                         "gamma=15", "estar=1", "seed=1", "t_end=1", "shear_force=1",
                         "shear_on=5", "shear_off=2", NULL};
  TH_CHECK(make_scene(&sc, order) != WG_OK, "scene: shear_off before shear_on is refused");
  const char *bins[] = {"dim=3", "n=100", "lx=10", "ly=10", "height=8", "s_crit=0.07", "f_b=4",
                        "gamma=15", "estar=1", "seed=1", "t_end=1", "shear_force=1",
                        "shear_bins=2", NULL};
  TH_CHECK(make_scene(&sc, bins) != WG_OK, "scene: shear_bins = 2 is refused");
  const char *neg[] = {"dim=3", "n=100", "lx=10", "ly=10", "height=8", "s_crit=0.07", "f_b=4",
                       "gamma=15", "estar=1", "seed=1", "t_end=1", "shear_force=-1", NULL};
  TH_CHECK(make_scene(&sc, neg) != WG_OK, "scene: a negative shear_force is refused");
  const char *td[] = {"engine=td", "dim=3", "n=100", "lx=10", "ly=10", "height=8",
                      "s_crit=0.07", "f_b=4", "gamma=15", "estar=1", "seed=1", "t_end=1",
                      "shear_force=1", NULL};
  TH_CHECK(make_scene(&sc, td) != WG_OK, "scene: shear_force with engine = td is refused");
  const char *good[] = {"dim=3", "n=100", "lx=10.4", "ly=10", "height=8", "s_crit=0.07",
                        "f_b=4", "gamma=15", "estar=1", "seed=1", "t_end=1", "shear_force=1",
                        NULL};
  TH_CHECK(make_scene(&sc, good) == WG_OK && sc.shear_bins == 10 && isinf(sc.shear_off) &&
           sc.shear_on == 0, "scene: defaults shear_bins = round(lx) = %d, on 0, off inf",
           sc.shear_bins);
}

int main(void)
{
  test_scene_errors();
  test_single_particle();
  test_off_until_on();
  test_ledger();
  test_special();
  test_bins();
  test_same_bin();
  test_random();
  test_grazing();
  test_cell_exit();
  return th_summary();
}
