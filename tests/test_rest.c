/* Resting contacts (scene key rest_speed, docs/engines.md "Resting on the floor"): a layer on a
   floor shaken at Gamma = 0.8 comes to rest and stays on it to 1e-9 d; a resting particle
   lifts off where the floor's acceleration falls to -g and lands where the free parabola meets
   the floor again (both against closed forms and an independent bisection); at Gamma = 1 it
   never leaves; collisions with a resting particle push against the floor; the ledger closes. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "ed.h"
#include "tharness.h"

static int scene(wg_scene *sc, const char *const *keys)
{
  wg_scene_init(sc);
  for (int k = 0; keys[k]; k++)
    if (wg_scene_set_override(sc, keys[k]) != WG_OK) return 1;
  return wg_scene_finish(sc) != WG_OK;
}

static long riders(const wg_ed *s)
{
  long k = 0;
  for (long i = 0; i < s->n; i++) k += s->riding[i];
  return k;
}

/* Largest |gap| between a resting particle and the floor, and the worst overlap of any pair. */
static void gaps(const wg_ed *s, double *rest_gap, double *overlap)
{
  double worst = 0, over = 0;
  for (long i = 0; i < s->n; i++) {
    double r[3], v[3];
    wg_ed_position_at(s, i, s->now, r, v);
    if (s->riding[i]) {
      double g = r[s->up] - s->p[i].radius - wg_wall_position(&s->wall[0], s->now);
      if (fabs(g) > worst) worst = fabs(g);
    }
    for (long j = i + 1; j < s->n; j++) {
      double q[3], u[3], d2 = 0;
      wg_ed_position_at(s, j, s->now, q, u);
      for (int k = 0; k < s->dim; k++) {
        double x = q[k] - r[k];
        if (s->periodic[k]) x -= s->box[k] * round(x / s->box[k]);
        d2 += x * x;
      }
      double o = sqrt(d2) - s->p[i].radius - s->p[j].radius;
      if (o < over) over = o;
    }
  }
  *rest_gap = worst;
  *overlap = over;
}

/* A sparse layer dropped from a little height onto a floor at Gamma = 0.8 (eps_wall = 0.5): it
   settles and then rides the floor, at rest on it to 1e-9 d, for 50 periods; with rest_speed = 0
   the same layer keeps bouncing (the floor's inelastic collapse at wall_min_speed). */
static void layer_at_rest(int dim, int wet_run)
{
  const char *wet = wet_run ? "wet" : "dry";
  const char *keys[16] = {dim == 2 ? "dim=2" : "dim=3", dim == 2 ? "n=12" : "n=30", "lx=24",
                          "height=6", "gamma=0.8", "eps=0.9", "eps_wall=0.5", "rest_speed=0.01",
                          "seed=3", "t_end=100"};
  int nk = 10;
  if (wet_run) {
    keys[nk++] = "s_crit=0.0711";
    keys[nk++] = "f_b=4";
    keys[nk++] = "estar=1";
    keys[nk++] = "tg_init=0.2";
  } else {
    keys[nk++] = "estar_d=0.5";
    keys[nk++] = "tg_init_abs=0.05";
  }
  if (dim == 3) keys[nk++] = "ly=24";
  keys[nk] = NULL;
  wg_scene sc;
  if (scene(&sc, keys)) {
    TH_CHECK(0, "%dD %s layer: scene accepted", dim, wet);
    return;
  }
  wg_ed s;
  TH_CHECK(wg_ed_alloc(&s, &sc) == WG_OK, "%dD layer set up", dim);
  int st = wg_ed_advance(&s, 30 * sc.t_driv);
  TH_CHECK(st == WG_OK && riders(&s) == s.n, "%dD %s: after 30 periods all %ld grains rest on "
           "the floor (%ld do; %llu contacts came to rest)", dim, wet, s.n, riders(&s),
           s.counts.rests);
  double worst = 0, overlap = 0;
  unsigned long long ev0 = s.counts.collisions + s.counts.wall_hits + s.counts.lift_offs;
  double t0 = s.now;
  for (int k = 1; k <= 50 * 16 && st == WG_OK; k++) {
    st = wg_ed_advance(&s, t0 + k * sc.t_driv / 16);
    double g, o;
    gaps(&s, &g, &o);
    if (g > worst) worst = g;
    if (o < overlap) overlap = o;
  }
  unsigned long long ev = s.counts.collisions + s.counts.wall_hits + s.counts.lift_offs - ev0;
  TH_CHECK(st == WG_OK && riders(&s) == s.n && worst <= 1e-9,
           "%dD %s: 50 periods at Gamma = 0.8, every grain still on the floor, largest height "
           "off it %.1e d (<= 1e-9); %llu collisions and wall contacts meanwhile", dim, wet,
           worst, ev);
  TH_CHECK(overlap > -1e-9, "%dD %s: no pair overlaps (worst %.1e d)", dim, wet, overlap);
  double res = wg_ed_ledger_residual(&s);
  TH_CHECK(res < 1e-9, "%dD %s: ledger closes with the floor's work on resting grains (%.1e)",
           dim, wet, res);
  wg_ed_free(&s);
}

/* Gap of a particle leaving the floor at t_l with the floor's velocity: free parabola less the
   floor (both from the floor's height at t_l). */
static double flight_gap(const wg_wall *w, double t_l, double t)
{
  double z0 = wg_wall_position(w, t_l), v0 = wg_wall_velocity(w, t_l), tau = t - t_l;
  return z0 + v0 * tau - 0.5 * tau * tau - wg_wall_position(w, t);
}

/* One grain at rest on the floor at Gamma = gamma: when it lifts off and when it lands. */
static void lift_off(double gamma)
{
  char gm[48];
  snprintf(gm, sizeof gm, "gamma=%.17g", gamma);
  const char *keys[] = {"dim=2", "n=1", "lx=10", "height=8", "sigma_p=0", gm, "estar_d=0.5",
                        "eps_wall=0.5", "rest_speed=0.01", "tg_init_abs=0", "seed=1",
                        "t_end=100", NULL};
  wg_scene sc;
  if (scene(&sc, keys)) {
    TH_CHECK(0, "Gamma = %g: scene accepted", gamma);
    return;
  }
  /* at t = 0 the floor is at z = 0 moving up at A w: the grain sits on it with that speed */
  double r[2] = {5, 0.5}, v[2] = {0, sc.amplitude * sc.omega}, rad[1] = {0.5};
  wg_ed s;
  TH_CHECK(wg_ed_alloc_state(&s, &sc, 1, r, v, rad, NULL, 0) == WG_OK, "one grain set up");
  int st = wg_ed_advance(&s, 1e-6);
  TH_CHECK(st == WG_OK && s.riding[0], "Gamma = %g: a grain on the floor with its velocity rests",
           gamma);
  const wg_wall *w = &s.wall[0];
  if (gamma <= 1) {
    double worst = 0;
    for (int k = 1; k <= 50 * 32 && st == WG_OK; k++) {
      st = wg_ed_advance(&s, k * sc.t_driv / 32);
      double q[3], u[3];
      wg_ed_position_at(&s, 0, s.now, q, u);
      double g = fabs(q[1] - 0.5 - wg_wall_position(w, s.now));
      if (g > worst) worst = g;
    }
    TH_CHECK(st == WG_OK && s.counts.lift_offs == 0 && worst <= 1e-9,
             "Gamma = %g: no lift-off in 50 periods (%llu), height off the floor %.1e <= 1e-9",
             gamma, s.counts.lift_offs, worst);
    wg_ed_free(&s);
    return;
  }
  /* the floor's acceleration -A w^2 sin(w t) falls through -g where sin(w t) = 1/Gamma, rising */
  double t_l = asin(1 / gamma) / sc.omega;
  st = wg_ed_advance(&s, t_l * (1 - 1e-9));
  int before = s.riding[0];
  st |= wg_ed_advance(&s, t_l * (1 + 1e-9));
  TH_CHECK(st == WG_OK && before && !s.riding[0] && s.counts.lift_offs == 1,
           "Gamma = %g: lift-off at w t = asin(1/Gamma) = %.9f, within 1e-9 relative", gamma,
           asin(1 / gamma));
  /* landing: the first root of the flight gap after t_l, bracketed on a fine scan and bisected */
  double a = t_l + 1e-3 * sc.t_driv, b = a;
  while (flight_gap(w, t_l, b) > 0 && b < t_l + 10 * sc.t_driv) a = b, b += 1e-3 * sc.t_driv;
  for (int k = 0; k < 200; k++) {
    double m = 0.5 * (a + b);
    if (flight_gap(w, t_l, m) > 0) a = m;
    else b = m;
  }
  double t_land = 0.5 * (a + b);
  double peak = 0;
  for (double t = t_l; t < t_land; t += (t_land - t_l) / 64) {
    st |= wg_ed_advance(&s, t);
    double q[3], u[3];
    wg_ed_position_at(&s, 0, s.now, q, u);
    double want = wg_wall_position(w, t) + flight_gap(w, t_l, t) + 0.5;
    if (fabs(q[1] - want) > peak) peak = fabs(q[1] - want);
  }
  TH_CHECK(st == WG_OK && peak < 1e-9, "Gamma = %g: the flight follows the parabola from the "
           "lift-off point (largest deviation %.1e d)", gamma, peak);
  unsigned long long hits = s.counts.wall_hits;
  st |= wg_ed_advance(&s, t_land - 1e-7);
  int early = s.counts.wall_hits == hits;
  st |= wg_ed_advance(&s, t_land + 1e-7);
  TH_CHECK(st == WG_OK && early && s.counts.wall_hits == hits + 1,
           "Gamma = %g: lands at t = %.9f (w t = %.6f) to 1e-7, flight %.4f periods", gamma,
           t_land, sc.omega * t_land, (t_land - t_l) / sc.t_driv);
  wg_ed_free(&s);
}

/* Two grains on a floor at Gamma = 0.8, one above the other: the lower one on the floor with
   its velocity, the upper one at rest at height z_upper; eps between the grains. */
static int stacked_pair(wg_ed *s, wg_scene *sc, const char *eps, double z_upper, const char *what)
{
  const char *keys[] = {"dim=2", "n=2", "lx=10", "height=8", "sigma_p=0", "gamma=0.8",
                        "estar_d=0.2", eps, "eps_wall=0.5", "rest_speed=0.01", "tg_init_abs=0",
                        "seed=1", "t_end=100", NULL};
  if (scene(sc, keys)) {
    TH_CHECK(0, "%s: scene accepted", what);
    return 1;
  }
  double vw = sc->amplitude * sc->omega;
  double r[4] = {5, 0.5, 5, z_upper}, v[4] = {0, vw, 0, 0}, rad[2] = {0.5, 0.5};
  int ok = wg_ed_alloc_state(s, sc, 2, r, v, rad, NULL, 0) == WG_OK;
  TH_CHECK(ok, "%s: set up", what);
  return !ok;
}

/* A grain falling straight onto a resting one: the floor takes the push, the resting grain
   stays put, and the falling grain leaves with its speed relative to the floor reversed
   (eps = 1), as if it had hit the floor itself; two resting grains meeting side by side swap
   their velocities along the floor and both stay on it. */
static void pairs(void)
{
  wg_scene sc;
  wg_ed s;
  if (stacked_pair(&s, &sc, "eps=1", 1.6, "pairs")) return;
  double vw = sc.amplitude * sc.omega, rad[2] = {0.5, 0.5};
  int st = wg_ed_advance(&s, 1e-6);
  long lower = s.slot[0], upper = s.slot[1];
  TH_CHECK(st == WG_OK && s.riding[lower] && !s.riding[upper], "the lower grain rests");
  unsigned long long c0 = s.counts.collisions;
  double tprev = s.now, urel = 0;
  while (s.counts.collisions == c0 && st == WG_OK && s.now < 5) {
    double q[3], u[3];
    wg_ed_position_at(&s, upper, s.now, q, u);
    urel = u[1] - wg_wall_velocity(&s.wall[0], s.now);
    tprev = s.now;
    st = wg_ed_advance(&s, s.now + 1e-4);
  }
  (void)tprev;
  double q[3], u[3], p[3], pv[3];
  wg_ed_position_at(&s, upper, s.now, q, u);
  wg_ed_position_at(&s, lower, s.now, p, pv);
  double after = u[1] - wg_wall_velocity(&s.wall[0], s.now);
  TH_CHECK(st == WG_OK && s.riding[lower] && pv[0] == 0,
           "after the hit the lower grain still rests, unmoved along the floor (v_x = %g)", pv[0]);
  TH_CHECK(fabs(after + urel) < 2e-3 * fabs(urel) + 2e-4,
           "the falling grain leaves at its approach speed relative to the floor: %.6f vs %.6f",
           after, -urel);
  /* it goes on bouncing on the resting grain (eps = 1); where a bounce is slower than rest_speed
     it hops at rest_speed, at most (g + A w^2) / (2 rest_speed) times per time unit, never
     every ~2 tc; either way it never sinks into the grain below */
  unsigned long long c1 = s.counts.collisions;
  double t1 = s.now, lowest = INFINITY;
  for (int k = 1; k <= 400 && st == WG_OK; k++) {
    st = wg_ed_advance(&s, t1 + k * 0.1);
    wg_ed_position_at(&s, upper, s.now, q, u);
    wg_ed_position_at(&s, lower, s.now, p, pv);
    double dd = hypot(q[0] - p[0], q[1] - p[1]);
    if (dd < lowest) lowest = dd;
  }
  double rate = (double)(s.counts.collisions - c1) / (s.now - t1);
  double bound = (1 + sc.amplitude * sc.omega * sc.omega) / (2 * 0.01);
  TH_CHECK(st == WG_OK && s.riding[lower] && lowest > 1 - 1e-9 && rate <= bound,
           "40 time units later: the lower grain rests, the upper one never sinks into it "
           "(least distance %.12f), %.1f collisions per time unit (<= %.0f)", lowest, rate, bound);
  double res = wg_ed_ledger_residual(&s);
  TH_CHECK(res < 1e-9, "pair on the floor: ledger closes (%.1e)", res);
  wg_ed_free(&s);

  double r2[4] = {3, 0.5, 6, 0.5}, v2[4] = {0.3, vw, -0.1, vw};
  TH_CHECK(wg_ed_alloc_state(&s, &sc, 2, r2, v2, rad, NULL, 0) == WG_OK, "side by side: set up");
  st = wg_ed_advance(&s, 8);
  long a = s.slot[0], b = s.slot[1];
  TH_CHECK(st == WG_OK && s.counts.collisions >= 1 && s.riding[a] && s.riding[b],
           "side by side: %llu collision, both still rest", s.counts.collisions);
  double ra[3], va[3], rb[3], vb[3];
  wg_ed_position_at(&s, a, s.now, ra, va);
  wg_ed_position_at(&s, b, s.now, rb, vb);
  TH_CHECK(fabs(va[0] + 0.1) < 1e-12 && fabs(vb[0] - 0.3) < 1e-12,
           "equal grains swap their velocities along the floor: %.15f, %.15f", va[0], vb[0]);
  wg_ed_free(&s);
}

/* An inelastic grain (eps = 0.5) dropped onto a resting one settles on it: it cannot ride a
   grain that may slide, so it hops at rest_speed, 5e-5 d high, at most (g + A w^2) /
   (2 rest_speed) times per time unit (without that it would bounce every ~2 tc, 10^5 times). */
static void hop_on_resting(void)
{
  wg_scene sc;
  wg_ed s;
  if (stacked_pair(&s, &sc, "eps=0.5", 1.8, "hop")) return;
  int st = wg_ed_advance(&s, 10);
  long lower = s.slot[0], upper = s.slot[1];
  unsigned long long c0 = s.counts.collisions;
  double lowest = INFINITY, highest = 0;
  for (int k = 1; k <= 2000 && st == WG_OK; k++) {
    st = wg_ed_advance(&s, 10 + k * 0.01);
    double q[3], u[3], p[3], pv[3];
    wg_ed_position_at(&s, upper, s.now, q, u);
    wg_ed_position_at(&s, lower, s.now, p, pv);
    double d = hypot(q[0] - p[0], q[1] - p[1]);
    if (d < lowest) lowest = d;
    if (d > highest) highest = d;
  }
  double rate = (double)(s.counts.collisions - c0) / 20;
  double bound = (1 + sc.amplitude * sc.omega * sc.omega) / (2 * 0.01);
  TH_CHECK(st == WG_OK && s.riding[lower] && !s.riding[upper] && lowest > 1 - 1e-9 &&
           highest < 1 + 1e-3 && rate > 1 && rate <= bound,
           "hop: the upper grain lies on the resting one (distance %.9f to %.9f), hopping %.1f "
           "times per time unit (1 < rate <= %.0f)", lowest, highest, rate, bound);
  double res = wg_ed_ledger_residual(&s);
  TH_CHECK(res < 1e-9, "hop: ledger closes (%.1e)", res);
  wg_ed_free(&s);
}

int main(void)
{
  layer_at_rest(2, 0);
  layer_at_rest(2, 1);
  layer_at_rest(3, 1);
  lift_off(1.0);
  lift_off(1.2);
  lift_off(2.0);
  lift_off(4.0);
  pairs();
  hop_on_resting();
  return th_summary();
}
