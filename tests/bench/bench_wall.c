/* Benchmark of the exact wall solver against the brute-force scan of thesis App. B.3
   (cf. Fig. B.10) on the trajectories of a realistic shaker: particles of diameter 1 within
   a few diameters of a floor driven at Gamma = 15 (A = 0.054, omega = 16.7, g = 1) and at
   Gamma = 1000 (same A), thermal velocities ~ 1.  Each set is timed for
     exact_first_root   wg_wall_first_root, tau_max = 100 T_driv
     exact_next_event   wg_wall_next_event, following ENTER events to the HIT
     scan_T/1000        wg_wall_first_root_scan, dt_scan = T_driv / 1000, same tau_max
   over the same trajectories, and the results are compared: a disagreement beyond 1e-9
   relative can only be a grazing shot that the scan steps over (reported).
   Output: tab-separated rows  gamma, method, calls, ns_per_call, evaluations_per_call
   (a call is one contact-time query per trajectory; for next_event the whole chain), then
   the ratio scan / exact (time, evaluations); lines starting with # are comments.  Usage: bench_wall [n15 [n1000]]. */
#define _POSIX_C_SOURCE 200809L

#include "wall.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define TWO_PI 6.28318530717958647692528676655900577
#define AGREE_REL 1e-9

typedef struct rng {
  uint64_t state;
} rng;

static uint64_t rng_next(rng *r) /* splitmix64 */
{
  uint64_t z = (r->state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

static double uniform(rng *r) { return ((double)(rng_next(r) >> 11) + 0.5) * 0x1.0p-53; }

static double gaussian(rng *r) /* Box–Muller */
{
  return sqrt(-2.0 * log(uniform(r))) * cos(TWO_PI * uniform(r));
}

static double now_ns(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return 1e9 * (double)ts.tv_sec + (double)ts.tv_nsec;
}

typedef struct result {
  int hit;
  double tau;
} result;

static void print_row(double gamma, const char *method, size_t calls, double ns,
                     const wg_wall_stats *st)
{
  printf("%g\t%s\t%zu\t%.1f\t%.1f\n", gamma, method, calls, ns / (double)calls,
         (double)st->evaluations / (double)calls);
}

/* Follows next_event through ENTER events (ballistic propagation) to HIT or NONE. */
static result follow_next_events(const wg_wall *w, wg_ballistic p, wg_wall_stats *st)
{
  result r = {0, 0.0};
  double elapsed = 0.0;
  for (int k = 0; k < 100; k++) {
    double tau = 0.0;
    wg_wall_outcome o = wg_wall_next_event(w, &p, &tau, st);
    if (o == WG_WALL_NONE) return r;
    if (o == WG_WALL_HIT) {
      r.hit = 1;
      r.tau = elapsed + tau;
      return r;
    }
    p.z0 = p.z0 + tau * (p.v0 - 0.5 * p.g * tau);
    p.v0 = p.v0 - p.g * tau;
    p.t0 = p.t0 + tau;
    elapsed += tau;
  }
  return r;
}

static int run_set(double gamma, size_t n, uint64_t seed)
{
  wg_wall w = {0.0, 0.054, sqrt(gamma / 0.054), +1};
  double T = TWO_PI / w.omega, tau_max = 100.0 * T;
  wg_ballistic *p = malloc(n * sizeof *p);
  result *exact = malloc(n * sizeof *exact), *chain = malloc(n * sizeof *chain);
  result *scan = malloc(n * sizeof *scan);
  if (!p || !exact || !chain || !scan) {
    fprintf(stderr, "bench_wall: out of memory\n");
    free(p), free(exact), free(chain), free(scan);
    return 1;
  }
  rng g = {seed};
  for (size_t i = 0; i < n; i++) {
    p[i].g = 1.0;
    p[i].R = 0.5;
    p[i].t0 = 1000.0 * uniform(&g);
    /* between the wall and 3 diameters above the top of its reach */
    double zw = wg_wall_position(&w, p[i].t0);
    p[i].z0 = zw + p[i].R + 1e-9 + (w.c + w.A + 3.0 - zw) * uniform(&g);
    p[i].v0 = gaussian(&g);
  }

  wg_wall_stats se = {0, 0, 0}, sc = {0, 0, 0}, ss = {0, 0, 0};
  double t_a = now_ns();
  for (size_t i = 0; i < n; i++)
    exact[i].hit = wg_wall_first_root(&w, &p[i], tau_max, &exact[i].tau, &se);
  double t_b = now_ns();
  for (size_t i = 0; i < n; i++) chain[i] = follow_next_events(&w, p[i], &sc);
  double t_c = now_ns();
  for (size_t i = 0; i < n; i++)
    scan[i].hit = wg_wall_first_root_scan(&w, &p[i], T / 1000.0, tau_max, &scan[i].tau, &ss);
  double t_d = now_ns();

  print_row(gamma, "exact_first_root", n, t_b - t_a, &se);
  print_row(gamma, "exact_next_event", n, t_c - t_b, &sc);
  print_row(gamma, "scan_T/1000", n, t_d - t_c, &ss);
  printf("#\tgamma %g: %llu next_event calls for %zu trajectories (ENTER then HIT)\n", gamma,
         sc.calls, n);
  printf("%g\tratio_scan/exact_first_root\t%zu\t%.1f\t%.1f\n", gamma, n,
         (t_d - t_c) / (t_b - t_a), (double)ss.evaluations / (double)se.evaluations);

  /* agreement */
  size_t disagree = 0, grazes_missed = 0, chain_disagree = 0;
  double chain_dev = 0.0;
  for (size_t i = 0; i < n; i++) {
    /* re-calling at propagated times t0 + tau (t0 up to 1000) rounds the absolute time to
       ulp(t0) ~ 1e-13, so the chain agrees to ~1e-12 relative, not to the last bit */
    if (chain[i].hit && exact[i].hit && chain[i].tau <= tau_max) {
      double dev = fabs(chain[i].tau - exact[i].tau) / fmax(exact[i].tau, T);
      if (dev > chain_dev) chain_dev = dev;
    }
    if (chain[i].hit && chain[i].tau > tau_max) chain[i].hit = 0; /* beyond the horizon */
    if (chain[i].hit != exact[i].hit ||
        (exact[i].hit && fabs(chain[i].tau - exact[i].tau) > AGREE_REL * fmax(exact[i].tau, T)))
    {
      chain_disagree++;
      if (chain_disagree <= 5)
        printf("#\tchain disagreement: z0 %.17g v0 %.17g t0 %.17g: first_root %d %.17g, "
               "next_event chain %d %.17g\n", p[i].z0, p[i].v0, p[i].t0, exact[i].hit,
               exact[i].tau, chain[i].hit, chain[i].tau);
    }
    int same = scan[i].hit == exact[i].hit &&
               (!exact[i].hit ||
                fabs(scan[i].tau - exact[i].tau) <= AGREE_REL * fmax(exact[i].tau, T));
    if (same) continue;
    disagree++;
    /* the scan steps over a graze: the exact solver's contact comes first */
    int graze = exact[i].hit && (!scan[i].hit || scan[i].tau > exact[i].tau);
    if (graze) grazes_missed++;
    if (disagree <= 5) {
      double th = fmod(w.omega * p[i].t0, TWO_PI) + w.omega * exact[i].tau;
      double v_rel = p[i].v0 - p[i].g * exact[i].tau - w.A * w.omega * cos(th);
      printf("#\tdisagreement: z0 %.6f v0 %.6f: exact %s %.12g (impact speed %.2e), scan %s "
             "%.12g%s\n",
             p[i].z0, p[i].v0, exact[i].hit ? "hit" : "none", exact[i].tau, fabs(v_rel),
             scan[i].hit ? "hit" : "none", scan[i].tau, graze ? " [graze missed by scan]" : "");
    }
  }
  printf("#\tgamma %g: scan disagrees with exact in %zu of %zu (%zu grazes missed by the "
         "scan, %zu other); next_event chain disagrees in %zu (max rel dev %.1e)\n",
         gamma, disagree, n, grazes_missed, disagree - grazes_missed, chain_disagree,
         chain_dev);
  free(p), free(exact), free(chain), free(scan);
  return disagree != grazes_missed || chain_disagree != 0;
}

int main(int argc, char **argv)
{
  size_t n15 = argc > 1 ? (size_t)strtoul(argv[1], NULL, 10) : 20000;
  size_t n1000 = argc > 2 ? (size_t)strtoul(argv[2], NULL, 10) : 2000;
  printf("gamma\tmethod\tcalls\tns_per_call\tevaluations_per_call\n");
  int bad = run_set(15.0, n15, 0x5eed15u);
  bad |= run_set(1000.0, n1000, 0x5eed1000u);
  return bad;
}
