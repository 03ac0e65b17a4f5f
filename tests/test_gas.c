/* Elastic hard disks and spheres in a periodic box: the pressure from the collision virial
   against the Henderson (2D) and Carnahan-Starling (3D) equations of state, and energy
   conservation over 10^7 collisions. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "ed.h"
#include "tharness.h"

static int gas_scene(wg_scene *sc, int dim, long n, double phi, unsigned seed)
{
  char d[32], nn[32], ph[32], sd[32];
  snprintf(d, sizeof d, "dim=%d", dim);
  snprintf(nn, sizeof nn, "n=%ld", n);
  snprintf(ph, sizeof ph, "phi=%.17g", phi);
  snprintf(sd, sizeof sd, "seed=%u", seed);
  const char *keys[] = {d, nn, ph, sd, "container=periodic", "sigma_p=0", "tg_init_abs=1",
                        "t_end=1", NULL};
  wg_scene_init(sc);
  for (int k = 0; keys[k]; k++)
    if (wg_scene_set_override(sc, keys[k]) != WG_OK) return 1;
  return wg_scene_finish(sc) != WG_OK;
}

/* Z = PV / (N T) = 1 + sum sigma |J| / (D N T t)  (collision virial) */
static double measure_z(int dim, long n, double phi, double t_eq, double t_meas)
{
  wg_scene sc;
  if (gas_scene(&sc, dim, n, phi, 7)) return NAN;
  wg_ed s;
  if (wg_ed_alloc(&s, &sc) != WG_OK) return NAN;
  wg_ed_advance(&s, t_eq);
  s.virial = 0;
  wg_ed_advance(&s, t_eq + t_meas);
  double ek, ep;
  wg_ed_energy(&s, &ek, &ep);
  double T = 2 * ek / (double)(dim * n);
  double z = 1 + s.virial / (dim * n * T * t_meas);
  printf("#   D = %d  phi = %.2f  N = %ld  collisions %llu  Z = %.4f\n", dim, phi, n,
         s.counts.collisions, z);
  wg_ed_free(&s);
  return z;
}

static double henderson(double eta) { return (1 + eta * eta / 8) / ((1 - eta) * (1 - eta)); }
static double carnahan_starling(double eta)
{
  return (1 + eta + eta * eta - eta * eta * eta) / pow(1 - eta, 3);
}

static void equation_of_state(void)
{
  const double phis[] = {0.1, 0.2, 0.3, 0.4};
  for (int k = 0; k < 4; k++) {
    double z2 = measure_z(2, 900, phis[k], 20, 150);
    double h = henderson(phis[k]);
    TH_CHECK(fabs(z2 / h - 1) < 0.02, "2D phi = %.1f: Z = %.4f vs Henderson %.4f (%.2f %%, band 2 %%)",
             phis[k], z2, h, 100 * (z2 / h - 1));
    double z3 = measure_z(3, 1000, phis[k], 20, 100);
    double cs = carnahan_starling(phis[k]);
    TH_CHECK(fabs(z3 / cs - 1) < 0.02,
             "3D phi = %.1f: Z = %.4f vs Carnahan-Starling %.4f (%.2f %%, band 2 %%)", phis[k], z3,
             cs, 100 * (z3 / cs - 1));
  }
}

static void energy_conservation(void)
{
  const unsigned long long target = getenv("WG_TEST_SHORT") ? 1000000ULL : 10000000ULL;
  wg_scene sc;
  gas_scene(&sc, 3, 2000, 0.3, 11);
  wg_ed s;
  TH_CHECK(wg_ed_alloc(&s, &sc) == WG_OK, "3D gas set up");
  double ek0, ep;
  wg_ed_energy(&s, &ek0, &ep);
  double t = 0;
  while (s.counts.collisions < target) wg_ed_advance(&s, t += 10);
  double ek1;
  wg_ed_energy(&s, &ek1, &ep);
  double px = 0;
  for (long i = 0; i < s.n; i++) px += s.p[i].v[0];
  TH_CHECK(fabs(ek1 / ek0 - 1) < 1e-11, "kinetic energy after %llu collisions: relative change %.2e < 1e-11",
           s.counts.collisions, ek1 / ek0 - 1);
  TH_CHECK(fabs(px) < 1e-9, "total momentum stays zero (%.2e)", px);
  TH_CHECK(s.zero_time_run < 100, "no run of simultaneous events");
  wg_ed_free(&s);
}

int main(void)
{
  equation_of_state();
  energy_conservation();
  return th_summary();
}
