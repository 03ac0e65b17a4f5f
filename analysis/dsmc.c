/* wetgran-dsmc: the spatially homogeneous Boltzmann equation of a white-noise-driven gas of
   hard disks or spheres (thesis App. A, Eq. A.34), solved by direct simulation Monte Carlo
   (Bird's majorant scheme), with the thesis's collision rules: restitution eps, and the
   thin-thread bridge's threshold of Eq. A.40-A.41.  It gives the Boltzmann equation's own
   a_2, against which the first Sonine approximation (Eq. A.59, wetgran-theory a2) and the
   event-driven runs (which add bound pairs and spatial correlations) are read. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "wg_args.h"

enum { K_DIM, K_N, K_EPS, K_EPS_CB, K_GAMMA, K_DT, K_T_END, K_BURN, K_BATCHES, K_SEED, NK };
static wg_num_key keys[NK] = {
    [K_DIM] = {"dim", 2, 2, 3, 1, "dimension D (2 or 3)"},
    [K_N] = {"n", 20000, 2, 1e8, 1, "particles"},
    [K_EPS] = {"eps", 1, 0, 1, 0, "coefficient of normal restitution"},
    [K_EPS_CB] = {"eps_cb", 0, 0, 20, 0,
                  "bridge energy as eps_cb = 2 E_cb / T at T = 1 (E_cb = eps_cb / 2); 0 = dry"},
    [K_GAMMA] = {"gamma", NAN, 0, 1e6, 0,
                 "noise strength (Eq. A.33); default: the value that holds T near 1"},
    [K_DT] = {"dt", 0.02, 1e-6, 1, 0, "time step (kicks once per step)"},
    [K_T_END] = {"t_end", 3000, 1, 1e9, 0, "simulated time"},
    [K_BURN] = {"burn", 200, 0, 1e9, 0, "time before sampling starts"},
    [K_BATCHES] = {"batches", 20, 2, 1000, 1, "batches of the samples for the error bars"},
    [K_SEED] = {"seed", 1, 0, 4294967295.0, 1, "seed of GSL's mt19937"},
};

static void usage(FILE *out)
{
  fprintf(out,
          "Usage: wetgran-dsmc [key=value ...]\n"
          "Direct simulation Monte Carlo of the homogeneous Boltzmann equation of hard disks\n"
          "(dim=2) or spheres (dim=3) kicked by white noise (thesis Eq. A.33-A.34); prints\n"
          "'key value' rows (header key, value): the stationary temperature T, eps_cb = 2 E_cb / T\n"
          "measured, and the Sonine coefficient a_2 = D/(D+2) <v^4>/<v^2>^2 - 1 with errors\n"
          "from batch means.  A pair meets at rate |u.s| per unit time (u the relative\n"
          "velocity, s a random unit vector; unit density and cross-section); it leaves with\n"
          "normal speed eps u, or, wet, sqrt(u^2 - 4 E_cb) if u^2 >= 4 E_cb (Eq. A.40, unit\n"
          "masses) and unchanged otherwise (slower pairs lie outside the integrals of\n"
          "Eq. A.54, as in the thesis).  Every dt each velocity takes a Gaussian kick of\n"
          "variance 2 gamma dt per axis, less the mean kick.  Keys (default):\n");
  wg_num_key_help(out, keys, NK);
  fprintf(out, "Example: wetgran-dsmc dim=2 eps_cb=0.2 | awk '$1 == \"a2\"'\n");
}

static int parse(int argc, char **argv)
{
  for (int a = 1; a < argc; a++)
    if (wg_num_key_set("wetgran-dsmc", keys, NK, argv[a])) return 2;
  if (keys[K_BURN].value >= keys[K_T_END].value) {
    fprintf(stderr, "wetgran-dsmc: burn (%g) must be shorter than t_end (%g)\n",
            keys[K_BURN].value, keys[K_T_END].value);
    return 2;
  }
  return 0;
}

static void random_direction(gsl_rng *r, int dim, double *s)
{
  if (dim == 3) {
    gsl_ran_dir_3d(r, &s[0], &s[1], &s[2]);
  } else {
    gsl_ran_dir_2d(r, &s[0], &s[1]);
    s[2] = 0;
  }
}

int main(int argc, char **argv)
{
  for (int a = 1; a < argc; a++)
    if (!strcmp(argv[a], "-h") || !strcmp(argv[a], "--help")) {
      usage(stdout);
      return 0;
    }
  if (parse(argc, argv)) return 2;
  int dim = (int)keys[K_DIM].value;
  long n = (long)keys[K_N].value;
  double eps = keys[K_EPS].value, e_cb = keys[K_EPS_CB].value / 2, dt = keys[K_DT].value;
  /* gamma that balances the losses at T = 1: collisions per particle and time nu = <u+> =
     1/sqrt(pi) (u.s ~ N(0, 2)); each takes E_cb e^(-eps_cb/2) (wet: the pairs that escape)
     plus (1 - eps^2) <u+^3>/<u+> / 4 = (1 - eps^2) (restitution); per particle D gamma */
  double gamma = keys[K_GAMMA].value;
  if (isnan(gamma)) {
    double nu = 1 / sqrt(M_PI);
    gamma = nu / 2 * (e_cb * exp(-keys[K_EPS_CB].value / 2) + (1 - eps * eps)) / dim;
  }
  if (!(gamma > 0)) {
    fprintf(stderr, "wetgran-dsmc: nothing dissipates or drives (eps = 1, eps_cb = 0, gamma = 0): give gamma > 0 or a loss\n");
    return 2;
  }
  double *v = malloc(sizeof *v * (size_t)n * 3);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  if (!v || !r) {
    fprintf(stderr, "wetgran-dsmc: out of memory for %ld particles\n", n);
    return 1;
  }
  gsl_rng_set(r, (unsigned long)keys[K_SEED].value);
  for (long i = 0; i < n * 3; i++) v[i] = (i % 3) < dim ? gsl_ran_gaussian_ziggurat(r, 1.0) : 0;
  double w_max = 6; /* majorant of u.s; raised (and the step's rate with it) when exceeded */
  double carry = 0, amp = sqrt(2 * gamma * dt);
  long steps = (long)ceil(keys[K_T_END].value / dt), burn = (long)(keys[K_BURN].value / dt);
  int nb = (int)keys[K_BATCHES].value;
  long per_batch = (steps - burn) / nb;
  if (per_batch < 1) {
    fprintf(stderr, "wetgran-dsmc: fewer steps after burn (%ld) than batches (%d)\n", steps - burn, nb);
    return 2;
  }
  double *ba2 = calloc((size_t)nb, sizeof *ba2), *bT = calloc((size_t)nb, sizeof *bT);
  unsigned long long collisions = 0;
  for (long step = 0; step < burn + per_batch * nb; step++) {
    /* candidate pairs in dt: n w_max dt / 2, each kept with probability u.s / w_max */
    carry += 0.5 * (double)n * w_max * dt;
    long cand = (long)carry;
    carry -= (double)cand;
    for (long c = 0; c < cand; c++) {
      long i = (long)gsl_rng_uniform_int(r, (unsigned long)n), j = (long)gsl_rng_uniform_int(r, (unsigned long)n - 1);
      if (j >= i) j++;
      double s[3], u = 0;
      random_direction(r, dim, s);
      for (int a = 0; a < dim; a++) u += (v[3 * i + a] - v[3 * j + a]) * s[a];
      if (u <= 0) continue;
      if (u > w_max) w_max = 1.05 * u;
      if (gsl_rng_uniform(r) * w_max > u) continue;
      double un = eps * u;
      if (e_cb > 0) {
        if (un * un < 4 * e_cb) continue; /* captured: outside the thesis's integrals */
        un = sqrt(un * un - 4 * e_cb);    /* Eq. A.40 with eps_cb v0^2 = 4 E_cb / m */
      }
      double du = 0.5 * (u + un);
      for (int a = 0; a < dim; a++) {
        v[3 * i + a] -= du * s[a];
        v[3 * j + a] += du * s[a];
      }
      collisions++;
    }
    double mean[3] = {0, 0, 0};
    for (long i = 0; i < n; i++)
      for (int a = 0; a < dim; a++) {
        v[3 * i + a] += amp * gsl_ran_gaussian_ziggurat(r, 1.0);
        mean[a] += v[3 * i + a];
      }
    for (long i = 0; i < n; i++)
      for (int a = 0; a < dim; a++) v[3 * i + a] -= mean[a] / (double)n;
    if (step >= burn) {
      double u2 = 0, u4 = 0;
      for (long i = 0; i < n; i++) {
        double w = 0;
        for (int a = 0; a < dim; a++) w += v[3 * i + a] * v[3 * i + a];
        u2 += w;
        u4 += w * w;
      }
      u2 /= (double)n;
      u4 /= (double)n;
      int b = (int)((step - burn) / per_batch);
      ba2[b] += (double)dim / (dim + 2) * u4 / (u2 * u2) - 1;
      bT[b] += u2 / dim;
    }
  }
  double a2 = 0, a2sq = 0, T = 0, Tsq = 0;
  for (int b = 0; b < nb; b++) {
    ba2[b] /= (double)per_batch;
    bT[b] /= (double)per_batch;
    a2 += ba2[b];
    a2sq += ba2[b] * ba2[b];
    T += bT[b];
    Tsq += bT[b] * bT[b];
  }
  a2 /= nb;
  T /= nb;
  double a2_err = sqrt(fmax(a2sq / nb - a2 * a2, 0) / (nb - 1));
  double T_err = sqrt(fmax(Tsq / nb - T * T, 0) / (nb - 1));
  printf("key\tvalue\n");
  printf("dim\t%d\nn\t%ld\neps\t%.10g\ne_cb\t%.10g\ngamma\t%.10g\n", dim, n, eps, e_cb, gamma);
  printf("temperature\t%.10g\ntemperature_err\t%.3g\n", T, T_err);
  printf("eps_cb\t%.10g\n", 2 * e_cb / T);
  printf("a2\t%.10g\na2_err\t%.3g\n", a2, a2_err);
  printf("collisions_per_particle\t%.10g\n", 2.0 * (double)collisions / (double)n);
  free(ba2);
  free(bT);
  free(v);
  gsl_rng_free(r);
  return 0;
}
