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

/* Earliest of the leaves first..first+count-1, the lowest index among equal times.  Without
   branches: which of eight times is the least is a coin toss for the branch predictor, so the
   least time is taken first (a < b ? a : b, one minsd) and then the first index holding it. */
static inline __attribute__((always_inline)) wg_evqueue_node
min_of_leaves_n(const double *key, long first, const long count)
{
  const double *k8 = key + first;
  double m = k8[0];
  for (long k = 1; k < count; k++) m = k8[k] < m ? k8[k] : m;
  long idx = count - 1;
  for (long k = count - 2; k >= 0; k--) idx = k8[k] == m ? k : idx;
  return (wg_evqueue_node){m, (int32_t)(first + idx)};
}

/* The same, unrolled for a whole group of FAN. */
static inline wg_evqueue_node min_of_leaves(const double *key, long first, long count)
{
  return count == FAN ? min_of_leaves_n(key, first, FAN) : min_of_leaves_n(key, first, count);
}

/* Earliest of a group of nodes; their subtrees are in index order, so again the first
   among equal times has the lowest index. */
static inline __attribute__((always_inline)) wg_evqueue_node
min_of_nodes_n(const wg_evqueue_node *g, const long count)
{
  double m = g[0].key;
  for (long k = 1; k < count; k++) m = g[k].key < m ? g[k].key : m;
  long at = count - 1;
  for (long k = count - 2; k >= 0; k--) at = g[k].key == m ? k : at;
  return g[at];
}

static inline wg_evqueue_node min_of_nodes(const wg_evqueue_node *g, long count)
{
  return count == FAN ? min_of_nodes_n(g, FAN) : min_of_nodes_n(g, count);
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
