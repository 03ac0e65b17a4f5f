/* Flat walls moving sinusoidally, z_w(t) = c + A sin(w t), and the exact time at which a
   ballistic particle under gravity meets one (thesis App. B).  The particle–wall gap is
       gap(tau) = side * (z(tau) - z_w(t0 + tau)) - R,   z(tau) = z0 + v0 tau - g tau^2 / 2,
   side = +1 for a floor (particle above it), -1 for a lid (particle below it).
   gap'' = side * (-g + A w^2 sin(w t)) vanishes where sin(w t) = g / (A w^2) = 1 / Gamma:
   closed form, twice per period.  Between those points gap' is monotonic, so it has at most
   one zero there (found by safeguarded Newton–bisection); between the zeros of gap' the gap
   is monotonic and holds at most one root, found the same way.  The result is exact to
   round-off and costs a few pieces per call, independent of any time resolution. */
#ifndef WG_WALL_H
#define WG_WALL_H

#include "wg.h"

typedef struct wg_wall {
  double c;       /* mean position of the wall [d] */
  double A;       /* amplitude [d], >= 0 */
  double omega;   /* angular frequency [sqrt(g/d)], > 0 when A > 0 */
  int side;       /* +1 floor (particle above), -1 lid (particle below) */
} wg_wall;

/* Vertical motion of a particle from its local time t0 on. */
typedef struct wg_ballistic {
  double t0;      /* absolute time of the reference point */
  double z0;      /* centre height at t0 [d] */
  double v0;      /* vertical velocity at t0 */
  double g;       /* gravity >= 0 (acts towards -z) */
  double R;       /* particle radius */
} wg_ballistic;

/* Counters of the solver's work, for benchmarks; every solver call takes one (may be NULL). */
typedef struct wg_wall_stats {
  unsigned long long calls;        /* solver calls */
  unsigned long long pieces;       /* monotonic pieces examined */
  unsigned long long evaluations;  /* evaluations of the gap or its derivatives */
} wg_wall_stats;

typedef enum {
  WG_WALL_NONE = 0,  /* no contact ever (only possible with g = 0 or no wall motion towards it) */
  WG_WALL_HIT = 1,   /* *tau is the contact time: gap crosses zero while closing */
  WG_WALL_ENTER = 2  /* *tau is when the particle next enters the wall's reach; call again then */
} wg_wall_outcome;

/* Wall position and velocity at absolute time t (phase reduced modulo 2 pi first). */
double wg_wall_position(const wg_wall *w, double t);
double wg_wall_velocity(const wg_wall *w, double t);

/* Acceleration of the wall at absolute time t. */
double wg_wall_acceleration(const wg_wall *w, double t);

/* A particle resting on a floor (side +1) rides it while the floor's acceleration stays above
   -g and leaves it where the acceleration falls through -g: the first time after t at which
   sin(w t) rises through 1/Gamma.  INFINITY for Gamma <= 1 (at Gamma = 1 the acceleration
   touches -g at the top of the stroke, and the floor, curving away more slowly than the free
   parabola, catches the particle at once), for a lid or a wall at rest. */
double wg_wall_lift_off_time(const wg_wall *w, double g, double t);

/* The first time after t at which the wall's position c + A sin(w t) passes `level` while
   rising (rising = 1) or falling (0); INFINITY if it never does. */
double wg_wall_level_time(const wg_wall *w, double t, double level, int rising);

/* Next wall event of particle p, tau >= 0 measured from p->t0.  The wall's reach is the slab
   swept by the wall (|z - c| <= A plus the radius).  Outside it the particle gets only the
   analytic entry time (WG_WALL_ENTER); inside it the exact first root is searched until the
   particle leaves the reach again (then WG_WALL_ENTER with the re-entry time, or NONE).
   If the gap is already <= 0 and closing, returns HIT with tau = 0 (App. B.5.6 overlap rule).
   Returns the outcome; *tau is set for HIT and ENTER. */
wg_wall_outcome wg_wall_next_event(const wg_wall *w, const wg_ballistic *p, double *tau,
                                   wg_wall_stats *st);

/* Exact first root within [0, tau_max] regardless of reach (the core of the above):
   returns 1 and sets *tau when the gap crosses zero while closing, else 0. */
int wg_wall_first_root(const wg_wall *w, const wg_ballistic *p, double tau_max, double *tau,
                       wg_wall_stats *st);

/* The brute-force method of thesis App. B.3, kept as the baseline for benchmarks:
   scan tau = k * dt_scan for a sign change of the gap, then bisection–Newton in the
   bracket.  Returns 1 and *tau if a root is found before tau_max, else 0. */
int wg_wall_first_root_scan(const wg_wall *w, const wg_ballistic *p, double dt_scan,
                            double tau_max, double *tau, wg_wall_stats *st);


#endif
