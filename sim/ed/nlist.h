/* Neighbour lists with a shell for the event-driven engine (scene key `shell`; docs/engines.md,
   "Neighbour lists").  Each particle has a list centre, its position when it was last listed,
   and stays within `reach` = shell/2 of it: a ball without gravity; under gravity a cylinder
   (3D) or rectangle (2D) of radius and half-height reach/sqrt 2, whose faces are reached at
   the roots of quadratics.  Particles i and j are listed together, in both lists, when their
   centres are closer than sigma_ij + s_crit + shell.  A pair that is not listed is then at
   least sigma_ij + s_crit apart while both stay in their regions: it can neither collide nor
   hold a bridge, so a particle's events need only its list.  The cells hold list centres
   and change only when a particle is listed anew (no cell crossings). */
#ifndef WG_NLIST_H
#define WG_NLIST_H

#include "wg.h"

typedef struct wg_nlist {
  int dim, cap;        /* cap: room per list; doubled when a list would overflow */
  double shell;        /* [d] */
  double reach;        /* shell / 2: farthest a particle goes from its centre [d] */
  double r_max;        /* largest radius (set by the engine) [d] */
  double *centre;      /* centre[3 i + k] */
  int32_t *nb;         /* nb[i * cap + k], k < nn[i]: the neighbours of i (slots) */
  uint16_t *nn;
} wg_nlist;

int wg_nlist_alloc(wg_nlist *l, int dim, long n, double shell);
void wg_nlist_free(wg_nlist *l);
size_t wg_nlist_bytes(const wg_nlist *l, long n);

/* Forget every list (before all are built afresh). */
void wg_nlist_clear(wg_nlist *l, long n);
/* List i and j together; the lists grow when full (WG_ENOMEM if they cannot). */
int wg_nlist_link(wg_nlist *l, long n, long i, long j);
/* Take i out of its neighbours' lists and empty its own. */
void wg_nlist_unlink_all(wg_nlist *l, long i);

/* Time, counted from the particle's reference point r, v (gravity g along -axis dim-1), at
   which it leaves the region around its centre, not earlier than tau_now; INFINITY if never. */
double wg_nlist_exit_time(const wg_nlist *l, long i, const double *r, const double *v, double g,
                          double tau_now);

#endif
