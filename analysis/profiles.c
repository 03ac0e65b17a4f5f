/* wetgran-profiles: time-averaged lateral profiles of a run file as a tab-separated table. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io_h5.h"
#include "run_open.h"

static const char *fields[] = {"number_density", "packing_fraction", "temperature",
                               "bridge_density"};

int main(int argc, char **argv)
{
  if (argc != 2 || !strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
    fprintf(argc == 2 ? stdout : stderr,
            "Usage: wetgran-profiles RUN.h5\n"
            "Prints the time-averaged lateral profiles (run with profile_bins > 0) as a\n"
            "tab-separated table, columns:\n"
            "  x                 [d]          centre of the lateral bin\n"
            "  number_density    [d^-(D-1)]\n"
            "  packing_fraction  [1]\n"
            "  temperature       [m g d]      T_g (Eq. 3.2)\n"
            "  temperature_ecb   [E_cb]       T_g / E_cb (wet runs; dry runs: nan)\n"
            "  bridge_density    [d^-(D-1)]   n_cb\n");
    return argc == 2 ? 0 : 2;
  }
  hid_t f = wg_run_open(argv[1]);
  if (f < 0) return 1;
  if (!wg_h5_exists(f, "/observables/profiles/x")) {
    fprintf(stderr, "wetgran-profiles: %s: no profiles in this run (set profile_bins > 0)\n", argv[1]);
    wg_h5_close(f);
    return 1;
  }
  int rank;
  hsize_t dims[8];
  int st = wg_h5_dims(f, "/observables/profiles/x", &rank, dims);
  if (st != WG_OK) {
    wg_h5_close(f);
    return 1;
  }
  size_t b = dims[0];
  double *data = malloc(sizeof(double) * b * 5), e_cb = 0;
  if (!data) return 1;
  if (st == WG_OK) st = wg_h5_read(f, "/observables/profiles/x", H5T_NATIVE_DOUBLE, data);
  for (int k = 0; k < 4 && st == WG_OK; k++) {
    char path[128];
    snprintf(path, sizeof path, "/observables/profiles/%s", fields[k]);
    st = wg_h5_read(f, path, H5T_NATIVE_DOUBLE, data + (size_t)(k + 1) * b);
  }
  if (st == WG_OK) st = wg_h5_read_attr_double(f, "/observables/profiles", "e_cb", &e_cb);
  wg_h5_close(f);
  if (st != WG_OK) {
    free(data);
    return 1;
  }
  printf("x\tnumber_density\tpacking_fraction\ttemperature\ttemperature_ecb\tbridge_density\n");
  for (size_t i = 0; i < b; i++)
    printf("%.10g\t%.10g\t%.10g\t%.10g\t%.10g\t%.10g\n", data[i], data[b + i], data[2 * b + i],
           data[3 * b + i], e_cb > 0 ? data[3 * b + i] / e_cb : NAN, data[4 * b + i]);
  free(data);
  return 0;
}
