/* Cell grid for neighbour search: cells at least one interaction range wide, particles in
   doubly linked lists per cell.  Axis dim-1 is the vertical; it is periodic only in a
   periodic container, otherwise its outermost cells extend to the walls' reach. */
#ifndef WG_CELLS_H
#define WG_CELLS_H

#include "wg.h"

typedef struct wg_cells {
  int dim;
  int nc[3];          /* cells per axis */
  double lo[3];       /* lower edge of the grid [d] */
  double len[3];      /* extent of the grid along each axis [d] */
  double w[3];        /* cell width per axis, >= the interaction range [d] */
  int periodic[3];
  long ncell;
  int32_t *head;      /* first particle of each cell, -1 when empty */
  int32_t *next, *prev; /* lists through the particles */
  int32_t *cell;      /* cell of each particle */
  uint8_t *interior;  /* 1 where the whole stencil lies inside the grid without wrapping */
  long stencil_offset[27]; /* flat offsets of the stencil of an interior cell */
  int stencil_size;
  long face_offset[3][2][9]; /* [axis][dir > 0] flat offsets of the face layer */
  int face_size;
  /* 1: a particle that came in rising against gravity leaves through that face again after its
     apex (wg_cells_exit_time).  0 (wg_cells_alloc's default): the face entered is left out for
     good, so a particle that turns round inside a cell keeps it until its next event -- the
     behaviour of engine version c450a5b3a17e0edb, a known defect (docs/engines.md, "Cell
     crossings under gravity") kept until the archived figures are checked without it. */
  int turn_back;
  /* 1 when every periodic axis has >= 5 cells: then the nearest image of a grain in the
     stencil is the one of its cell (wg_cells_stencil_images) with a margin of half a cell,
     so a separation needs no minimum-image test of its own */
  int images_exact;
} wg_cells;

/* The grid over [lo, lo + len) with cells of width >= range; periodic axes need >= 3 cells. */
int wg_cells_alloc(wg_cells *c, int dim, const double *lo, const double *len,
                   const int *periodic, double range, long n);
void wg_cells_free(wg_cells *c);

/* Cell containing position r (wrapped on periodic axes, clamped on the others). */
long wg_cells_locate(const wg_cells *c, const double *r);
void wg_cells_insert(wg_cells *c, long i, long cell);
void wg_cells_remove(wg_cells *c, long i);
/* Index of `cell` along one axis (0 .. nc[axis] - 1). */
int wg_cells_coord(const wg_cells *c, long cell, int axis);

/* Empty all cells and insert particles 0..n-1 at their positions (deterministic order). */
void wg_cells_rebuild(wg_cells *c, long n, const double *r, size_t stride);

/* Index of the cell one step along axis (dir = +1/-1), or -1 past a non-periodic edge;
   *wrapped is set to +1/-1 when the step crosses a periodic boundary upwards/downwards. */
long wg_cells_step(const wg_cells *c, long cell, int axis, int dir, int *wrapped);

/* The 3^dim cells around a cell (itself included, duplicates and out-of-grid cells left
   out); returns their number. */
int wg_cells_stencil_general(const wg_cells *c, long cell, long *out);
static inline int wg_cells_stencil(const wg_cells *c, long cell, long *out)
{
  if (!c->interior[cell]) return wg_cells_stencil_general(c, cell, out);
  for (int k = 0; k < c->stencil_size; k++) out[k] = cell + c->stencil_offset[k];
  return c->stencil_size;
}
/* The stencil (cells as wg_cells_stencil_general) and each cell's periodic image:
   image[3 k + a] (-1, 0, +1) times the box length along axis a is to be added to a separation
   r_j - r_i for the grains j of cell out[k].  Exact (the minimum image) when images_exact and
   every grain lies in its cell. */
int wg_cells_stencil_images(const wg_cells *c, long cell, long *out, int8_t *image);
/* The 3^(dim-1) cells of the stencil's face one layer beyond cell along axis/dir: the cells
   that join the stencil when a particle has just stepped into `cell` moving along axis/dir. */
int wg_cells_face_general(const wg_cells *c, long cell, int axis, int dir, long *out);
/* The face with its cells' periodic images, as wg_cells_stencil_images. */
int wg_cells_face_images(const wg_cells *c, long cell, int axis, int dir, long *out,
                         int8_t *image);
static inline int wg_cells_face(const wg_cells *c, long cell, int axis, int dir, long *out)
{
  if (!c->interior[cell]) return wg_cells_face_general(c, cell, axis, dir, out);
  const long *off = c->face_offset[axis][dir > 0];
  for (int k = 0; k < c->face_size; k++) out[k] = cell + off[k];
  return c->face_size;
}

/* The stencil, or (axis >= 0) the face of wg_cells_face, with the periodic images of its
   cells in `image` (three per cell: 3 x 27, or 3 x 9 for a face).  *images is NULL for an
   interior cell, whose stencil crosses no boundary, else image. */
static inline int wg_cells_imaged(const wg_cells *c, long cell, int axis, int dir, long *out,
                                  int8_t *image, const int8_t **images)
{
  if (c->interior[cell]) {
    *images = NULL;
    return axis < 0 ? wg_cells_stencil(c, cell, out) : wg_cells_face(c, cell, axis, dir, out);
  }
  *images = image;
  return axis < 0 ? wg_cells_stencil_images(c, cell, out, image)
                  : wg_cells_face_images(c, cell, axis, dir, out, image);
}

/* Time, counted from the particle's reference point r, v (gravity g along -axis dim-1), at
   which it leaves `cell`, not earlier than tau_now; *axis and *dir tell through which face.
   The face (skip_axis, skip_dir) is left out (skip_axis = -1: none): the one just crossed,
   so that a particle grazing a face at the top of its flight does not cross back and forth --
   except, with c->turn_back, the lower face along gravity, which a particle that came in
   rising leaves through again after its apex (the later root).  INFINITY if never. */
double wg_cells_exit_time(const wg_cells *c, long cell, const double *r, const double *v,
                          double g, double tau_now, int skip_axis, int skip_dir, int *axis,
                          int *dir);

#endif
