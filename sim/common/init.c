#include "init.h"
#include "io_h5.h"

#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>

double wg_init_temperature(const wg_scene *sc)
{
  return sc->tg_init_abs > 0 ? sc->tg_init_abs : sc->tg_init * sc->e_cb;
}

/* Lattice of sites with spacing close to a over the region lo..lo+len: the number of sites
   per axis is chosen as the largest spacing that still gives at least n sites. */
static int lattice_counts(int dim, const double *len, long n, double dmax, int *count)
{
  double volume = 1;
  for (int k = 0; k < dim; k++) volume *= len[k];
  double a = pow(volume / (double)n, 1.0 / dim);
  for (int iter = 0; iter < 10000; iter++, a *= 0.995) {
    long sites = 1;
    for (int k = 0; k < dim; k++) {
      count[k] = (int)floor(len[k] / a);
      if (count[k] < 1) count[k] = 1;
      sites *= count[k];
    }
    if (sites < n) continue;
    for (int k = 0; k < dim; k++)
      if (len[k] / count[k] < dmax * 1.0000001 && !(count[k] == 1 && len[k] >= dmax))
        return wg_error(WG_EINVAL, "initial state",
                        "%ld particles of diameter up to %g do not fit on a lattice in the "
                        "container; lower n or enlarge the box", n, dmax);
    return WG_OK;
  }
  return wg_error(WG_EINVAL, "initial state", "no lattice found for %ld particles", n);
}

/* A packed bed on the floor: rows of disks (hexagonal) or layers of spheres (square layers,
   each shifted by half a spacing onto the hollows of the one below), lateral spacing
   L / floor(L / dmax) >= dmax, filled from the floor up. */
static int packed_bed(const wg_scene *sc, double dmax, wg_particle *p)
{
  int dim = sc->dim, up = dim - 1;
  double len[2] = {sc->lx, sc->ly}, a[2] = {1, 1};
  long per[2] = {1, 1};
  for (int k = 0; k < dim - 1; k++) {
    per[k] = (long)floor(len[k] / (dmax * 1.0000001));
    a[k] = len[k] / (double)per[k];
  }
  double amax = dim == 3 ? fmax(a[0], a[1]) : a[0];
  /* rows touch when their sites are dmax apart: vertical step sqrt(dmax^2 - shift^2) */
  double shift2 = dim == 2 ? 0.25 * a[0] * a[0] : 0.25 * (a[0] * a[0] + a[1] * a[1]);
  double dz = sqrt(fmax(dmax * dmax * 1.000001 - fmin(shift2, 0.5 * amax * amax), 0.0));
  long per_layer = per[0] * per[1], layers = (sc->n + per_layer - 1) / per_layer;
  double top = 0.5 * dmax + (double)(layers - 1) * dz + 0.5 * dmax;
  if (top >= sc->height - 2 * sc->amplitude)
    return wg_error(WG_EINVAL, "initial state",
                    "a packed bed of %ld layers is %.3g high: no room in a container of height %g "
                    "shaken with amplitude %g", layers, top, sc->height, sc->amplitude);
  for (long i = 0; i < sc->n; i++) {
    long layer = i / per_layer, site = i % per_layer;
    long c[2] = {site % per[0], site / per[0]};
    for (int k = 0; k < dim - 1; k++) p[i].r[k] = (c[k] + 0.5 * (layer % 2)) * a[k];
    p[i].r[up] = 0.5 * dmax + (double)layer * dz;
  }
  return WG_OK;
}

static int state_from_run(const wg_scene *sc, wg_particle *p, double *mass)
{
  const char *path = sc->init_from;
  int dim = sc->dim, up = dim - 1, rank, st;
  long n = sc->n;
  hsize_t dims[8];
  hid_t f = wg_h5_open_read(path);
  if (f < 0) return WG_EIO;
  st = wg_h5_dims(f, "/particles/all/position/value", &rank, dims);
  if (st == WG_OK && (rank != 3 || dims[0] < 1 || (long)dims[1] != n || (int)dims[2] != dim))
    st = wg_error(WG_EINVAL, path, "init_from: the last snapshot must hold %ld particles in %dD", n, dim);
  hsize_t last = st == WG_OK ? dims[0] - 1 : 0;
  double *buf = malloc(sizeof *buf * (size_t)n * 3), *t = malloc(sizeof *t * (last + 1));
  double edges[3] = {0, 0, 0}, amp = 0, omega = 0;
  if (st == WG_OK && (!buf || !t)) st = wg_error(WG_ENOMEM, path, "init_from: no memory");
  if (st == WG_OK) st = wg_h5_read(f, "/particles/all/position/time", H5T_NATIVE_DOUBLE, t);
  if (st == WG_OK) st = wg_h5_read(f, "/particles/all/box/edges", H5T_NATIVE_DOUBLE, edges);
  if (st == WG_OK) st = wg_h5_read_param_double(f, "amplitude", &amp);
  if (st == WG_OK) st = wg_h5_read_param_double(f, "omega", &omega);
  double len[2] = {sc->lx, sc->ly};
  for (int k = 0; st == WG_OK && k < up; k++)
    if (fabs(edges[k] - len[k]) > 1e-9 * len[k])
      st = wg_error(WG_EINVAL, path, "init_from: its box is %g d along axis %d, the scene's %g d", edges[k], k, len[k]);
  double shift = amp * sin(omega * t[last]); /* the old floor's position then */
  if (st == WG_OK) st = wg_h5_read_rows(f, "/particles/all/position/value", H5T_NATIVE_DOUBLE, last, 1, buf);
  for (long i = 0; st == WG_OK && i < n; i++)
    for (int k = 0; k < dim; k++) p[i].r[k] = buf[dim * i + k] - (k == up ? shift : 0);
  if (st == WG_OK) st = wg_h5_read_rows(f, "/particles/all/velocity/value", H5T_NATIVE_DOUBLE, last, 1, buf);
  for (long i = 0; st == WG_OK && i < n; i++)
    for (int k = 0; k < dim; k++) p[i].v[k] = buf[dim * i + k];
  if (st == WG_OK && sc->init_jitter > 0) {
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    if (!rng) st = wg_error(WG_ENOMEM, path, "init_jitter: cannot allocate the RNG");
    else {
      gsl_rng_set(rng, (unsigned long)sc->seed);
      for (long i = 0; i < n; i++)
        for (int k = 0; k < dim; k++) p[i].v[k] *= 1 + sc->init_jitter * gsl_ran_gaussian_ziggurat(rng, 1);
      gsl_rng_free(rng);
    }
  }
  if (st == WG_OK) st = wg_h5_read(f, "/particles/all/diameter", H5T_NATIVE_DOUBLE, buf);
  for (long i = 0; st == WG_OK && i < n; i++) {
    p[i].radius = 0.5 * buf[i];
    p[i].t = 0;
    if (wg_scene_walled(sc) &&
        (p[i].r[up] < 0.5 * p[i].radius || p[i].r[up] > sc->height - 0.5 * p[i].radius))
      st = wg_error(WG_EINVAL, path, "init_from: particle %ld (z = %g) is outside the container "
                    "(height %g)", i, p[i].r[up], sc->height);
  }
  if (st == WG_OK && mass) st = wg_h5_read(f, "/particles/all/mass", H5T_NATIVE_DOUBLE, mass);
  free(buf);
  free(t);
  wg_h5_close(f);
  return st;
}

int wg_init_bonds(const wg_scene *sc, int32_t **pairs, long *n_pairs)
{
  const char *path = sc->init_from;
  *pairs = NULL;
  *n_pairs = 0;
  hid_t f = wg_h5_open_read(path);
  if (f < 0) return WG_EIO;
  int rank, st = WG_OK;
  hsize_t dims[8];
  if (!wg_h5_exists(f, "/bridges/offset")) {
    wg_h5_close(f);
    return WG_OK;
  }
  st = wg_h5_dims(f, "/bridges/offset", &rank, dims);
  hsize_t frames = st == WG_OK && dims[0] > 0 ? dims[0] - 1 : 0;
  long long off[2] = {0, 0};
  if (st == WG_OK && frames > 0)
    st = wg_h5_read_rows(f, "/bridges/offset", H5T_NATIVE_LLONG, frames - 1, 2, off);
  long nb = (long)(off[1] - off[0]);
  if (st == WG_OK && nb > 0) {
    *pairs = malloc(sizeof **pairs * 2 * (size_t)nb);
    if (!*pairs) st = wg_error(WG_ENOMEM, path, "init_from: no memory for %ld bridges", nb);
    if (st == WG_OK)
      st = wg_h5_read_rows(f, "/bridges/pairs", H5T_NATIVE_INT32, (hsize_t)off[0], (hsize_t)nb, *pairs);
    for (long k = 0; st == WG_OK && k < 2 * nb; k++)
      if ((*pairs)[k] < 0 || (*pairs)[k] >= sc->n) st = wg_error(WG_EIO, path, "init_from: bridge partner out of range");
    if (st == WG_OK) *n_pairs = nb;
  }
  wg_h5_close(f);
  if (st != WG_OK) {
    free(*pairs);
    *pairs = NULL;
  }
  return st;
}

int wg_init_state(const wg_scene *sc, wg_particle *p, double *mass)
{
  if (sc->init_from[0]) return state_from_run(sc, p, mass);
  int dim = sc->dim, up = dim - 1;
  long n = sc->n;
  double half_width = sqrt(3.0) * sc->sigma_p;
  double dmax = 1 + half_width;
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  if (!rng) return wg_error(WG_ENOMEM, "initial state", "cannot allocate the RNG");
  gsl_rng_set(rng, (unsigned long)sc->seed);

  for (long i = 0; i < n; i++) {
    double d = 1 + half_width * (2 * gsl_rng_uniform(rng) - 1); /* Eq. 2.21 */
    p[i].radius = 0.5 * d;
    p[i].t = 0;
    if (mass) mass[i] = pow(d, dim);
  }

  /* Sites fill the box; in a shaker they keep half the largest diameter from the walls. */
  double lo[3] = {0, 0, 0}, len[3] = {sc->lx, dim == 3 ? sc->ly : sc->height, sc->height};
  int periodic_z = sc->container == WG_CONTAINER_PERIODIC;
  if (!periodic_z) {
    lo[up] = 0.5 * dmax;
    len[up] = sc->height - dmax;
  }
  int count[3];
  int st = sc->init_packing ? packed_bed(sc, dmax, p) : lattice_counts(dim, len, n, dmax, count);
  if (st != WG_OK) {
    gsl_rng_free(rng);
    return st;
  }
  for (long i = 0; !sc->init_packing && i < n; i++) {
    long rest = i;
    for (int k = 0; k < dim; k++) {
      long c = rest % count[k];
      rest /= count[k];
      double spacing = (!periodic_z && k == up && count[k] > 1) ? len[k] / (count[k] - 1)
                                                                 : len[k] / count[k];
      double offset = (!periodic_z && k == up) ? 0 : 0.5 * spacing;
      p[i].r[k] = lo[k] + offset + c * spacing;
      if (!periodic_z && k == up && count[k] == 1) p[i].r[k] = lo[k] + 0.5 * len[k];
    }
  }

  double T = wg_init_temperature(sc);
  double msum = 0, vcm[3] = {0, 0, 0};
  for (long i = 0; i < n; i++) {
    double m = mass ? mass[i] : 1.0;
    for (int k = 0; k < dim; k++) {
      p[i].v[k] = gsl_ran_gaussian(rng, sqrt(T / m));
      vcm[k] += m * p[i].v[k];
    }
    msum += m;
  }
  gsl_rng_free(rng);
  if (n > 1)
    for (int k = 0; k < dim; k++) vcm[k] /= msum;
  else
    vcm[0] = vcm[1] = vcm[2] = 0;
  double sum2 = 0;
  for (long i = 0; i < n; i++) {
    double m = mass ? mass[i] : 1.0;
    for (int k = 0; k < dim; k++) {
      p[i].v[k] -= vcm[k];
      sum2 += m * p[i].v[k] * p[i].v[k];
    }
  }
  double T_now = sum2 / (double)(n * dim); /* Eq. 3.2 */
  double scale = T_now > 0 ? sqrt(T / T_now) : 0;
  for (long i = 0; i < n; i++)
    for (int k = 0; k < dim; k++) p[i].v[k] *= scale;
  return WG_OK;
}
