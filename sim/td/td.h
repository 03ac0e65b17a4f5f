/* The time-driven engine (thesis Sec. 2.2-2.3): soft disks or spheres with a normal contact
   law (contact.h), the minimal capillary model, gravity, periodic lateral boundaries and a
   floor and lid moving as A sin(w t), integrated by velocity Verlet (default) or the thesis's
   fifth-order Gear predictor-corrector, with a neighbour list (cut-off: contact + s_crit +
   skin, rebuilt when a particle has moved half a skin).

   Minimal capillary model (model.md): a pair bonds when it touches; while bonded it attracts
   with the constant force F_B, overlapping or not, until its gap exceeds s_crit, where the
   bond breaks.  Its potential is F_B * gap (zero at contact), so a rupture takes F_B s_crit
   = E_cb from the pair, as in the thin-thread model.

   Friction (mu > 0 or mu_wall > 0, friction.h): tangential springs with Coulomb's bound at
   every contact, torques, and rotation of uniform disks or spheres, integrated as the
   velocities are (Verlet's kicks, or Gear's predictor-corrector for w' = tau / I).

   Energy ledger: kinetic (with rotation) + gravitational + elastic (with the tangential
   springs) + bond energy now, minus that at t = 0, equals the work of the walls minus the
   dissipation (dashpots, slip, and the bond energy taken by ruptures); the integrals are
   sampled at every force evaluation.  A contact that starts
   between two steps costs an energy error ~ (pi dt / t_c)^2 of the pair's energy, so the
   residual falls faster than dt (measured: by 2.7 when dt halves; tests/test_td.c). */
#ifndef WG_TD_H
#define WG_TD_H

#include "cells.h"
#include "contact.h"
#include "ksum.h"
#include "particle.h"
#include "scene.h"
#include "friction.h"
#include "wall.h"

typedef struct wg_td_params {
  int dim;                 /* 2 or 3; axis dim-1 is the vertical */
  double box[3];           /* lengths of the periodic axes [d] */
  int periodic[3];
  double lo[3], hi[3];     /* extent of the neighbour grid on non-periodic axes [d] */
  double g;                /* gravity along -axis dim-1 */
  int nwalls;              /* 0 or 2: floor (side +1) and lid (side -1) */
  wg_wall wall[2];
  wg_contact pp, pw;       /* particle-particle and particle-wall laws */
  double f_b, s_crit;      /* minimal capillary model; f_b = 0: dry, no bond bookkeeping */
  int wall_bonds;          /* 1: particles bond to the walls too (same F_B, s_crit) */
  double willett;          /* > 0: Willett's law (Eq. 2.9) with s^ = gap * willett
                              (= sqrt(R/V)); 0: constant F_B */
  double dt;               /* time step [sqrt(d/g)] */
  double skin;             /* neighbour-list skin [d] */
  int integrator;          /* WG_TD_VERLET or WG_TD_GEAR */
  wg_friction fric, fric_wall; /* tangential forces (friction.h); mu = 0 on both: no
                              rotation, no spring history */
} wg_td_params;

enum { WG_TD_VERLET = 0, WG_TD_GEAR = 1 };

/* A pair in the neighbour list.  Its state outlives list rebuilds (carried over by identity):
   the bond, the contact and (with friction) the tangential spring in wg_td.spring. */
typedef struct wg_td_pair {
  int32_t i, j;            /* i < j */
  uint8_t bonded;
  uint8_t touching;        /* overlapping at the last force evaluation (counts contacts) */
} wg_td_pair;

typedef struct wg_td {
  wg_td_params par;
  int up;
  long n;
  double *r, *v, *f;       /* n x 3 */
  double *vp;              /* velocities predicted at the full step (n x 3) */
  double *gear;            /* Gear only: scaled derivatives dt^k/k! d^k r/dt^k, k = 2..5
                              (n x 3 x 4); NULL for Verlet */
  double *gear_w;          /* Gear with friction: dt^k/k! d^k w/dt^k, k = 1..4 (n x 3 x 4) */
  double *radius, *mass;   /* mass NULL: every mass is 1 */
  double *w, *wp, *tq;     /* with friction: angular velocities, their prediction at the full
                              step and torques (n x 3; 2D: z only); NULL without */
  wg_spring *spring;       /* with friction: the spring of pair[k] (pair_cap); NULL without */
  wg_spring *wall_spring;  /* with friction: particle i's spring on wall w at 2 i + w */
  double *r_built;         /* positions at the last list build (n x 3) */
  uint8_t *wall_touch;     /* bit w: touching wall w at the last force evaluation;
                              bit w + 2: bonded to wall w */
  double r_max;            /* largest radius */
  wg_td_pair *pair;
  long npair, pair_cap;
  wg_cells cells;
  double t, t0;             /* now = t0 + steps dt */
  unsigned long long steps, rebuilds, captures, ruptures;
  unsigned long long contacts, wall_contacts; /* particle-particle and wall contacts begun */
  /* ledger [m g d] */
  wg_ksum injected_wall, dissipated, dissipated_wall, dissipated_rupt;
  double e0;
  double u_contact, u_bond; /* elastic and bond energy at the last force evaluation */
  double p_wall, p_diss, p_diss_wall; /* their powers there (dashpots: particle, wall) */
  int rot;                  /* friction on: rotation and springs */
} wg_td;

/* The engine's parameters for a finished scene: container, gravity, driving; the contact
   law (contact, t_contact or Hertz's K and hertz_ad, eps and eps_wall as the linear law's
   restitution); the bridge (F_B, s_crit, bridge_law, bridge_volume); dt and skin. */
void wg_td_params_from_scene(const wg_scene *sc, wg_td_params *p);

/* Set up from a finished scene with the event-driven engine's initial state: the same
   lattice, diameters and velocities from the same seed. */
int wg_td_alloc(wg_td *s, const wg_scene *sc);

/* Allocate for n particles and copy positions, velocities, radii, masses (may be NULL: unit
   masses); time t0.  Builds the neighbour list and the first forces. */
int wg_td_alloc_state(wg_td *s, const wg_td_params *par, long n, const double *r,
                      const double *v, const double *radius, const double *mass, double t0);
void wg_td_free(wg_td *s);

/* Bond the listed pairs (ids, two per pair; each must be in the neighbour list, i.e. within
   reach of a bridge) and recompute forces and the ledger's E(0): a run continued from
   another's last snapshot. */
int wg_td_set_bonds(wg_td *s, const int32_t *pairs, long nb);

/* Set the angular velocities (n x 3; 2D: z only) of a run with friction and recompute
   forces and the ledger's E(0): bodies spinning at the start. */
int wg_td_set_angular_velocities(wg_td *s, const double *w);

/* Advance by whole steps of dt until t >= t_stop (to within dt / 2). */
int wg_td_advance(wg_td *s, double t_stop);

/* Kinetic, gravitational, elastic and bond energy now [m g d]. */
void wg_td_energy(const wg_td *s, double *kinetic, double *potential);
/* |E(now) - E(0) - injected + dissipated| / (largest of |E|, injected, dissipated, 1e-300). */
double wg_td_ledger_residual(const wg_td *s);
/* Number of bonded pairs. */
long wg_td_bond_total(const wg_td *s);
/* Bond energy of a bonded pair at gap s (zero at contact): F_B s (constant law, and during
   overlap) or the integral of Eq. 2.9. */
double wg_td_bond_energy(const wg_td_params *p, double gap);
/* Bytes of engine memory per particle (arrays and neighbour list). */
double wg_td_bytes_per_particle(const wg_td *s);

#endif
