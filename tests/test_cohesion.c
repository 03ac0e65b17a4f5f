/* The cohesion of Waitukaitis et al. (2011) in the time-driven engine: a constant force F_coh
   switched on at contact and acting out to a surface gap l_c (the engine's constant bridge law,
   f_b = F_coh, s_crit = l_c), beside the linear spring-dashpot.  Against closed forms for a
   head-on pair (reduced mass mu):
     contact: mu xi'' = -k xi - gamma xi' + F_coh, xi(0) = 0, xi'(0) = u, until xi = 0 again
              (xi = F/k + exp(-beta t) (A cos w t + B sin w t));
     then the gap opens against F_coh: u_out^2 = u_1^2 - 2 F_coh l_c / mu, or the pair stays
     (captured) when u_1^2 < 2 F_coh l_c / mu.
   The engine breaks the bond at the first step whose gap exceeds l_c, so F_coh acts over up to
   one step's travel more: u_out is low by up to F_coh dt / mu, a first-order error with the
   phase of the step.  Checked: u_out at three approach speeds within that bound (plus 0.1 %)
   at dt = t_c/200 and t_c/1000; the capture speed; the ledger. */
#include <math.h>
#include <stdio.h>

#include "tharness.h"
#include "td.h"
#include "td_bed.h"

static const double e = 0.9, t_c = 0.01, mu = 0.5, f_coh = 40, l_c = 0.002;

/* Exit speed of the contact phase for approach speed u (closed form); NAN when the pair
   never leaves contact. */
static double contact_exit(const wg_contact *c, double u)
{
  double k = c->k, gamma = 2 * c->zeta * sqrt(c->k * mu);
  double beta = gamma / (2 * mu), w = sqrt(k / mu - beta * beta);
  double A = -f_coh / k, B = (u + beta * A) / w;
  /* xi(t) = F/k + exp(-beta t) (A cos wt + B sin wt); its first return to 0 after t = 0 lies
     within the first period: scan, then bisect */
  double lo = 1e-9 / w, hi = NAN, prev = 1;
  for (int n = 1; n <= 4000; n++) {
    double t = n * (2 * M_PI / w) / 2000;
    double xi = f_coh / k + exp(-beta * t) * (A * cos(w * t) + B * sin(w * t));
    if (xi < 0 && prev >= 0) { hi = t; break; }
    prev = xi;
    lo = t;
  }
  if (isnan(hi)) return NAN;
  for (int it = 0; it < 200; it++) {
    double m = 0.5 * (lo + hi);
    double xi = f_coh / k + exp(-beta * m) * (A * cos(w * m) + B * sin(w * m));
    if (xi > 0) lo = m; else hi = m;
  }
  double t = 0.5 * (lo + hi);
  double xidot = exp(-beta * t) * ((-beta * A + w * B) * cos(w * t) + (-beta * B - w * A) * sin(w * t));
  return -xidot;
}

/* The engine: a pair touching at t = 0 and approaching at u; the separation speed once the
   gap exceeds l_c, or NAN when it is still bonded at t = 0.5 (captured). */
static double engine_exit(const wg_td_params *p, double u, double *residual)
{
  double rad[2] = {0.5, 0.5};
  double r[6] = {8, 10, 0, 9, 10, 0}, v[6] = {0.5 * u, 0, 0, -0.5 * u, 0, 0};
  wg_td s;
  if (wg_td_alloc_state(&s, p, 2, r, v, rad, NULL, 0) != WG_OK) return NAN;
  wg_td_advance(&s, 0.5);
  double out = wg_td_bond_total(&s) == 0 ? s.v[3] - s.v[0] : NAN;
  *residual = wg_td_ledger_residual(&s);
  wg_td_free(&s);
  return out;
}

int main(void)
{
  wg_td_params p;
  periodic_box(&p, 2, t_c / 200);
  p.pp = p.pw = wg_contact_linear(e, t_c, mu);
  p.f_b = f_coh;
  p.s_crit = l_c;
  double w_coh = f_coh * l_c;
  printf("# e = %.2f, t_c = %g, F_coh = %g, l_c = %g (W_coh = %g; F_coh / k = %.2e)\n", e, t_c,
         f_coh, l_c, w_coh, f_coh / p.pp.k);

  /* without cohesion the contact returns e u; with it, less: against the closed form */
  for (int level = 0; level < 2; level++) {
    wg_td_params q = p;
    q.dt = t_c / (level ? 1000 : 200);
    double band_dt = f_coh * q.dt / mu;
    for (int n = 0; n < 3; n++) {
      double u = (double[]){0.8, 1.0, 2.0}[n], res;
      double u1 = contact_exit(&q.pp, u);
      double expect = sqrt(u1 * u1 - 2 * f_coh * l_c / mu);
      double got = engine_exit(&q, u, &res);
      TH_CHECK(fabs(got - expect) <= band_dt + 1e-3 * expect,
               "u = %.1f, dt = t_c/%d: separation %.5f vs closed form %.5f (contact exit %.5f, e u = %.2f; band %.1e)",
               u, level ? 1000 : 200, got, expect, u1, e * u, band_dt + 1e-3 * expect);
      if (level == 0) TH_CHECK(res < 1e-3, "ledger across contact, cohesion and rupture: residual %.2e", res);
    }
  }
  /* capture: the approach speed at which the contact's exit speed just pays W_coh */
  double lo = 0.01, hi = 3;
  for (int it = 0; it < 100; it++) {
    double m = 0.5 * (lo + hi), u1 = contact_exit(&p.pp, m);
    if (!isnan(u1) && 0.5 * mu * u1 * u1 > w_coh) hi = m; else lo = m;
  }
  double u_cap = 0.5 * (lo + hi), res;
  printf("#   capture speed (closed form) %.5f; without cohesion in contact it would be %.5f\n", u_cap,
         sqrt(2 * w_coh / mu) / e);
  double below = engine_exit(&p, 0.97 * u_cap, &res), above = engine_exit(&p, 1.03 * u_cap, &res);
  TH_CHECK(isnan(below), "captured 3 %% below the capture speed %.4f", u_cap);
  TH_CHECK(!isnan(above) && above > 0, "escapes 3 %% above it (separation speed %.4f)", above);
  return th_summary();
}
