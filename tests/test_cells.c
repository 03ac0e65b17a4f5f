/* The cell grid's stencils (sim/common/cells.c) against brute force: the stencil of every
   cell holds exactly the cells whose grains can lie within one cell width of its own along
   every axis, each once; and the periodic image that wg_cells_stencil_images and
   wg_cells_face_images give a cell is the minimum image of every separation to a grain in
   it, bit for bit (the event-driven engine then skips the minimum-image test of each pair).
   Grids from the smallest allowed (5 cells along a periodic axis) up, mixed periodic and
   walled axes, 2D and 3D; separations drawn at random in the cells and at their corners. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cells.h"
#include "tharness.h"

static unsigned long long rng_state = 0x9E3779B97F4A7C15ULL;
static double uniform(void)
{
  rng_state ^= rng_state << 13;
  rng_state ^= rng_state >> 7;
  rng_state ^= rng_state << 17;
  return (double)(rng_state >> 11) * 0x1.0p-53;
}

static double min_image(double x, double len)
{
  if (x > 0.5 * len) return x - len;
  if (x < -0.5 * len) return x + len;
  return x;
}

/* A point of cell `cell` (corner: one of its corners, else uniform inside). */
static void point_in(const wg_cells *c, long cell, int corner, double *r)
{
  long k = cell;
  for (int a = 0; a < 3; a++) {
    int ix = (int)(k % c->nc[a]);
    k /= c->nc[a];
    double f = corner >= 0 ? (double)((corner >> a) & 1) : uniform();
    r[a] = a < c->dim ? c->lo[a] + (ix + f) * c->w[a] : 0;
    if (a < c->dim && r[a] >= c->lo[a] + c->len[a]) r[a] = nextafter(c->lo[a] + c->len[a], 0);
  }
}

/* Brute force: the cells within one step of `cell` along every axis (wrapped or clipped). */
static int brute_neighbour(const wg_cells *c, long cell, long other)
{
  long a0 = cell, b0 = other;
  for (int a = 0; a < 3; a++) {
    int ia = (int)(a0 % c->nc[a]), ib = (int)(b0 % c->nc[a]);
    a0 /= c->nc[a];
    b0 /= c->nc[a];
    int d = abs(ia - ib);
    if (c->periodic[a] && d == c->nc[a] - 1) d = 1;
    if (d > 1) return 0;
  }
  return 1;
}

/* Every grain pair (i in cell, j in out[k]) gets the image image[3k..]: check on draws. */
static int check_images(const wg_cells *c, long cell, const long *out, const int8_t *image,
                        int m, double *worst)
{
  int bad = 0;
  for (int k = 0; k < m; k++)
    for (int draw = -1; draw < 8; draw++)
      for (int trial = 0; trial < (draw < 0 ? 4 : 1); trial++) {
        double ri[3], rj[3];
        point_in(c, cell, draw < 0 ? -1 : draw, ri);
        point_in(c, out[k], draw < 0 ? -1 : 7 - draw, rj);
        for (int a = 0; a < c->dim; a++) {
          double x = rj[a] - ri[a];
          double imaged = x + image[3 * k + a] * c->len[a];
          double nearest = c->periodic[a] ? min_image(x, c->len[a]) : x;
          if (memcmp(&imaged, &nearest, sizeof imaged) != 0 && !(imaged == 0 && nearest == 0))
            bad++;
          double margin = 0.5 * c->len[a] - fabs(imaged);
          if (c->periodic[a] && margin < *worst) *worst = margin;
          if (!c->periodic[a] && image[3 * k + a] != 0) bad++;
        }
      }
  return bad;
}

static void check_grid(int dim, const int *nc, const int *periodic)
{
  double lo[3] = {-2.5, 0.25, 1}, len[3], range = 1.1;
  for (int a = 0; a < 3; a++) len[a] = nc[a] * range * 1.03;
  wg_cells c;
  long n = 1;
  TH_CHECK(wg_cells_alloc(&c, dim, lo, len, periodic, range, n) == WG_OK, "grid allocated");
  long out[27];
  int8_t image[3 * 27];
  int missing = 0, extra = 0, twice = 0, bad = 0, faces_bad = 0;
  double worst = INFINITY;
  for (long cell = 0; cell < c.ncell; cell++) {
    int m = wg_cells_stencil_images(&c, cell, out, image);
    long plain[27];
    int mp = wg_cells_stencil(&c, cell, plain);
    if (mp != m) bad++;
    for (int k = 0; k < m && k < mp; k++)
      if (plain[k] != out[k]) bad++;
    int count = 0;
    for (long other = 0; other < c.ncell; other++) {
      int seen = 0;
      for (int k = 0; k < m; k++) seen += out[k] == other;
      int want = brute_neighbour(&c, cell, other);
      if (want && seen == 0) missing++;
      if (!want && seen) extra++;
      if (seen > 1) twice++;
      count += want;
    }
    if (count != m) bad++;
    bad += check_images(&c, cell, out, image, m, &worst);
    for (int axis = 0; axis < dim; axis++)
      for (int dir = -1; dir <= 1; dir += 2) {
        long face[9], plain_face[9];
        int8_t fimage[3 * 9];
        int mf = wg_cells_face_images(&c, cell, axis, dir, face, fimage);
        int mpf = wg_cells_face(&c, cell, axis, dir, plain_face);
        if (mf != mpf) faces_bad++;
        for (int k = 0; k < mf && k < mpf; k++)
          if (face[k] != plain_face[k]) faces_bad++;
        faces_bad += check_images(&c, cell, face, fimage, mf, &worst);
      }
  }
  TH_CHECK(missing == 0 && extra == 0 && twice == 0 && bad == 0,
           "%dD grid %d x %d x %d (periodic %d%d%d): every stencil is its neighbours, each once, and "
           "its images are the minimum images (missing %d, extra %d, twice %d, wrong %d)",
           dim, nc[0], nc[1], nc[2], periodic[0], periodic[1], periodic[2], missing, extra, twice,
           bad);
  TH_CHECK(faces_bad == 0, "  the faces' cells and images agree with the stencil's (%d wrong)",
           faces_bad);
  TH_CHECK(c.images_exact == 1 && worst >= 0.5 * range,
           "  images_exact, and every stencil separation is >= half a cell (%.3f) short of half "
           "the box: %.3f", 0.5 * range, worst);
  wg_cells_free(&c);
}

int main(void)
{
  check_grid(3, (int[]){5, 5, 5}, (int[]){1, 1, 1});
  check_grid(3, (int[]){6, 7, 5}, (int[]){1, 1, 1});
  check_grid(3, (int[]){7, 5, 6}, (int[]){1, 0, 0});
  check_grid(3, (int[]){5, 6, 3}, (int[]){1, 1, 0});
  check_grid(2, (int[]){9, 5, 1}, (int[]){1, 0, 0});
  check_grid(2, (int[]){5, 6, 1}, (int[]){1, 1, 0});

  /* fewer than 5 cells along a periodic axis: a stencil separation can reach half the box,
     where the cell's image and the nearest image part; the engine then tests each pair */
  double lo[3] = {0, 0, 0}, len[3] = {4.4, 8, 8};
  wg_cells c;
  TH_CHECK(wg_cells_alloc(&c, 3, lo, len, (int[]){1, 1, 1}, 1.1, 1) == WG_OK && c.images_exact == 0,
           "4 cells along a periodic axis: images_exact = 0");
  wg_cells_free(&c);
  return th_summary();
}
