/* The cosine shear field (thesis Eq. 2.20, Sec. 2.4.4, 5.3.2, Ch. 7-8):
       F_s(x) = F_smax cos(2 pi x / L_x),
   a body force along axis `axis` (y in 3D; the second axis in 2D) that varies along x, made
   piecewise constant in nbins bins of width L_x / nbins (about one diameter, the thesis's
   event-driven scheme): bin k acts with F_smax cos(2 pi (k + 1/2) / nbins), its centre's
   value.  Between events a particle then flies a parabola with acceleration F_bin / m along
   the field axis (plus gravity); x moves linearly, so bin crossings are linear events.

   Two particles in different bins accelerate relative to each other, so the time at which
   their distance reaches sigma is a root of the quartic
       p(tau) = |dr + dv tau + da tau^2 / 2|^2 - sigma^2
   (thesis footnote 6 of Sec. 2.4.4; the thesis used Herbison-Evans's closed-form solver).
   Here it is found exactly instead: p'(tau) / 2 = d(tau).d'(tau) is a cubic whose real roots
   (closed form, GSL, then polished by Newton) split [0, tau_max] into pieces on which p is
   monotonic; the first piece whose ends straddle zero in the wanted direction holds exactly
   one crossing, found by safeguarded Newton-bisection to round-off.  p is evaluated from
   d(tau) itself, not from expanded coefficients, which keeps the cancellation of
   |d|^2 - sigma^2 as small as in the quadratic case. */
#ifndef WG_SHEAR_H
#define WG_SHEAR_H

#include "cells.h"
#include "wg.h"

typedef struct wg_shear {
  double fmax;      /* F_smax [m g] */
  int nbins;        /* bins across L_x */
  double lx;        /* L_x [d] */
  double width;     /* bin width L_x / nbins [d] */
  double t_on;      /* the field acts for t_on <= t < t_off [sqrt(d/g)] */
  double t_off;
  int axis;         /* axis the force acts along (1) */
  double *force;    /* force of each bin [m g] */
} wg_shear;

/* Set up the field (allocates the bin table); wg_shear_free releases it. */
int wg_shear_init(wg_shear *f, double fmax, int nbins, double lx, double t_on, double t_off,
                  int axis);
void wg_shear_free(wg_shear *f);

/* Whether the field acts at time t. */
static inline int wg_shear_active(const wg_shear *f, double t)
{
  return f && f->fmax != 0 && t >= f->t_on && t < f->t_off;
}

/* Bin of position x (any real x: periodic in L_x). */
int wg_shear_bin_of(const wg_shear *f, double x);

/* Time until a particle at x (in bin `bin`, possibly an image shifted by multiples of L_x)
   moving with vx leaves the bin; *dir = +1 / -1 says through which face.  INFINITY if
   vx == 0.  Never negative. */
double wg_shear_bin_exit(const wg_shear *f, int bin, double x, double vx, int *dir);

/* The bin entered through face dir (+1 / -1) of bin `bin`, with periodic wrap. */
static inline int wg_shear_bin_step(const wg_shear *f, int bin, int dir)
{
  int b = bin + dir;
  return b < 0 ? f->nbins - 1 : b >= f->nbins ? 0 : b;
}

/* First time tau in (0, tau_max] at which p(tau) = |dr + dv tau + da tau^2/2|^2 - sigma^2
   crosses zero in direction dir: dir = -1, from > 0 to <= 0 (a contact while approaching);
   dir = +1, from < 0 to >= 0 (a bonded pair reaching the edge of its well).  The sign of p at
   tau = 0 is taken as it is computed; a start already on the far side gets the next crossing
   after p has come back.  Returns 1 and *tau, or 0 when there is none before tau_max
   (tau_max may be INFINITY).  da may be zero (then p is a quadratic). */
int wg_shear_pair_root(const double *dr, const double *dv, const double *da, int dim,
                       double sigma, int dir, double tau_max, double *tau);

/* First tau >= 0 at which q(tau) = d(tau).d'(tau) (half of p') crosses the level `level`
   upwards (from < level to >= level); 0 if q(0) >= level already; INFINITY if never. */
double wg_shear_pair_speed_time(const double *dr, const double *dv, const double *da, int dim,
                                double level);

/* Time, counted from the particle's reference point r, v with constant acceleration acc
   (per axis), at which it leaves `cell`, not earlier than tau_now (the same contract as
   wg_cells_exit_time, which is the case acc = (0, .., -g)). */
double wg_shear_cell_exit_time(const wg_cells *c, long cell, const double *r, const double *v,
                               const double *acc, double tau_now, int skip_axis, int skip_dir,
                               int *axis, int *dir);

#endif
