#include "cells.h"

#include <math.h>
#include <stdlib.h>

static inline long flat(const wg_cells *c, const int *ix);
static inline void unflat(const wg_cells *c, long cell, int *ix);

/* Interior cells (stencil within the grid, no wrap) use fixed flat offsets; the rest take
   the general path with wrapping and clipping. */
static void precompute_stencils(wg_cells *c)
{
  long stride[3] = {1, c->nc[0], (long)c->nc[0] * c->nc[1]};
  int lo[3], hi[3];
  for (int a = 0; a < 3; a++) {
    lo[a] = a < c->dim ? -1 : 0;
    hi[a] = a < c->dim ? 1 : 0;
  }
  c->stencil_size = 0;
  for (int dz = lo[2]; dz <= hi[2]; dz++)
    for (int dy = lo[1]; dy <= hi[1]; dy++)
      for (int dx = lo[0]; dx <= hi[0]; dx++)
        c->stencil_offset[c->stencil_size++] = dx * stride[0] + dy * stride[1] + dz * stride[2];
  for (int axis = 0; axis < c->dim; axis++)
    for (int d = 0; d < 2; d++) {
      int m = 0;
      int flo[3] = {lo[0], lo[1], lo[2]}, fhi[3] = {hi[0], hi[1], hi[2]};
      flo[axis] = fhi[axis] = d ? 1 : -1;
      for (int dz = flo[2]; dz <= fhi[2]; dz++)
        for (int dy = flo[1]; dy <= fhi[1]; dy++)
          for (int dx = flo[0]; dx <= fhi[0]; dx++)
            c->face_offset[axis][d][m++] = dx * stride[0] + dy * stride[1] + dz * stride[2];
      c->face_size = m;
    }
  for (long k = 0; k < c->ncell; k++) {
    int ix[3];
    unflat(c, k, ix);
    int in = 1;
    for (int a = 0; a < c->dim; a++)
      if (ix[a] < 1 || ix[a] > c->nc[a] - 2) in = 0;
    c->interior[k] = (uint8_t)in;
  }
}

int wg_cells_alloc(wg_cells *c, int dim, const double *lo, const double *len,
                   const int *periodic, double range, long n)
{
  c->dim = dim;
  c->turn_back = 0;
  c->ncell = 1;
  for (int a = 0; a < 3; a++) {
    if (a >= dim) {
      c->nc[a] = 1; c->lo[a] = 0; c->len[a] = 1; c->w[a] = 1; c->periodic[a] = 0;
      continue;
    }
    c->lo[a] = lo[a];
    c->len[a] = len[a];
    c->periodic[a] = periodic[a];
    long k = (long)floor(len[a] / range);
    if (k < 1) k = 1;
    if (k > 4096) k = 4096;
    if (periodic[a] && k < 3)
      return wg_error(WG_EINVAL, "cells",
                      "periodic box length %g along axis %d is below 3 interaction ranges (%g)",
                      len[a], a, 3 * range);
    c->nc[a] = (int)k;
    c->w[a] = len[a] / (double)k;
    c->ncell *= k;
  }
  if (c->ncell > INT32_MAX)
    return wg_error(WG_ERANGE, "cells", "%ld cells: more than a cell index holds (2^31 - 1)",
                    c->ncell);
  c->head = malloc(sizeof *c->head * (size_t)c->ncell);
  c->interior = malloc((size_t)c->ncell);
  c->next = malloc(sizeof *c->next * (size_t)n);
  c->prev = malloc(sizeof *c->prev * (size_t)n);
  c->cell = malloc(sizeof *c->cell * (size_t)n);
  if (!c->head || !c->next || !c->prev || !c->cell || !c->interior) {
    wg_cells_free(c);
    return wg_error(WG_ENOMEM, "cells", "cannot allocate %ld cells for %ld particles", c->ncell, n);
  }
  for (long k = 0; k < c->ncell; k++) c->head[k] = -1;
  c->images_exact = 1;
  for (int a = 0; a < dim; a++)
    if (c->periodic[a] && c->nc[a] < 5) c->images_exact = 0;
  precompute_stencils(c);
  return WG_OK;
}

void wg_cells_free(wg_cells *c)
{
  free(c->head); free(c->next); free(c->prev); free(c->cell); free(c->interior);
  c->head = c->next = c->prev = c->cell = NULL;
  c->interior = NULL;
}

static inline long flat(const wg_cells *c, const int *ix)
{
  return ix[0] + (long)c->nc[0] * (ix[1] + (long)c->nc[1] * ix[2]);
}

/* In 32 bits (a cell index is an int32_t, wg_cells_alloc): a 64-bit division costs several
   times more, and cell crossings and stencils unflatten at every event. */
static inline void unflat(const wg_cells *c, long cell, int *ix)
{
  uint32_t k = (uint32_t)cell, n0 = (uint32_t)c->nc[0], n1 = (uint32_t)c->nc[1];
  ix[0] = (int)(k % n0);
  k /= n0;
  ix[1] = (int)(k % n1);
  ix[2] = (int)(k / n1);
}

int wg_cells_coord(const wg_cells *c, long cell, int axis)
{
  int ix[3];
  unflat(c, cell, ix);
  return ix[axis];
}

long wg_cells_locate(const wg_cells *c, const double *r)
{
  int ix[3] = {0, 0, 0};
  for (int a = 0; a < c->dim; a++) {
    long k = (long)floor((r[a] - c->lo[a]) / c->w[a]);
    if (c->periodic[a]) {
      k %= c->nc[a];
      if (k < 0) k += c->nc[a];
    } else {
      if (k < 0) k = 0;
      if (k >= c->nc[a]) k = c->nc[a] - 1;
    }
    ix[a] = (int)k;
  }
  return flat(c, ix);
}

void wg_cells_insert(wg_cells *c, long i, long cell)
{
  c->cell[i] = (int32_t)cell;
  c->prev[i] = -1;
  c->next[i] = c->head[cell];
  if (c->head[cell] >= 0) c->prev[c->head[cell]] = (int32_t)i;
  c->head[cell] = (int32_t)i;
}

void wg_cells_remove(wg_cells *c, long i)
{
  if (c->prev[i] >= 0) c->next[c->prev[i]] = c->next[i];
  else c->head[c->cell[i]] = c->next[i];
  if (c->next[i] >= 0) c->prev[c->next[i]] = c->prev[i];
}

void wg_cells_rebuild(wg_cells *c, long n, const double *r, size_t stride)
{
  for (long k = 0; k < c->ncell; k++) c->head[k] = -1;
  /* inserting in reverse keeps each cell's list in increasing particle order */
  for (long i = n - 1; i >= 0; i--)
    wg_cells_insert(c, i, wg_cells_locate(c, r + (size_t)i * stride));
}

long wg_cells_step(const wg_cells *c, long cell, int axis, int dir, int *wrapped)
{
  int ix[3];
  unflat(c, cell, ix);
  ix[axis] += dir;
  *wrapped = 0;
  if (ix[axis] < 0 || ix[axis] >= c->nc[axis]) {
    if (!c->periodic[axis]) return -1;
    *wrapped = dir;
    ix[axis] = ix[axis] < 0 ? c->nc[axis] - 1 : 0;
  }
  return flat(c, ix);
}

/* Cells at offsets lo_off..hi_off per axis around ix, without duplicates: each axis's
   coordinates are wrapped (periodic) or dropped (beyond a wall) once, then combined.  With
   `image`, image[3 m + a] is -1 where cell m lies across the periodic boundary below ix along
   axis a (its grains are a box length too far up: subtract one from r_j - r_i), +1 across the
   one above, else 0. */
static int block(const wg_cells *c, const int *ix, const int *lo_off, const int *hi_off, long *out,
                 int8_t *image)
{
  long coord[3][3];
  int8_t wrap[3][3];
  int count[3];
  long stride[3] = {1, c->nc[0], (long)c->nc[0] * c->nc[1]};
  for (int a = 0; a < 3; a++) {
    count[a] = 0;
    for (int d = lo_off[a]; d <= hi_off[a]; d++) {
      int x = ix[a] + d;
      int8_t w = 0;
      if (x < 0 || x >= c->nc[a]) {
        if (!c->periodic[a]) continue;
        w = x < 0 ? -1 : 1;
        x = x < 0 ? x + c->nc[a] : x - c->nc[a];
      }
      wrap[a][count[a]] = w;
      coord[a][count[a]++] = x * stride[a];
    }
  }
  int m = 0;
  for (int z = 0; z < count[2]; z++)
    for (int y = 0; y < count[1]; y++)
      for (int x = 0; x < count[0]; x++) {
        if (image) {
          image[3 * m] = wrap[0][x];
          image[3 * m + 1] = wrap[1][y];
          image[3 * m + 2] = wrap[2][z];
        }
        out[m++] = coord[0][x] + coord[1][y] + coord[2][z];
      }
  return m;
}

static void stencil_offsets(const wg_cells *c, int *lo_off, int *hi_off)
{
  for (int a = 0; a < 3; a++) {
    lo_off[a] = a < c->dim ? -1 : 0;
    hi_off[a] = a < c->dim ? 1 : 0;
  }
}

int wg_cells_stencil_general(const wg_cells *c, long cell, long *out)
{
  int ix[3], lo_off[3], hi_off[3];
  unflat(c, cell, ix);
  stencil_offsets(c, lo_off, hi_off);
  return block(c, ix, lo_off, hi_off, out, NULL);
}

int wg_cells_stencil_images(const wg_cells *c, long cell, long *out, int8_t *image)
{
  int ix[3], lo_off[3], hi_off[3];
  unflat(c, cell, ix);
  stencil_offsets(c, lo_off, hi_off);
  return block(c, ix, lo_off, hi_off, out, image);
}

static int face_block(const wg_cells *c, long cell, int axis, int dir, long *out, int8_t *image)
{
  int ix[3], lo_off[3], hi_off[3];
  unflat(c, cell, ix);
  stencil_offsets(c, lo_off, hi_off);
  lo_off[axis] = hi_off[axis] = dir;
  return block(c, ix, lo_off, hi_off, out, image);
}

int wg_cells_face_general(const wg_cells *c, long cell, int axis, int dir, long *out)
{
  return face_block(c, cell, axis, dir, out, NULL);
}

int wg_cells_face_images(const wg_cells *c, long cell, int axis, int dir, long *out,
                         int8_t *image)
{
  return face_block(c, cell, axis, dir, out, image);
}

/* Crossing times of a height zb by z(tau) = z0 + v tau - g tau^2 / 2 (g > 0), counted only
   from tau_now on.  Upwards: the earlier root, if not yet passed.  Downwards: the later root. */
static double rise_to(double dz, double v, double g, double tau_now)
{
  double disc = v * v - 2 * g * dz; /* dz = zb - z0 > 0 */
  if (v <= 0 || disc < 0) return INFINITY;
  double tau = 2 * dz / (v + sqrt(disc));
  return tau >= tau_now ? tau : INFINITY;
}

static double fall_to(double dz, double v, double g, double tau_now)
{
  double disc = v * v - 2 * g * dz; /* dz = zb - z0 <= 0 */
  if (disc < 0) disc = 0;
  double tau = (v + sqrt(disc)) / g;
  return tau > tau_now ? tau : tau_now;
}

double wg_cells_exit_time(const wg_cells *c, long cell, const double *r, const double *v,
                          double g, double tau_now, int skip_axis, int skip_dir, int *axis,
                          int *dir)
{
  int ix[3];
  unflat(c, cell, ix);
  double best = INFINITY;
  *axis = 0;
  *dir = 0;
  for (int a = 0; a < c->dim; a++) {
    double lower = c->lo[a] + ix[a] * c->w[a];
    double upper = lower + c->w[a];
    /* Under gravity a grain that came in through the lower face rising leaves through it again
       after turning round: fall_to gives that later root, never the crossing just made, so
       the face stays in. */
    int fall_back = c->turn_back && a == c->dim - 1 && g > 0;
    int has_lower = (c->periodic[a] || ix[a] > 0) && !(a == skip_axis && skip_dir == -1 && !fall_back);
    int has_upper = (c->periodic[a] || ix[a] < c->nc[a] - 1) && !(a == skip_axis && skip_dir == 1);
    double t_up = INFINITY, t_down = INFINITY;
    if (a == c->dim - 1 && g > 0) {
      if (has_upper) t_up = rise_to(upper - r[a], v[a], g, tau_now);
      if (has_lower) t_down = fall_to(lower - r[a], v[a], g, tau_now);
    } else if (v[a] > 0 && has_upper) {
      t_up = (upper - r[a]) / v[a];
      if (t_up < tau_now) t_up = tau_now;
    } else if (v[a] < 0 && has_lower) {
      t_down = (lower - r[a]) / v[a];
      if (t_down < tau_now) t_down = tau_now;
    }
    if (t_up < best) { best = t_up; *axis = a; *dir = 1; }
    if (t_down < best) { best = t_down; *axis = a; *dir = -1; }
  }
  return best;
}
