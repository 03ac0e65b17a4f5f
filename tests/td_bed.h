/* Fixtures of the time-driven tests and benchmark.

   The shaken wet bed the time-driven tests use: 60 disks in three rows on a floor
   shaken at Gamma = 3 (A = 0.3) under a lid at 10, F_B = 4 mg, s_crit = 0.0711, wall law
   e = 0.9; positions, velocities and radii into r, v, rad (60 x 3, 60 x 3, 60). */
#ifndef WG_TEST_TD_BED_H
#define WG_TEST_TD_BED_H

#include <math.h>
#include <string.h>

#include "td.h"

static inline void shaken_bed(wg_td_params *p, double *r, double *v, double *rad)
{
  p->periodic[1] = 0;
  p->lo[1] = -1;
  p->hi[1] = 12;
  p->g = 1;
  p->nwalls = 2;
  double gamma = 3, a = 0.3, w = sqrt(gamma / a);
  p->wall[0] = (wg_wall){.c = 0, .A = a, .omega = w, .side = +1};
  p->wall[1] = (wg_wall){.c = 10, .A = a, .omega = w, .side = -1};
  p->pw = wg_contact_linear(0.9, 0.01, 1.0);
  p->f_b = 4;
  p->s_crit = 0.0711;
  for (int k = 0; k < 60; k++) {
    r[3 * k] = 0.5 + (k % 20);
    r[3 * k + 1] = 0.9 + 1.1 * (k / 20);
    r[3 * k + 2] = 0;
    v[3 * k] = 0.3 * sin(1.7 * k);
    v[3 * k + 1] = 0.3 * cos(2.3 * k);
    v[3 * k + 2] = 0;
    rad[k] = 0.45 + 0.01 * (k % 7);
  }
}

/* Gravity and a resting floor at 0 under the vertical axis, room up to hi. */
static inline void resting_floor(wg_td_params *p, double hi)
{
  int up = p->dim - 1;
  p->periodic[up] = 0;
  p->lo[up] = -1;
  p->hi[up] = hi;
  p->g = 1;
  p->nwalls = 1;
  p->wall[0] = (wg_wall){.c = 0, .A = 0, .omega = 1, .side = +1};
}

/* A periodic dim-D box of side 20 without gravity or walls, time step dt, skin 0.2. */
static inline void periodic_box(wg_td_params *p, int dim, double dt)
{
  memset(p, 0, sizeof *p);
  p->dim = dim;
  for (int a = 0; a < dim; a++) {
    p->box[a] = 20;
    p->periodic[a] = 1;
  }
  p->dt = dt;
  p->skin = 0.2;
}

#endif
