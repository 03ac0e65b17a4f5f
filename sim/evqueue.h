/* Event queue: a complete binary tournament tree over the particles.  Each leaf holds the
   time of its particle's next event; each inner node the index of the earlier of its two
   children.  Updating one particle walks one leaf-to-root path: O(log N) per event, no
   allocation after wg_evqueue_alloc, and ties are broken towards the lower index, so the
   order of events is reproducible. */
#ifndef WG_EVQUEUE_H
#define WG_EVQUEUE_H

#include "wg.h"

typedef struct wg_evqueue {
  long n;          /* number of particles */
  long size;       /* leaves, a power of two >= n */
  int32_t *node;   /* node[1..2*size-1]: index of the winner below; leaves at size..2*size-1 */
  const double *key; /* key[i]: next event time of particle i (owned by the caller) */
} wg_evqueue;

int wg_evqueue_alloc(wg_evqueue *q, long n, const double *key);
void wg_evqueue_free(wg_evqueue *q);
/* Rebuild from the keys (O(N)). */
void wg_evqueue_build(wg_evqueue *q);
/* Particle i's key changed. */
void wg_evqueue_update(wg_evqueue *q, long i);
/* Particle with the earliest key. */
static inline long wg_evqueue_top(const wg_evqueue *q) { return q->node[1]; }

#endif
