/* The event-driven engine: hard disks (dim 2) or spheres (dim 3) with the thin-thread
   capillary bridge model, restitution with the TC model, gravity, periodic lateral
   boundaries and a container whose floor and lid move as A sin(w t) (thesis Ch. 2, App. B).
   Particles are updated lazily: each keeps its own time t and is moved only when it takes
   part in an event.  Each particle holds its earliest physical event (collision, bridge
   edge, wall) and its next cell crossing; a tournament tree orders the particles. */
#ifndef WG_ED_H
#define WG_ED_H

#include "cells.h"
#include "ksum.h"
#include "particle.h"
#include "evqueue.h"
#include "nlist.h"
#include "scene.h"
#include "shear.h"
#include "wall.h"



/* A particle's next events and the counter that validates them: what an event reads and
   writes of a particle besides its trajectory, in one 32-byte record (half a cache line). */
typedef struct wg_evrec {
  double t_phys;           /* earliest physical event */
  double t_cell;           /* next cell crossing (with neighbour lists: next relist) */
  int32_t partner;         /* partner particle, or wall index, or bin step */
  uint32_t partner_count;  /* the partner's count when the event was predicted */
  uint32_t count;          /* this particle's trajectory changes (validates others' predictions) */
  uint8_t type;            /* wg_event_type of t_phys */
  int8_t axis, dir;        /* face of the cell crossing */
} wg_evrec;

typedef enum {
  WG_EV_NONE = 0,
  WG_EV_COLLISION,     /* hard-core contact of a pair */
  WG_EV_BRIDGE_EDGE,   /* bonded pair reaches gap s_crit: rupture or reflection */
  WG_EV_WALL_HIT,      /* contact with floor (partner 0) or lid (partner 1) */
  WG_EV_WALL_ENTER,    /* enters a wall's reach: solve for the exact contact then */
  WG_EV_CELL,          /* cell crossing (bookkeeping) */
  WG_EV_BIN,           /* crossing into the next bin of the shear field (partner: +1 / -1) */
  WG_EV_LIFT_OFF       /* a particle resting on the floor leaves it (floor acceleration -g) */
} wg_event_type;

/* Counts of every event type; the ledger of energy. */
typedef struct wg_counts {
  unsigned long long collisions, captures, ruptures, reflections, wall_hits, wall_enters,
      cell_crossings,         /* bookkeeping events: cell crossings, or relists (shell > 0) */
      stale,                  /* popped predictions whose partner had moved on */
      rigid,                  /* collisions at one instant in a rigid cluster (RIGID_TIME) */
      grazing,                /* bridge reflections raised to GRAZING_ANGLE */
      bin_crossings,          /* crossings between the shear field's bins */
      rests,                  /* floor contacts that came to rest (rest_speed) */
      lift_offs,              /* resting particles that left the floor */
      kicks;                  /* instants at which the random force kicked every particle */
} wg_counts;

/* Energy ledger [m g d], compensated sums. */
typedef struct wg_ledger {
  wg_ksum injected_wall;     /* work done by the moving walls */
  wg_ksum dissipated_coll;   /* lost in inelastic particle collisions */
  wg_ksum dissipated_wall;   /* lost in inelastic wall collisions */
  wg_ksum dissipated_rupt;   /* taken by bridge ruptures, E_cb each */
  wg_ksum injected_field;    /* work of the shear field, booked when a particle moves */
  wg_ksum injected_noise;    /* work of the random kicks (noise > 0) */
  double e0;                 /* kinetic + potential energy at t = 0 */
  double scale;              /* largest kinetic + |potential| energy seen; for the residual */
} wg_ledger;

typedef struct wg_ed {
  const wg_scene *sc;
  int dim, up;                 /* up = dim - 1: the vertical axis */
  long n;
  double g;                    /* gravity */
  double box[3];               /* box lengths (periodic axes) */
  int periodic[3];
  int nwalls;                  /* 0 (periodic) or 2 (floor, lid) */
  wg_wall wall[2];
  int wet;                     /* bridges in use */
  double s_crit, e_cb;
  int bond_cap;                /* bonds per particle */
  int inelastic;               /* eps < 1 or eps_wall < 1: TC bookkeeping */
  double eps, eps_wall, tc, grazing_angle;
  double wall_min_speed;       /* least speed of a particle leaving a wall (see wall_collide) */
  /* Resting contacts (scene key rest_speed > 0): riding[i] = 1 while particle i rests on the
     floor and moves with it (docs/engines.md, "Resting on the floor"); NULL when off, and then
     nothing of it runs. */
  double rest_speed;
  uint8_t *riding;
  /* The cosine shear field (shear.h): NULL when the scene has none.  While it acts
     (sheared = 1) every free flight, prediction and the ledger use each particle's own
     acceleration (gravity + its bin's force / m) in functions of their own; sheared = 0
     runs exactly today's code. */
  wg_shear *shear;
  int sheared;
  int32_t *bin;                /* bin of each particle (with a field) */
  /* The random force (scene key noise > 0; thesis Sec. 2.4.2, Eq. 2.12): every noise_dt each
     particle's velocity takes a Gaussian kick of variance 2 noise noise_dt per axis, less the
     mass-weighted mean kick (docs/engines.md, "Random force").  Kick k falls at k noise_dt. */
  double noise, noise_dt;

  /* Particles are stored in slots, renumbered in cell order at every synchronisation so that
     neighbours sit close in memory; id[slot] is the particle's fixed identity (input order,
     output order), slot[id] its current slot. */
  wg_particle *p;
  int32_t *id, *slot;
  double *mass;                /* NULL: every mass is 1 */
  double *t_last;              /* time of the last collision (TC model); NULL when elastic */
  int32_t *bond;               /* bond[i * bond_cap + k]: partners of i; NULL when dry */
  uint8_t *nbond;

  wg_evrec *ev;                /* next events of each particle, one record each */
  double *key;                 /* min(t_phys, t_cell) of ev[]: the queue's leaves, kept apart so
                                  that a group of 8 is one cache line */

  wg_cells cells;              /* with neighbour lists: of the list centres */
  /* 1: a pair's periodic image is its cell's (wg_cells_stencil_images), exact because every
     grain lies in its cell (cells.images_exact, and no periodic axis along gravity, where a
     grain that turns round may stay in the cell above: cells.turn_back) */
  int cell_images;
  int gather;                  /* stencils in two passes, records fetched ahead (large systems) */
  /* Neighbour lists (scene key shell > 0; nlist.h): each particle's events come from its list,
     and it is listed anew (a "relist", in place of cell crossings) when it leaves the region
     around its list centre.  listed = 0: the cells' stencils and cell crossings instead. */
  int listed;
  wg_nlist nl;
  wg_evqueue queue;
  double now;                  /* time of the event being processed */
  wg_counts counts;
  wg_ledger ledger;
  double virial;               /* sum over collisions of sigma_ij |J| (pressure, Eq. of state) */
  wg_wall_stats wall_stats;
  unsigned long long zero_time_run; /* consecutive events within a burst (stuck guard) */
  double burst_start;               /* time of the burst's first event */
  unsigned long long since_sync;    /* events since the last synchronisation */
  unsigned long long sync_interval; /* synchronise (and renumber) after this many events */
  /* the observer of wg_ed_set_watch(); check_at = min(sync_interval, watch_at) keeps the event
     loop at one comparison per event for both */
  int (*watch)(void *user);
  void *watch_user;
  unsigned long long watch_at;      /* since_sync at which the watch is next called */
  unsigned long long check_at;
} wg_ed;

/* Set up from a finished scene: allocate, place particles on a lattice with Gaussian
   velocities (seeded RNG), predict all events. */
int wg_ed_alloc(wg_ed *s, const wg_scene *sc);
void wg_ed_free(wg_ed *s);

/* Build with given particle state (particle k of the arrays gets identity k) (positions, velocities, radii, local times all equal to
   t0) instead of the lattice: used by tests and checkpoint resume.  Radii and, if non-NULL,
   masses are copied. */
int wg_ed_alloc_state(wg_ed *s, const wg_scene *sc, long n, const double *r, const double *v,
                      const double *radius, const double *mass, double t0);

/* The two halves of wg_ed_alloc, for callers that set the state themselves (checkpoint
   resume): allocate for n particles; then, after p[], mass[], bonds and t_last are filled,
   build the cells and predict every event with all local times equal to t0.  The energy
   ledger starts from the energy at t0. */
int wg_ed_alloc_empty(wg_ed *s, const wg_scene *sc, long n);
int wg_ed_start(wg_ed *s, double t0);

/* Process events until the next one would lie beyond t_stop; then now = t_stop. */
int wg_ed_advance(wg_ed *s, double t_stop);

/* Have wg_ed_advance() call watch(user) every WG_ED_WATCH_EVENTS events (cell crossings
   included), e.g. to report progress or notice a run that stalls between two sampling times.
   The watch may read the state (counts, now) but must not change it; a return other than
   WG_OK stops the advance with that status.  NULL removes it. */
enum { WG_ED_WATCH_EVENTS = 65536 };
void wg_ed_set_watch(wg_ed *s, int (*watch)(void *user), void *user);

/* Bring every particle to time now, wrap positions into the box, renumber the slots in cell
   order, rebuild the cells and predict every event afresh.  The state after this depends
   only on the particle states, so a checkpointed run resumes bit-identically.  Runs also do
   this every sync_interval events (16 N), to keep neighbours close in memory. */
int wg_ed_synchronize(wg_ed *s);

/* Position and velocity of the particle in slot i extrapolated to time t (no state change). */
void wg_ed_position_at(const wg_ed *s, long i, double t, double *r, double *v);
/* The same for the particle with identity id (input and output order). */
static inline void wg_ed_position_of(const wg_ed *s, long id, double t, double *r, double *v)
{
  wg_ed_position_at(s, s->slot[id], t, r, v);
}

static inline double wg_ed_mass(const wg_ed *s, long i) { return s->mass ? s->mass[i] : 1.0; }

/* Work done by the walls since t = 0 up to now (booked plus the floor's work on resting
   particles since their local times) [m g d]. */
double wg_ed_wall_work(const wg_ed *s);

/* Kinetic and potential energy of the whole system at time now [m g d]. */
void wg_ed_energy(const wg_ed *s, double *kinetic, double *potential);
/* |E(now) - E(0) - injected + dissipated| / energy scale. */
double wg_ed_ledger_residual(wg_ed *s);

/* Work done by the shear field since t = 0 up to now (booked plus the flights in progress)
   [m g d]; 0 without a field. */
double wg_ed_field_work(const wg_ed *s);

/* Bytes allocated by the engine (particles, events, queue, cells, bonds). */
size_t wg_ed_bytes(const wg_ed *s);

/* Bond bookkeeping (wet runs). */
int wg_ed_bonded(const wg_ed *s, long i, long j);
long wg_ed_bond_total(const wg_ed *s);

#endif
