/* Sums over the particles in the cells of a lateral grid, sample after sample: what both the
   time-averaged profiles along x (run.c) and the lateral maps per window (maps.c) are made
   of.  Per cell: count, (optionally) particle volume, mass, momentum, sum m v^2, bridges
   (half a bridge per particle end). */
#ifndef WG_CELLSUMS_H
#define WG_CELLSUMS_H

#include <stddef.h>
#include <hdf5.h>

typedef struct wg_cellsums {
  size_t cells;
  double *count, *volume, *mass, *mom, *mv2, *bridges; /* mom: cells x 3; volume may be NULL */
} wg_cellsums;

int wg_cellsums_alloc(wg_cellsums *s, size_t cells, int with_volume);
void wg_cellsums_free(wg_cellsums *s);
void wg_cellsums_clear(wg_cellsums *s);

/* One particle of mass m and velocity v (dim components), volume (ignored without volume
   sums) and nbond bridges, in cell c. */
static inline void wg_cellsums_add(wg_cellsums *s, size_t c, int dim, const double v[3], double m,
                                   double volume, int nbond)
{
  s->count[c] += 1;
  if (s->volume) s->volume[c] += volume;
  s->mass[c] += m;
  for (int k = 0; k < dim; k++) {
    s->mom[3 * c + (size_t)k] += m * v[k];
    s->mv2[c] += m * v[k] * v[k];
  }
  s->bridges[c] += 0.5 * nbond;
}

/* Eq. 3.2 in cell c: sum m |v - V_c|^2 / (count D), V_c the cell's mean velocity over all its
   samples; NAN in a cell that held no particle. */
double wg_cellsums_temperature(const wg_cellsums *s, size_t c, int dim);

/* Checkpoint: datasets <prefix>count, <prefix>volume (when kept), <prefix>mass, ... */
int wg_cellsums_checkpoint_write(const wg_cellsums *s, hid_t f, const char *prefix);
int wg_cellsums_checkpoint_read(wg_cellsums *s, hid_t f, const char *path, const char *prefix);

#endif
