/* The advective Cahn-Hilliard solver (ch.h): pseudo-spectral, FFTW's half-complex Fourier
   series along x and DCT-II (REDFT10, inverse REDFT01) along z. */
#include "ch.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const double pi = 3.14159265358979323846;

static double f_prime(const wg_ch_params *p, double c) { return p->K * c * (c - 1) * (c - p->c_o); }
static double f_bulk(const wg_ch_params *p, double c)
{
  return p->K * (p->c_o * c * c / 2 - (1 + p->c_o) * c * c * c / 3 + c * c * c * c / 4); /* Eq. 3 */
}

/* x frequency of half-complex index ix: ix <= nx/2 holds the real part of frequency ix, the
   others the imaginary part of frequency nx - ix (FFTW's R2HC layout) */
static int x_freq(int nx, int ix) { return ix <= nx / 2 ? ix : nx - ix; }

int wg_ch_init(wg_ch *s, const wg_ch_params *p)
{
  memset(s, 0, sizeof *s);
  s->p = *p;
  size_t n = (size_t)p->nx * (size_t)p->nz;
  s->c = fftw_malloc(sizeof(double) * n);
  s->hat = fftw_malloc(sizeof(double) * n);
  s->work = fftw_malloc(sizeof(double) * n);
  s->work2 = fftw_malloc(sizeof(double) * n);
  s->fp = malloc(sizeof(double) * n);
  s->adv = malloc(sizeof(double) * n);
  s->k2 = malloc(sizeof(double) * n);
  s->kx = malloc(sizeof(double) * (size_t)p->nx);
  if (!s->c || !s->hat || !s->work || !s->work2 || !s->fp || !s->adv || !s->k2 || !s->kx) {
    wg_ch_free(s);
    return 1;
  }
  /* FFTW_ESTIMATE: the plan, hence the rounding, does not depend on timing measurements, so
     the same parameters give the same bytes */
  s->fwd = fftw_plan_r2r_2d(p->nx, p->nz, s->work, s->work2, FFTW_R2HC, FFTW_REDFT10, FFTW_ESTIMATE);
  s->bwd = fftw_plan_r2r_2d(p->nx, p->nz, s->work, s->work2, FFTW_HC2R, FFTW_REDFT01, FFTW_ESTIMATE);
  if (!s->fwd || !s->bwd) {
    wg_ch_free(s);
    return 1;
  }
  s->norm = 1.0 / (2.0 * p->nx * p->nz);
  for (int ix = 0; ix < p->nx; ix++) {
    int f = x_freq(p->nx, ix);
    /* the Nyquist frequency (even nx) has no imaginary partner: its derivative is dropped */
    s->kx[ix] = (2 * f == p->nx) ? 0 : 2 * pi * f / p->lx;
    for (int iz = 0; iz < p->nz; iz++) {
      double kx = 2 * pi * f / p->lx, kz = pi * iz / p->lz;
      s->k2[(size_t)ix * p->nz + iz] = kx * kx + kz * kz;
    }
  }
  return 0;
}

void wg_ch_free(wg_ch *s)
{
  if (s->fwd) fftw_destroy_plan(s->fwd);
  if (s->bwd) fftw_destroy_plan(s->bwd);
  fftw_free(s->c);
  fftw_free(s->hat);
  fftw_free(s->work);
  fftw_free(s->work2);
  free(s->fp);
  free(s->adv);
  free(s->k2);
  free(s->kx);
  memset(s, 0, sizeof *s);
}

/* work2 = spectral coefficients of work */
static void forward(wg_ch *s) { fftw_execute(s->fwd); }
/* work2 = real values of the coefficients in work, normalised */
static void backward(wg_ch *s)
{
  fftw_execute(s->bwd);
  size_t n = (size_t)s->p.nx * s->p.nz;
  for (size_t k = 0; k < n; k++) s->work2[k] *= s->norm;
}

/* d/dx of the coefficients in `in`, into `out` (half-complex pairs along x) */
static void d_dx(const wg_ch *s, const double *in, double *out)
{
  int nx = s->p.nx, nz = s->p.nz;
  for (int ix = 0; ix < nx; ix++) {
    int f = x_freq(nx, ix);
    for (int iz = 0; iz < nz; iz++) {
      size_t k = (size_t)ix * nz + iz;
      if (f == 0 || s->kx[ix] == 0) { out[k] = 0; continue; }
      /* (re + i im) i kx = -kx im + i kx re */
      if (ix <= nx / 2) out[k] = -s->kx[ix] * in[(size_t)(nx - ix) * nz + iz];
      else out[k] = s->kx[ix] * in[(size_t)(nx - ix) * nz + iz];
    }
  }
}

/* hat = c's coefficients, transformed only when c was set anew */
static void coefficients(wg_ch *s)
{
  if (s->hat_valid) return;
  size_t n = (size_t)s->p.nx * s->p.nz;
  memcpy(s->work, s->c, sizeof(double) * n);
  forward(s);
  memcpy(s->hat, s->work2, sizeof(double) * n);
  s->hat_valid = 1;
}

void wg_ch_step(wg_ch *s)
{
  const wg_ch_params *p = &s->p;
  size_t n = (size_t)p->nx * p->nz;
  double dt = p->dt, M = p->mobility;
  int advect = p->shear != 0 && p->nx > 1;
  coefficients(s); /* after a step hat is c's already: one transform saved per step */
  for (size_t k = 0; k < n; k++) s->work[k] = f_prime(p, s->c[k]);
  forward(s);
  memcpy(s->fp, s->work2, sizeof(double) * n);
  if (advect) { /* u . grad c = shear (z - lz/2) dc/dx, made in real space */
    d_dx(s, s->hat, s->work);
    backward(s);
    for (int ix = 0; ix < p->nx; ix++)
      for (int iz = 0; iz < p->nz; iz++) {
        size_t k = (size_t)ix * p->nz + iz;
        s->work[k] = p->shear * ((iz + 0.5) * p->lz / p->nz - 0.5 * p->lz) * s->work2[k];
      }
    forward(s);
    memcpy(s->adv, s->work2, sizeof(double) * n);
  }
  for (size_t k = 0; k < n; k++) {
    double k2 = s->k2[k];
    double rhs = s->hat[k] * (1 + dt * M * p->S * k2) - dt * M * k2 * s->fp[k] - (advect ? dt * s->adv[k] : 0);
    s->hat[k] = rhs / (1 + dt * M * p->S * k2 + dt * M * p->kappa * k2 * k2);
  }
  memcpy(s->work, s->hat, sizeof(double) * n);
  backward(s);
  memcpy(s->c, s->work2, sizeof(double) * n);
  s->t += dt;
  s->steps++;
}

double wg_ch_gain(const wg_ch_params *p, int mx, int mz)
{
  double kx = 2 * pi * mx / p->lx, kz = pi * mz / p->lz, k2 = kx * kx + kz * kz;
  double fpp = -p->K * p->c_o * (1 - p->c_o); /* f''(c_o) */
  return (1 + p->dt * p->mobility * k2 * (p->S - fpp)) /
         (1 + p->dt * p->mobility * k2 * (p->S + p->kappa * k2));
}

double wg_ch_mass(const wg_ch *s)
{
  size_t n = (size_t)s->p.nx * s->p.nz;
  double m = 0;
  for (size_t k = 0; k < n; k++) m += s->c[k];
  return m / (double)n;
}

/* lap c in real space, into work2 */
static void laplacian(wg_ch *s)
{
  size_t n = (size_t)s->p.nx * s->p.nz;
  coefficients(s);
  for (size_t k = 0; k < n; k++) s->work[k] = -s->k2[k] * s->hat[k];
  backward(s);
}

double wg_ch_grad2(wg_ch *s)
{
  size_t n = (size_t)s->p.nx * s->p.nz;
  laplacian(s);
  double g = 0;
  for (size_t k = 0; k < n; k++) g -= s->c[k] * s->work2[k];
  return g / (double)n;
}

double wg_ch_bulk_energy(const wg_ch *s)
{
  size_t n = (size_t)s->p.nx * s->p.nz;
  double f = 0;
  for (size_t k = 0; k < n; k++) f += f_bulk(&s->p, s->c[k]);
  return f / (double)n;
}

double wg_ch_free_energy(wg_ch *s) { return wg_ch_bulk_energy(s) + 0.5 * s->p.kappa * wg_ch_grad2(s); }

double wg_ch_mode(wg_ch *s, int mx, int mz)
{
  coefficients(s);
  /* R2HC of cos(2 pi mx x/lx) gives nx/2 (nx at mx = 0); REDFT10 of cos(pi mz z/lz) gives nz
     (2 nz at mz = 0) */
  double scale = (mx == 0 ? s->p.nx : 0.5 * s->p.nx) * (mz == 0 ? 2.0 * s->p.nz : s->p.nz);
  return s->hat[(size_t)mx * s->p.nz + mz] / scale;
}

void wg_ch_profile(const wg_ch *s, double *prof)
{
  for (int iz = 0; iz < s->p.nz; iz++) {
    double m = 0;
    for (int ix = 0; ix < s->p.nx; ix++) m += s->c[(size_t)ix * s->p.nz + iz];
    prof[iz] = m / s->p.nx;
  }
}

int wg_ch_layers(const double *prof, int nz)
{
  double mean = 0;
  for (int iz = 0; iz < nz; iz++) mean += prof[iz];
  mean /= nz;
  int bands = 0, above = 0;
  for (int iz = 0; iz < nz; iz++) {
    int a = prof[iz] > mean;
    if (a && !above) bands++;
    above = a;
  }
  return bands;
}
