#include "maps.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io_h5.h"
#include "wg.h"

static size_t cells(const wg_map *m) { return (size_t)m->nx * (size_t)m->ny; }
static int height(const wg_map *m) { return m->kind == WG_MAP_HEIGHT; }

int wg_map_init(wg_map *m, int nx, int ny, int dim, double lx, double ly, double start,
                double window, int samples)
{
  memset(m, 0, sizeof *m);
  if (nx <= 0) return WG_OK;
  *m = (wg_map){.kind = WG_MAP_LATERAL, .nx = nx, .ny = dim == 3 ? ny : 1, .dim = dim,
                .lx = lx, .ly = ly, .start = start, .window = window, .samples = samples};
  return wg_cellsums_alloc(&m->sums, cells(m), 0);
}

int wg_map_init_height(wg_map *m, int nx, int dim, double lx, double ly, double z0,
                       double span, double start, double window, int samples)
{
  memset(m, 0, sizeof *m);
  if (nx <= 0) return WG_OK;
  *m = (wg_map){.kind = WG_MAP_HEIGHT, .nx = nx, .ny = 1, .dim = dim, .lx = lx, .ly = ly,
                .z0 = z0, .span = span, .start = start, .window = window, .samples = samples};
  return wg_cellsums_alloc(&m->sums, cells(m), 1);
}

void wg_map_free(wg_map *m)
{
  wg_cellsums_free(&m->sums);
  free(m->time); free(m->density); free(m->bridge_density); free(m->temperature);
  free(m->packing);
  memset(m, 0, sizeof *m);
}

double wg_map_next_time(const wg_map *m)
{
  if (m->nx <= 0) return INFINITY;
  return m->start + (double)m->k * (m->window / m->samples);
}

/* Volume (3D) or area (2D) of a grain of radius a below height u above its centre
   (-a <= u <= a): a spherical cap, pi (a + u)^2 (2a - u) / 3, or a circular segment,
   a^2 acos(-u/a) + u sqrt(a^2 - u^2). */
static double volume_below(int dim, double a, double u)
{
  if (u <= -a) return 0;
  if (u >= a) u = a;
  if (dim == 3) return M_PI * (a + u) * (a + u) * (2 * a - u) / 3;
  return a * a * acos(-u / a) + u * sqrt(a * a - u * u);
}

/* A grain at height z: its centre's slab gets the count, momentum and bridges, every slab it
   cuts its slice of the volume (slices outside z0 ... z0 + span are dropped). */
static void add_height(wg_map *m, double z, const double v[3], double mass, double radius,
                       int bridges)
{
  double w = m->span / m->nx;
  int c = (int)floor((z - m->z0) / w);
  if (c >= 0 && c < m->nx) wg_cellsums_add(&m->sums, (size_t)c, m->dim, v, mass, 0, bridges);
  int lo = (int)floor((z - radius - m->z0) / w), hi = (int)floor((z + radius - m->z0) / w);
  if (lo < 0) lo = 0;
  if (hi >= m->nx) hi = m->nx - 1;
  double below = volume_below(m->dim, radius, m->z0 + lo * w - z);
  for (int k = lo; k <= hi; k++) {
    double above = volume_below(m->dim, radius, m->z0 + (k + 1) * w - z);
    m->sums.volume[k] += above - below;
    below = above;
  }
}

void wg_map_add(wg_map *m, const double r[3], const double v[3], double mass, double radius,
                int bridges)
{
  if (height(m)) {
    add_height(m, r[m->dim - 1], v, mass, radius, bridges);
    return;
  }
  int bx = (int)(r[0] / m->lx * m->nx), by = 0;
  if (bx >= m->nx) bx = m->nx - 1;
  if (bx < 0) bx = 0;
  if (m->dim == 3) {
    by = (int)(r[1] / m->ly * m->ny);
    if (by >= m->ny) by = m->ny - 1;
    if (by < 0) by = 0;
  }
  wg_cellsums_add(&m->sums, (size_t)by * (size_t)m->nx + (size_t)bx, m->dim, v, mass, 0, bridges);
}

/* Close the open window: its fields become a frame, its sums start again from zero. */
static int flush_window(wg_map *m)
{
  size_t c = cells(m);
  if (m->nframes == m->cap) {
    long cap = m->cap ? 2 * m->cap : 16;
    double *t = realloc(m->time, sizeof(double) * (size_t)cap);
    if (t) m->time = t;
    double *d = realloc(m->density, sizeof(double) * (size_t)cap * c);
    if (d) m->density = d;
    double *b = realloc(m->bridge_density, sizeof(double) * (size_t)cap * c);
    if (b) m->bridge_density = b;
    double *g = realloc(m->temperature, sizeof(double) * (size_t)cap * c);
    if (g) m->temperature = g;
    double *q = height(m) ? realloc(m->packing, sizeof(double) * (size_t)cap * c) : NULL;
    if (q) m->packing = q;
    if (!t || !d || !b || !g || (height(m) && !q))
      return wg_error(WG_ENOMEM, "maps", "no memory for %ld frames", cap);
    m->cap = cap;
  }
  /* a lateral cell's area, or a slab's volume (its width times the lateral area) */
  double lateral = m->dim == 3 ? m->lx * m->ly : m->lx;
  double area = height(m) ? m->span / m->nx * lateral
                          : (m->lx / m->nx) * (m->dim == 3 ? m->ly / m->ny : 1);
  double norm = 1.0 / (m->samples * area);
  size_t o = (size_t)m->nframes * c;
  long long w = m->k / m->samples - 1; /* the window just completed */
  double dts = m->window / m->samples;
  m->time[m->nframes] = m->start + ((double)w * m->samples + 0.5 * (m->samples - 1)) * dts;
  const wg_cellsums *u = &m->sums;
  for (size_t i = 0; i < c; i++) {
    m->density[o + i] = u->count[i] * norm;
    m->bridge_density[o + i] = u->bridges[i] * norm;
    m->temperature[o + i] = wg_cellsums_temperature(u, i, m->dim);
    if (height(m)) m->packing[o + i] = u->volume[i] * norm;
  }
  m->nframes++;
  wg_cellsums_clear(&m->sums);
  return WG_OK;
}

int wg_map_end_sample(wg_map *m)
{
  m->k++;
  return m->k % m->samples == 0 ? flush_window(m) : WG_OK;
}

int wg_map_write(const wg_map *m, hid_t f, long long (*step_of)(const void *, double),
                 const void *clock)
{
  if (m->nx <= 0) return WG_OK;
  static const struct {
    const char *name, *unit3, *unit2, *desc;
  } lateral[3] = {
    {"number_density", "d-2", "d-1", "particles per lateral area (projected along gravity), "
                                     "averaged over the window's samples"},
    {"bridge_density", "d-2", "d-1", "capillary bridges per lateral area, n_cb (half a bridge "
                                     "per particle end), averaged over the window's samples"},
    {"temperature", "m d+2 tau-2", "m d+2 tau-2",
     "granular temperature in the cell: sum m |v - V_cell|^2 / (count D) over the window"},
  }, slab[4] = {
    {"number_density", "d-3", "d-2", "particles (by centre) per slab volume, averaged over the "
                                     "window's samples"},
    {"bridge_density", "d-3", "d-2", "capillary bridges per slab volume (half a bridge per "
                                     "particle end, by centre), averaged over the window's samples"},
    {"temperature", "m d+2 tau-2", "m d+2 tau-2",
     "granular temperature in the slab: sum m |v - V_slab|^2 / (count D) over the window"},
    {"packing_fraction", "1", "1", "fraction of the slab's volume (2D: area) inside grains, "
                                   "averaged over the window's samples"},
  };
  const char *group = height(m) ? "/observables/heights" : "/observables/maps";
  int nfield = height(m) ? 4 : 3;
  const double *data[4] = {m->density, m->bridge_density, m->temperature, m->packing};
  long long *step = malloc(sizeof(long long) * (size_t)(m->nframes ? m->nframes : 1));
  if (!step) return wg_error(WG_ENOMEM, "run file", "no memory for the maps' steps");
  for (long i = 0; i < m->nframes; i++) step[i] = step_of(clock, m->time[i]);
  hsize_t dv[3] = {(hsize_t)m->nframes, (hsize_t)m->ny, (hsize_t)m->nx};
  int rank = m->dim == 3 && !height(m) ? 3 : 2;
  if (rank == 2) dv[1] = (hsize_t)m->nx;
  hsize_t dt[1] = {(hsize_t)m->nframes};
  int st = WG_OK;
  for (int k = 0; k < nfield; k++) {
    const char *name = height(m) ? slab[k].name : lateral[k].name;
    const char *unit = height(m) ? (m->dim == 3 ? slab[k].unit3 : slab[k].unit2)
                                 : (m->dim == 3 ? lateral[k].unit3 : lateral[k].unit2);
    char p[128];
    snprintf(p, sizeof p, "%s/%s/value", group, name);
    st |= wg_h5_write(f, p, H5T_NATIVE_DOUBLE, rank, dv, data[k], unit,
                      height(m) ? slab[k].desc : lateral[k].desc);
    snprintf(p, sizeof p, "%s/%s/time", group, name);
    st |= wg_h5_write(f, p, H5T_NATIVE_DOUBLE, 1, dt, m->time, "tau",
                      "centre of the window (mean of its sample times)");
    snprintf(p, sizeof p, "%s/%s/step", group, name);
    st |= wg_h5_write(f, p, H5T_NATIVE_LLONG, 1, dt, step, "1", WG_H5_STEP_MEANING);
  }
  free(step);
  int n[2] = {m->nx, m->ny};
  st |= wg_h5_attr_ints(f, group, "cells", height(m) ? 1 : 2, n);
  st |= wg_h5_attr_double(f, group, "window", m->window);
  st |= wg_h5_attr_llong(f, group, "samples_per_window", m->samples);
  st |= wg_h5_attr_double(f, group, "start", m->start);
  if (height(m)) {
    st |= wg_h5_attr_double(f, group, "z0", m->z0);
    st |= wg_h5_attr_double(f, group, "span", m->span);
    st |= wg_h5_attr_string(f, group, "layout",
                            "value[frame][slab]; slab k spans z in [z0 + k span / n, z0 + (k + 1) "
                            "span / n), z the lab frame's height (the floor at rest is z = 0)");
  } else {
    st |= wg_h5_attr_string(f, group, "layout",
                            "value[frame][y cell][x cell] (3D) or value[frame][x cell] (2D); cell "
                            "(i, j) spans x in [i, i + 1) lx / nx, y in [j, j + 1) ly / ny");
  }
  return st;
}

/* checkpoint datasets run/<prefix>...: map_ (lateral) or height_ */
static void ckname(const wg_map *m, char *buf, size_t size, const char *what)
{
  snprintf(buf, size, "run/%s%s", height(m) ? "height_" : "map_", what);
}

int wg_map_checkpoint_write(const wg_map *m, hid_t f)
{
  if (m->nx <= 0) return WG_OK;
  size_t c = cells(m);
  hsize_t df[1] = {(hsize_t)m->nframes * c}, dt[1] = {(hsize_t)m->nframes};
  long long k[2] = {m->k, m->nframes};
  hsize_t d2[1] = {2};
  char p[64];
  ckname(m, p, sizeof p, "");
  int st = wg_cellsums_checkpoint_write(&m->sums, f, p);
  ckname(m, p, sizeof p, "counters");
  st |= wg_h5_write(f, p, H5T_NATIVE_LLONG, 1, d2, k, "1", "sample, frames");
  if (m->nframes > 0) {
    const char *name[5] = {"time", "density", "bridge_density", "temperature", "packing"};
    const double *data[5] = {m->time, m->density, m->bridge_density, m->temperature, m->packing};
    for (int i = 0; i < (height(m) ? 5 : 4); i++) {
      ckname(m, p, sizeof p, name[i]);
      st |= wg_h5_write(f, p, H5T_NATIVE_DOUBLE, 1, i ? df : dt, data[i], i ? "-" : "tau", "frames");
    }
  }
  return st;
}

static int read_exact(hid_t f, const char *ckpt, const char *path, hid_t type, void *buf,
                      hsize_t expect)
{
  int rank;
  hsize_t dims[8], total = 1;
  if (wg_h5_dims(f, path, &rank, dims) != WG_OK)
    return wg_error(WG_EIO, ckpt, "dataset %s missing (a checkpoint without maps?)", path);
  for (int i = 0; i < rank; i++) total *= dims[i];
  if (total != expect)
    return wg_error(WG_EIO, ckpt, "dataset %s has %llu values, expected %llu", path,
                    (unsigned long long)total, (unsigned long long)expect);
  return wg_h5_read(f, path, type, buf);
}

int wg_map_checkpoint_read(wg_map *m, hid_t f, const char *path)
{
  if (m->nx <= 0) return WG_OK;
  size_t c = cells(m);
  long long k[2];
  char p[64];
  ckname(m, p, sizeof p, "counters");
  int st = read_exact(f, path, p, H5T_NATIVE_LLONG, k, 2);
  ckname(m, p, sizeof p, "");
  if (st == WG_OK) st = wg_cellsums_checkpoint_read(&m->sums, f, path, p);
  if (st != WG_OK) return st;
  m->k = k[0];
  long nf = (long)k[1];
  if (nf > 0) {
    const char *name[5] = {"time", "density", "bridge_density", "temperature", "packing"};
    double **data[5] = {&m->time, &m->density, &m->bridge_density, &m->temperature, &m->packing};
    m->cap = nf;
    for (int i = 0; i < (height(m) ? 5 : 4) && st == WG_OK; i++) {
      hsize_t n = i ? (hsize_t)nf * c : (hsize_t)nf;
      if (!(*data[i] = malloc(sizeof(double) * n)))
        return wg_error(WG_ENOMEM, path, "no memory for %ld map frames", nf);
      ckname(m, p, sizeof p, name[i]);
      st = read_exact(f, path, p, H5T_NATIVE_DOUBLE, *data[i], n);
    }
  }
  m->nframes = nf;
  return st;
}
