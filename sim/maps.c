#include "maps.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io_h5.h"
#include "wg.h"

static size_t cells(const wg_map *m) { return (size_t)m->nx * (size_t)m->ny; }

int wg_map_init(wg_map *m, int nx, int ny, int dim, double lx, double ly, double start,
                double window, int samples)
{
  memset(m, 0, sizeof *m);
  if (nx <= 0) return WG_OK;
  *m = (wg_map){.nx = nx, .ny = dim == 3 ? ny : 1, .dim = dim, .lx = lx, .ly = ly,
                .start = start, .window = window, .samples = samples};
  return wg_cellsums_alloc(&m->sums, cells(m), 0);
}

void wg_map_free(wg_map *m)
{
  wg_cellsums_free(&m->sums);
  free(m->time); free(m->density); free(m->bridge_density); free(m->temperature);
  memset(m, 0, sizeof *m);
}

double wg_map_next_time(const wg_map *m)
{
  if (m->nx <= 0) return INFINITY;
  return m->start + (double)m->k * (m->window / m->samples);
}

void wg_map_add(wg_map *m, const double r[3], const double v[3], double mass, int bridges)
{
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
    if (!t || !d || !b || !g) return wg_error(WG_ENOMEM, "maps", "no memory for %ld frames", cap);
    m->cap = cap;
  }
  double area = (m->lx / m->nx) * (m->dim == 3 ? m->ly / m->ny : 1);
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
  } field[3] = {
    {"number_density", "d-2", "d-1", "particles per lateral area (projected along gravity), "
                                     "averaged over the window's samples"},
    {"bridge_density", "d-2", "d-1", "capillary bridges per lateral area, n_cb (half a bridge "
                                     "per particle end), averaged over the window's samples"},
    {"temperature", "m d+2 tau-2", "m d+2 tau-2",
     "granular temperature in the cell: sum m |v - V_cell|^2 / (count D) over the window"},
  };
  const double *data[3] = {m->density, m->bridge_density, m->temperature};
  long long *step = malloc(sizeof(long long) * (size_t)(m->nframes ? m->nframes : 1));
  if (!step) return wg_error(WG_ENOMEM, "run file", "no memory for the maps' steps");
  for (long i = 0; i < m->nframes; i++) step[i] = step_of(clock, m->time[i]);
  hsize_t dv[3] = {(hsize_t)m->nframes, (hsize_t)m->ny, (hsize_t)m->nx};
  if (m->dim == 2) dv[1] = (hsize_t)m->nx;
  hsize_t dt[1] = {(hsize_t)m->nframes};
  int st = WG_OK;
  for (int k = 0; k < 3; k++) {
    char p[128];
    snprintf(p, sizeof p, "/observables/maps/%s/value", field[k].name);
    st |= wg_h5_write(f, p, H5T_NATIVE_DOUBLE, m->dim == 3 ? 3 : 2, dv, data[k],
                      m->dim == 3 ? field[k].unit3 : field[k].unit2, field[k].desc);
    snprintf(p, sizeof p, "/observables/maps/%s/time", field[k].name);
    st |= wg_h5_write(f, p, H5T_NATIVE_DOUBLE, 1, dt, m->time, "tau",
                      "centre of the window (mean of its sample times)");
    snprintf(p, sizeof p, "/observables/maps/%s/step", field[k].name);
    st |= wg_h5_write(f, p, H5T_NATIVE_LLONG, 1, dt, step, "1", WG_H5_STEP_MEANING);
  }
  free(step);
  int n[2] = {m->nx, m->ny};
  st |= wg_h5_attr_ints(f, "/observables/maps", "cells", 2, n);
  st |= wg_h5_attr_double(f, "/observables/maps", "window", m->window);
  st |= wg_h5_attr_llong(f, "/observables/maps", "samples_per_window", m->samples);
  st |= wg_h5_attr_double(f, "/observables/maps", "start", m->start);
  st |= wg_h5_attr_string(f, "/observables/maps", "layout",
                          "value[frame][y cell][x cell] (3D) or value[frame][x cell] (2D); cell "
                          "(i, j) spans x in [i, i + 1) lx / nx, y in [j, j + 1) ly / ny");
  return st;
}

int wg_map_checkpoint_write(const wg_map *m, hid_t f)
{
  if (m->nx <= 0) return WG_OK;
  size_t c = cells(m);
  hsize_t df[1] = {(hsize_t)m->nframes * c}, dt[1] = {(hsize_t)m->nframes};
  long long k[2] = {m->k, m->nframes};
  hsize_t d2[1] = {2};
  int st = wg_cellsums_checkpoint_write(&m->sums, f, "run/map_");
  st |= wg_h5_write(f, "run/map_counters", H5T_NATIVE_LLONG, 1, d2, k, "1", "sample, frames");
  if (m->nframes > 0) {
    st |= wg_h5_write(f, "run/map_time", H5T_NATIVE_DOUBLE, 1, dt, m->time, "tau", "frames");
    st |= wg_h5_write(f, "run/map_density", H5T_NATIVE_DOUBLE, 1, df, m->density, "-", "frames");
    st |= wg_h5_write(f, "run/map_bridge_density", H5T_NATIVE_DOUBLE, 1, df, m->bridge_density, "-", "frames");
    st |= wg_h5_write(f, "run/map_temperature", H5T_NATIVE_DOUBLE, 1, df, m->temperature, "-", "frames");
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
  int st = read_exact(f, path, "run/map_counters", H5T_NATIVE_LLONG, k, 2);
  if (st == WG_OK) st = wg_cellsums_checkpoint_read(&m->sums, f, path, "run/map_");
  if (st != WG_OK) return st;
  m->k = k[0];
  long nf = (long)k[1];
  if (nf > 0) {
    m->cap = nf;
    m->time = malloc(sizeof(double) * (size_t)nf);
    m->density = malloc(sizeof(double) * (size_t)nf * c);
    m->bridge_density = malloc(sizeof(double) * (size_t)nf * c);
    m->temperature = malloc(sizeof(double) * (size_t)nf * c);
    if (!m->time || !m->density || !m->bridge_density || !m->temperature)
      return wg_error(WG_ENOMEM, path, "no memory for %ld map frames", nf);
    hsize_t n = (hsize_t)nf * c;
    st = read_exact(f, path, "run/map_time", H5T_NATIVE_DOUBLE, m->time, (hsize_t)nf);
    if (st == WG_OK) st = read_exact(f, path, "run/map_density", H5T_NATIVE_DOUBLE, m->density, n);
    if (st == WG_OK) st = read_exact(f, path, "run/map_bridge_density", H5T_NATIVE_DOUBLE, m->bridge_density, n);
    if (st == WG_OK) st = read_exact(f, path, "run/map_temperature", H5T_NATIVE_DOUBLE, m->temperature, n);
  }
  m->nframes = nf;
  return st;
}
