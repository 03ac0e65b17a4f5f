/* wetgran-frame: one particle snapshot of a run file as a tab-separated table. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io_h5.h"
#include "run_open.h"
#include "wg_args.h"

int main(int argc, char **argv)
{
  const char *path = NULL;
  long frame = -1; /* last */
  for (int a = 1; a < argc; a++) {
    if (!strcmp(argv[a], "-h") || !strcmp(argv[a], "--help")) {
      printf("Usage: wetgran-frame RUN.h5 [-f K]\n"
             "Prints snapshot K (default: the last; negative counts from the end) as a\n"
             "tab-separated table: index, position (x, [y,] z) [d], velocity, diameter [d],\n"
             "kinetic energy [m g d], bridge count.  The first line is a header; a comment\n"
             "line '# time ...' gives the snapshot time.\n");
      return 0;
    }
    if (!strcmp(argv[a], "-f")) {
      if (a + 1 == argc) {
        fprintf(stderr, "wetgran-frame: option -f needs a snapshot number (see --help)\n");
        return 2;
      }
      if (wg_arg_long("-f", argv[++a], &frame) != WG_OK) return 2;
    } else if (argv[a][0] == '-' && argv[a][1] && !(argv[a][1] >= '0' && argv[a][1] <= '9')) {
      fprintf(stderr, "wetgran-frame: unknown option '%s' (see --help)\n", argv[a]);
      return 2;
    } else if (!path) path = argv[a];
    else {
      fprintf(stderr, "wetgran-frame: unexpected argument '%s' (see --help)\n", argv[a]);
      return 2;
    }
  }
  if (!path) {
    fprintf(stderr, "wetgran-frame: no run file given (see --help)\n");
    return 2;
  }
  hid_t f = wg_run_open(path);
  if (f < 0) return 1;
  int rank;
  hsize_t dims[8];
  int st = wg_h5_dims(f, "/particles/all/position/value", &rank, dims);
  if (st != WG_OK) { wg_h5_close(f); return 1; }
  long nf = (long)dims[0], n = (long)dims[1];
  int dim = (int)dims[2];
  if (frame < 0) frame += nf;
  if (frame < 0 || frame >= nf) {
    fprintf(stderr, "wetgran-frame: %s: snapshot %ld out of range (the run has %ld)\n", path, frame, nf);
    wg_h5_close(f);
    return 1;
  }
  double *r = malloc(sizeof(double) * (size_t)(n * dim)), *v = malloc(sizeof(double) * (size_t)(n * dim));
  double *d = malloc(sizeof(double) * (size_t)n), *m = malloc(sizeof(double) * (size_t)n), t = 0;
  unsigned char *nb = malloc((size_t)n);
  if (!r || !v || !d || !m || !nb) return 1;
  st = wg_h5_read_rows(f, "/particles/all/position/value", H5T_NATIVE_DOUBLE, (hsize_t)frame, 1, r);
  if (st == WG_OK) st = wg_h5_read_rows(f, "/particles/all/velocity/value", H5T_NATIVE_DOUBLE, (hsize_t)frame, 1, v);
  if (st == WG_OK) st = wg_h5_read_rows(f, "/particles/all/bridge_count/value", H5T_NATIVE_UINT8, (hsize_t)frame, 1, nb);
  if (st == WG_OK) st = wg_h5_read_rows(f, "/particles/all/position/time", H5T_NATIVE_DOUBLE, (hsize_t)frame, 1, &t);
  if (st == WG_OK) st = wg_h5_read(f, "/particles/all/diameter", H5T_NATIVE_DOUBLE, d);
  if (st == WG_OK) st = wg_h5_read(f, "/particles/all/mass", H5T_NATIVE_DOUBLE, m);
  wg_h5_close(f);
  if (st == WG_OK) {
    const char *ax[3] = {"x", dim == 3 ? "y" : "z", "z"};
    printf("# time %.10g snapshot %ld of %ld\n", t, frame, nf);
    printf("i");
    for (int k = 0; k < dim; k++) printf("\t%s", ax[k]);
    for (int k = 0; k < dim; k++) printf("\tv%s", ax[k]);
    printf("\tdiameter\tkinetic_energy\tbridges\n");
    for (long i = 0; i < n; i++) {
      double ke = 0;
      printf("%ld", i);
      for (int k = 0; k < dim; k++) printf("\t%.10g", r[i * dim + k]);
      for (int k = 0; k < dim; k++) {
        printf("\t%.10g", v[i * dim + k]);
        ke += 0.5 * m[i] * v[i * dim + k] * v[i * dim + k];
      }
      printf("\t%.6g\t%.10g\t%d\n", d[i], ke, nb[i]);
    }
  }
  free(r); free(v); free(d); free(m); free(nb);
  return st == WG_OK ? 0 : 1;
}
