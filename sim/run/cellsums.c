#include "cellsums.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io_h5.h"
#include "wg.h"

int wg_cellsums_alloc(wg_cellsums *s, size_t cells, int with_volume)
{
  memset(s, 0, sizeof *s);
  s->cells = cells;
  s->count = calloc(cells, sizeof(double));
  s->volume = with_volume ? calloc(cells, sizeof(double)) : NULL;
  s->mass = calloc(cells, sizeof(double));
  s->mom = calloc(3 * cells, sizeof(double));
  s->mv2 = calloc(cells, sizeof(double));
  s->bridges = calloc(cells, sizeof(double));
  if (!s->count || (with_volume && !s->volume) || !s->mass || !s->mom || !s->mv2 || !s->bridges)
    return wg_error(WG_ENOMEM, "cell sums", "cannot allocate %zu cells", cells);
  return WG_OK;
}

void wg_cellsums_free(wg_cellsums *s)
{
  free(s->count); free(s->volume); free(s->mass); free(s->mom); free(s->mv2); free(s->bridges);
  memset(s, 0, sizeof *s);
}

void wg_cellsums_clear(wg_cellsums *s)
{
  size_t c = s->cells;
  memset(s->count, 0, sizeof(double) * c);
  if (s->volume) memset(s->volume, 0, sizeof(double) * c);
  memset(s->mass, 0, sizeof(double) * c);
  memset(s->mom, 0, 3 * sizeof(double) * c);
  memset(s->mv2, 0, sizeof(double) * c);
  memset(s->bridges, 0, sizeof(double) * c);
}

double wg_cellsums_temperature(const wg_cellsums *s, size_t c, int dim)
{
  double p2 = 0;
  for (int a = 0; a < dim; a++) p2 += s->mom[3 * c + (size_t)a] * s->mom[3 * c + (size_t)a];
  return s->count[c] > 0 ? (s->mv2[c] - p2 / s->mass[c]) / (s->count[c] * dim) : NAN;
}

/* the sums in checkpoint order: name, array, values per cell */
#define NSUMS 6
static void sums_table(const wg_cellsums *s, const char *name[NSUMS], double *arr[NSUMS], int per[NSUMS])
{
  static const char *const names[NSUMS] = {"count", "volume", "mass", "mom", "mv2", "bridges"};
  double *a[NSUMS] = {s->count, s->volume, s->mass, s->mom, s->mv2, s->bridges};
  for (int k = 0; k < NSUMS; k++) {
    name[k] = names[k];
    arr[k] = a[k];
    per[k] = k == 3 ? 3 : 1;
  }
}

int wg_cellsums_checkpoint_write(const wg_cellsums *s, hid_t f, const char *prefix)
{
  const char *name[NSUMS];
  double *arr[NSUMS];
  int per[NSUMS], st = WG_OK;
  sums_table(s, name, arr, per);
  for (int k = 0; k < NSUMS; k++) {
    if (!arr[k]) continue;
    char path[128];
    hsize_t d[1] = {(hsize_t)per[k] * s->cells};
    snprintf(path, sizeof path, "%s%s", prefix, name[k]);
    st |= wg_h5_write(f, path, H5T_NATIVE_DOUBLE, 1, d, arr[k], "-", "cell sums");
  }
  return st;
}

int wg_cellsums_checkpoint_read(wg_cellsums *s, hid_t f, const char *ckpt, const char *prefix)
{
  const char *name[NSUMS];
  double *arr[NSUMS];
  int per[NSUMS];
  sums_table(s, name, arr, per);
  for (int k = 0; k < NSUMS; k++) {
    if (!arr[k]) continue;
    char path[128];
    int rank;
    hsize_t dims[8], total = 1, want = (hsize_t)per[k] * s->cells;
    snprintf(path, sizeof path, "%s%s", prefix, name[k]);
    if (wg_h5_dims(f, path, &rank, dims) != WG_OK)
      return wg_error(WG_EIO, ckpt, "dataset %s missing", path);
    for (int i = 0; i < rank; i++) total *= dims[i];
    if (total != want)
      return wg_error(WG_EIO, ckpt, "dataset %s has %llu values, expected %llu", path,
                      (unsigned long long)total, (unsigned long long)want);
    if (wg_h5_read(f, path, H5T_NATIVE_DOUBLE, arr[k]) != WG_OK) return WG_EIO;
  }
  return WG_OK;
}
