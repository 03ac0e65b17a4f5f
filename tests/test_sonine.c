/* The algebra of thesis App. A: the first Sonine coefficient a_2 of the white-noise-driven wet
   gas solves nu_4 / nu_2 = d + 2 (Eq. A.45), with the moments of the collision integral (Eq.
   A.39) taken over a Maxwellian times (1 + a_2 S), S = L_2(c_1^2) + L_2(c_2^2) (Eq. A.42, A.53),
   and the rule of Eq. A.40-A.41: a pair with normal speed u = c_12.s >= sqrt(eps_cb) leaves with
   sqrt(u^2 - eps_cb); slower pairs lie outside the integrals.  Both moments are linear in a_2,
   nu_n = A_n + a_2 B_n, so a_2 = ((d+2) A_2 - A_4) / (B_4 - (d+2) B_2); here A_n, B_n are
   sampled by Monte Carlo (GSL, seeded) and a_2 is checked against the closed form, Eq. A.59,
   within 4 of its Monte Carlo errors.  A wrong closed form (or eps_cb read as E_cb/T_g on one
   side only) would miss by far more. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_sf_bessel.h>

#include "tharness.h"

static double a59(double e, int d)
{
  double z = 32.0 * (d - 1) * e * gsl_sf_bessel_K1_scaled(e / 4); /* exp(e/4) K1(e/4) */
  return -16 * (e - 2) * e / (-128 + 16 * d * (8 + e * (5 + e)) + e * (10 + e * (75 + (e - 4) * e)) + z);
}

/* Monte Carlo a_2 at eps_cb e in d dimensions from m samples; *err its standard error */
static double sampled(double e, int d, long m, gsl_rng *r, double *err)
{
  double sn = 0, sd = 0, snn = 0, sdd = 0, snd = 0;
  for (long k = 0; k < m; k++) {
    double c1[3] = {0, 0, 0}, c2[3] = {0, 0, 0}, s[3] = {0, 0, 0}, u = 0;
    for (int a = 0; a < d; a++) {
      c1[a] = gsl_ran_gaussian_ziggurat(r, M_SQRT1_2); /* phi(c) = pi^(-d/2) exp(-c^2) */
      c2[a] = gsl_ran_gaussian_ziggurat(r, M_SQRT1_2);
    }
    if (d == 2) gsl_ran_dir_2d(r, &s[0], &s[1]);
    else gsl_ran_dir_3d(r, &s[0], &s[1], &s[2]);
    for (int a = 0; a < d; a++) u += (c1[a] - c2[a]) * s[a];
    double g = 0, h = 0;
    if (u > 0 && u * u >= e) {
      double q = sqrt(u * u - e), x1 = 0, x2 = 0, y1 = 0, y2 = 0;
      for (int a = 0; a < d; a++) {
        double p1 = c1[a] - 0.5 * s[a] * (u + q), p2 = c2[a] + 0.5 * s[a] * (u + q); /* Eq. A.40-A.41 */
        x1 += c1[a] * c1[a];
        x2 += c2[a] * c2[a];
        y1 += p1 * p1;
        y2 += p2 * p2;
      }
      double d2 = 0.5 * (y1 + y2 - x1 - x2), d4 = 0.5 * (y1 * y1 + y2 * y2 - x1 * x1 - x2 * x2);
      double L = 0.5 * (x1 * x1 + x2 * x2) - 0.5 * (d + 2) * (x1 + x2) + 0.25 * d * (d + 2); /* Eq. A.53 */
      g = u * ((d + 2) * d2 - d4);
      h = u * L * (d4 - (d + 2) * d2);
    }
    sn += g; sd += h; snn += g * g; sdd += h * h; snd += g * h;
  }
  double mn = sn / m, md = sd / m;
  double vn = snn / m - mn * mn, vd = sdd / m - md * md, cnd = snd / m - mn * md;
  double a2 = mn / md;
  /* delta method for a ratio of means */
  *err = fabs(a2) * sqrt((vn / (mn * mn) + vd / (md * md) - 2 * cnd / (mn * md)) / m);
  return a2;
}

int main(void)
{
  long m = getenv("WG_TEST_SHORT") ? 2000000 : 10000000;
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 11);
  const double eps[] = {0.3, 1.0, 3.0};
  for (int d = 2; d <= 3; d++)
    for (int k = 0; k < 3; k++) {
      double err, a = sampled(eps[k], d, m, r, &err), th = a59(eps[k], d);
      TH_CHECK(fabs(a - th) < 4 * err,
               "d = %d, eps_cb = %.1f: Monte Carlo of the first-Sonine integrals a_2 = %.5f +- %.5f, Eq. A.59 %.5f "
               "(band 4 errors; A.59 at eps_cb/2: %.5f)", d, eps[k], a, err, th, a59(eps[k] / 2, d));
    }
  gsl_rng_free(r);
  return th_summary();
}
