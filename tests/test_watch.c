/* The event-driven engine's watch hook (wg_ed_set_watch): called every WG_ED_WATCH_EVENTS
   events, across synchronisations; an engine with a watch computes exactly what one without
   does (every particle bit for bit); a watch that returns an error stops the advance with it. */
#include <stdio.h>
#include <string.h>

#include "ed.h"
#include "tharness.h"

/* A wet shaken bed: synchronisations (16 N = 6400 events) far more often than the watch. */
static int bed_scene(wg_scene *sc)
{
  const char *keys[] = {"dim=2", "n=400", "lx=80", "height=9", "s_crit=0.0711", "f_b=4",
                        "eps=0.9", "gamma=15", "estar=1.42", "seed=3", "t_end=1", NULL};
  wg_scene_init(sc);
  for (int k = 0; keys[k]; k++)
    if (wg_scene_set_override(sc, keys[k]) != WG_OK) return 1;
  return wg_scene_finish(sc) != WG_OK;
}

typedef struct {
  const wg_ed *s;
  int calls, stop_at;
  unsigned long long loop_events[64]; /* all events processed at each call */
} watch_log;

static unsigned long long loop_events(const wg_ed *s)
{
  const wg_counts *c = &s->counts;
  return c->collisions + c->ruptures + c->reflections + c->wall_hits + c->wall_enters +
         c->cell_crossings + c->stale;
}

static int watch(void *user)
{
  watch_log *w = user;
  if (w->calls < 64) w->loop_events[w->calls] = loop_events(w->s);
  w->calls++;
  return w->stop_at && w->calls >= w->stop_at ? WG_ERANGE : WG_OK;
}

static int same_state(const wg_ed *a, const wg_ed *b)
{
  if (a->n != b->n || a->now != b->now || memcmp(&a->counts, &b->counts, sizeof a->counts))
    return 0;
  for (long id = 0; id < a->n; id++) {
    double ra[3], va[3], rb[3], vb[3];
    wg_ed_position_of(a, id, a->now, ra, va);
    wg_ed_position_of(b, id, b->now, rb, vb);
    if (memcmp(ra, rb, sizeof ra[0] * (size_t)a->dim) || memcmp(va, vb, sizeof va[0] * (size_t)a->dim))
      return 0;
  }
  return 1;
}

int main(void)
{
  wg_scene sc;
  TH_CHECK(bed_scene(&sc) == 0, "scene");
  wg_ed a, b;
  int ok = wg_ed_alloc(&a, &sc) == WG_OK && wg_ed_alloc(&b, &sc) == WG_OK;
  TH_CHECK(ok, "two engines of the same scene");
  if (!ok) return th_summary();
  watch_log w = {.s = &b};
  wg_ed_set_watch(&b, watch, &w);
  /* in several pieces, as the run loop advances from one sampling time to the next */
  int st_a = WG_OK, st_b = WG_OK;
  for (int k = 1; k <= 120 && st_a == WG_OK && st_b == WG_OK; k++) {
    st_a = wg_ed_advance(&a, 0.5 * k);
    st_b = wg_ed_advance(&b, 0.5 * k);
  }
  unsigned long long total = loop_events(&b);
  TH_CHECK(st_a == WG_OK && st_b == WG_OK && total > 5 * WG_ED_WATCH_EVENTS,
           "60 time units: %llu events (%llu watch periods), status %d %d, now %g", total,
           total / WG_ED_WATCH_EVENTS, st_a, st_b, b.now);
  TH_CHECK(same_state(&a, &b), "with and without a watch: the same particles, bit for bit, "
           "and the same counts");
  TH_CHECK(w.calls == (int)(total / WG_ED_WATCH_EVENTS), "watch called %d times for %llu events",
           w.calls, total);
  int regular = w.calls > 0;
  for (int k = 0; k < w.calls && k < 64; k++)
    if (w.loop_events[k] != (unsigned long long)(k + 1) * WG_ED_WATCH_EVENTS) regular = 0;
  TH_CHECK(regular, "every %d events exactly, across synchronisations every %llu",
           WG_ED_WATCH_EVENTS, b.sync_interval);
  /* a watch that stops: the advance returns its status at once */
  watch_log w2 = {.s = &b, .stop_at = 2};
  wg_ed_set_watch(&b, watch, &w2);
  unsigned long long before = loop_events(&b);
  int st = wg_ed_advance(&b, 1e9);
  TH_CHECK(st == WG_ERANGE && w2.calls == 2 && loop_events(&b) - before == 2 * WG_ED_WATCH_EVENTS,
           "a watch returning an error stops the advance (status %d after %llu events)", st,
           loop_events(&b) - before);
  /* removed: never called again */
  wg_ed_set_watch(&b, NULL, NULL);
  st = wg_ed_advance(&b, b.now + 2);
  TH_CHECK(st == WG_OK && w2.calls == 2, "removed: not called (%d calls)", w2.calls);
  wg_ed_free(&a);
  wg_ed_free(&b);
  return th_summary();
}
