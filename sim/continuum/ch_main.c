/* wetgran-cahn-hilliard: the advective Cahn-Hilliard model of Mahajan & Singh (2025, Eq. 1-4)
   in 1D or 2D (ch.h), its run file, and two readers of it. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <gsl/gsl_rng.h>

#include "ch.h"
#include "io_h5.h"
#include "wg_args.h"

#define PROG "wetgran-cahn-hilliard"

enum { K_NX, K_NZ, K_LX, K_LZ, K_K, K_KAPPA, K_CO, K_CMEAN, K_MOB, K_SHEAR, K_S, K_DT, K_TEND,
       K_DTSER, K_DTSNAP, K_INIT, K_AMP, K_MX, K_MZ, K_SEED, NK };
static wg_num_key keys[NK] = {
    [K_NX] = {"nx", 1, 1, 8192, 1, "grid points along x, the flow (1: the 1D problem along z)"},
    [K_NZ] = {"nz", 128, 4, 8192, 1, "grid points along z, across the flow"},
    [K_LX] = {"lx", 6.283185307179586, 1e-3, 1e6, 0, "box length along x (periodic)"},
    [K_LZ] = {"lz", 6.283185307179586, 1e-3, 1e6, 0, "box length along z (walls; 2 pi: the paper's implied size)"},
    [K_K] = {"K", 25, -1e6, 1e6, 0, "bulk energy scale K of Eq. 3 (K < 0: a single well, no segregation)"},
    [K_KAPPA] = {"kappa", 0.7, 1e-9, 1e6, 0, "gradient energy kappa of Eq. 3"},
    [K_CO] = {"c_o", 0.5, 0, 1, 0, "unstable point c_o of the double well (Eq. 3)"},
    [K_CMEAN] = {"c_mean", NAN, -10, 10, 0, "mean concentration (default c_o)"},
    [K_MOB] = {"mobility", 0.1, 1e-9, 1e6, 0, "mobility M = M_o gamma_dot, in strain units M_o (Eq. 2; not given by the paper: at 0.1 the shear holds ~k_c layers, at 1 they coarsen to one; docs/layering.md)"},
    [K_SHEAR] = {"shear", 1, -1e3, 1e3, 0, "velocity gradient du_x/dz in strain units: 1 = the paper's shear, 0 = none"},
    [K_S] = {"S", NAN, 0, 1e9, 0, "stabiliser of the semi-implicit step (default 2 |K|: energy-stable for |c - 1/2| < 1)"},
    [K_DT] = {"dt", 1e-3, 1e-9, 10, 0, "time step, in strain units"},
    [K_TEND] = {"t_end", 50, 0, 1e9, 0, "strain at the end"},
    [K_DTSER] = {"dt_series", NAN, 0, 1e9, 0, "interval of the series (default t_end/500)"},
    [K_DTSNAP] = {"dt_snapshot", NAN, 0, 1e9, 0, "interval of the field snapshots (default t_end/10)"},
    [K_INIT] = {"init", 0, 0, 1, 1, "initial state: 0 = c_mean plus uniform noise of amplitude amp, 1 = c_mean + amp cos(2 pi mode_x x/lx) cos(pi mode_z z/lz)"},
    [K_AMP] = {"amp", 0.01, 0, 10, 0, "amplitude of the initial noise or mode"},
    [K_MX] = {"mode_x", 0, 0, 4096, 1, "x index of the initial mode, and of the series' amplitude"},
    [K_MZ] = {"mode_z", 3, 0, 8192, 1, "z index of the initial mode, and of the series' amplitude"},
    [K_SEED] = {"seed", 1, 0, 4294967295.0, 1, "seed of the initial noise (GSL mt19937)"},
};
#define V(k) keys[k].value

static void usage(FILE *out)
{
  fprintf(out,
          "Usage: " PROG " run [key=value ...] -o OUT.h5 [-q]\n"
          "       " PROG " series OUT.h5\n"
          "       " PROG " profile OUT.h5 [-f K]\n"
          "The advective Cahn-Hilliard equation of Mahajan & Singh (2025), Eq. 1-4, in strain\n"
          "units: dc/dt + shear (z - lz/2) dc/dx = M lap(f'(c) - kappa lap c), f'(c) = K c (c -\n"
          "1)(c - c_o), periodic in x, between walls at z = 0 and lz that let nothing through;\n"
          "pseudo-spectral (FFTW: Fourier x cosine series), semi-implicit first-order steps.\n"
          "run writes OUT.h5 (renamed from OUT.h5.tmp when complete): /observables (time, mass,\n"
          "free_energy, grad2 = <|grad c|^2>, layers = bands of the x-averaged c(z) above its\n"
          "mean, amplitude of mode (mode_x, mode_z)), /fields/c snapshots, /parameters.\n"
          "series prints the observables as a tab-separated table; profile the x-averaged c(z)\n"
          "of snapshot K (default the last; negative counts from the end).\n"
          "A mode k of small amplitude grows at M k^2 (K c_o (1 - c_o) - kappa k^2); k_c =\n"
          "sqrt(K c_o (1 - c_o) / kappa) (sqrt(K / (4 kappa)) at c_o = 1/2).\n"
          "Keys (default):\n");
  wg_num_key_help(out, keys, NK);
  fprintf(out, "Example: " PROG " run K=25 kappa=0.7 t_end=200 -o layers.h5 && " PROG " profile layers.h5\n");
}

enum { NSER = 6 };
static const char *const ser_name[NSER] = {"time", "mass", "free_energy", "grad2", "layers", "amplitude"};

static int run(int argc, char **argv)
{
  const char *out = NULL;
  int quiet = 0;
  for (int a = 0; a < argc; a++) {
    if (!strcmp(argv[a], "-o") && a + 1 < argc) out = argv[++a];
    else if (!strcmp(argv[a], "-q")) quiet = 1;
    else if (wg_num_key_set(PROG " run", keys, NK, argv[a])) return 2;
  }
  if (!out) {
    fprintf(stderr, PROG " run: no output file (-o OUT.h5)\n");
    return 2;
  }
  if (isnan(V(K_CMEAN))) V(K_CMEAN) = V(K_CO);
  if (isnan(V(K_S))) V(K_S) = 2 * fabs(V(K_K));
  if (isnan(V(K_DTSER))) V(K_DTSER) = V(K_TEND) / 500;
  if (isnan(V(K_DTSNAP))) V(K_DTSNAP) = V(K_TEND) / 10;
  if ((int)V(K_MX) > (int)V(K_NX) / 2 || (int)V(K_MZ) >= (int)V(K_NZ)) {
    fprintf(stderr, PROG " run: mode (%g, %g) outside the grid (mode_x <= nx/2, mode_z < nz)\n", V(K_MX), V(K_MZ));
    return 2;
  }
  wg_ch_params p = {(int)V(K_NX), (int)V(K_NZ), V(K_LX), V(K_LZ), V(K_K), V(K_KAPPA), V(K_CO),
                    V(K_MOB), V(K_SHEAR), V(K_S), V(K_DT)};
  wg_ch s;
  if (wg_ch_init(&s, &p)) {
    fprintf(stderr, PROG " run: cannot allocate a %d x %d grid\n", p.nx, p.nz);
    return 1;
  }
  size_t n = (size_t)p.nx * p.nz;
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, (unsigned long)V(K_SEED));
  double sum = 0;
  for (int ix = 0; ix < p.nx; ix++)
    for (int iz = 0; iz < p.nz; iz++) {
      size_t k = (size_t)ix * p.nz + iz;
      if (V(K_INIT) == 0) s.c[k] = V(K_AMP) * (2 * gsl_rng_uniform(rng) - 1);
      else s.c[k] = V(K_AMP) * cos(2 * M_PI * V(K_MX) * ix / p.nx) * cos(M_PI * V(K_MZ) * (iz + 0.5) / p.nz);
      sum += s.c[k];
    }
  gsl_rng_free(rng);
  for (size_t k = 0; k < n; k++) s.c[k] += V(K_CMEAN) - (V(K_INIT) == 0 ? sum / (double)n : 0);

  long steps = lround(V(K_TEND) / p.dt);
  long every_ser = V(K_DTSER) > 0 ? lround(V(K_DTSER) / p.dt) : steps + 1;
  long every_snap = V(K_DTSNAP) > 0 ? lround(V(K_DTSNAP) / p.dt) : steps + 1;
  if (every_ser < 1) every_ser = 1;
  if (every_snap < 1) every_snap = 1;
  size_t nrow = (size_t)(steps / every_ser + 2), nsnap = (size_t)(steps / every_snap + 2);
  double *ser = malloc(sizeof(double) * NSER * nrow), *snap = malloc(sizeof(double) * n * nsnap);
  double *snap_t = malloc(sizeof(double) * nsnap), *prof = malloc(sizeof(double) * (size_t)p.nz);
  if (!ser || !snap || !snap_t || !prof) {
    fprintf(stderr, PROG " run: out of memory for the series and snapshots\n");
    return 1;
  }
  size_t rows = 0, snaps = 0;
  int tty = !quiet && isatty(2);
  for (long st = 0;; st++) {
    if (st % every_ser == 0 || st == steps) {
      double *r = ser + NSER * rows++;
      wg_ch_profile(&s, prof);
      r[0] = s.t;
      r[1] = wg_ch_mass(&s);
      r[3] = wg_ch_grad2(&s);
      r[2] = wg_ch_bulk_energy(&s) + 0.5 * p.kappa * r[3];
      r[4] = wg_ch_layers(prof, p.nz);
      r[5] = wg_ch_mode(&s, (int)V(K_MX), (int)V(K_MZ));
      if (!isfinite(r[1]) || !isfinite(r[2])) {
        fprintf(stderr, PROG " run: the solution diverged at strain %g (dt %g too large for the shear "
                "or the stabiliser S = %g too small?)\n", s.t, p.dt, p.S);
        return 1;
      }
    }
    if (st % every_snap == 0 || st == steps) {
      memcpy(snap + n * snaps, s.c, sizeof(double) * n);
      snap_t[snaps++] = s.t;
    }
    if (st == steps) break;
    wg_ch_step(&s);
    if (tty && st % 1000 == 0) fprintf(stderr, "\rstrain %g / %g", s.t, V(K_TEND));
  }
  if (tty) fprintf(stderr, "\n");

  char tmp[4096];
  snprintf(tmp, sizeof tmp, "%s.tmp", out);
  hid_t f = wg_h5_create(tmp);
  if (f < 0) return 1;
  int rc = 0;
  double *col = malloc(sizeof(double) * rows);
  for (int c = 0; c < NSER; c++) {
    char path[64];
    for (size_t r = 0; r < rows; r++) col[r] = ser[NSER * r + c];
    snprintf(path, sizeof path, "observables/%s", ser_name[c]);
    hsize_t d[1] = {rows};
    rc |= wg_h5_write(f, path, H5T_NATIVE_DOUBLE, 1, d, col, "1", ser_name[c]);
  }
  hsize_t d3[3] = {snaps, (hsize_t)p.nx, (hsize_t)p.nz}, d1[1] = {snaps};
  rc |= wg_h5_write(f, "fields/c", H5T_NATIVE_DOUBLE, 3, d3, snap, "1", "concentration c[snapshot][ix][iz] at x = ix lx/nx, z = (iz + 1/2) lz/nz");
  rc |= wg_h5_write(f, "fields/time", H5T_NATIVE_DOUBLE, 1, d1, snap_t, "1", "strain of each snapshot");
  hid_t g = wg_h5_group(f, "parameters");
  for (int k = 0; k < NK; k++) rc |= wg_h5_attr_double(g, ".", keys[k].name, keys[k].value);
  H5Gclose(g);
  rc |= wg_h5_close(f);
  free(col);
  if (rc || rename(tmp, out) != 0) {
    fprintf(stderr, PROG " run: cannot write %s (%s)\n", out, rc ? "HDF5 error" : strerror(errno));
    remove(tmp);
    return 1;
  }
  const double *last = ser + NSER * (rows - 1);
  printf("summary: strain=%g steps=%ld mass=%.17g mass_drift=%.3g free_energy=%.10g grad2=%.10g layers=%g k_c=%.6g\n",
         s.t, s.steps, last[1], last[1] - ser[1], last[2], last[3], last[4],
         p.K * p.c_o * (1 - p.c_o) > 0 ? sqrt(p.K * p.c_o * (1 - p.c_o) / p.kappa) : 0.0);
  free(ser);
  free(snap);
  free(snap_t);
  free(prof);
  wg_ch_free(&s);
  fftw_cleanup();
  return 0;
}

static int read_param(hid_t f, const char *name, double *v)
{
  return wg_h5_read_attr_double(f, "parameters", name, v);
}

static int series(const char *path)
{
  hid_t f = wg_h5_open_read(path);
  if (f < 0) return 1;
  int rank;
  hsize_t d[8];
  if (wg_h5_dims(f, "observables/time", &rank, d) != WG_OK) {
    fprintf(stderr, PROG " series: %s: no /observables/time (not a run file of this tool)\n", path);
    wg_h5_close(f);
    return 1;
  }
  size_t rows = d[0];
  double *data = malloc(sizeof(double) * NSER * (rows ? rows : 1));
  int st = WG_OK;
  for (int c = 0; c < NSER && st == WG_OK; c++) {
    char p[64];
    snprintf(p, sizeof p, "observables/%s", ser_name[c]);
    st = wg_h5_read(f, p, H5T_NATIVE_DOUBLE, data + rows * c);
  }
  wg_h5_close(f);
  if (st != WG_OK) {
    fprintf(stderr, PROG " series: %s: damaged observables\n", path);
    free(data);
    return 1;
  }
  for (int c = 0; c < NSER; c++) printf("%s%s", c ? "\t" : "", ser_name[c]);
  printf("\n");
  for (size_t r = 0; r < rows; r++)
    for (int c = 0; c < NSER; c++) printf("%.10g%s", data[rows * c + r], c + 1 < NSER ? "\t" : "\n");
  free(data);
  return 0;
}

static int profile(const char *path, long which)
{
  hid_t f = wg_h5_open_read(path);
  if (f < 0) return 1;
  int rank;
  hsize_t d[8];
  double lz;
  if (wg_h5_dims(f, "fields/c", &rank, d) != WG_OK || rank != 3 || read_param(f, "lz", &lz) != WG_OK) {
    fprintf(stderr, PROG " profile: %s: no /fields/c snapshots or no lz (not a run file of this tool)\n", path);
    wg_h5_close(f);
    return 1;
  }
  long ns = (long)d[0], k = which < 0 ? ns + which : which;
  if (k < 0 || k >= ns) {
    fprintf(stderr, PROG " profile: %s: snapshot %ld out of range (%ld snapshots)\n", path, which, ns);
    wg_h5_close(f);
    return 1;
  }
  size_t nx = d[1], nz = d[2];
  double *c = malloc(sizeof(double) * nx * nz), t = 0;
  int st = wg_h5_read_rows(f, "fields/c", H5T_NATIVE_DOUBLE, (hsize_t)k, 1, c);
  double *times = malloc(sizeof(double) * (size_t)ns);
  if (st == WG_OK && wg_h5_read(f, "fields/time", H5T_NATIVE_DOUBLE, times) == WG_OK) t = times[k];
  wg_h5_close(f);
  if (st != WG_OK) {
    fprintf(stderr, PROG " profile: %s: cannot read snapshot %ld\n", path, k);
    return 1;
  }
  printf("# strain %g snapshot %ld of %ld\nz\tc\n", t, k, ns);
  for (size_t iz = 0; iz < nz; iz++) {
    double m = 0;
    for (size_t ix = 0; ix < nx; ix++) m += c[ix * nz + iz];
    printf("%.10g\t%.10g\n", (iz + 0.5) * lz / (double)nz, m / (double)nx);
  }
  free(c);
  free(times);
  return 0;
}

int main(int argc, char **argv)
{
  if (argc < 2 || !strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
    usage(argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  wg_h5_quiet();
  if (!strcmp(argv[1], "run")) return run(argc - 2, argv + 2);
  if (!strcmp(argv[1], "series") && argc == 3) return series(argv[2]);
  if (!strcmp(argv[1], "profile") && (argc == 3 || (argc == 5 && !strcmp(argv[3], "-f")))) {
    long k = -1;
    if (argc == 5 && wg_arg_long("-f", argv[4], &k) != WG_OK) return 2;
    return profile(argv[2], k);
  }
  fprintf(stderr, PROG ": unknown mode or arguments '%s' (run, series FILE, profile FILE [-f K]; --help)\n", argv[1]);
  return 2;
}
