/* Elastic hard disks and spheres in a periodic box: the pressure from the collision virial
   against the Henderson (2D) and Carnahan-Starling (3D) equations of state, energy
   conservation over 10^7 collisions, and a dilute gas on the coarse cells of dilute boxes
   (collision frequency against Enskog's, no overlap at the end).  The same with neighbour
   lists (scene key shell): the equation of state, energy and momentum, Enskog's frequency, and
   no overlap in a dense gas, where a pair left out of the lists would pass through. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "ed.h"
#include "tharness.h"

/* shell > 0: neighbour lists with that shell */
static double shell = 0;

static int gas_scene(wg_scene *sc, int dim, long n, double phi, unsigned seed)
{
  char d[32], nn[32], ph[32], sd[32], sh[32];
  snprintf(d, sizeof d, "dim=%d", dim);
  snprintf(nn, sizeof nn, "n=%ld", n);
  snprintf(ph, sizeof ph, "phi=%.17g", phi);
  snprintf(sd, sizeof sd, "seed=%u", seed);
  snprintf(sh, sizeof sh, "shell=%.17g", shell);
  const char *keys[] = {d, nn, ph, sd, sh, "container=periodic", "sigma_p=0", "tg_init_abs=1",
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

static void equation_of_state(const double *phis, int nphi)
{
  for (int k = 0; k < nphi; k++) {
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

static void energy_conservation(unsigned long long target)
{
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

/* The closest distance of any pair at time now (unit diameters: < 1 is an overlap). */
static double closest_pair(const wg_ed *s)
{
  double worst = INFINITY;
  for (long i = 0; i < s->n; i++)
    for (long j = i + 1; j < s->n; j++) {
      double ri[3], rj[3], v[3], d2 = 0;
      wg_ed_position_at(s, i, s->now, ri, v);
      wg_ed_position_at(s, j, s->now, rj, v);
      for (int k = 0; k < s->dim; k++) {
        double x = rj[k] - ri[k];
        x -= s->box[k] * nearbyint(x / s->box[k]);
        d2 += x * x;
      }
      if (d2 < worst) worst = d2;
    }
  return sqrt(worst);
}

/* Neighbour lists in a dense gas: every sampled instant, no pair closer than a diameter (a
   pair missing from the lists would pass through), and lists symmetric. */
static void dense_lists(int dim, long n, double phi)
{
  wg_scene sc;
  gas_scene(&sc, dim, n, phi, 17);
  wg_ed s;
  TH_CHECK(wg_ed_alloc(&s, &sc) == WG_OK && s.listed, "%dD gas at phi = %.2f with lists set up", dim, phi);
  double closest = INFINITY;
  int symmetric = 1;
  for (int k = 1; k <= 20; k++) {
    wg_ed_advance(&s, 0.5 * k);
    double c = closest_pair(&s);
    if (c < closest) closest = c;
    for (long i = 0; i < s.n; i++)
      for (int q = 0; q < s.nl.nn[i]; q++) {
        long j = s.nl.nb[(size_t)i * s.nl.cap + q];
        int back = 0;
        for (int m = 0; m < s.nl.nn[j]; m++) back |= s.nl.nb[(size_t)j * s.nl.cap + m] == i;
        symmetric &= back;
      }
  }
  TH_CHECK(closest > 1 - 1e-9 && s.counts.cell_crossings > (unsigned long long)n,
           "%dD phi = %.2f with lists: closest pair over 20 instants %.12f d (>= 1 - 1e-9); %llu "
           "collisions, %llu relists", dim, phi, closest, s.counts.collisions, s.counts.cell_crossings);
  TH_CHECK(symmetric, "%dD phi = %.2f: every listed pair is in both lists", dim, phi);
  wg_ed_free(&s);
}

/* A dilute gas (phi = 0.005, as the thesis's free cooling, Fig. 2.6) gets cells wider than the
   interaction range (at most 8 per particle, ed.c setup_cells).  Its collision frequency per
   particle must be Enskog's, omega = 2 (dim - 1) n sigma^(dim-1) g(sigma) sqrt(pi T / m) with the
   contact value g of Henderson (2D) or Carnahan-Starling (3D), and no pair may overlap at the
   end: a collision missed across the wide cells would show in both. */
static void dilute_gas(int dim, long n, double t_end)
{
  const double phi = 0.005;
  wg_scene sc;
  gas_scene(&sc, dim, n, phi, 13);
  wg_ed s;
  TH_CHECK(wg_ed_alloc(&s, &sc) == WG_OK, "%dD dilute gas set up", dim);
  double range_cells = 1;
  for (int k = 0; k < dim; k++) range_cells *= floor(s.box[k]);
  TH_CHECK(s.cells.ncell <= 8 * n && (shell > 0 || s.cells.ncell < range_cells),
           "%dD dilute gas: %ld cells for %ld particles (one range wide: %.0f)", dim, s.cells.ncell, n,
           range_cells);
  wg_ed_advance(&s, t_end);
  double ek, ep;
  wg_ed_energy(&s, &ek, &ep);
  double T = 2 * ek / (double)(dim * n);
  double density = dim == 3 ? 6 * phi / M_PI : 4 * phi / M_PI;
  double g = dim == 3 ? (1 - phi / 2) / pow(1 - phi, 3) : (1 - 7 * phi / 16) / pow(1 - phi, 2);
  double omega = 2 * (dim - 1) * density * g * sqrt(M_PI * T);
  double measured = 2.0 * (double)s.counts.collisions / ((double)n * t_end);
  double err = 1 / sqrt((double)s.counts.collisions);
  TH_CHECK(fabs(measured / omega - 1) < 5 * err,
           "%dD dilute gas: collision frequency %.5f vs Enskog %.5f (%+.2f %%, band 5 sigma = %.1f %%, %llu collisions)",
           dim, measured, omega, 100 * (measured / omega - 1), 500 * err, s.counts.collisions);
  double closest = closest_pair(&s);
  TH_CHECK(closest > 1 - 1e-9, "%dD dilute gas: closest pair at the end %.12f d (>= 1 - 1e-9)", dim,
           closest);
  wg_ed_free(&s);
}

/* The stencil's pairs in two passes (large systems, ed.c PAIRS_GATHERED) and in one give the
   same events in the same order: positions and velocities equal bit for bit after t_end, with
   the two paths forced on and off in the same system. */
static void gathered_same_bits(long n, double phi, double t_end)
{
  wg_scene sc;
  wg_ed a, b;
  if (gas_scene(&sc, 3, n, phi, 11) || wg_ed_alloc(&a, &sc) != WG_OK || wg_ed_alloc(&b, &sc) != WG_OK) {
    TH_CHECK(0, "gathered pairs: set-up");
    return;
  }
  a.gather = 1;
  b.gather = 0;
  wg_ed_advance(&a, t_end);
  wg_ed_advance(&b, t_end);
  long differ = 0;
  for (long i = 0; i < n; i++)
    for (int k = 0; k < 3; k++) {
      double ra[3], va[3], rb[3], vb[3];
      wg_ed_position_at(&a, i, t_end, ra, va);
      wg_ed_position_at(&b, i, t_end, rb, vb);
      if (ra[k] != rb[k] || va[k] != vb[k]) differ++;
    }
  TH_CHECK(differ == 0 && a.counts.collisions == b.counts.collisions && a.counts.collisions > 10 * (unsigned long long)n,
           "N = %ld, phi = %.2f: the stencil gathered first or walked once, %llu and %llu "
           "collisions, %ld coordinates differ", n, phi, a.counts.collisions, b.counts.collisions,
           differ);
  wg_ed_free(&a);
  wg_ed_free(&b);
}

int main(void)
{
  int quick = getenv("WG_TEST_SHORT") != NULL;
  const double phis[] = {0.1, 0.2, 0.3, 0.4};
  equation_of_state(phis, 4);
  energy_conservation(quick ? 1000000ULL : 10000000ULL);
  dilute_gas(3, 2000, 400);
  dilute_gas(2, 900, 1200);
  gathered_same_bits(4000, 0.42, 6);
  printf("# neighbour lists (shell = 0.4)\n");
  shell = 0.4;
  equation_of_state(phis + 2, 2);
  energy_conservation(1000000ULL);
  dilute_gas(3, 2000, 400);
  dense_lists(3, 2000, 0.45);
  dense_lists(2, 900, 0.6);
  return th_summary();
}
