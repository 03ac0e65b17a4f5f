/* wetgran-series: the time series of a run file as a tab-separated table. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io_h5.h"

static const char *default_cols[] = {
    "kinetic_energy", "potential_energy", "injected_wall", "dissipated_collisions",
    "dissipated_wall", "dissipated_ruptures", "ledger_residual", "temperature", "bridges",
    "collisions", "captures", "ruptures", "reflections", "wall_hits", "wall_enters",
    "cell_crossings", "steps", "list_rebuilds"};

static void usage(FILE *out)
{
  fprintf(out,
          "Usage: wetgran-series RUN.h5 [COLUMN ...]\n"
          "Prints the time series of a wetgran-run file as a tab-separated table on stdout:\n"
          "a header line, then one row per sample: time and the chosen columns (default: all\n"
          "that the run's engine records; event-driven: reflections, wall_enters,\n"
          "cell_crossings; time-driven: steps, list_rebuilds).\n"
          "Columns: /observables/<name>/value of the run file; units are in the file.\n");
}

int main(int argc, char **argv)
{
  if (argc < 2 || !strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
    usage(argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  wg_h5_quiet();
  const char *present[sizeof default_cols / sizeof *default_cols];
  const char **cols = present;
  int ncol = 0;
  hid_t f = wg_h5_open_read(argv[1]);
  if (f < 0) return 1;
  if (argc > 2) {
    cols = (const char **)(argv + 2);
    ncol = argc - 2;
  } else {
    for (size_t c = 0; c < sizeof default_cols / sizeof *default_cols; c++) {
      char path[256];
      snprintf(path, sizeof path, "/observables/%s/value", default_cols[c]);
      if (wg_h5_exists(f, path)) present[ncol++] = default_cols[c];
    }
  }
  int rank;
  hsize_t dims[8];
  if (wg_h5_dims(f, "/observables/temperature/time", &rank, dims) != WG_OK) {
    wg_h5_close(f);
    return 1;
  }
  size_t rows = dims[0];
  double *data = malloc(sizeof(double) * rows * (size_t)(ncol + 1));
  if (!data) return 1;
  int st = wg_h5_read(f, "/observables/temperature/time", H5T_NATIVE_DOUBLE, data);
  for (int c = 0; c < ncol && st == WG_OK; c++) {
    char path[256];
    snprintf(path, sizeof path, "/observables/%s/value", cols[c]);
    if (!wg_h5_exists(f, path)) {
      fprintf(stderr, "wetgran-series: %s: no column '%s'\n", argv[1], cols[c]);
      st = WG_EINVAL;
      break;
    }
    st = wg_h5_read(f, path, H5T_NATIVE_DOUBLE, data + (size_t)(c + 1) * rows);
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
