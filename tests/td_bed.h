/* The shaken wet bed both engines' time-driven tests use: 60 disks in three rows on a floor
   shaken at Gamma = 3 (A = 0.3) under a lid at 10, F_B = 4 mg, s_crit = 0.0711, wall law
   e = 0.9; positions, velocities and radii into r, v, rad (60 x 3, 60 x 3, 60). */
#ifndef WG_TEST_TD_BED_H
#define WG_TEST_TD_BED_H

#include <math.h>

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

#endif
