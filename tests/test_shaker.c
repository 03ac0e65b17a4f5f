/* The engine at the walls: a particle resting on a floor shaken below Gamma = 1 stays on it;
   a shaker at Gamma = 1000 keeps every particle inside and closes its energy ledger; a fast
   particle entering the wall's reach late in a long run, closer than the clock resolves,
   does not stall the run. */
#include <math.h>
#include <stdio.h>

#include "ed.h"
#include "tharness.h"

static int scene(wg_scene *sc, const char *const *keys)
{
  wg_scene_init(sc);
  for (int k = 0; keys[k]; k++)
    if (wg_scene_set_override(sc, keys[k]) != WG_OK) return 1;
  return wg_scene_finish(sc) != WG_OK;
}

/* Largest gap between any particle and the floor or lid (negative: overlap) at time now. */
static void wall_gaps(const wg_ed *s, double *worst_overlap, double *max_floor_gap)
{
  *worst_overlap = 0;
  *max_floor_gap = -INFINITY;
  for (long i = 0; i < s->n; i++) {
    double r[3], v[3];
    wg_ed_position_at(s, i, s->now, r, v);
    double R = s->p[i].radius;
    double floor_gap = r[s->up] - R - wg_wall_position(&s->wall[0], s->now);
    double lid_gap = wg_wall_position(&s->wall[1], s->now) - r[s->up] - R;
    if (floor_gap < *worst_overlap) *worst_overlap = floor_gap;
    if (lid_gap < *worst_overlap) *worst_overlap = lid_gap;
    if (floor_gap > *max_floor_gap) *max_floor_gap = floor_gap;
  }
}

static void resting_below_gamma_one(void)
{
  const char *keys[] = {"dim=2", "n=1", "lx=10", "height=5", "sigma_p=0", "gamma=0.8",
                        "estar_d=0.01", "tc=1e-4", "tg_init_abs=0", "seed=1", "t_end=100", NULL};
  wg_scene sc;
  TH_CHECK(scene(&sc, keys) == 0, "Gamma = 0.8 scene accepted");
  /* on the floor at t = 0 (floor at z = 0, moving up with A w) */
  double r[2] = {5, 0.5}, v[2] = {0, sc.amplitude * sc.omega}, rad[1] = {0.5};
  wg_ed s;
  TH_CHECK(wg_ed_alloc_state(&s, &sc, 1, r, v, rad, NULL, 0) == WG_OK, "state set up");
  double overlap = 0, highest = 0;
  int st = WG_OK;
  for (int k = 1; k <= 400 && st == WG_OK; k++) {
    st = wg_ed_advance(&s, k * sc.t_driv / 20);
    double o, h;
    wall_gaps(&s, &o, &h);
    if (o < overlap) overlap = o;
    if (h > highest) highest = h;
  }
  TH_CHECK(st == WG_OK, "20 periods run (%llu wall contacts)", s.counts.wall_hits);
  TH_CHECK(highest < 1e-6, "the particle stays on the floor: highest gap %.2e < 1e-6 d", highest);
  TH_CHECK(overlap > -1e-12, "it never sinks into the floor: worst overlap %.2e", overlap);
  double res = wg_ed_ledger_residual(&s);
  TH_CHECK(res < 1e-9, "ledger closes (%.2e)", res);
  wg_ed_free(&s);
}

static void gamma_thousand(const char *shell)
{
  const char *keys[] = {"dim=2", "n=200", "lx=50", "height=12", "s_crit=0.0711", "f_b=4",
                        "eps=0.9", "gamma=1000", "estar=50", "seed=2", "t_end=20", shell, NULL};
  wg_scene sc;
  TH_CHECK(scene(&sc, keys) == 0, "Gamma = 1000 scene accepted (A = %.3g d, w = %.4g, %s)",
           sc.amplitude, sc.omega, shell);
  wg_ed s;
  TH_CHECK(wg_ed_alloc(&s, &sc) == WG_OK, "set up");
  double overlap = 0, worst = 0, highest;
  int st = WG_OK;
  for (int k = 1; k <= 200 && st == WG_OK; k++) {
    st = wg_ed_advance(&s, k * sc.t_end / 200);
    double o;
    wall_gaps(&s, &o, &highest);
    if (o < overlap) overlap = o;
    double res = wg_ed_ledger_residual(&s);
    if (res > worst) worst = res;
  }
  TH_CHECK(st == WG_OK && s.counts.wall_hits > 500, "run completes (%llu wall hits, %llu collisions)",
           s.counts.wall_hits, s.counts.collisions);
  TH_CHECK(overlap > -1e-9, "no particle leaves the container: worst wall overlap %.2e", overlap);
  TH_CHECK(worst < 1e-9, "ledger residual %.2e < 1e-9", worst);
  wg_ed_free(&s);
}

/* At t = 16385 the clock resolves 3.6e-12; a particle falling at 150 sqrt(g d) that is
   2e-10 d above the reach of the floor (the slab the floor sweeps, plus its radius) enters
   it 1.3e-12 later, which rounds to now.  The run must go on and hit the floor (a 20 000
   time-unit run of Fig. 3.31 once stalled at an event repeated at one instant). */
static void entry_below_clock_resolution(void)
{
  const char *keys[] = {"dim=2", "n=1", "lx=10", "height=400", "sigma_p=0", "gamma=15",
                        "estar_d=1", "tg_init_abs=0", "seed=1", "t_end=20000", NULL};
  wg_scene sc;
  TH_CHECK(scene(&sc, keys) == 0, "fast-particle scene accepted");
  double t0 = 16385, R = 0.5;
  double r[2] = {5, fabs(sc.amplitude) + R + 2e-10}, v[2] = {0, -150}, rad[1] = {R};
  TH_CHECK(t0 + (r[1] - fabs(sc.amplitude) - R) / 150 == t0, "the entry rounds to the present");
  wg_ed s;
  TH_CHECK(wg_ed_alloc_state(&s, &sc, 1, r, v, rad, NULL, t0) == WG_OK, "state set up at t = %g", t0);
  int st = wg_ed_advance(&s, t0 + 0.01);
  TH_CHECK(st == WG_OK && s.counts.wall_hits >= 1 && s.counts.wall_enters >= 1,
           "the run goes on: the particle enters the reach and hits the floor (%llu hits, %llu entries)",
           s.counts.wall_hits, s.counts.wall_enters);
  double rr[3], vv[3];
  wg_ed_position_at(&s, 0, s.now, rr, vv);
  TH_CHECK(vv[1] > 100, "and bounces back up (v = %.1f)", vv[1]);
  wg_ed_free(&s);
}

/* Two grains thrown up one above the other, the lower one faster: each rises through cells,
   turns round inside one and falls; they meet at t = 5, the upper one 4.5 below its apex.
   Sixty bystanders far away keep the engine from re-synchronising meanwhile.  The scene rests
   grains on the floor (rest_speed), which switches on the cells' turn_back rule; without it
   (every other scene, engine version c450a5b3a17e0edb) a grain that turned round in a cell
   keeps that cell until its next physical event and these two pass through each other unseen
   (docs/engines.md, "Cell crossings under gravity").  Neighbour lists (shell) have no cell
   crossings: they must see the meeting too, the bystanders falling freely. */
static void fall_through_cells(const char *rule)
{
  enum { NB = 60 };
  const char *keys[] = {"dim=2", "n=62", "lx=200", "height=40", "sigma_p=0", "gamma=0.5",
                        "estar_d=1e-4", "tg_init_abs=0", rule, "seed=1", "t_end=100",
                        NULL};
  wg_scene sc;
  TH_CHECK(scene(&sc, keys) == 0, "tall box scene accepted");
  for (int k = 0; k < 4; k++) {
    double r[2 * (NB + 2)], v[2 * (NB + 2)], rad[NB + 2];
    double zb = 6 + 0.29 * k; /* the upper grain's start: apexes at assorted heights in a cell */
    r[0] = 5, r[1] = zb - 4, v[0] = 0, v[1] = 2.6; /* lower grain, 3 below, apex at t = 2.6 */
    r[2] = 5, r[3] = zb, v[2] = 0, v[3] = 2;       /* upper grain: apex 2 higher at t = 2 */
    for (int b = 0; b < NB; b++) {
      r[4 + 2 * b] = 100 + 1.5 * b, r[5 + 2 * b] = 35, v[4 + 2 * b] = v[5 + 2 * b] = 0;
    }
    for (int b = 0; b < NB + 2; b++) rad[b] = 0.5;
    wg_ed s;
    if (wg_ed_alloc_state(&s, &sc, NB + 2, r, v, rad, NULL, 0) != WG_OK) {
      TH_CHECK(0, "set up");
      return;
    }
    /* relative speed 0.6 across a gap of 3: contact at t = 5, the upper grain 4.5 below its
       apex, the lower one 2.9 below its own */
    int st = wg_ed_advance(&s, 5.05);
    double a[3], va[3], c[3], vc[3];
    wg_ed_position_at(&s, s.slot[0], s.now, a, va);
    wg_ed_position_at(&s, s.slot[1], s.now, c, vc);
    TH_CHECK(st == WG_OK && s.counts.collisions == 1 && c[1] - a[1] > 1 - 1e-9,
             "%s, start %.2f: the falling grain meets the rising one (%llu collision, height "
             "difference %.6f >= 1 just after)", rule, zb, s.counts.collisions, c[1] - a[1]);
    wg_ed_free(&s);
  }
}

int main(void)
{
  fall_through_cells("rest_speed=0.01");
  fall_through_cells("shell=0.4");
  resting_below_gamma_one();
  gamma_thousand("shell=0");
  gamma_thousand("shell=0.3");
  entry_below_clock_resolution();
  return th_summary();
}
