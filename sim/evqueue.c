#include "evqueue.h"

#include <math.h>
#include <stdlib.h>

/* Winner of two entries; an entry < 0 is an empty leaf (padding beyond n). */
static inline int32_t earlier(const double *key, int32_t a, int32_t b)
{
  if (a < 0) return b;
  if (b < 0) return a;
  if (key[b] < key[a]) return b;
  if (key[a] < key[b]) return a;
  return a < b ? a : b;
}

int wg_evqueue_alloc(wg_evqueue *q, long n, const double *key)
{
  q->n = n;
  q->size = 1;
  while (q->size < n) q->size *= 2;
  q->key = key;
  q->node = malloc(sizeof *q->node * 2 * (size_t)q->size);
  if (!q->node) return wg_error(WG_ENOMEM, "event queue", "cannot allocate %ld nodes", 2 * q->size);
  return WG_OK;
}

void wg_evqueue_free(wg_evqueue *q)
{
  free(q->node);
  q->node = NULL;
}

void wg_evqueue_build(wg_evqueue *q)
{
  for (long k = 0; k < q->size; k++) q->node[q->size + k] = k < q->n ? (int32_t)k : -1;
  for (long k = q->size - 1; k >= 1; k--)
    q->node[k] = earlier(q->key, q->node[2 * k], q->node[2 * k + 1]);
}

/* Once a node keeps a winner other than i, nothing above it can change. */
void wg_evqueue_update(wg_evqueue *q, long i)
{
  for (long k = (q->size + i) / 2; k >= 1; k /= 2) {
    int32_t w = earlier(q->key, q->node[2 * k], q->node[2 * k + 1]);
    if (w == q->node[k] && w != i) break;
    q->node[k] = w;
  }
}
