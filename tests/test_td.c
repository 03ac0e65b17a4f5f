/* The time-driven engine against closed forms: restitution and contact time of the linear
   spring-dashpot (any reduced mass), the elastic Hertz contact time, a ball bouncing on a
   floor, the minimal capillary model's rupture energy E_cb = F_B s_crit and a bound pair that
   stays bound, and the energy ledger of a shaken wet bed converging faster than dt (contacts
   start between steps, which costs an energy error ~ (pi dt / t_c)^2 per contact). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "tharness.h"
#include "td.h"
#include "td_bed.h"

/* 2D, periodic 20 x 20 box, no gravity, no walls; the linear law with e, t_c. */
static wg_td_params free_params(double e, double t_c)
{
  wg_td_params p;
  periodic_box(&p, 2, t_c / 50);
  p.pp = p.pw = wg_contact_linear(e, t_c, 0.5);
  return p;
}

/* Two particles approaching head-on along x at relative speed u; returns the relative speed
   after the contact and the contact's duration (first to last step with overlap). */
static double head_on(const wg_td_params *par, const double *rad, const double *m, double u,
                      double *duration)
{
  double r[6] = {8, 10, 0, 8 + rad[0] + rad[1] + 0.05, 10, 0}, v[6] = {0.5 * u, 0, 0, -0.5 * u, 0, 0};
  wg_td s;
  if (wg_td_alloc_state(&s, par, 2, r, v, rad, m, 0) != WG_OK) return NAN;
  double t_in = -1, t_out = -1;
  while (s.t < 1) {
    wg_td_advance(&s, s.t + par->dt);
    double gap = s.r[3] - s.r[0] - rad[0] - rad[1];
    if (gap < 0 && t_in < 0) t_in = s.t;
    if (gap < 0) t_out = s.t;
    if (gap > 0 && t_out > 0) break; /* the contact is over (no periodic re-encounter) */
  }
  *duration = t_out - t_in + par->dt;
  double du = s.v[3] - s.v[0];
  wg_td_free(&s);
  return du;
}

/* The linear law with e = 0.9 under an integrator: the dashpot force jumps at the start of a
   contact, which falls between steps, so the restitution converges to e at first order in dt
   at least; the error must fall by more than 3 for dt / 4.  Returns the parameters at t_c/50. */
static wg_td_params restitution_converges(const char *name, int integrator, double tol50)
{
  double rad[2] = {0.5, 0.5}, dur;
  wg_td_params p = free_params(0.9, 0.01);
  p.integrator = integrator;
  double du = head_on(&p, rad, NULL, 2.0, &dur);
  double err50 = fabs(du / 2.0 - 0.9);
  TH_CHECK(err50 < tol50, "%s, linear law: restitution %.5f vs e = 0.9 at dt = t_c/50", name, du / 2.0);
  TH_CLOSE("linear law: contact time t_c = 0.01 (to a step)", dur, 0.01, 0, 1.5 * p.dt);
  p.dt = 0.01 / 200;
  du = head_on(&p, rad, NULL, 2.0, &dur);
  double err200 = fabs(du / 2.0 - 0.9);
  TH_CHECK(err200 < err50 / 3, "%s at dt = t_c/200: %.5f (error down by %.1f for dt / 4)", name, du / 2.0, err50 / err200);
  p.dt = 0.01 / 50;
  return p;
}

static void linear_contact(void)
{
  double rad[2] = {0.5, 0.5}, dur, du;
  wg_td_params p = restitution_converges("Verlet", WG_TD_VERLET, 5e-3);
  double m[2] = {1.0, 3.0};
  du = head_on(&p, rad, m, 2.0, &dur);
  TH_CLOSE("linear law: e = 0.9 also for m_eff = 0.75 (damping per pair)", du / 2.0, 0.9, 5e-3, 0);
  TH_CLOSE("linear law: contact time scales as sqrt(m_eff / m_ref)", dur, 0.01 * sqrt(1.5), 0, 1.5 * p.dt);
  p = free_params(1.0, 0.01);
  du = head_on(&p, rad, NULL, 2.0, &dur);
  TH_CLOSE("linear law, e = 1: relative speed restored", du / 2.0, 1.0, 1e-4, 0);
}

/* Elastic Hertz: 1/2 m_eff u^2 = (2/5) K sqrt(R_eff) xi_max^(5/2), t_c = 2.9432 xi_max / u. */
static void hertz_contact(void)
{
  double rad[2] = {0.5, 0.5}, dur, u = 1.0, kh = 1e5;
  wg_td_params p = free_params(1.0, 0.01);
  p.pp = wg_contact_hertz(kh, 0);
  double xi_max = pow(5 * 0.5 * u * u / (4 * kh * sqrt(0.25)), 0.4), tc = 2.9432 * xi_max / u;
  p.dt = tc / 200;
  double du = head_on(&p, rad, NULL, u, &dur);
  TH_CLOSE("Hertz, A_d = 0: elastic", du / u, 1.0, 1e-4, 0);
  TH_CLOSE("Hertz: contact time 2.9432 xi_max / u", dur, tc, 0, 1.5 * p.dt);
  p.pp = wg_contact_hertz(kh, 1e-3);
  du = head_on(&p, rad, NULL, u, &dur);
  TH_CHECK(du / u < 0.999 && du / u > 0.5, "Hertz with A_d = 1e-3: inelastic, e = %.4f", du / u);
}

/* A ball dropped on a resting floor (wall law e = 0.8) leaves it at 0.8 of its impact speed. */
static void floor_bounce(void)
{
  wg_td_params p = free_params(1.0, 0.01);
  resting_floor(&p, 30);
  p.pw = wg_contact_linear(0.8, 0.01, 1.0);
  double r[3] = {10, 5.5, 0}, v[3] = {0, 0, 0}, rad[1] = {0.5};
  wg_td s;
  TH_CHECK(wg_td_alloc_state(&s, &p, 1, r, v, rad, NULL, 0) == WG_OK, "ball above the floor");
  double u_in = NAN, u_out = NAN;
  int touched = 0;
  while (s.t < 4 && isnan(u_out)) {
    double vz = s.v[1];
    wg_td_advance(&s, s.t + p.dt);
    if (!touched && s.r[1] < 0.5) touched = 1, u_in = -vz;
    if (touched && s.r[1] > 0.5) u_out = s.v[1];
  }
  /* gravity acts during the contact too: a correction of order g t_c / u = 0.4 % */
  TH_CLOSE("ball leaves the floor at e_wall times its impact speed", u_out, 0.8 * u_in, 1e-2, 0);
  TH_CHECK(wg_td_ledger_residual(&s) < 1e-3, "ledger of the bounce closes: residual %.2e", wg_td_ledger_residual(&s));
  wg_td_free(&s);
}

/* Minimal capillary model: a pair touching (bond forms at contact) and separating at speed u
   loses F_B s_crit when the bond breaks; below that energy it stays bound. */
static void capillary_pair(void)
{
  double f_b = 4, s_crit = 0.0711, e_cb = f_b * s_crit, mu = 0.5;
  wg_td_params p = free_params(1.0, 0.005);
  p.f_b = f_b;
  p.s_crit = s_crit;
  double rad[2] = {0.5, 0.5};
  double u = sqrt(2 * 3 * e_cb / mu); /* 1/2 mu u^2 = 3 E_cb */
  double r[6] = {8, 10, 0, 8.999999, 10, 0}, v[6] = {-0.5 * u, 0, 0, 0.5 * u, 0, 0};
  wg_td s;
  TH_CHECK(wg_td_alloc_state(&s, &p, 2, r, v, rad, NULL, 0) == WG_OK, "touching pair");
  TH_CHECK(s.captures == 1 && wg_td_bond_total(&s) == 1, "the pair bonds at contact");
  wg_td_advance(&s, 1);
  double du = s.v[3] - s.v[0];
  TH_CHECK(s.ruptures == 1 && wg_td_bond_total(&s) == 0, "the bond breaks once (ruptures %llu)", s.ruptures);
  TH_CLOSE("kinetic energy after rupture: 1/2 mu u^2 - E_cb", 0.5 * mu * du * du, 2 * e_cb, 1e-2, 0);
  TH_CHECK(wg_td_ledger_residual(&s) < 1e-3, "ledger closes across the rupture: residual %.2e", wg_td_ledger_residual(&s));
  wg_td_free(&s);

  u = sqrt(2 * 0.5 * e_cb / mu); /* half the bond energy: bound */
  double v2[6] = {-0.5 * u, 0, 0, 0.5 * u, 0, 0};
  TH_CHECK(wg_td_alloc_state(&s, &p, 2, r, v2, rad, NULL, 0) == WG_OK, "slow pair");
  double gap_max = 0;
  while (s.t < 5) {
    wg_td_advance(&s, s.t + p.dt);
    double gap = s.r[3] - s.r[0] - 1.0;
    if (gap > gap_max) gap_max = gap;
  }
  TH_CHECK(s.ruptures == 0 && wg_td_bond_total(&s) == 1, "with 1/2 mu u^2 = E_cb / 2 the pair stays bound");
  TH_CLOSE("its largest gap: 1/2 mu u^2 / F_B = s_crit / 2", gap_max, 0.5 * s_crit, 0.02, 0);
  wg_td_free(&s);
}

/* A wet, inelastic bed of 60 disks on a shaken floor under a lid: the ledger residual after
   4 time units, at two time steps. */
static double shaken_bed_residual(double dt_factor, unsigned long long *ruptures, int integrator)
{
  wg_td_params p = free_params(0.8, 0.01);
  p.integrator = integrator;
  p.dt = 0.01 / dt_factor;
  double r[180], v[180], rad[60];
  shaken_bed(&p, r, v, rad);
  wg_td s;
  if (wg_td_alloc_state(&s, &p, 60, r, v, rad, NULL, 0) != WG_OK) return NAN;
  wg_td_advance(&s, 4);
  double res = wg_td_ledger_residual(&s);
  *ruptures = s.ruptures;
  wg_td_free(&s);
  return res;
}

static void ledger_convergence(void)
{
  unsigned long long n1, n2;
  double r1 = shaken_bed_residual(25, &n1, WG_TD_VERLET), r2 = shaken_bed_residual(50, &n2, WG_TD_VERLET);
  TH_CHECK(n1 > 0 && n2 > 0, "the shaken bed breaks bonds (%llu, %llu ruptures)", n1, n2);
  TH_CHECK(r1 < 1e-2 && r2 < 3e-3, "shaken wet bed: ledger residual %.2e (dt = t_c/25), %.2e (t_c/50)", r1, r2);
  TH_CHECK(r2 < r1 / 2.4, "the residual falls faster than dt (ratio %.2f for dt halved)", r1 / r2);
}

/* Scene-derived settings: Hertz's K from t_contact (the elastic contact at speed 1 lasts
   t_contact), and Willett's law (Eq. 2.9-2.10): the pair loses exactly the scene's E_cb. */
static wg_td_params scene_params(const char *const *kv)
{
  wg_scene sc;
  wg_td_params p;
  memset(&p, 0, sizeof p);
  wg_scene_init(&sc);
  for (int k = 0; kv[k]; k++)
    if (wg_scene_set_override(&sc, kv[k]) != WG_OK) return p;
  if (wg_scene_finish(&sc) != WG_OK) return p;
  wg_td_params_from_scene(&sc, &p);
  /* the scene's container, without gravity: a free pair */
  p.g = 0;
  p.nwalls = 0;
  p.periodic[1] = 1;
  p.box[1] = 20;
  return p;
}

static void scene_laws(void)
{
  const char *hertz[] = {"engine=td", "dim=2", "n=2", "lx=20", "height=20", "container=periodic",
                         "gravity=0", "sigma_p=0", "contact=hertz", "t_contact=0.004",
                         "steps_per_contact=400", "tg_init_abs=1", "seed=1", "t_end=1", NULL};
  wg_td_params p = scene_params(hertz);
  double rad[2] = {0.5, 0.5}, dur;
  TH_CHECK(p.dt > 0 && p.pp.law == WG_CONTACT_HERTZ, "scene with contact = hertz: dt = %g", p.dt);
  double du = head_on(&p, rad, NULL, 1.0, &dur);
  TH_CLOSE("Hertz K from t_contact: the contact at speed 1 lasts t_contact = 0.004", dur, 0.004, 0, 1.5 * p.dt);
  TH_CLOSE("... and is elastic (hertz_ad = 0)", du, 1.0, 1e-4, 0);
  du = head_on(&p, rad, NULL, 32.0, &dur);
  TH_CLOSE("at speed 32 it lasts t_contact 32^(-1/5) = t_contact / 2", dur, 0.002, 0, 1.5 * p.dt);

  const char *willett[] = {"engine=td", "dim=2", "n=2", "lx=20", "height=20", "container=periodic",
                           "gravity=0", "sigma_p=0", "bridge_law=willett", "bridge_volume=0.001",
                           "f_b=4", "tg_init_abs=1", "seed=1", "t_end=1", NULL};
  p = scene_params(willett);
  double s_crit = 0.5 * (0.2 + 0.1 * 0.04), x_c = s_crit * sqrt(0.5 / 0.001);
  /* E_cb: F_B sqrt(V/R) times the integral of 1 / (1 + 1.05 x + 2.5 x^2) from 0 to x_c, by
     the midpoint rule here (the code uses the closed form) */
  double integral = 0;
  for (int k = 0; k < 100000; k++) {
    double x = (k + 0.5) * x_c / 100000;
    integral += x_c / 100000 / (1 + 1.05 * x + 2.5 * x * x);
  }
  double e_cb = 4 * sqrt(0.001 / 0.5) * integral, mu = 0.5;
  TH_CLOSE("Willett: s_crit from Eq. 2.10 (V = 0.001, R = 1/2)", p.s_crit, s_crit, 1e-12, 0);
  TH_CLOSE("Willett: the scene's E_cb is F_B times the integral of Eq. 2.9", wg_td_bond_energy(&p, s_crit), e_cb, 1e-6, 0);
  double u = sqrt(2 * 3 * e_cb / mu);
  double r[6] = {8, 10, 0, 8.999999, 10, 0}, v[6] = {-0.5 * u, 0, 0, 0.5 * u, 0, 0};
  wg_td s;
  TH_CHECK(wg_td_alloc_state(&s, &p, 2, r, v, rad, NULL, 0) == WG_OK && wg_td_bond_total(&s) == 1,
           "Willett pair bonded at contact");
  wg_td_advance(&s, 1);
  du = s.v[3] - s.v[0];
  TH_CHECK(s.ruptures == 1, "the Willett bond breaks once");
  TH_CLOSE("kinetic energy after rupture: 1/2 mu u^2 - E_cb (Willett)", 0.5 * mu * du * du, 2 * e_cb, 2e-3, 0);
  TH_CHECK(wg_td_ledger_residual(&s) < 1e-4, "ledger across the Willett rupture: residual %.2e", wg_td_ledger_residual(&s));
  wg_td_free(&s);
}

/* Wall bridges: a ball bonded to a resting floor (no gravity) and launched upward with
   1/2 m u^2 = 3 E_cb leaves with 2 E_cb; with E_cb / 2 it stays bound, reaching s_crit / 2. */
static void wall_bridge(void)
{
  double f_b = 4, s_crit = 0.0711, e_cb = f_b * s_crit;
  wg_td_params p = free_params(1.0, 0.005);
  p.periodic[1] = 0;
  p.lo[1] = -1;
  p.hi[1] = 30;
  p.nwalls = 1;
  p.wall[0] = (wg_wall){.c = 0, .A = 0, .omega = 1, .side = +1};
  p.pw = wg_contact_linear(1.0, 0.005, 1.0);
  p.f_b = f_b;
  p.s_crit = s_crit;
  p.wall_bonds = 1;
  double rad[1] = {0.5}, u = sqrt(2 * 3 * e_cb);
  double r[3] = {10, 0.499999, 0}, v[3] = {0, u, 0};
  wg_td s;
  TH_CHECK(wg_td_alloc_state(&s, &p, 1, r, v, rad, NULL, 0) == WG_OK && s.captures == 1,
           "a ball touching the floor bonds to it");
  wg_td_advance(&s, 0.5);
  TH_CHECK(s.ruptures == 1, "the wall bridge breaks once");
  TH_CLOSE("kinetic energy after the wall bridge's rupture: 1/2 m u^2 - E_cb", 0.5 * s.v[1] * s.v[1], 2 * e_cb, 1e-2, 0);
  TH_CHECK(wg_td_ledger_residual(&s) < 1e-4, "ledger across it: residual %.2e", wg_td_ledger_residual(&s));
  wg_td_free(&s);
  v[1] = sqrt(e_cb);
  TH_CHECK(wg_td_alloc_state(&s, &p, 1, r, v, rad, NULL, 0) == WG_OK, "slow ball on the floor");
  double gap_max = 0;
  while (s.t < 3) {
    wg_td_advance(&s, s.t + p.dt);
    if (s.r[1] - 0.5 > gap_max) gap_max = s.r[1] - 0.5;
  }
  TH_CHECK(s.ruptures == 0, "with 1/2 m u^2 = E_cb / 2 it stays bound to the floor");
  TH_CLOSE("its largest gap: s_crit / 2", gap_max, 0.5 * s_crit, 0.02, 0);
  wg_td_free(&s);
}

/* init = packed: a bed on the floor without overlaps, its lowest centres half the largest
   diameter above the floor, as few layers as the lateral spacing allows. */
static void packed_bed(void)
{
  const char *kv2[] = {"engine=td", "dim=2", "n=300", "lx=100", "height=9", "sigma_p=0.06",
                       "init=packed", "tg_init_abs=0", "gamma=2", "estar_d=0.1", "seed=3",
                       "t_end=1", NULL};
  const char *kv3[] = {"engine=td", "dim=3", "n=300", "lx=7.5", "ly=7.5", "height=45",
                       "sigma_p=0.02", "init=packed", "tg_init_abs=0", "gamma=2",
                       "estar_d=0.1", "seed=3", "t_end=1", NULL};
  const char *const *kv[2] = {kv2, kv3};
  for (int q = 0; q < 2; q++) {
    wg_scene sc;
    wg_scene_init(&sc);
    int ok = 1;
    for (int k = 0; kv[q][k]; k++) ok &= wg_scene_set_override(&sc, kv[q][k]) == WG_OK;
    ok &= wg_scene_finish(&sc) == WG_OK;
    wg_td s;
    ok &= wg_td_alloc(&s, &sc) == WG_OK;
    TH_CHECK(ok, "packed bed, %dD: set up", q + 2);
    if (!ok) continue;
    double dmax = 1 + sqrt(3.0) * sc.sigma_p, zmin = 1e9, zmax = -1e9, gap_min = 1e9;
    int up = sc.dim - 1;
    for (long i = 0; i < s.n; i++) {
      zmin = fmin(zmin, s.r[3 * i + up]);
      zmax = fmax(zmax, s.r[3 * i + up]);
    }
    for (long k = 0; k < s.npair; k++) {
      long i = s.pair[k].i, j = s.pair[k].j;
      double d2 = 0;
      for (int a = 0; a < sc.dim; a++) {
        double d = s.r[3 * j + a] - s.r[3 * i + a];
        if (s.par.periodic[a]) d -= s.par.box[a] * nearbyint(d / s.par.box[a]);
        d2 += d * d;
      }
      gap_min = fmin(gap_min, sqrt(d2) - s.radius[i] - s.radius[j]);
    }
    /* lateral spacing a = L / floor(L / dmax); neighbouring rows touch: 2D, 90 per row,
       4 rows, steps sqrt(dmax^2 - a^2/4); 3D, 7 x 7 per layer, 7 layers, steps
       sqrt(dmax^2 - a^2/2) */
    double a = q == 0 ? 100.0 / 90 : 7.5 / 7;
    double top = 0.5 * dmax + (q == 0 ? 3 * sqrt(dmax * dmax - a * a / 4) : 6 * sqrt(dmax * dmax - a * a / 2));
    TH_CHECK(gap_min >= 0 && s.contacts == 0, "packed bed, %dD: no overlaps (smallest gap %.3g)", q + 2, gap_min);
    TH_CLOSE("packed bed: lowest centres at half the largest diameter", zmin, 0.5 * dmax, 1e-9, 0);
    TH_CLOSE("packed bed: top layer where the count of layers puts it", zmax, top, 1e-5, 0);
    wg_td_free(&s);
  }
}

/* The Gear predictor-corrector (integrator = gear): exact for a parabola (free fall), the
   linear law's restitution converging to e, an elastic contact restoring the speed, and the
   ledger of the shaken wet bed closing.  A bond switches on or off between steps and Gear
   has no half-step correction for it, so that residual falls only as dt. */
static void gear_integrator(void)
{
  wg_td_params p = free_params(0.9, 0.01);
  p.integrator = WG_TD_GEAR;
  p.g = 1;
  double r[3] = {5, 5, 0}, v[3] = {0.3, 2, 0}, rad[1] = {0.5};
  wg_td s;
  TH_CHECK(wg_td_alloc_state(&s, &p, 1, r, v, rad, NULL, 0) == WG_OK && s.gear, "Gear: set up with its derivatives");
  wg_td_advance(&s, 1.5);
  TH_CLOSE("Gear: free fall is a parabola, y(1.5) = 5 + 2 t - t^2/2", s.r[1], 5 + 3 - 1.125, 1e-10, 0);
  TH_CLOSE("Gear: and v_y(1.5) = 2 - t", s.v[1], 0.5, 1e-10, 0);
  wg_td_free(&s);
  restitution_converges("Gear", WG_TD_GEAR, 1e-2);
  double rad2[2] = {0.5, 0.5}, dur, du;
  p = free_params(1.0, 0.01);
  p.integrator = WG_TD_GEAR;
  du = head_on(&p, rad2, NULL, 2.0, &dur);
  TH_CLOSE("Gear, e = 1: relative speed restored", du / 2.0, 1.0, 1e-3, 0);
  unsigned long long n1, n2;
  double r1 = shaken_bed_residual(25, &n1, WG_TD_GEAR), r2 = shaken_bed_residual(50, &n2, WG_TD_GEAR);
  TH_CHECK(n1 > 0 && n2 > 0 && r2 < 1e-2, "Gear, shaken wet bed: ledger residual %.2e (t_c/25), %.2e (t_c/50)", r1, r2);
  TH_CHECK(r2 < r1 / 1.6, "Gear: the residual falls at least as dt (ratio %.2f for dt halved)", r1 / r2);
}

int main(void)
{
  linear_contact();
  hertz_contact();
  floor_bounce();
  capillary_pair();
  ledger_convergence();
  scene_laws();
  wall_bridge();
  packed_bed();
  gear_integrator();
  return th_summary();
}
