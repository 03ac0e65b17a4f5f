/* Event queue: a tournament tree of fan-out 8 over the particles.  The leaves are the
   particles' next event times (key[], owned by the caller); each node above holds the time
   and index of the earliest leaf below it.  The eight children of a node lie side by side in
   memory (one or two cache lines), so updating one particle reads one group per level:
   log_8 N groups, about 6 at N = 10^5, where a binary tree of indices reads 2 log_2 N scattered
   keys.  No allocation after wg_evqueue_alloc; ties go to the lower index, so the order of
   events is reproducible (and the same as any queue ordering by time, then index). */
#ifndef WG_EVQUEUE_H
#define WG_EVQUEUE_H

#include "wg.h"

enum { WG_EVQUEUE_FAN = 8 };

typedef struct wg_evqueue_node {
  double key;   /* earliest time below */
  int32_t idx;  /* its particle (the lowest index among equal times) */
} wg_evqueue_node;

typedef struct wg_evqueue {
  long n;                  /* number of particles */
  int levels;              /* node levels above the leaves (>= 1) */
  long width[16];          /* nodes per level; level 0 is just above the leaves */
  wg_evqueue_node *level[16];
  wg_evqueue_node *nodes;  /* one allocation for all levels */
  const double *key;       /* key[i]: next event time of particle i (owned by the caller) */
} wg_evqueue;

int wg_evqueue_alloc(wg_evqueue *q, long n, const double *key);
void wg_evqueue_free(wg_evqueue *q);
/* Rebuild from the keys (O(N)). */
void wg_evqueue_build(wg_evqueue *q);
/* Particle i's key changed. */
void wg_evqueue_update(wg_evqueue *q, long i);
/* Particle with the earliest key, and that key (kept at the root: no visit to key[]). */
static inline long wg_evqueue_top(const wg_evqueue *q) { return q->level[q->levels - 1][0].idx; }
static inline double wg_evqueue_top_key(const wg_evqueue *q) { return q->level[q->levels - 1][0].key; }
/* Bytes held by the queue. */
size_t wg_evqueue_bytes(const wg_evqueue *q);

#endif
