#include "evqueue.h"

#include <math.h>
#include <stdlib.h>

enum { FAN = WG_EVQUEUE_FAN };

int wg_evqueue_alloc(wg_evqueue *q, long n, const double *key)
{
  q->n = n;
  q->key = key;
  q->levels = 0;
  long total = 0, w = n;
  do {
    w = (w + FAN - 1) / FAN;
    q->width[q->levels++] = w;
    total += w;
  } while (w > 1);
  q->nodes = malloc(sizeof *q->nodes * (size_t)total);
  if (!q->nodes)
    return wg_error(WG_ENOMEM, "event queue", "cannot allocate %ld nodes", total);
  wg_evqueue_node *p = q->nodes;
  for (int l = 0; l < q->levels; l++) {
    q->level[l] = p;
    p += q->width[l];
  }
  return WG_OK;
}

void wg_evqueue_free(wg_evqueue *q)
{
  free(q->nodes);
  q->nodes = NULL;
}

size_t wg_evqueue_bytes(const wg_evqueue *q)
{
  size_t total = 0;
  for (int l = 0; l < q->levels; l++) total += (size_t)q->width[l];
  return total * sizeof(wg_evqueue_node);
}

/* Earliest of the leaves first..first+count-1: scanned in index order with a strict <, so
   the lowest index wins a tie. */
static inline wg_evqueue_node min_of_leaves(const double *key, long first, long count)
{
  wg_evqueue_node m = {key[first], (int32_t)first};
  for (long k = 1; k < count; k++)
    if (key[first + k] < m.key) {
      m.key = key[first + k];
      m.idx = (int32_t)(first + k);
    }
  return m;
}

/* Earliest of a group of nodes; their subtrees are in index order, so again the first
   among equal times has the lowest index. */
static inline wg_evqueue_node min_of_nodes(const wg_evqueue_node *g, long count)
{
  wg_evqueue_node m = g[0];
  for (long k = 1; k < count; k++)
    if (g[k].key < m.key) m = g[k];
  return m;
}

static inline long group_size(long width, long group) /* children of node `group` */
{
  long rest = width - group * FAN;
  return rest < FAN ? rest : FAN;
}

void wg_evqueue_build(wg_evqueue *q)
{
  for (long g = 0; g < q->width[0]; g++)
    q->level[0][g] = min_of_leaves(q->key, g * FAN, group_size(q->n, g));
  for (int l = 1; l < q->levels; l++)
    for (long g = 0; g < q->width[l]; g++)
      q->level[l][g] = min_of_nodes(q->level[l - 1] + g * FAN, group_size(q->width[l - 1], g));
}

/* Once a node keeps its entry, nothing above it can change. */
void wg_evqueue_update(wg_evqueue *q, long i)
{
  long g = i / FAN;
  wg_evqueue_node m = min_of_leaves(q->key, g * FAN, group_size(q->n, g));
  wg_evqueue_node *node = &q->level[0][g];
  if (m.key == node->key && m.idx == node->idx) return;
  *node = m;
  for (int l = 1; l < q->levels; l++) {
    long child = g;
    g = child / FAN;
    m = min_of_nodes(q->level[l - 1] + g * FAN, group_size(q->width[l - 1], g));
    node = &q->level[l][g];
    if (m.key == node->key && m.idx == node->idx) return;
    *node = m;
  }
}
