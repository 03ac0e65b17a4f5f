/* Friction and rotation of the time-driven engine against closed forms: a disk and a sphere
   sliding on a floor until they roll (final speed v0 / (1 + I / m R^2), deceleration mu g,
   the energy lost in slip), the tangential restitution of a sticking elastic contact
   (-cos(omega_t t_c), omega_t^2 = (k_t / m_eff)(1 + m R^2 / I) for equal bodies), angular
   momentum conserved to round-off, rolling resistance (deceleration mu_r g / (1 + I / m R^2),
   then rest) and the ledger of a shaken frictional bed; each with velocity Verlet and with
   Gear's predictor-corrector, except rolling resistance (Verlet only: under Gear's corrector
   its capped torque chatters, flipping sign every step). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "tharness.h"
#include "td.h"
#include "td_bed.h"

/* dim-D, periodic lateral axes of 20, no gravity, no walls; the linear law with e and t_c;
   friction mu with k_t / k_n = kt and gamma_t / gamma_n = gt; integrator ig. */
static wg_td_params rough_params(int ig, int dim, double e, double t_c, double mu, double kt, double gt)
{
  wg_td_params p;
  periodic_box(&p, dim, t_c / 50);
  p.integrator = ig;
  p.pp = wg_contact_linear(e, t_c, 0.5);
  p.pw = wg_contact_linear(e, t_c, 1.0);
  p.fric = p.fric_wall = (wg_friction){mu, kt, gt, 0};
  return p;
}

/* A disk (2D) or sphere (3D) set on a resting floor at its static overlap, sliding along x at
   v0 without spin: sliding, it decelerates at mu g and spins up at mu m g R / I until its
   contact point rests; it then rolls at v0 / (1 + I / m R^2), having lost
   m v0^2 / 2 * (1 - 1 / (1 + I / m R^2)) in slip. */
static void slide_to_roll(int ig, int dim)
{
  double mu = 0.3, v0 = 2, R = 0.5, t_c = 0.01;
  const char *by = ig == WG_TD_GEAR ? "Gear" : "Verlet";
  char name[160];
  wg_td_params p = rough_params(ig, dim, 0.5, t_c, mu, 2.0 / 7, 1); /* damped: rolls steadily */
  int up = dim - 1;
  resting_floor(&p, 10);
  double r[3] = {5, 5, 5}, v[3] = {v0, 0, 0}, rad[1] = {R};
  r[up] = R - 1 / p.pw.k; /* the static overlap m g / k */
  wg_td s;
  TH_CHECK(wg_td_alloc_state(&s, &p, 1, r, v, rad, NULL, 0) == WG_OK && s.rot,
           "%s, %dD: a rough body on the floor, set up with rotation", by, dim);
  double f = 1 / (1 + (dim == 2 ? 0.5 : 0.4)); /* v_roll / v0 */
  double t_roll = v0 * (1 - f) / (mu * 1.0);
  /* the deceleration while it slides */
  wg_td_advance(&s, 0.2 * t_roll);
  double v1 = s.v[0], t1 = s.t;
  wg_td_advance(&s, 0.6 * t_roll);
  double decel = -(s.v[0] - v1) / (s.t - t1);
  snprintf(name, sizeof name, "%s: %s slides at deceleration mu g", by, dim == 2 ? "disk" : "sphere");
  TH_CLOSE(name, decel, mu, 1e-3, 0);
  /* when does the contact point come to rest? */
  int wz = dim == 2 ? 2 : 1; /* the axis of spin: z in 2D; y in 3D (x motion, z up) */
  double sgn = dim == 2 ? 1 : -1; /* contact-point velocity v_x + sgn w R */
  double t_rolled = NAN;
  while (s.t < 2 * t_roll) {
    wg_td_advance(&s, s.t + p.dt);
    if (isnan(t_rolled) && fabs(s.v[0] + sgn * s.w[wz] * R) < 1e-3 * v0) t_rolled = s.t;
  }
  snprintf(name, sizeof name, "%s, %dD: it rolls from t = v0 (1 - f) / (mu g)", by, dim);
  TH_CLOSE(name, t_rolled, t_roll, 2e-2, 0);
  snprintf(name, sizeof name, "%s: %s", by, dim == 2 ? "disk rolls on at 2/3 v0" : "sphere rolls on at 5/7 v0");
  TH_CLOSE(name, s.v[0], f * v0, 2e-3, 0);
  snprintf(name, sizeof name, "%s, %dD: rolling without slip: v = w R", by, dim);
  TH_CLOSE(name, s.v[0], -sgn * s.w[wz] * R, 1e-3, 0);
  double lost = s.dissipated_wall.s + s.dissipated_wall.c;
  snprintf(name, sizeof name, "%s, %dD: energy lost in slip: m v0^2 / 2 (1 - f)", by, dim);
  TH_CLOSE(name, lost, 0.5 * v0 * v0 * (1 - f), 5e-3, 0);
  TH_CHECK(wg_td_ledger_residual(&s) < 1e-4, "%s, %dD rolling: ledger residual %.2e", by, dim, wg_td_ledger_residual(&s));
  wg_td_free(&s);
}

/* Two equal elastic particles meeting off-centre with a sticking (mu large), undamped
   tangential spring: the contact-point velocity's tangential part leaves reversed times
   beta = -cos(omega_t t_c), omega_t^2 = (k_t / m_eff)(1 + m R^2 / I) for equal bodies
   (1 + m R^2 / I = 7/2 for spheres, 3 for disks), t_c = pi / omega_n.  With k_t = 2/7 k_n
   spheres return it exactly (beta = 1), and so do disks with k_t = 1/3 k_n. */
static void sticking_impact(int ig, int dim, double kt)
{
  double t_c = 0.01, R = 0.5;
  const char *by = ig == WG_TD_GEAR ? "Gear" : "Verlet";
  char name[160];
  wg_td_params p = rough_params(ig, dim, 1.0, t_c, 1e6, kt, 0);
  p.dt = t_c / 200;
  double r[6] = {8, 10, 10, 8 + 2 * R + 0.02, 10, 10}, v[6] = {0.5, 0.2, 0, -0.5, -0.2, 0};
  double rad[2] = {R, R};
  wg_td s;
  TH_CHECK(wg_td_alloc_state(&s, &p, 2, r, v, rad, NULL, 0) == WG_OK, "%s, %dD off-centre pair", by, dim);
  double k0, u0;
  wg_td_energy(&s, &k0, &u0);
  double L0 = 0; /* angular momentum about z at the origin */
  for (int i = 0; i < 2; i++) L0 += s.r[3 * i] * s.v[3 * i + 1] - s.r[3 * i + 1] * s.v[3 * i] + 0;
  wg_td_advance(&s, 0.1);
  double L = 0;
  for (int i = 0; i < 2; i++)
    L += s.r[3 * i] * s.v[3 * i + 1] - s.r[3 * i + 1] * s.v[3 * i] +
         wg_inertia(dim, 1, R) * s.w[3 * i + 2];
  double orbit = L - wg_inertia(dim, 1, R) * (s.w[2] + s.w[5]);
  TH_CHECK(fabs(L - L0) < 1e-10 && fabs(orbit - L0) > 1e-3,
           "%s, %dD: angular momentum conserved to round-off: %.17g vs %.17g (the orbital part "
           "alone changes by %.2e)", by, dim, L, L0, orbit - L0);
  TH_CHECK(s.contacts == 1 && s.pair[0].touching == 0, "%s, %dD: one contact, over", by, dim);
  double k1, u1;
  wg_td_energy(&s, &k1, &u1);
  /* tangential (y) velocity of the contact point of 2 against 1: v_y2 - v_y1 - R (w1 + w2) */
  double vt0 = -0.4, vt1 = s.v[4] - s.v[1] - R * (s.w[2] + s.w[5]);
  double g = 1 + 1 / (dim == 2 ? 0.5 : 0.4), beta = -cos(M_PI * sqrt(kt * g));
  /* the tangential mode (mass m_eff / g) keeps beta^2 of its energy; the spring's rest goes
     when the contact ends */
  snprintf(name, sizeof name, "%s, %dD: undamped sticking contact: kinetic energy less the spring's at release", by, dim);
  TH_CLOSE(name, k1, k0 - 0.5 * (0.5 / g) * vt0 * vt0 * (1 - beta * beta), 2e-4, 0);
  snprintf(name, sizeof name, "%s: %s: tangential restitution -cos(omega_t t_c)", by, dim == 2 ? "disks" : "spheres");
  TH_CLOSE(name, -vt1 / vt0, beta, 0, 5e-3);
  wg_td_free(&s);
}

/* Rolling resistance on the floor: a body rolling without slip at v0 feels the torque
   mu_roll m g R against its spin, so it decelerates at mu_roll g / (1 + I / m R^2) and stops
   after v0 (1 + I / m R^2) / (mu_roll g), then stays at rest. */
static void rolling_stops(int ig, int dim)
{
  double mu_r = 0.05, v0 = 1, R = 0.5, t_c = 0.01;
  const char *by = ig == WG_TD_GEAR ? "Gear" : "Verlet";
  char name[160];
  wg_td_params p = rough_params(ig, dim, 0.5, t_c, 0.5, 2.0 / 7, 1);
  p.fric.mu_roll = p.fric_wall.mu_roll = mu_r;
  int up = dim - 1, wz = dim == 2 ? 2 : 1;
  double sgn = dim == 2 ? 1 : -1, c = dim == 2 ? 0.5 : 0.4;
  resting_floor(&p, 10);
  double r[3] = {5, 5, 5}, v[3] = {v0, 0, 0}, rad[1] = {R};
  r[up] = R - 1 / p.pw.k;
  wg_td s;
  TH_CHECK(wg_td_alloc_state(&s, &p, 1, r, v, rad, NULL, 0) == WG_OK, "%s, %dD: rolling body set up", by, dim);
  double w0[3] = {0, 0, 0};
  w0[wz] = -sgn * v0 / R; /* rolling from the start */
  TH_CHECK(wg_td_set_angular_velocities(&s, w0) == WG_OK, "%s, %dD: set rolling", by, dim);
  double t_stop = v0 * (1 + c) / mu_r;
  wg_td_advance(&s, 0.2 * t_stop);
  double v1 = s.v[0], t1 = s.t;
  wg_td_advance(&s, 0.6 * t_stop);
  snprintf(name, sizeof name, "%s: %s", by, dim == 2 ? "disk: rolling resistance decelerates at mu_r g / (1 + 1/2)"
                                                    : "sphere: rolling resistance decelerates at mu_r g / (1 + 2/5)");
  TH_CLOSE(name, -(s.v[0] - v1) / (s.t - t1), mu_r / (1 + c), 2e-3, 0);
  wg_td_advance(&s, 1.5 * t_stop);
  TH_CHECK(fabs(s.v[0]) < 1e-3 * v0 && fabs(s.w[wz]) * R < 1e-3 * v0,
           "%s, %dD: it stops and stays (v = %.2e, w R = %.2e at 1.5 t_stop)", by, dim, s.v[0], s.w[wz] * R);
  snprintf(name, sizeof name, "%s, %dD: the rolling energy went to the ledger's dissipation", by, dim);
  TH_CLOSE(name, s.dissipated_wall.s + s.dissipated_wall.c, 0.5 * v0 * v0 * (1 + c), 2e-3, 0);
  TH_CHECK(wg_td_ledger_residual(&s) < 1e-6, "%s, %dD rolling resistance: ledger residual %.2e", by, dim,
           wg_td_ledger_residual(&s));
  wg_td_free(&s);
}

/* Unequal spinning disks in a sliding, rolling contact: the pair's torques cancel, so the
   angular momentum is kept to round-off while spin is dissipated. */
static void rolling_pair_momentum(void)
{
  wg_td_params p = rough_params(WG_TD_VERLET, 2, 0.7, 0.01, 0.5, 2.0 / 7, 0.5);
  p.fric.mu_roll = 0.2;
  double r[6] = {8, 10, 0, 8.82, 10.1, 0}, v[6] = {0.3, 0.1, 0, -0.3, -0.1, 0}, rad[2] = {0.5, 0.3};
  double m[2] = {1, 0.36};
  wg_td s;
  TH_CHECK(wg_td_alloc_state(&s, &p, 2, r, v, rad, m, 0) == WG_OK, "unequal rough pair set up");
  double w0[6] = {0, 0, 3, 0, 0, -1};
  wg_td_set_angular_velocities(&s, w0);
  double L0 = 0, k0, u0;
  for (int i = 0; i < 2; i++)
    L0 += m[i] * (s.r[3 * i] * s.v[3 * i + 1] - s.r[3 * i + 1] * s.v[3 * i]) +
          wg_inertia(2, m[i], rad[i]) * s.w[3 * i + 2];
  wg_td_energy(&s, &k0, &u0);
  wg_td_advance(&s, 0.1);
  double L = 0, k1, u1;
  for (int i = 0; i < 2; i++)
    L += m[i] * (s.r[3 * i] * s.v[3 * i + 1] - s.r[3 * i + 1] * s.v[3 * i]) +
         wg_inertia(2, m[i], rad[i]) * s.w[3 * i + 2];
  wg_td_energy(&s, &k1, &u1);
  TH_CHECK(fabs(L - L0) < 1e-10, "unequal pair with rolling resistance: angular momentum %.17g vs %.17g", L, L0);
  TH_CHECK(k1 < 0.9 * k0 && wg_td_ledger_residual(&s) < 1e-3,
           "it loses energy (%.4f of %.4f left), ledger residual %.2e", k1, k0, wg_td_ledger_residual(&s));
  wg_td_free(&s);
}

/* 60 rough, wet, inelastic disks on a shaken floor under a lid (as test_td's bed): the ledger
   residual after 4 time units, with rolling, slip and contacts ending between steps. */
static double rough_bed_residual(int ig, double dt_factor, double *slip, int hertz)
{
  wg_td_params p = rough_params(ig, 2, 0.8, 0.01, 0.5, 2.0 / 7, 0.5);
  p.dt = 0.01 / dt_factor;
  double r[180], v[180], rad[60];
  shaken_bed(&p, r, v, rad);
  if (hertz) p.pp = p.pw = wg_contact_hertz(1e5, 1e-3); /* k_t grows with the overlap */
  wg_td s;
  if (wg_td_alloc_state(&s, &p, 60, r, v, rad, NULL, 0) != WG_OK) return NAN;
  wg_td_advance(&s, 4);
  double res = wg_td_ledger_residual(&s), spin = 0;
  for (long i = 0; i < s.n; i++) spin += fabs(s.w[3 * i + 2]);
  *slip = spin / (double)s.n;
  wg_td_free(&s);
  return res;
}

static void rough_bed_ledger(int ig)
{
  const char *by = ig == WG_TD_GEAR ? "Gear" : "Verlet";
  double w1, w2;
  double r1 = rough_bed_residual(ig, 25, &w1, 0), r2 = rough_bed_residual(ig, 50, &w2, 0);
  TH_CHECK(w1 > 0.1 && w2 > 0.1, "%s: rough shaken bed: the disks spin (mean |w| %.2f, %.2f)", by, w1, w2);
  TH_CHECK(r1 < 1e-2 && r2 < 3e-3, "%s: rough shaken bed: ledger residual %.2e (dt = t_c/25), %.2e (t_c/50)", by, r1, r2);
  TH_CHECK(r2 < r1 / 1.6, "%s: rough bed: the residual falls at least as dt (ratio %.2f for dt halved)", by, r1 / r2);
  r1 = rough_bed_residual(ig, 25, &w1, 1), r2 = rough_bed_residual(ig, 50, &w2, 1);
  TH_CHECK(w1 > 0.1 && r1 < 1e-2 && r2 < r1 / 1.6,
           "%s: rough Hertz bed (k_t changes with the overlap): ledger residual %.2e (t_c/25), %.2e (t_c/50)", by, r1, r2);
}

int main(void)
{
  for (int ig = WG_TD_VERLET; ig <= WG_TD_GEAR; ig++) {
    slide_to_roll(ig, 2);
    slide_to_roll(ig, 3);
    sticking_impact(ig, 2, 2.0 / 7);
    sticking_impact(ig, 3, 2.0 / 7);
    sticking_impact(ig, 2, 1.0 / 3);
    rough_bed_ledger(ig);
  }
  wg_td_params p = rough_params(WG_TD_GEAR, 2, 0.5, 0.01, 0.5, 2.0 / 7, 1);
  p.fric.mu_roll = 0.05;
  double r[3] = {5, 5, 0}, v[3] = {0, 0, 0}, rad[1] = {0.5};
  wg_td s;
  TH_CHECK(wg_td_alloc_state(&s, &p, 1, r, v, rad, NULL, 0) == WG_EINVAL, "rolling resistance with Gear is refused");
  rolling_stops(WG_TD_VERLET, 2);
  rolling_stops(WG_TD_VERLET, 3);
  rolling_pair_momentum();
  return th_summary();
}
