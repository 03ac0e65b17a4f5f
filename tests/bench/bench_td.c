/* Benchmark of the time-driven engine (issue 4):
     1. particle-steps per second for a 3D vibrated bed of 10^4 spheres (3.24 per d^2 on
        55.6 d x 55.6 d, 8 d high, Gamma = 4), dry and wet (F_B = 16 m g, s_crit = 0.0711);
     2. time-driven against event-driven cost for the same fluid-gas coexistence state, the
        2D shaker of thesis Fig. 3.2 (1200 disks, Gamma = 15, E* = 1.42): the event-driven
        run goes to t = 100 untimed, is timed over the next sim_time_2d, and hands its state
        to the time-driven engine, timed over the same span: wall-clock seconds per time
        unit and their ratio, in one run (thesis: event-driven faster by more than 100x).
   Time-driven settings: linear law, t_c = 0.005, dt = t_c / 50, skin 0.1 (td.h defaults).
   The 3D bed falls for 5 time units from its lattice start before it is timed.
     3. accuracy against cost for two bodies, the error of the restitution (e = 0.9, linear
        law) and of the energy a bridge rupture takes (F_B s_crit) against their closed forms
        as dt = t_c / k for k = 10 ... 400, with the CPU time per contact, for velocity Verlet
        and for Gear's predictor-corrector: the table from which the default k = 50 is chosen.
   Output: tab-separated rows  case, engine, n, sim_time, wall_s, rate, unit; then the
   ratio; then the accuracy table (k, dt, mean relative errors of restitution and rupture
   energy over 8 phases of the contact against the step grid, microseconds of CPU per time
   unit of a two-body run); then the same for friction (friction_table).
   Usage: bench_td [sim_time_3d [sim_time_2d]]. */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "ed.h"
#include "td.h"
#include "td_bed.h"

#define SETTLE 5.0   /* time units before the 3D bed is timed */
#define WARM 100.0   /* time units of the event-driven run before the comparison */

static double now_s(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int scene(wg_scene *sc, const char *const *kv)
{
  wg_scene_init(sc);
  for (int k = 0; kv[k]; k++)
    if (wg_scene_set_override(sc, kv[k]) != WG_OK) return 1;
  return wg_scene_finish(sc) != WG_OK;
}

static double td_bed(const char *name, const char *const *kv, double t_sim)
{
  wg_scene sc;
  if (scene(&sc, kv)) exit(1);
  wg_td s;
  if (wg_td_alloc(&s, &sc) != WG_OK) exit(1);
  wg_td_advance(&s, SETTLE); /* let the lattice start fall into a bed, out of the timing */
  unsigned long long steps0 = s.steps;
  double w0 = now_s();
  wg_td_advance(&s, SETTLE + t_sim);
  double w = now_s() - w0, ps = (double)(s.steps - steps0) * (double)s.n;
  printf("%s\ttd\t%ld\t%g\t%.3f\t%.4g\tparticle_steps_per_s\n", name, s.n, t_sim, w, ps / w);
  printf("# %s: %llu steps, %llu list rebuilds, %ld pairs in the list, %ld bonds, ledger residual %.2e\n",
         name, s.steps - steps0, s.rebuilds, s.npair, wg_td_bond_total(&s), wg_td_ledger_residual(&s));
  wg_td_free(&s);
  return ps / w;
}

/* Two unit-mass disks of diameter 1 in a periodic 2D box, approaching (u < 0) or separating
   (u > 0) along x from contact; returns the relative speed after 1 time unit. */
static double pair_after(const wg_td_params *par, double u, double gap0)
{
  double r[6] = {8, 10, 0, 9 + gap0, 10, 0}, v[6] = {-0.5 * u, 0, 0, 0.5 * u, 0, 0}, rad[2] = {0.5, 0.5};
  wg_td s;
  if (wg_td_alloc_state(&s, par, 2, r, v, rad, NULL, 0) != WG_OK) exit(1);
  wg_td_advance(&s, 1);
  double du = s.v[3] - s.v[0];
  wg_td_free(&s);
  return du;
}

static void accuracy_table(void)
{
  double t_c = 0.005, f_b = 4, s_crit = 0.0711, e_cb = f_b * s_crit;
  printf("# accuracy against cost, two bodies, t_c = %g\n", t_c);
  printf("k\tdt\trestitution_rel_err\trupture_energy_rel_err\tus_per_time_unit\tintegrator\n");
  const int ks[] = {10, 20, 50, 100, 200, 400};
  for (int q = 0; q < 12; q++) {
    wg_td_params p;
    periodic_box(&p, 2, t_c / ks[q % 6]);
    p.integrator = q < 6 ? WG_TD_VERLET : WG_TD_GEAR;
    /* contacts start and end anywhere between steps: errors are averaged over 8 phases of
       the start against the step grid (the pair closes by 2 dt per step) */
    double w0 = now_s(), err_e = 0, err_b = 0;
    for (int j = 0; j < 8; j++) {
      p.pp = p.pw = wg_contact_linear(0.9, t_c, 0.5);
      p.f_b = 0;
      p.s_crit = 0;
      double e = pair_after(&p, -2.0, 0.05 + 2.0 * p.dt * (j + 0.5) / 8) / 2.0;
      err_e += fabs(e - 0.9) / 0.9 / 8;
      p.pp = p.pw = wg_contact_linear(1.0, t_c, 0.5);
      p.f_b = f_b;
      p.s_crit = s_crit;
      double u = sqrt(2 * 3 * e_cb / 0.5) * (1 + 0.0137 * j), du = pair_after(&p, u, -1e-6);
      err_b += fabs(0.5 * 0.5 * (u * u - du * du) - e_cb) / e_cb / 8;
    }
    double w = (now_s() - w0) / 16; /* per pair run of one time unit */
    printf("%d\t%.3g\t%.3e\t%.3e\t%.1f\t%s\n", ks[q % 6], p.dt, err_e, err_b, 1e6 * w, q < 6 ? "verlet" : "gear");
  }
}

/* Friction against its closed forms as dt = t_c / k: (a) two elastic spheres meeting
   off-centre with a sticking, undamped tangential spring (k_t = 2/7 k_n) leave with their
   contact point's tangential velocity reversed exactly (beta = 1; test_friction.c), averaged
   over 8 phases of the contact's start against the step grid; (b) a sphere sliding on a
   floor (mu = 0.3, v0 = 2) rolls on at 5/7 v0. */
static void friction_table(void)
{
  double t_c = 0.005;
  printf("# friction accuracy against cost, t_c = %g (velocity Verlet and Gear)\n", t_c);
  printf("k\tintegrator\tdt\ttangential_restitution_err\trolling_speed_rel_err\tus_per_time_unit\n");
  const int ks[] = {10, 20, 50, 100, 200, 400};
  for (int ig = WG_TD_VERLET; ig <= WG_TD_GEAR; ig++)
  for (int q = 0; q < 6; q++) {
    wg_td_params p;
    periodic_box(&p, 3, t_c / ks[q]);
    p.integrator = ig;
    p.pp = wg_contact_linear(1.0, t_c, 0.5);
    p.pw = wg_contact_linear(0.5, t_c, 1.0);
    p.fric = p.fric_wall = (wg_friction){1e6, 2.0 / 7, 0, 0};
    double w0 = now_s(), err_b = 0, t_run = 0;
    for (int j = 0; j < 8; j++) {
      double gap0 = 0.02 + 1.0 * p.dt * (j + 0.5) / 8; /* the pair closes by 1 per time unit */
      double r[6] = {8, 10, 10, 9 + gap0, 10, 10}, v[6] = {0.5, 0.2, 0, -0.5, -0.2, 0}, rad[2] = {0.5, 0.5};
      wg_td s;
      if (wg_td_alloc_state(&s, &p, 2, r, v, rad, NULL, 0) != WG_OK) exit(1);
      wg_td_advance(&s, 0.1);
      t_run += 0.1;
      double vt = s.v[4] - s.v[1] - 0.5 * (s.w[2] + s.w[5]);
      err_b += fabs(-vt / -0.4 - 1) / 8;
      wg_td_free(&s);
    }
    /* a sphere sliding on a floor */
    resting_floor(&p, 10);
    p.fric = p.fric_wall = (wg_friction){0.3, 2.0 / 7, 1, 0};
    double r[3] = {5, 5, 0.5 - 1 / p.pw.k}, v[3] = {2, 0, 0}, rad[1] = {0.5};
    wg_td s;
    if (wg_td_alloc_state(&s, &p, 1, r, v, rad, NULL, 0) != WG_OK) exit(1);
    double t_roll = 2 * (1 - 5.0 / 7) / 0.3;
    wg_td_advance(&s, 2 * t_roll);
    t_run += 2 * t_roll;
    double err_v = fabs(s.v[0] / 2 - 5.0 / 7) / (5.0 / 7);
    wg_td_free(&s);
    double w = (now_s() - w0) / t_run;
    printf("%d\t%s\t%.3g\t%.3e\t%.3e\t%.1f\n", ks[q], ig == WG_TD_GEAR ? "gear" : "verlet", p.dt, err_b,
           err_v, 1e6 * w);
  }
}

int main(int argc, char **argv)
{
  double t3 = argc > 1 ? atof(argv[1]) : 0.5, t2 = argc > 2 ? atof(argv[2]) : 5;
  printf("case\tengine\tn\tsim_time\twall_s\trate\tunit\n");
  const char *bed_dry[] = {"engine=td", "dim=3", "n=10000", "lx=55.57", "ly=55.57", "height=8", "sigma_p=0.06",
                           "eps=0.9", "eps_wall=0.9", "gamma=4", "estar_d=2", "tg_init_abs=1",
                           "seed=1", "t_end=1", NULL};
  const char *bed_wet[] = {"engine=td", "dim=3", "n=10000", "lx=55.57", "ly=55.57", "height=8", "sigma_p=0.06",
                           "eps=0.9", "eps_wall=0.9", "gamma=4", "estar=2", "s_crit=0.0711",
                           "f_b=16", "tg_init=1", "seed=1", "t_end=1", NULL};
  const char *bed_rough[] = {"engine=td", "dim=3", "n=10000", "lx=55.57", "ly=55.57", "height=8", "sigma_p=0.06",
                             "eps=0.9", "eps_wall=0.9", "gamma=4", "estar_d=2", "tg_init_abs=1",
                             "seed=1", "t_end=1", "mu=0.5", "gt_ratio=0.5", NULL};
  double dry = td_bed("bed3d_N1e4_dry", bed_dry, t3);
  td_bed("bed3d_N1e4_wet", bed_wet, t3);
  double rough = td_bed("bed3d_N1e4_friction", bed_rough, t3);
  printf("# bed3d_N1e4: friction (mu = 0.5, rotation, spring history) costs %.2f x the frictionless step\n", dry / rough);

  const char *coex[] = {"dim=2", "n=1200", "lx=400", "height=9", "sigma_p=0.06", "s_crit=0.0711",
                        "f_b=4", "gamma=15", "estar=1.42", "tg_init=20", "seed=1", "t_end=100", NULL};
  wg_scene sc;
  if (scene(&sc, coex)) return 1;
  wg_ed ed;
  if (wg_ed_alloc(&ed, &sc) != WG_OK) return 1;
  wg_ed_advance(&ed, WARM); /* into coexistence, out of the timing */
  double w0 = now_s();
  wg_ed_advance(&ed, WARM + t2);
  double w_ed = now_s() - w0;
  printf("coexistence2d\ted\t%ld\t%g\t%.3f\t%.4g\twall_s_per_time_unit\n", ed.n, t2, w_ed, w_ed / t2);
  /* the time-driven engine takes over the state the event-driven one has reached (bonds
     form again at contact) */
  long n = ed.n;
  double *r = calloc(3 * (size_t)n, sizeof *r), *v = calloc(3 * (size_t)n, sizeof *v);
  double *rad = malloc(sizeof *rad * (size_t)n);
  if (!r || !v || !rad) return 1;
  for (long id = 0; id < n; id++) {
    wg_ed_position_of(&ed, id, ed.now, r + 3 * id, v + 3 * id);
    rad[id] = ed.p[ed.slot[id]].radius;
  }
  sc.engine = WG_ENGINE_TD; /* the time-driven engine's defaults for the same physics */
  if (wg_scene_finish(&sc) != WG_OK) return 1;
  wg_td_params par;
  wg_td_params_from_scene(&sc, &par);
  wg_td td;
  if (wg_td_alloc_state(&td, &par, n, r, v, rad, NULL, ed.now) != WG_OK) return 1;
  wg_ed_free(&ed);
  w0 = now_s();
  wg_td_advance(&td, td.t + t2);
  double w_td = now_s() - w0;
  printf("coexistence2d\ttd\t%ld\t%g\t%.3f\t%.4g\twall_s_per_time_unit\n", td.n, t2, w_td, w_td / t2);
  printf("# coexistence2d: time-driven / event-driven cost per simulated time = %.1f (%llu steps, %.4g particle-steps/s)\n",
         w_td / w_ed, td.steps, (double)td.steps * (double)td.n / w_td);
  wg_td_free(&td);
  free(r);
  free(v);
  free(rad);
  accuracy_table();
  friction_table();
  return 0;
}
