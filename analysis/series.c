/* wetgran-series: the time series of a run file as a tab-separated table. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io_h5.h"
#include "run_open.h"

/* Every column a run may hold (/observables/<name>/value), in the order of the default table,
   with its unit (as the run file's "unit" attribute says); temperature_ecb is derived here. */
static const struct { const char *name, *unit, *what; } known[] = {
    {"kinetic_energy", "m g d", "total kinetic energy"},
    {"potential_energy", "m g d", "potential energy (gravity; time-driven: + overlaps, bonds)"},
    {"injected_wall", "m g d", "work done by the moving walls since t = 0"},
    {"dissipated_collisions", "m g d", "energy lost in particle collisions since t = 0"},
    {"dissipated_wall", "m g d", "energy lost at the walls since t = 0"},
    {"dissipated_ruptures", "m g d", "energy taken by bridge ruptures since t = 0"},
    {"ledger_residual", "1", "energy ledger's relative residual"},
    {"temperature", "m g d", "granular temperature T_g (Eq. 3.2)"},
    {"bridges", "1", "number of capillary bridges"},
    {"collisions", "1", "particle-particle collisions since t = 0"},
    {"captures", "1", "bridges formed since t = 0"},
    {"ruptures", "1", "bridges ruptured since t = 0"},
    {"reflections", "1", "bonded pairs reflected at s_crit since t = 0 (event-driven)"},
    {"wall_hits", "1", "particle-wall collisions since t = 0"},
    {"wall_enters", "1", "entries into a wall's reach since t = 0 (event-driven)"},
    {"cell_crossings", "1", "cell crossings since t = 0 (event-driven)"},
    {"steps", "1", "time steps since t = 0 (time-driven)"},
    {"list_rebuilds", "1", "neighbour-list rebuilds since t = 0 (time-driven)"},
    {"field_work", "m g d", "work done by the shear field since t = 0 (event-driven, shear_force)"},
    {"e_par", "m g d", "kinetic energy per particle along the shear force (Ch. 8: E_par)"},
    {"e_perp", "m g d", "kinetic energy per particle across it, along x (Ch. 8: E_perp)"},
    {"injected_noise", "m g d", "work done by the random force since t = 0 (event-driven, noise)"},
    {"a2", "1", "Sonine coefficient a_2 of the velocities (Eq. A.32; with noise)"},
    {"a2_free", "1", "a_2 of the grains without a bridge (with noise)"},
    {"temperature_free", "m g d", "T_g of the grains without a bridge (with noise)"},
    {"temperature_ecb", "E_cb", "T_g / E_cb (wet runs, E_cb > 0 only)"},
};
#define NKNOWN (sizeof known / sizeof *known)
#define TG_ECB "temperature_ecb"

static void usage(FILE *out)
{
  fprintf(out,
          "Usage: wetgran-series RUN.h5 [COLUMN ...]\n"
          "Prints the time series of a wetgran-run file as a tab-separated table on stdout:\n"
          "a header line, then one row per sample: time [sqrt(d/g)] and the chosen columns\n"
          "(default: all that the run holds, in this order):\n");
  for (size_t c = 0; c < NKNOWN; c++)
    fprintf(out, "  %-22s [%s] %s\n", known[c].name, known[c].unit, known[c].what);
}

/* E_cb from the run's parameters; 0 if the run has none (dry) or it cannot be read. */
static double run_e_cb(hid_t f)
{
  double e = 0;
  if (H5Aexists_by_name(f, "/parameters", "e_cb", H5P_DEFAULT) <= 0 ||
      wg_h5_read_param_double(f, "e_cb", &e) != WG_OK)
    return 0;
  return e > 0 && isfinite(e) ? e : 0;
}

static int present(hid_t f, const char *name, double e_cb)
{
  char path[256];
  if (!strcmp(name, TG_ECB)) return e_cb > 0 && wg_h5_exists(f, "/observables/temperature/value");
  if (strlen(name) > 200 || strchr(name, '/')) return 0;
  snprintf(path, sizeof path, "/observables/%s/value", name);
  return wg_h5_exists(f, path);
}

int main(int argc, char **argv)
{
  if (argc < 2 || !strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
    usage(argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const char *run = argv[1];
  hid_t f = wg_run_open(run);
  if (f < 0) return 1;
  if (!wg_h5_exists(f, "/observables/temperature/time")) {
    fprintf(stderr, "wetgran-series: %s: no time series (/observables/temperature missing)\n", run);
    wg_h5_close(f);
    return 1;
  }
  double e_cb = run_e_cb(f);
  const char *have[NKNOWN];
  int nhave = 0;
  for (size_t c = 0; c < NKNOWN; c++)
    if (present(f, known[c].name, e_cb)) have[nhave++] = known[c].name;
  const char **cols = have;
  int ncol = nhave;
  if (argc > 2) {
    cols = (const char **)(argv + 2);
    ncol = argc - 2;
    for (int c = 0; c < ncol; c++) {
      if (present(f, cols[c], e_cb)) continue;
      fprintf(stderr, "wetgran-series: %s: no column '%s' (this run has:", run, cols[c]);
      for (int k = 0; k < nhave; k++) fprintf(stderr, "%s %s", k ? "," : "", have[k]);
      fprintf(stderr, "%s)\n", !strcmp(cols[c], TG_ECB) ? "; temperature_ecb needs E_cb > 0" : "");
      wg_h5_close(f);
      return 1;
    }
  }
  int rank;
  hsize_t dims[8];
  if (wg_h5_dims(f, "/observables/temperature/time", &rank, dims) != WG_OK) {
    wg_h5_close(f);
    return 1;
  }
  size_t rows = dims[0];
  double *data = malloc(sizeof(double) * (rows ? rows : 1) * (size_t)(ncol + 1));
  if (!data) {
    fprintf(stderr, "wetgran-series: out of memory\n");
    wg_h5_close(f);
    return 1;
  }
  int st = wg_h5_read(f, "/observables/temperature/time", H5T_NATIVE_DOUBLE, data);
  for (int c = 0; c < ncol && st == WG_OK; c++) {
    char path[256];
    int derived = !strcmp(cols[c], TG_ECB);
    snprintf(path, sizeof path, "/observables/%s/value", derived ? "temperature" : cols[c]);
    double *col = data + (size_t)(c + 1) * rows;
    st = wg_h5_dims(f, path, &rank, dims);
    if (st == WG_OK && (rank != 1 || dims[0] != rows)) {
      fprintf(stderr, "wetgran-series: %s: column '%s' has not one value per sample\n", run, cols[c]);
      st = WG_EINVAL;
    }
    if (st == WG_OK) st = wg_h5_read(f, path, H5T_NATIVE_DOUBLE, col);
    for (size_t r = 0; derived && st == WG_OK && r < rows; r++) col[r] /= e_cb;
  }
  wg_h5_close(f);
  if (st != WG_OK) {
    free(data);
    return 1;
  }
  printf("time");
  for (int c = 0; c < ncol; c++) printf("\t%s", cols[c]);
  printf("\n");
  for (size_t r = 0; r < rows; r++) {
    printf("%.10g", data[r]);
    for (int c = 0; c < ncol; c++) printf("\t%.10g", data[(size_t)(c + 1) * rows + r]);
    printf("\n");
  }
  free(data);
  return 0;
}
