/* Event-driven engine: set-up, prediction and processing of events.  Equation numbers
   refer to the thesis (Roeller 2010); the bridge and wall rules to ../shared/spec/model.md. */
#include "ed.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_cdf.h>

#include "counter_rng.h"
#include "init.h"

/* Bonds a particle can hold: a disk touches at most 6 equal neighbours, a sphere 12; the
   polydisperse margin and the gap s_crit leave room for a few more. */
enum { BOND_CAP_2D = 8, BOND_CAP_3D = 16 };
/* Consecutive events at one instant beyond which a run is declared stuck. */
#define STUCK_EVENTS 10000000ULL
#define BURST_TIME 1e-4 /* [sqrt(d/g)]: 10^7 events in less than this is no physics */
/* Collisions of a particle closer in time than this to its previous collision belong to one
   instant: a rigid cluster of bonded grains (contacts closed, bridges taut) pressed by a
   dissipative collision.  The TC model would keep them elastic and the cluster would ring
   forever at one instant; they are made perfectly inelastic instead, which projects the
   velocities onto the motions the cluster allows, a few sweeps per jam. */
#define RIGID_TIME 1e-9 /* [sqrt(d/g)] */
/* Normal speeds below this at a closed contact are rest: after a perfectly inelastic
   collision the remaining u_n is round-off, which must not trigger another collision. */
#define REST_SPEED 1e-10 /* [sqrt(g d)] */
/* A bonded pair that reaches gap s_crit with a normal speed below grazing_angle (a scene
   key, default 0.05 rad: about pi / angle reflections per revolution) times its
   relative speed grazes the edge: a rotating taut bridge would bounce ever more often
   (a particle sliding along the inside of a circle), so it leaves at this angle, the
   normal speed taken from the tangential motion (energy and momentum are kept).  A rigid
   cluster spinning on a taut bridge so sheds its spin within ~1/angle^2 reflections; the
   normal energy handed over can rupture a bridge only if 1/2 mu u^2 > E_cb / angle^2. */
/* A floor contact rests only where the floor's acceleration exceeds -g (1 - LIFT_MARGIN). */
#define LIFT_MARGIN 1e-9
/* Without the TC model, the time scale of wall_min_speed [sqrt(d/g)]. */
#define WALL_MIN_TIME 1e-12
/* Most cells per particle of a periodic box (setup_cells). */
#define CELLS_PER_PARTICLE 8.0

/* ---------- small helpers ---------- */

static void *zalloc(size_t n, size_t size, int *fail)
{
  void *p = calloc(n ? n : 1, size);
  if (!p) *fail = 1;
  return p;
}



static inline double dot(const double *a, const double *b, int dim)
{
  double s = a[0] * b[0] + a[1] * b[1];
  return dim == 3 ? s + a[2] * b[2] : s;
}

static inline double reduced_mass(const wg_ed *s, long i, long j)
{
  double mi = wg_ed_mass(s, i), mj = wg_ed_mass(s, j);
  return mi * mj / (mi + mj);
}

/* The shear field's functions are kept out of line and marked cold, and their flag tested
   as unlikely: without a field the hot paths compile nearly as before the field existed
   (callgrind: +0.2 to +0.5 % instructions, a few predicted branches per event). */
#define SHEARED(s) __builtin_expect((s)->sheared, 0)

static void advance_sheared(wg_ed *s, long i, double t) __attribute__((cold, noinline));

/* Resting contacts likewise: RESTING is false unless the scene sets rest_speed. */
#define RESTING(s) __builtin_expect((s)->riding != NULL, 0)
static inline int rides(const wg_ed *s, long i) { return RESTING(s) && s->riding[i]; }
static void advance_rider(wg_ed *s, long i, double t) __attribute__((cold, noinline));

/* Move particle i along its trajectory to time t. */
static void advance(wg_ed *s, long i, double t)
{
  wg_particle *p = &s->p[i];
  double dt = t - p->t;
  if (dt == 0) return;
  if (SHEARED(s)) {
    advance_sheared(s, i, t);
    return;
  }
  if (rides(s, i)) {
    advance_rider(s, i, t);
    return;
  }
  for (int k = 0; k < s->dim; k++) p->r[k] += p->v[k] * dt;
  if (s->g > 0) {
    p->r[s->up] -= 0.5 * s->g * dt * dt;
    p->v[s->up] -= s->g * dt;
  }
  p->t = t;
}

/* ---------- free flight in the shear field ---------- */

/* Acceleration of particle i while the field acts: gravity plus its bin's force / m. */
static inline __attribute__((always_inline)) void accel_of(const wg_ed *s, long i, double *acc)
{
  acc[0] = acc[1] = acc[2] = 0;
  if (s->g > 0) acc[s->up] = -s->g;
  acc[s->shear->axis] += s->shear->force[s->bin[i]] / wg_ed_mass(s, i);
}

/* Position and velocity of particle i at time t on its parabola (no wrapping). */
static inline __attribute__((always_inline)) void flight_at(const wg_ed *s, long i, double t,
                                                           double *r, double *v)
{
  const wg_particle *p = &s->p[i];
  double dt = t - p->t, acc[3];
  accel_of(s, i, acc);
  for (int k = 0; k < 3; k++) {
    r[k] = k < s->dim ? p->r[k] + p->v[k] * dt + 0.5 * acc[k] * dt * dt : 0;
    v[k] = k < s->dim ? p->v[k] + acc[k] * dt : 0;
  }
}

/* Work of the bin's force on the flight of particle i from its local time to t: the force is
   constant along the path, so it is F times the displacement along the field. */
static double field_work_to(const wg_ed *s, long i, double t)
{
  const wg_particle *p = &s->p[i];
  double dt = t - p->t, acc[3];
  accel_of(s, i, acc);
  int a = s->shear->axis;
  return s->shear->force[s->bin[i]] * (p->v[a] * dt + 0.5 * acc[a] * dt * dt);
}

/* Particle i's trajectory from a new reference point (r, v) at time t. */
static void set_reference(wg_ed *s, long i, double t, const double *r, const double *v)
{
  for (int k = 0; k < s->dim; k++) {
    s->p[i].r[k] = r[k];
    s->p[i].v[k] = v[k];
  }
  s->p[i].t = t;
}

typedef void path_fn(const wg_ed *s, long i, double t, double *r, double *v);

/* Move particle i to time t along a path other than the free parabola (the shear field's, the
   floor's), booking the work `work` done on it meanwhile into `account`. */
static void advance_on(wg_ed *s, long i, double t, path_fn *path, wg_ksum *account, double work)
{
  wg_ksum_add(account, work);
  double r[3], v[3];
  path(s, i, t, r, v);
  set_reference(s, i, t, r, v);
}

static void advance_sheared(wg_ed *s, long i, double t)
{
  advance_on(s, i, t, flight_at, &s->ledger.injected_field, field_work_to(s, i, t));
}

double wg_ed_field_work(const wg_ed *s)
{
  if (!s->shear) return 0;
  double w = wg_ksum_value(&s->ledger.injected_field);
  if (s->sheared)
    for (long i = 0; i < s->n; i++) w += field_work_to(s, i, s->now);
  return w;
}

/* ---------- resting on the floor ---------- */

/* A resting particle rides the floor: its height is the floor's plus its radius, its vertical
   velocity the floor's, while it moves freely (without friction) along the floor. */
static void rider_at(const wg_ed *s, long i, double t, double *r, double *v)
{
  const wg_particle *p = &s->p[i];
  double dt = t - p->t;
  for (int k = 0; k < 3; k++) {
    r[k] = k < s->dim ? p->r[k] + p->v[k] * dt : 0;
    v[k] = k < s->dim ? p->v[k] : 0;
  }
  r[s->up] = wg_wall_position(&s->wall[0], t) + p->radius;
  v[s->up] = wg_wall_velocity(&s->wall[0], t);
}

/* Work of the floor on a resting particle from its local time to t: the change of its
   vertical kinetic and potential energy (the floor's force m (a_w + g) times its velocity). */
static double rider_work_to(const wg_ed *s, long i, double t)
{
  const wg_wall *w = &s->wall[0];
  double v0 = wg_wall_velocity(w, s->p[i].t), v1 = wg_wall_velocity(w, t);
  double z0 = wg_wall_position(w, s->p[i].t), z1 = wg_wall_position(w, t);
  return wg_ed_mass(s, i) * (0.5 * (v1 * v1 - v0 * v0) + s->g * (z1 - z0));
}

static void advance_rider(wg_ed *s, long i, double t)
{
  advance_on(s, i, t, rider_at, &s->ledger.injected_wall, rider_work_to(s, i, t));
}

double wg_ed_wall_work(const wg_ed *s)
{
  double w = wg_ksum_value(&s->ledger.injected_wall);
  if (RESTING(s))
    for (long i = 0; i < s->n; i++)
      if (s->riding[i]) w += rider_work_to(s, i, s->now);
  return w;
}

/* Periodic coordinates of r into [0, box) (fmod is exact). */
static void wrap_into_box(const wg_ed *s, double *r)
{
  for (int k = 0; k < s->dim; k++)
    if (s->periodic[k]) {
      r[k] = fmod(r[k], s->box[k]);
      if (r[k] < 0) r[k] += s->box[k];
    }
}

void wg_ed_position_at(const wg_ed *s, long i, double t, double *r, double *v)
{
  const wg_particle *p = &s->p[i];
  double dt = t - p->t;
  if (rides(s, i)) {
    rider_at(s, i, t, r, v);
  } else if (SHEARED(s)) {
    flight_at(s, i, t, r, v);
  } else {
    for (int k = 0; k < s->dim; k++) {
      r[k] = p->r[k] + p->v[k] * dt;
      v[k] = p->v[k];
    }
    if (s->g > 0) {
      r[s->up] -= 0.5 * s->g * dt * dt;
      v[s->up] -= s->g * dt;
    }
  }
  wrap_into_box(s, r);
}

/* Separation dr = r_j - r_i (minimum image) and relative velocity dv = v_j - v_i at the
   later of the two local times, which is returned.  Gravity drops out of relative motion
   except through the different local times. */
static inline double pair_state(const wg_ed *s, long i, long j, double *dr, double *dv)
{
  const wg_particle *a = &s->p[i], *b = &s->p[j];
  double t = a->t > b->t ? a->t : b->t;
  double ta = t - a->t, tb = t - b->t;
  for (int k = 0; k < s->dim; k++) {
    dr[k] = (b->r[k] + b->v[k] * tb) - (a->r[k] + a->v[k] * ta);
    dv[k] = b->v[k] - a->v[k];
  }
  if (s->g > 0) {
    dr[s->up] -= 0.5 * s->g * (tb * tb - ta * ta);
    dv[s->up] -= s->g * (tb - ta);
  }
  for (int k = 0; k < s->dim; k++)
    if (s->periodic[k]) {
      if (dr[k] > 0.5 * s->box[k]) dr[k] -= s->box[k];
      else if (dr[k] < -0.5 * s->box[k]) dr[k] += s->box[k];
    }
  return t;
}

/* ---------- bonds ---------- */

int wg_ed_bonded(const wg_ed *s, long i, long j)
{
  const int32_t *b = s->bond + (size_t)i * s->bond_cap;
  for (int k = 0; k < s->nbond[i]; k++)
    if (b[k] == j) return 1;
  return 0;
}

long wg_ed_bond_total(const wg_ed *s)
{
  long total = 0;
  if (!s->wet) return 0;
  for (long i = 0; i < s->n; i++) total += s->nbond[i];
  return total / 2;
}

static int bond_add_one(wg_ed *s, long i, long j)
{
  if (s->nbond[i] >= s->bond_cap)
    return wg_error(WG_ERANGE, "bridges",
                    "particle %ld would hold more than %d bridges at t = %.17g", i, s->bond_cap,
                    s->now);
  s->bond[(size_t)i * s->bond_cap + s->nbond[i]++] = (int32_t)j;
  return WG_OK;
}

static void bond_remove_one(wg_ed *s, long i, long j)
{
  int32_t *b = s->bond + (size_t)i * s->bond_cap;
  for (int k = 0; k < s->nbond[i]; k++)
    if (b[k] == j) {
      b[k] = b[--s->nbond[i]];
      return;
    }
}

/* ---------- prediction ---------- */

typedef struct candidate {
  double t;
  int type;
  int32_t partner;
} candidate;

static inline void consider(candidate *best, double t, int type, long partner)
{
  if (t < best->t) {
    best->t = t;
    best->type = type;
    best->partner = (int32_t)partner;
  }
}

/* Particle i seen from the present, with the constants of the neighbour loop kept at hand:
   its position and velocity extrapolated to now, computed once and then compared with every
   neighbour. */
typedef struct probe {
  long i;
  double r[3], v[3], radius;
  double now, g, box[3], half[3];
  int periodic[3];
  int bonds;       /* bridges of particle i (wet runs) */
} probe;

static inline void probe_at_now(const wg_ed *s, long i, probe *pr)
{
  const wg_particle *a = &s->p[i];
  double dt = s->now - a->t;
  pr->i = i;
  pr->radius = a->radius;
  pr->now = s->now;
  pr->g = s->g;
  pr->bonds = s->wet ? s->nbond[i] : 0;
  for (int k = 0; k < 3; k++) {
    pr->r[k] = a->r[k] + a->v[k] * dt;
    pr->v[k] = a->v[k];
    pr->box[k] = s->box[k];
    pr->half[k] = 0.5 * s->box[k];
    pr->periodic[k] = k < s->dim && s->periodic[k];
  }
  if (s->g > 0) {
    pr->r[s->up] -= 0.5 * s->g * dt * dt;
    pr->v[s->up] -= s->g * dt;
  }
}

/* The bonded pair's next arrival at the gap s_crit (thin-thread model), given r2 = |dr|^2,
   bdot = dr.dv and a = |dv|^2 at now. */
static void predict_bridge_edge(const wg_ed *s, double now, long j, double sigma, double r2,
                                double bdot, double a, candidate *best)
{
  double edge = sigma + s->s_crit;
  double c = r2 - edge * edge;
  double t;
  if (c >= 0 && bdot > REST_SPEED * edge) {
    t = 0;
  } else if (c >= 0) {
    /* on (or, by round-off, just beyond) the edge, moving in or at rest: back at the far
       root, and not before the pair moves out faster than REST_SPEED (bdot grows as a t) */
    if (a == 0) return;
    double disc = bdot * bdot - a * c;
    t = fmax((-bdot + sqrt(disc > 0 ? disc : 0)) / a, (REST_SPEED * edge - bdot) / a);
  } else {
    if (a == 0) return;
    double disc = bdot * bdot - a * c;
    t = bdot > 0 ? -c / (bdot + sqrt(disc)) : (-bdot + sqrt(disc)) / a;
  }
  consider(best, now + t, WG_EV_BRIDGE_EDGE, j);
}

/* Minimum image of one component of a separation. */
static inline __attribute__((always_inline)) double min_image(double x, double half, double box)
{
  if (x > half) return x - box;
  if (x < -half) return x + box;
  return x;
}

/* t if ok, else INFINITY, without a branch (the compiler turns a ?: into one). */
static inline double keep_or_inf(int ok, double t)
{
  uint64_t bits, inf = 0x7ff0000000000000ULL, mask = -(uint64_t)ok;
  memcpy(&bits, &t, sizeof bits);
  bits = (bits & mask) | (inf & ~mask);
  memcpy(&t, &bits, sizeof t);
  return t;
}

/* Earliest event of the pair (probe, j): hard-core contact while approaching (Eq. B.3), or,
   for a bonded pair, the moment the gap reaches s_crit.  Overlapping pairs that approach
   collide at once; overlapping pairs that separate are left alone (App. B.5.6).  Relative
   motion is free flight: gravity drops out.  dim and wet are constants at each call site, so
   the compiler specialises the code.  This is the engine's hot loop: the separation is kept
   in scalars, and since whether a pair approaches and whether the paths meet are each a coin
   toss, the contact root is computed for every pair and kept or dropped without a branch
   (every operation is the one of the plain formula, in the same order). */
static inline __attribute__((always_inline)) void
pair_events(const wg_ed *s, const probe *pr, long j, double radius_j, double x, double y,
            double z, double u, double v, double w, candidate *best, const int dim, const int wet);

/* How a pair's separation is brought to its periodic image: not at all (no periodic axis
   between the two cells), by the image of j's cell (shift[a], 0 or +-box[a]), or by the
   minimum-image test of each component. */
enum { IMAGE_NONE, IMAGE_OF_CELL, IMAGE_NEAREST };
/* Grains gathered at a time (PAIRS_GATHERED), and the systems that gather: from 2^14
   particles, 1 MiB of records (a core's L2 cache here), gathering gained 1.11x at N = 32 000
   and 1.26x at 2.56e5 (gas, phi = 0.3) and lost 3 % at N = 4000 (docs/benchmarks.md). */
enum { GATHER = 128, GATHER_MIN_N = 16384 };

static inline __attribute__((always_inline)) void
predict_pair(const wg_ed *s, const probe *pr, long j, const double *shift, candidate *best,
             const int dim, const int wet, const int gravity, const int image)
{
  const wg_particle *b = &s->p[j];
  double dt = pr->now - b->t;
  double x = b->r[0] + b->v[0] * dt - pr->r[0], u = b->v[0] - pr->v[0];
  double y = b->r[1] + b->v[1] * dt - pr->r[1], v = b->v[1] - pr->v[1];
  double z = 0, w = 0;
  if (dim == 3) {
    z = b->r[2] + b->v[2] * dt - pr->r[2];
    w = b->v[2] - pr->v[2];
  }
  if (gravity && pr->g > 0) { /* the vertical axis is the last one */
    if (dim == 3) {
      z -= 0.5 * pr->g * dt * dt;
      w -= pr->g * dt;
    } else {
      y -= 0.5 * pr->g * dt * dt;
      v -= pr->g * dt;
    }
  }
  if (image == IMAGE_OF_CELL) { /* x - box is x + (-box): the same bits as min_image */
    x += shift[0];
    y += shift[1];
    if (dim == 3) z += shift[2];
  } else if (image == IMAGE_NEAREST) {
    if (pr->periodic[0]) x = min_image(x, pr->half[0], pr->box[0]);
    if (pr->periodic[1]) y = min_image(y, pr->half[1], pr->box[1]);
    if (dim == 3 && pr->periodic[2]) z = min_image(z, pr->half[2], pr->box[2]);
  }
  pair_events(s, pr, j, b->radius, x, y, z, u, v, w, best, dim, wet);
}

/* The events of the pair (probe, j) from their separation (x, y, z) and relative velocity
   (u, v, w) at now, in free flight relative to each other. */
static inline __attribute__((always_inline)) void
pair_events(const wg_ed *s, const probe *pr, long j, double radius_j, double x, double y,
            double z, double u, double v, double w, candidate *best, const int dim, const int wet)
{
  double bdot = x * u + y * v;
  double r2 = x * x + y * y, a = u * u + v * v;
  if (dim == 3) {
    bdot += z * w;
    r2 += z * z;
    a += w * w;
  }
  double sigma = pr->radius + radius_j;
  double c = r2 - sigma * sigma;
  if (__builtin_expect(c <= 0, 0)) { /* overlap */
    if (bdot < 0) {
      if (bdot < -REST_SPEED * sigma) consider(best, pr->now, WG_EV_COLLISION, j);
    } else if (wet && wg_ed_bonded(s, pr->i, j)) {
      predict_bridge_edge(s, pr->now, j, sigma, r2, bdot, a, best);
    }
    return;
  }
  double disc = bdot * bdot - a * c;
  double t = pr->now + c / (-bdot + sqrt(disc > 0 ? disc : 0));
  int hit = (bdot < 0) & (disc > 0);
  t = keep_or_inf(hit, t);
  if (t < best->t) {
    best->t = t;
    best->type = WG_EV_COLLISION;
    best->partner = (int32_t)j;
  }
  if (wet && !hit && pr->bonds && wg_ed_bonded(s, pr->i, j))
    predict_bridge_edge(s, pr->now, j, sigma, r2, bdot, a, best);
}

static void predict_pairs_sheared(const wg_ed *s, long i, const long *cells, int ncells,
                                  candidate *best) __attribute__((cold, noinline));
static void predict_pairs_resting(const wg_ed *s, long i, const long *cells, int ncells,
                                  candidate *best) __attribute__((cold, noinline));

/* A loop LOOP(DIM, WET) compiled for each (dim, wet), the one of the scene run. */
#define BY_DIM_WET(s, LOOP)                                                                  \
  do {                                                                                       \
    if ((s)->dim == 3) {                                                                     \
      if ((s)->wet) LOOP(3, 1);                                                              \
      else LOOP(3, 0);                                                                       \
    } else {                                                                                 \
      if ((s)->wet) LOOP(2, 1);                                                              \
      else LOOP(2, 0);                                                                       \
    }                                                                                        \
  } while (0)

/* The grains of one cell against the probe, j's image given by IMAGE (shift: the cell's). */
#define CELL_PAIRS(DIM, WET, GRAVITY, IMAGE)                                                 \
  do {                                                                                       \
    for (int32_t j = head[cell]; j >= 0; j = next[j])                                        \
      if (j != i) predict_pair(s, &pr, j, shift, best, DIM, WET, GRAVITY, IMAGE);           \
  } while (0)

/* The loop over the cells, specialised for each (dim, wet) and for gravity; with cell
   images, a cell away from every periodic boundary needs no image at all. */
#define PAIRS_IN(DIM, WET)                                                                   \
  do {                                                                                       \
    for (int k = 0; k < ncells; k++) {                                                       \
      long cell = cells[k];                                                                  \
      if (!cell_images) {                                                                    \
        CELL_PAIRS(DIM, WET, 1, IMAGE_NEAREST);                                              \
        continue;                                                                            \
      }                                                                                      \
      const int8_t *im = image ? image + 3 * k : NULL;                                       \
      if (!im || (im[0] | im[1] | im[2]) == 0) {                                             \
        if (gravity) CELL_PAIRS(DIM, WET, 1, IMAGE_NONE);                                    \
        else CELL_PAIRS(DIM, WET, 0, IMAGE_NONE);                                            \
      } else {                                                                               \
        for (int a = 0; a < 3; a++) shift[a] = im[a] * pr.box[a];                            \
        CELL_PAIRS(DIM, WET, 1, IMAGE_OF_CELL);                                              \
      }                                                                                      \
    }                                                                                        \
  } while (0)

/* The same with no image anywhere, in two passes: the cells' lists walked first, each
   grain's record fetched ahead, then the pairs in the same order.  For large systems, whose
   records are beyond the caches: the loads then overlap instead of following each other. */
#define PAIRS_GATHERED(DIM, WET)                                                             \
  do {                                                                                       \
    int32_t gathered[GATHER];                                                                \
    int m = 0;                                                                               \
    for (int k = 0; k < ncells; k++)                                                         \
      for (int32_t j = head[cells[k]]; j >= 0; j = next[j]) {                                \
        if (j == i) continue;                                                                \
        __builtin_prefetch(&s->p[j]);                                                        \
        gathered[m++] = j;                                                                   \
        if (m == GATHER) {                                                                   \
          for (int q = 0; q < m; q++)                                                        \
            predict_pair(s, &pr, gathered[q], shift, best, DIM, WET, gravity, IMAGE_NONE);   \
          m = 0;                                                                             \
        }                                                                                    \
      }                                                                                      \
    for (int q = 0; q < m; q++)                                                              \
      predict_pair(s, &pr, gathered[q], shift, best, DIM, WET, gravity, IMAGE_NONE);         \
  } while (0)

/* Every pair of particle i with the particles of the given cells; image: the cells'
   periodic images (wg_cells_stencil_images), NULL when none of them lies across a periodic
   boundary (or when the engine takes the nearest image pair by pair: !cell_images). */
static void predict_pairs_in(const wg_ed *s, long i, const long *cells, const int8_t *image,
                             int ncells, candidate *best)
{
  if (SHEARED(s)) {
    predict_pairs_sheared(s, i, cells, ncells, best);
    return;
  }
  if (RESTING(s)) {
    predict_pairs_resting(s, i, cells, ncells, best);
    return;
  }
  probe pr;
  probe_at_now(s, i, &pr);
  const int32_t *head = s->cells.head, *next = s->cells.next;
  const int gravity = pr.g > 0, cell_images = s->cell_images;
  double shift[3] = {0, 0, 0};
  candidate found = *best; /* a local: the loop's stores cannot alias the engine's arrays */
  {
    candidate *best = &found;
    if (cell_images && !image && s->gather) BY_DIM_WET(s, PAIRS_GATHERED);
    else BY_DIM_WET(s, PAIRS_IN);
  }
  *best = found;
}

/* Every pair of particle i with its listed neighbours (neighbour lists). */
#define PAIRS_LISTED(DIM, WET)                                                               \
  do {                                                                                       \
    for (int k = 0; k < m; k++)                                                              \
      predict_pair(s, &pr, nb[k], NULL, best, DIM, WET, 1, IMAGE_NEAREST);                  \
  } while (0)

static void predict_pairs_listed(const wg_ed *s, long i, candidate *best)
{
  probe pr;
  probe_at_now(s, i, &pr);
  const int32_t *nb = s->nl.nb + (size_t)i * s->nl.cap;
  int m = s->nl.nn[i];
  BY_DIM_WET(s, PAIRS_LISTED);
}

/* The events of one pair (probe, j). */
static void predict_pair_of(const wg_ed *s, const probe *pr, long j, candidate *best)
{
#define ONE_PAIR(DIM, WET) predict_pair(s, pr, j, NULL, best, DIM, WET, 1, IMAGE_NEAREST)
  BY_DIM_WET(s, ONE_PAIR);
#undef ONE_PAIR
}

/* The pair (i, j) while the field acts: particles in different bins (or of different
   masses) accelerate relative to each other, and contact and bridge edge are the roots of
   quartics (wg_shear_pair_root); the overlap and edge rules are those of predict_pair. */
static void predict_pair_sheared(const wg_ed *s, long i, const double *ri, const double *vi,
                                 const double *ai, long j, candidate *best)
{
  double rj[3], vj[3], aj[3], dr[3] = {0, 0, 0}, dv[3] = {0, 0, 0}, da[3] = {0, 0, 0};
  flight_at(s, j, s->now, rj, vj);
  accel_of(s, j, aj);
  for (int k = 0; k < s->dim; k++) {
    dr[k] = rj[k] - ri[k];
    dv[k] = vj[k] - vi[k];
    da[k] = aj[k] - ai[k];
    if (s->periodic[k]) {
      if (dr[k] > 0.5 * s->box[k]) dr[k] -= s->box[k];
      else if (dr[k] < -0.5 * s->box[k]) dr[k] += s->box[k];
    }
  }
  double bdot = dot(dr, dv, s->dim);
  int bonded = s->wet && wg_ed_bonded(s, i, j);
  /* receding now and for ever: d.d' is a cubic with no negative coefficient */
  if (!bonded && bdot >= 0 && dot(dv, da, s->dim) >= 0 &&
      dot(dv, dv, s->dim) + dot(dr, da, s->dim) >= 0)
    return;
  double r2 = dot(dr, dr, s->dim);
  double sigma = s->p[i].radius + s->p[j].radius;
  double tau;
  if (r2 - sigma * sigma <= 0) {
    if (bdot < -REST_SPEED * sigma) {
      consider(best, s->now, WG_EV_COLLISION, j);
      return;
    }
  }
  /* Only events before the best one so far matter (horizon T).  Within T the distance stays
     within margin = |da| T^2 / 2 of the unaccelerated |dr + dv tau|, whose least value is
     closed form and whose largest is at an end: pairs that cannot reach sigma (or the edge)
     within T skip the quartic.  SKIP_SAFETY keeps the test clear of round-off. */
  const double SKIP_SAFETY = 1e-9;
  double T = best->t - s->now, a2 = dot(dv, dv, s->dim);
  double margin = isinf(T) ? INFINITY : 0.5 * sqrt(dot(da, da, s->dim)) * T * T;
  double tmin = bdot < 0 && a2 > 0 ? fmin(-bdot / a2, T) : 0;
  double dmin2 = 0, dend2 = 0;
  for (int k = 0; k < s->dim; k++) {
    double x = dr[k] + dv[k] * tmin, y = dr[k] + dv[k] * T;
    dmin2 += x * x;
    dend2 += y * y;
  }
  double reach = sigma * (1 + SKIP_SAFETY) + margin;
  if (!(dmin2 > reach * reach) &&
      wg_shear_pair_root(dr, dv, da, s->dim, sigma, -1, T, &tau))
    consider(best, s->now + tau, WG_EV_COLLISION, j);
  if (!bonded) return;
  double edge = sigma + s->s_crit;
  double t;
  if (r2 - edge * edge >= 0 && bdot > REST_SPEED * edge) {
    t = 0;
  } else if (r2 < edge * edge) { /* inside the well: its edge within T, if at all */
    T = best->t - s->now;
    margin = isinf(T) ? INFINITY : 0.5 * sqrt(dot(da, da, s->dim)) * T * T;
    double far = sqrt(fmax(r2, isinf(T) ? INFINITY : dend2)) + margin;
    if (far < edge * (1 - SKIP_SAFETY)) return;
    if (!wg_shear_pair_root(dr, dv, da, s->dim, edge, 1, T, &t)) return;
  } else {
    int found = wg_shear_pair_root(dr, dv, da, s->dim, edge, 1, INFINITY, &t);
    /* on (or just beyond) the edge, moving in or at rest: not before the pair moves out
       faster than REST_SPEED */
    double ts = wg_shear_pair_speed_time(dr, dv, da, s->dim, REST_SPEED * edge);
    t = found ? fmax(t, ts) : ts;
    if (isinf(t)) return;
  }
  consider(best, s->now + t, WG_EV_BRIDGE_EDGE, j);
}

static void predict_pairs_sheared(const wg_ed *s, long i, const long *cells, int ncells,
                                  candidate *best)
{
  double ri[3], vi[3], ai[3];
  flight_at(s, i, s->now, ri, vi);
  accel_of(s, i, ai);
  const int32_t *head = s->cells.head, *next = s->cells.next;
  for (int k = 0; k < ncells; k++)
    for (int32_t j = head[cells[k]]; j >= 0; j = next[j])
      if (j != i) predict_pair_sheared(s, i, ri, vi, ai, j, best);
}

/* ---------- pairs with a particle resting on the floor ---------- */

/* A resting particle q and a free one f: along the floor their separation is linear in time,
   across it dz(tau) is the free parabola less the floor's sine.  |dr|^2 - L^2 has no closed-form
   root, so it is searched by conservative advancement: from a point where it is positive, step
   as far as a lower bound -- its tangent line less M/2 times the step squared, M a bound on its
   second derivative over the step -- stays positive.  Steps shrink like Newton's towards a
   crossing and never pass one. */
typedef struct rest_pair {
  const wg_wall *floor;
  double now, g;
  double G2;             /* bound on |dz''| = |-g + A w^2 sin|: g + A w^2 */
  double dh[3], dvh[3];  /* separation and relative velocity along the floor (vertical part 0) */
  double dvh2;           /* |dvh|^2 */
  double zf, vf, rq;     /* the free particle's height and vertical velocity at now; q's radius */
} rest_pair;

/* f = |dr|^2 - L2, f' and dz, dz' at tau. */
static void rest_pair_at(const rest_pair *q, double tau, double L2, double *f, double *fp,
                         double *dz, double *dzp)
{
  double h = 0, hp = 0;
  for (int k = 0; k < 3; k++) {
    double x = q->dh[k] + q->dvh[k] * tau;
    h += x * x;
    hp += x * q->dvh[k];
  }
  double t = q->now + tau;
  *dz = q->zf + tau * (q->vf - 0.5 * q->g * tau) - (wg_wall_position(q->floor, t) + q->rq);
  *dzp = q->vf - q->g * tau - wg_wall_velocity(q->floor, t);
  *f = h + *dz * *dz - L2;
  *fp = 2 * (hp + *dz * *dzp);
}

enum { REST_ROOT_STEPS = 200 };

/* First tau in [0, T] at which F = sgn (|dr|^2 - L^2) falls through 0 while falling (sgn = +1:
   contact from outside; -1: the bridge's edge from inside).  Returns 1 and *tau; 0 if there is
   none before T; -1 if the steps ran out (*tau: how far the pair is known to be clear). */
static int rest_pair_root(const rest_pair *q, double L, int sgn, double T, double *tau_out)
{
  double L2 = L * L, tol = 1e-12 * L2, tau = 0, guess = T;
  for (int it = 0; it < REST_ROOT_STEPS; it++) {
    double f, fp, dz, dzp;
    rest_pair_at(q, tau, L2, &f, &fp, &dz, &dzp);
    double F = sgn * f, Fp = sgn * fp;
    if (F <= tol && Fp < -2 * REST_SPEED * L) { /* closing faster than rest (predict_pair) */
      *tau_out = tau;
      return 1;
    }
    if (tau >= T) return 0;
    double step = fmin(guess, T - tau);
    double Z1 = fabs(dzp) + q->G2 * step;                         /* >= |dz'| on the step */
    double Z0 = fabs(dz) + (fabs(dzp) + 0.5 * q->G2 * step) * step; /* >= |dz| */
    double M = 2 * (q->dvh2 + Z1 * Z1 + Z0 * q->G2);               /* >= |f''| */
    double Fa = F > 0 ? F : 0;
    double x = (Fp + sqrt(Fp * Fp + 2 * M * Fa)) / M; /* F + F' x - M x^2 / 2 = 0 */
    if (x < step) step = x; /* M shrinks with the step: x stays safe */
    /* touching at rest: on by as much as the pair needs to close faster than REST_SPEED */
    step = fmax(step, F <= tol ? 2 * REST_SPEED * L / M : 1e-14 * (1 + tau));
    tau = fmin(tau + step, T);
    guess = 4 * step;
  }
  *tau_out = tau;
  return -1;
}

/* The free particle's state at now. */
static void free_at_now(const wg_ed *s, long i, double *r, double *v)
{
  probe pr;
  probe_at_now(s, i, &pr);
  memcpy(r, pr.r, sizeof pr.r);
  memcpy(v, pr.v, sizeof pr.v);
}

/* Events of the pair (i, j), exactly one of which rests on the floor; the overlap and edge
   rules are those of predict_pair. */
static void predict_rest_pair(const wg_ed *s, long i, long j, double t_lift, candidate *best)
{
  long q = s->riding[i] ? i : j, f = q == i ? j : i;
  const wg_wall *floor = &s->wall[0];
  double rq[3], vq[3], rf[3], vf[3];
  rider_at(s, q, s->now, rq, vq);
  free_at_now(s, f, rf, vf);
  int up = s->up;
  rest_pair P = {floor, s->now, s->g, s->g + floor->A * floor->omega * floor->omega,
                 {0, 0, 0}, {0, 0, 0}, 0, rf[up], vf[up], s->p[q].radius};
  for (int k = 0; k < up; k++) {
    P.dh[k] = min_image(rf[k] - rq[k], 0.5 * s->box[k], s->box[k]);
    P.dvh[k] = vf[k] - vq[k];
    P.dvh2 += P.dvh[k] * P.dvh[k];
  }
  double dz = rf[up] - rq[up], dzv = vf[up] - vq[up];
  double r2 = dz * dz, bdot = dz * dzv;
  for (int k = 0; k < up; k++) {
    r2 += P.dh[k] * P.dh[k];
    bdot += P.dh[k] * P.dvh[k];
  }
  double sigma = s->p[q].radius + s->p[f].radius;
  int bonded = s->wet && wg_ed_bonded(s, i, j);
  /* Only events before the best so far, before q lifts off (t_lift) and before f falls below
     the floor's lowest point (it meets the floor first) matter. */
  double drop = rf[up] - (floor->c - floor->A + s->p[f].radius);
  double t_floor = (vf[up] + sqrt(fmax(vf[up] * vf[up] + 2 * s->g * drop, 0))) / s->g;
  double T = fmin(fmin(best->t, t_lift) - s->now, t_floor);
  if (!(T > 0)) T = 0;
  double tau;
  int found;
  if (r2 - sigma * sigma <= 0 && bdot < 0) { /* overlap, closing */
    if (bdot < -REST_SPEED * sigma) consider(best, s->now, WG_EV_COLLISION, j);
    return;
  }
  { /* unlike two free grains, a separating pair may come back (the floor accelerates q);
       along the floor alone it must come within sigma */
    double hd = 0;
    for (int k = 0; k < up; k++) hd += P.dh[k] * P.dvh[k];
    double tmin = P.dvh2 > 0 ? fmin(fmax(-hd / P.dvh2, 0), T) : 0;
    double hmin = 0;
    for (int k = 0; k < up; k++) {
      double x = P.dh[k] + P.dvh[k] * tmin;
      hmin += x * x;
    }
    if (hmin < sigma * sigma) {
      found = rest_pair_root(&P, sigma, +1, T, &tau);
      if (found == 1) consider(best, s->now + tau, WG_EV_COLLISION, j);
      else if (found < 0) consider(best, s->now + tau, WG_EV_WALL_ENTER, 0); /* look again then */
    }
  }
  if (!bonded) return;
  double edge = sigma + s->s_crit;
  if (r2 - edge * edge >= 0 && bdot > REST_SPEED * edge) {
    consider(best, s->now, WG_EV_BRIDGE_EDGE, j);
    return;
  }
  T = fmin(T, best->t - s->now);
  found = rest_pair_root(&P, edge, -1, T, &tau);
  if (found == 1) consider(best, s->now + tau, WG_EV_BRIDGE_EDGE, j);
  else if (found < 0) consider(best, s->now + tau, WG_EV_WALL_ENTER, 0);
}

/* Both resting: the height difference is constant (the difference of the radii) and the
   relative motion is linear, as between two free particles. */
static void predict_riders_pair(const wg_ed *s, const probe *pr, long j, candidate *best)
{
  double rj[3], vj[3], d[3] = {0, 0, 0}, dv[3] = {0, 0, 0};
  rider_at(s, j, s->now, rj, vj);
  for (int k = 0; k < s->up; k++) {
    d[k] = min_image(rj[k] - pr->r[k], pr->half[k], pr->box[k]);
    dv[k] = vj[k] - pr->v[k];
  }
  d[s->up] = s->p[j].radius - pr->radius;
  pair_events(s, pr, j, s->p[j].radius, d[0], d[1], d[2], dv[0], dv[1], dv[2], best, s->dim,
              s->wet);
}

/* Every pair of particle i with the given cells when some particles may rest on the floor. */
static void predict_pairs_resting(const wg_ed *s, long i, const long *cells, int ncells,
                                  candidate *best)
{
  probe pr;
  probe_at_now(s, i, &pr);
  int qi = s->riding[i];
  if (qi) rider_at(s, i, s->now, pr.r, pr.v);
  double t_lift = wg_wall_lift_off_time(&s->wall[0], s->g, s->now);
  const int32_t *head = s->cells.head, *next = s->cells.next;
  for (int k = 0; k < ncells; k++)
    for (int32_t j = head[cells[k]]; j >= 0; j = next[j]) {
      if (j == i) continue;
      int qj = s->riding[j];
      if (!qi && !qj) predict_pair(s, &pr, j, NULL, best, s->dim, s->wet, 1, IMAGE_NEAREST);
      else if (qi && qj) predict_riders_pair(s, &pr, j, best);
      else predict_rest_pair(s, i, j, t_lift, best);
    }
}

/* The next bin crossing (x moves linearly: the field has no x component). */
static __attribute__((cold, noinline)) void predict_bin(const wg_ed *s, long i, candidate *best)
{
  const wg_particle *p = &s->p[i];
  int dir;
  double x = p->r[0] + p->v[0] * (s->now - p->t);
  double tau = wg_shear_bin_exit(s->shear, s->bin[i], x, p->v[0], &dir);
  consider(best, s->now + tau, WG_EV_BIN, dir);
}

static void predict_walls(wg_ed *s, long i, candidate *best)
{
  const wg_particle *p = &s->p[i];
  wg_ballistic traj = {p->t, p->r[s->up], p->v[s->up], s->g, p->radius};
  for (int w = 0; w < s->nwalls; w++) {
    double tau;
    wg_wall_outcome out = wg_wall_next_event(&s->wall[w], &traj, &tau, &s->wall_stats);
    if (out == WG_WALL_NONE) continue;
    double t = p->t + tau;
    /* an entry closer than the clock resolves (t ~ 10^4 and |v| ~ 10^2: 3.6e-12 apart, a
       displacement of 10^-9) would repeat at the same instant forever: step to the next
       representable time, where the particle is inside */
    if (out == WG_WALL_ENTER && !(t > p->t)) t = nextafter(p->t, INFINITY);
    consider(best, t > s->now ? t : s->now, out == WG_WALL_HIT ? WG_EV_WALL_HIT : WG_EV_WALL_ENTER, w);
  }
}

/* The queue's key of a particle: its next event of either kind. */
static inline double next_event_time(const wg_evrec *e)
{
  return e->t_phys < e->t_cell ? e->t_phys : e->t_cell;
}

static void schedule(wg_ed *s, long i)
{
  s->key[i] = next_event_time(&s->ev[i]);
  wg_evqueue_update(&s->queue, i);
}

static void set_phys(wg_ed *s, long i, const candidate *best)
{
  s->ev[i].t_phys = best->t;
  s->ev[i].type = (uint8_t)best->type;
  s->ev[i].partner = best->partner;
  if (best->type == WG_EV_COLLISION || best->type == WG_EV_BRIDGE_EDGE)
    s->ev[i].partner_count = s->ev[best->partner].count;
}

/* The next cell crossing while the field acts: each axis a parabola of its own. */
static __attribute__((cold, noinline)) void predict_cell_sheared(wg_ed *s, long i, int skip_axis,
                                                                 int skip_dir)
{
  const wg_particle *p = &s->p[i];
  int axis, dir;
  double acc[3];
  accel_of(s, i, acc);
  double t = p->t + wg_shear_cell_exit_time(&s->cells, s->cells.cell[i], p->r, p->v, acc,
                                            s->now - p->t, skip_axis, skip_dir, &axis, &dir);
  s->ev[i].t_cell = t > s->now ? t : s->now;
  s->ev[i].axis = (int8_t)axis;
  s->ev[i].dir = (int8_t)dir;
}

/* The next cell crossing of a particle resting on the floor: along the floor in a straight
   line, up and down with the floor (upwards only while it rises, downwards only while it
   falls, so the face just crossed is not crossed again at once). */
static __attribute__((cold, noinline)) void predict_cell_rider(wg_ed *s, long i, int skip_axis,
                                                               int skip_dir)
{
  const wg_particle *p = &s->p[i];
  const wg_cells *c = &s->cells;
  int up = s->up, axis, dir;
  double v[3] = {p->v[0], p->v[1], p->v[2]};
  v[up] = 0;
  double t = p->t + wg_cells_exit_time(c, c->cell[i], p->r, v, 0.0, s->now - p->t,
                                       skip_axis == up ? -1 : skip_axis, skip_dir, &axis, &dir);
  int iz = wg_cells_coord(c, c->cell[i], up);
  /* the floor's heights at which the particle reaches the cell's faces */
  double lower = c->lo[up] + iz * c->w[up] - p->radius;
  double upper = c->lo[up] + (iz + 1) * c->w[up] - p->radius; /* = the next cell's lower */
  double z = wg_wall_position(&s->wall[0], s->now);
  /* already beyond a face (the particle came to rest there): through it now -- but not back
     through the face just entered, which round-off may place a hair on the wrong side */
  int entered_up = skip_axis == up && skip_dir == -1, entered_down = skip_axis == up && skip_dir == 1;
  if (iz < c->nc[up] - 1) {
    double tu = z > upper && !entered_down ? s->now : wg_wall_level_time(&s->wall[0], s->now, upper, 1);
    if (tu < t) { t = tu; axis = up; dir = 1; }
  }
  if (iz > 0) {
    double td = z < lower && !entered_up ? s->now : wg_wall_level_time(&s->wall[0], s->now, lower, 0);
    if (td < t) { t = td; axis = up; dir = -1; }
  }
  s->ev[i].t_cell = t > s->now ? t : s->now;
  s->ev[i].axis = (int8_t)axis;
  s->ev[i].dir = (int8_t)dir;
}

/* Next cell crossing; (skip_axis, skip_dir) is the face just entered through, if any. */
static void predict_cell(wg_ed *s, long i, int skip_axis, int skip_dir)
{
  const wg_particle *p = &s->p[i];
  int axis, dir;
  if (SHEARED(s)) {
    predict_cell_sheared(s, i, skip_axis, skip_dir);
    return;
  }
  if (rides(s, i)) {
    predict_cell_rider(s, i, skip_axis, skip_dir);
    return;
  }
  double dt = wg_cells_exit_time(&s->cells, s->cells.cell[i], p->r, p->v, s->g, s->now - p->t,
                                 skip_axis, skip_dir, &axis, &dir);
  double t = p->t + dt;
  s->ev[i].t_cell = t > s->now ? t : s->now;
  s->ev[i].axis = (int8_t)axis;
  s->ev[i].dir = (int8_t)dir;
}

/* When particle i leaves the region around its list centre (neighbour lists). */
static void predict_relist(wg_ed *s, long i)
{
  const wg_particle *p = &s->p[i];
  double t = p->t + wg_nlist_exit_time(&s->nl, i, p->r, p->v, s->g, s->now - p->t);
  s->ev[i].t_cell = t > s->now ? t : s->now;
}

/* Every event of particle i afresh: walls, all pairs in the surrounding cells (or its list),
   next cell crossing (or relist). */
static void predict_all(wg_ed *s, long i, int reschedule)
{
  candidate best = {INFINITY, WG_EV_NONE, -1};
  long stencil[27];
  if (rides(s, i))
    consider(&best, wg_wall_lift_off_time(&s->wall[0], s->g, s->now), WG_EV_LIFT_OFF, 0);
  else if (s->nwalls)
    predict_walls(s, i, &best);
  if (SHEARED(s)) predict_bin(s, i, &best);
  if (s->listed) {
    predict_pairs_listed(s, i, &best);
    set_phys(s, i, &best);
    predict_relist(s, i);
  } else {
    int8_t image[3 * 27];
    const int8_t *images;
    int m = wg_cells_imaged(&s->cells, s->cells.cell[i], -1, 0, stencil, image, &images);
    predict_pairs_in(s, i, stencil, images, m, &best);
    set_phys(s, i, &best);
    predict_cell(s, i, -1, 0);
  }
  if (reschedule) schedule(s, i);
}

/* Every particle's events afresh (all trajectories changed, or the cells were rebuilt), and
   the queue built over them. */
static void predict_everything(wg_ed *s)
{
  for (long i = 0; i < s->n; i++) predict_all(s, i, 0);
  for (long i = 0; i < s->n; i++) s->key[i] = next_event_time(&s->ev[i]);
  wg_evqueue_build(&s->queue);
}

/* ---------- events ---------- */

/* Unit vector n from i to j at the current time and the normal relative velocity
   u_n = (v_j - v_i).n (negative while approaching); *dist is |r_j - r_i|. */
static double contact_normal(const wg_ed *s, long i, long j, double *n, double *dist)
{
  double dr[3] = {0, 0, 0}, dv[3] = {0, 0, 0};
  pair_state(s, i, j, dr, dv);
  *dist = sqrt(dot(dr, dr, s->dim));
  for (int k = 0; k < 3; k++) n[k] = k < s->dim ? dr[k] / *dist : 0;
  return dot(dv, n, s->dim);
}

/* The pair's reduced mass along n.  The floor holds a resting particle's vertical motion, so
   along n it has inverse mass (1 - n_z^2) / m (infinite mass across the floor). */
static double pair_mass(const wg_ed *s, long i, long j, const double *n)
{
  if (!RESTING(s) || !(s->riding[i] | s->riding[j])) return reduced_mass(s, i, j);
  double nz2 = n[s->up] * n[s->up];
  double wi = (s->riding[i] ? 1 - nz2 : 1) / wg_ed_mass(s, i);
  double wj = (s->riding[j] ? 1 - nz2 : 1) / wg_ed_mass(s, j);
  return 1 / (wi + wj);
}

/* An impulse changing the normal relative velocity by du along n (push = +1: i along -n and j
   along +n, as a contact; -1: the reverse, as a bridge) lifts off a resting particle it would
   throw up from the floor faster than rest_speed.  A smaller upward kick is taken by the floor:
   the particle would land again at once, slower than rest_speed, and rest. */
static void hold_or_lift(wg_ed *s, long i, long j, const double *n, int push, double du)
{
  double a = push * n[s->up] * reduced_mass(s, i, j) * fabs(du);
  if (s->riding[i] && -a > s->rest_speed * wg_ed_mass(s, i))
    s->riding[i] = 0, s->counts.lift_offs++;
  if (s->riding[j] && a > s->rest_speed * wg_ed_mass(s, j))
    s->riding[j] = 0, s->counts.lift_offs++;
}

/* Change the normal relative velocity by du, conserving momentum:
   dv_i = -mu/m_i du n, dv_j = +mu/m_j du n.  For a resting particle the floor takes the
   vertical part, and its work (impulse times the floor's velocity) goes to the ledger. */
static void normal_kick(wg_ed *s, long i, long j, const double *n, double du)
{
  double mu = pair_mass(s, i, j, n);
  double ki = mu * du / wg_ed_mass(s, i), kj = mu * du / wg_ed_mass(s, j);
  double vi = s->p[i].v[s->up], vj = s->p[j].v[s->up];
  for (int k = 0; k < s->dim; k++) {
    s->p[i].v[k] -= ki * n[k];
    s->p[j].v[k] += kj * n[k];
  }
  if (RESTING(s)) {
    double vw = wg_wall_velocity(&s->wall[0], s->now);
    if (s->riding[i]) {
      s->p[i].v[s->up] = vi;
      wg_ksum_add(&s->ledger.injected_wall, wg_ed_mass(s, i) * ki * n[s->up] * vw);
    }
    if (s->riding[j]) {
      s->p[j].v[s->up] = vj;
      wg_ksum_add(&s->ledger.injected_wall, -wg_ed_mass(s, j) * kj * n[s->up] * vw);
    }
  }
}

/* Contact of two hard particles with restitution (Eq. 2.3-2.6 for any masses):
   u_n -> -e u_n.  The TC model makes the collision elastic when either particle collided
   less than tc ago, unless that was at the same instant (RIGID_TIME).  An unbonded wet pair
   forms a bridge. */
static int collide(wg_ed *s, long i, long j)
{
  double n[3], dist;
  double un = contact_normal(s, i, j, n, &dist);
  if (un >= 0) return WG_OK; /* already separating: nothing to do */
  double e = s->eps;
  if (s->t_last) {
    double since = fmin(s->now - s->t_last[i], s->now - s->t_last[j]);
    if (since <= RIGID_TIME && !(rides(s, i) && rides(s, j))) {
      e = 0;
      s->counts.rigid++;
    } else if (since < s->tc) {
      e = 1;
    }
    s->t_last[i] = s->t_last[j] = s->now;
  }
  if (RESTING(s)) hold_or_lift(s, i, j, n, +1, (1 + e) * un);
  double mu = pair_mass(s, i, j, n);
  double du = -(1 + e) * un;
  if (RESTING(s) && (s->riding[i] ^ s->riding[j])) {
    /* a free particle pressed onto a resting one by the floor's acceleration would bounce
       ever more often, as on the floor itself.  Speeds below rest_speed count as rest; a
       particle cannot rest on a moving one here, so it hops: it leaves at rest_speed, the
       floor's work paying the difference. */
    double hop = fmax(s->rest_speed, s->wall_min_speed);
    if (-e * un < hop) {
      du = hop - un;
      wg_ksum_add(&s->ledger.injected_wall, 0.5 * mu * (hop * hop - e * e * un * un));
    }
  }
  normal_kick(s, i, j, n, du);
  s->virial -= dist * (1 + e) * mu * un; /* sigma |J| */
  if (e < 1) wg_ksum_add(&s->ledger.dissipated_coll, 0.5 * mu * (1 - e * e) * un * un); /* Eq. 2.6 */
  s->counts.collisions++;
  if (s->wet && !wg_ed_bonded(s, i, j)) {
    int st = bond_add_one(s, i, j);
    if (st == WG_OK) st = bond_add_one(s, j, i);
    if (st != WG_OK) return st;
    s->counts.captures++;
  }
  return WG_OK;
}

/* A bonded pair separating through gap s_crit (thin-thread model): the bridge ruptures if
   the normal kinetic energy exceeds E_cb, taking exactly E_cb; otherwise the pair is
   reflected back into the well without loss (at no less than grazing_angle). */
static void bridge_edge(wg_ed *s, long i, long j)
{
  double n[3], dist;
  double un = contact_normal(s, i, j, n, &dist);
  if (un <= 0) return;
  if (RESTING(s)) hold_or_lift(s, i, j, n, -1, 2 * un);
  double mu = pair_mass(s, i, j, n);
  if (0.5 * mu * un * un > s->e_cb) {
    bond_remove_one(s, i, j);
    bond_remove_one(s, j, i);
    wg_ksum_add(&s->ledger.dissipated_rupt, s->e_cb);
    s->counts.ruptures++;
    normal_kick(s, i, j, n, sqrt(un * un - 2 * s->e_cb / mu) - un);
    return;
  }
  s->counts.reflections++;
  double dr[3], du[3] = {0, 0, 0};
  pair_state(s, i, j, dr, du);
  double u2 = dot(du, du, s->dim), u_min = s->grazing_angle * sqrt(u2);
  /* (a pair that grazed before comes back at u_min; a resting particle reflects plainly) */
  if (un >= u_min * (1 - 1e-9) || rides(s, i) || rides(s, j)) {
    normal_kick(s, i, j, n, -2 * un);
    return;
  }
  /* grazing: u_n -> -u_min, tangential part shrunk so that |u| is unchanged */
  double ut2 = u2 - un * un, f = ut2 > 0 ? sqrt(fmax(u2 - u_min * u_min, 0) / ut2) : 0;
  double kick[3] = {0, 0, 0};
  for (int k = 0; k < s->dim; k++) {
    double ut = du[k] - un * n[k];
    kick[k] = (-u_min - un) * n[k] + (f - 1) * ut;
  }
  double ki = mu / wg_ed_mass(s, i), kj = mu / wg_ed_mass(s, j);
  for (int k = 0; k < s->dim; k++) {
    s->p[i].v[k] -= ki * kick[k];
    s->p[j].v[k] += kj * kick[k];
  }
  s->counts.grazing++;
}

/* A floor contact slower than rest_speed while the floor's acceleration exceeds -g ends the
   particle's bouncing (the limit of its ever shorter bounces, or the floor's inelastic collapse):
   it rests on the floor, its motion relative to the floor taken out as in a perfectly
   inelastic wall collision, and rides it until the floor's acceleration falls to -g. */
static void come_to_rest(wg_ed *s, long i, double vw)
{
  wg_particle *p = &s->p[i];
  double m = wg_ed_mass(s, i), v = p->v[s->up], u = v - vw;
  double z = wg_wall_position(&s->wall[0], s->now) + p->radius;
  double loss = 0.5 * m * u * u;
  wg_ksum_add(&s->ledger.injected_wall, 0.5 * m * (vw * vw - v * v) + m * s->g * (z - p->r[s->up]) + loss);
  wg_ksum_add(&s->ledger.dissipated_wall, loss);
  p->r[s->up] = z;
  p->v[s->up] = vw;
  if (s->t_last) s->t_last[i] = s->now;
  s->riding[i] = 1;
  s->counts.rests++;
  s->counts.wall_hits++;
}

/* Reflection at a moving wall: the velocity relative to the wall reverses and shrinks by
   eps_wall.  A particle pressed onto a wall that accelerates towards it would bounce ever
   more often (the wall's inelastic collapse); it leaves with at least wall_min_speed, the
   speed at which the wall catches it again only after about 2 tc.  The wall's work and the
   loss go to the ledger either way. */
static void wall_collide(wg_ed *s, long i, int w)
{
  wg_particle *p = &s->p[i];
  int side = s->wall[w].side;
  double vw = wg_wall_velocity(&s->wall[w], s->now);
  double v = p->v[s->up];
  double u = v - vw;
  /* (the margin keeps a particle just lifted off, at a_w = -g to round-off, from resting again
     at the same instant) */
  if (RESTING(s) && side > 0 && fabs(u) < s->rest_speed &&
      wg_wall_acceleration(&s->wall[w], s->now) > -s->g * (1 - LIFT_MARGIN)) {
    come_to_rest(s, i, vw);
    return;
  }
  double e = s->eps_wall;
  if (s->t_last) {
    if (s->now - s->t_last[i] < s->tc) e = 1;
    s->t_last[i] = s->now;
  }
  double m = wg_ed_mass(s, i);
  double loss = 0;
  double v_after = v;
  if (u * side < 0) { /* closing */
    v_after = vw - e * u;
    loss = 0.5 * m * (1 - e * e) * u * u;
  }
  if ((v_after - vw) * side < s->wall_min_speed) v_after = vw + side * s->wall_min_speed;
  p->v[s->up] = v_after;
  wg_ksum_add(&s->ledger.injected_wall, 0.5 * m * (v_after * v_after - v * v) + loss);
  if (loss > 0) wg_ksum_add(&s->ledger.dissipated_wall, loss);
  s->counts.wall_hits++;
}

static void cell_crossing(wg_ed *s, long i)
{
  int axis = s->ev[i].axis, dir = s->ev[i].dir, wrapped;
  long from = s->cells.cell[i];
  long to = wg_cells_step(&s->cells, from, axis, dir, &wrapped);
  s->counts.cell_crossings++;
  if (to < 0) { /* cannot happen: the outer cells have no outward face */
    s->ev[i].t_cell = INFINITY;
    schedule(s, i);
    return;
  }
  if (wrapped) s->p[i].r[axis] -= wrapped * s->box[axis];
  wg_cells_remove(&s->cells, i);
  wg_cells_insert(&s->cells, i, to);
  /* only the particles in the newly adjacent cells can add an earlier event */
  candidate best = {s->ev[i].t_phys, s->ev[i].type, s->ev[i].partner};
  long face[9];
  int8_t image[3 * 9];
  const int8_t *images;
  int m = wg_cells_imaged(&s->cells, to, axis, dir, face, image, &images);
  predict_pairs_in(s, i, face, images, m, &best);
  if (best.t < s->ev[i].t_phys) set_phys(s, i, &best);
  predict_cell(s, i, axis, -dir);
  schedule(s, i);
}

/* List particle i (slot) anew around its centre: every j whose centre is within
   r_i + r_max + s_crit + shell of it (r_max: the largest radius, so that the scan reads only
   the centres), found in the cells' stencil.  later_only: only j > i (all lists built at once,
   each pair once).  With `old` (i's previous list, nold entries) every j not in it is a new
   pair, whose events, seen from the probe pr of i, are considered into *best. */
static int list_neighbours(wg_ed *s, long i, int later_only, const int32_t *old, int nold,
                           const probe *pr, candidate *best)
{
  long stencil[27];
  int m = wg_cells_stencil(&s->cells, s->cells.cell[i], stencil);
  const int32_t *head = s->cells.head, *next = s->cells.next;
  const double *ci = s->nl.centre + 3 * i;
  double cut = s->p[i].radius + s->nl.r_max + s->s_crit + s->nl.shell, cut2 = cut * cut;
  for (int k = 0; k < m; k++)
    for (int32_t j = head[stencil[k]]; j >= 0; j = next[j]) {
      if (j == i || (later_only && j < i)) continue;
      const double *cj = s->nl.centre + 3 * j;
      double r2 = 0;
      for (int a = 0; a < s->dim; a++) {
        double x = cj[a] - ci[a];
        if (s->periodic[a]) x = min_image(x, 0.5 * s->box[a], s->box[a]);
        r2 += x * x;
      }
      if (r2 >= cut2) continue;
      int st = wg_nlist_link(&s->nl, s->n, i, j);
      if (st != WG_OK) return st;
      if (!old) continue;
      int q = 0;
      while (q < nold && old[q] != j) q++;
      if (q == nold) predict_pair_of(s, pr, j, best);
    }
  return WG_OK;
}

/* Particle i has reached the edge of its region: its centre moves to where it is (wrapped
   into the box), its cell and list follow.  Its trajectory is unchanged, so its predicted
   event and the others' predictions with it stand: only the pairs new to its list can bring
   an earlier event. */
static int relist(wg_ed *s, long i)
{
  wg_particle *p = &s->p[i];
  s->counts.cell_crossings++;
  advance(s, i, s->now);
  wrap_into_box(s, p->r);
  int nold = s->nl.nn[i];
  int32_t old_small[64], *old = old_small;
  if (nold > 64 && !(old = malloc((size_t)nold * sizeof *old)))
    return wg_error(WG_ENOMEM, "engine", "no memory to relist particle %ld", i);
  memcpy(old, s->nl.nb + (size_t)i * s->nl.cap, (size_t)nold * sizeof *old);
  wg_nlist_unlink_all(&s->nl, i);
  double *c = s->nl.centre + 3 * i;
  for (int k = 0; k < s->dim; k++) c[k] = p->r[k];
  long cell = wg_cells_locate(&s->cells, c);
  if (cell != s->cells.cell[i]) {
    wg_cells_remove(&s->cells, i);
    wg_cells_insert(&s->cells, i, cell);
  }
  candidate best = {s->ev[i].t_phys, s->ev[i].type, s->ev[i].partner};
  probe pr;
  probe_at_now(s, i, &pr);
  int st = list_neighbours(s, i, 0, old, nold, &pr, &best);
  if (old != old_small) free(old);
  if (st != WG_OK) return st;
  if (best.t < s->ev[i].t_phys) set_phys(s, i, &best);
  predict_relist(s, i);
  schedule(s, i);
  return WG_OK;
}

static int physical_event(wg_ed *s, long i)
{
  long j = s->ev[i].partner;
  int type = s->ev[i].type;
  int st = WG_OK;
  switch (type) {
  case WG_EV_COLLISION:
  case WG_EV_BRIDGE_EDGE:
    if (s->ev[j].count != s->ev[i].partner_count) { /* partner moved since: predict again */
      s->counts.stale++;
      predict_all(s, i, 1);
      return WG_OK;
    }
    advance(s, i, s->now);
    advance(s, j, s->now);
    if (type == WG_EV_COLLISION) st = collide(s, i, j);
    else bridge_edge(s, i, j);
    s->ev[i].count++;
    s->ev[j].count++;
    predict_all(s, i, 1);
    predict_all(s, j, 1);
    return st;
  case WG_EV_WALL_HIT:
    advance(s, i, s->now);
    wall_collide(s, i, (int)j);
    s->ev[i].count++;
    predict_all(s, i, 1);
    return WG_OK;
  case WG_EV_LIFT_OFF:
    advance(s, i, s->now);
    s->riding[i] = 0;
    s->counts.lift_offs++;
    s->ev[i].count++;
    predict_all(s, i, 1);
    return WG_OK;
  case WG_EV_BIN:
    /* the old bin's force acts up to the face; the new bin's from here on */
    advance(s, i, s->now);
    s->bin[i] = wg_shear_bin_step(s->shear, s->bin[i], (int)j);
    s->counts.bin_crossings++;
    s->ev[i].count++;
    predict_all(s, i, 1);
    return WG_OK;
  case WG_EV_WALL_ENTER:
    /* same trajectory, new reference point: the solver then sees the particle inside */
    advance(s, i, s->now);
    s->counts.wall_enters++;
    predict_all(s, i, 1);
    return WG_OK;
  default:
    return wg_error(WG_EFAIL, "event loop", "particle %ld has no event at t = %g", i, s->now);
  }
}

static void set_check_at(wg_ed *s)
{
  s->check_at = s->watch && s->watch_at < s->sync_interval ? s->watch_at : s->sync_interval;
}

void wg_ed_set_watch(wg_ed *s, int (*watch)(void *user), void *user)
{
  s->watch = watch;
  s->watch_user = user;
  s->watch_at = s->since_sync + WG_ED_WATCH_EVENTS;
  set_check_at(s);
}

/* The watch, when due, then the synchronisation, when due (exactly when it was due without a
   watch: the watch never moves it). */
static int tick(wg_ed *s)
{
  if (s->watch && s->since_sync >= s->watch_at) {
    s->watch_at = s->since_sync + WG_ED_WATCH_EVENTS;
    int st = s->watch(s->watch_user);
    if (st != WG_OK) {
      set_check_at(s);
      return st;
    }
  }
  if (s->since_sync >= s->sync_interval) return wg_ed_synchronize(s); /* sets check_at */
  set_check_at(s);
  return WG_OK;
}

static int advance_events(wg_ed *s, double t_stop)
{
  for (;;) {
    long i = wg_evqueue_top(&s->queue);
    double t = wg_evqueue_top_key(&s->queue);
    if (!(t <= t_stop)) break;
    /* a burst: events piling up within BURST_TIME of each other (same instant, or ulps
       apart as in a rigid cluster of bonded grains) */
    if (t - s->burst_start <= BURST_TIME) {
      if (++s->zero_time_run > STUCK_EVENTS)
        return wg_error(WG_ERANGE, "event loop",
                        "more than %llu events within %g of t = %.17g (particle %ld): the run is "
                        "stuck (a rigid cluster or inelastic collapse)", STUCK_EVENTS, BURST_TIME,
                        t, i);
    } else {
      s->zero_time_run = 0;
      s->burst_start = t;
    }
    s->now = t;
    if (s->ev[i].t_cell <= s->ev[i].t_phys) {
      if (s->listed) {
        int st = relist(s, i);
        if (st != WG_OK) return st;
      } else {
        cell_crossing(s, i);
      }
    } else {
      int st = physical_event(s, i);
      if (st != WG_OK) return st;
    }
    if (++s->since_sync >= s->check_at) {
      int st = tick(s);
      if (st != WG_OK) return st;
    }
  }
  s->now = t_stop;
  return WG_OK;
}

/* Switch the shear field on or off at time now: every particle finishes its flight under the
   old accelerations, then all events are predicted afresh under the new ones. */
static int switch_field(wg_ed *s, int on)
{
  for (long i = 0; i < s->n; i++) advance(s, i, s->now);
  s->sheared = on;
  return wg_ed_synchronize(s);
}

/* ---------- the random force (thesis Sec. 2.4.2) ---------- */

/* Kicks made by time t: the k >= 1 with k noise_dt <= t, compared as the event loop does. */
static unsigned long long kicks_by(const wg_ed *s, double t)
{
  double k = t > 0 ? floor(t / s->noise_dt) : 0;
  while ((k + 1) * s->noise_dt <= t) k++;
  while (k > 0 && k * s->noise_dt > t) k--;
  return (unsigned long long)k;
}

static double next_kick_time(const wg_ed *s)
{
  return (double)(s->counts.kicks + 1) * s->noise_dt;
}

/* Standard Gaussian number of kick k, particle identity id, axis a. */
static double kick_gauss(const wg_ed *s, unsigned long long k, long id, int a)
{
  return gsl_cdf_ugaussian_Pinv(wg_counter_uniform(s->sc->seed, k, (uint64_t)id, (uint64_t)a));
}

/* Eq. 2.12 over one interval: dv = sqrt(2 noise noise_dt) xi per axis, less the mass-weighted
   mean kick so that the total momentum stays as it is (the kicks' correlations change by
   -1/N).  Sums run in identity order, so the result does not depend on the slots.  Every
   trajectory changes: all events are predicted afresh. */
static int noise_kick(wg_ed *s)
{
  unsigned long long k = ++s->counts.kicks;
  double amp = sqrt(2 * s->noise * s->noise_dt), mean[3] = {0, 0, 0}, mtot = 0;
  for (long id = 0; id < s->n; id++) {
    double m = wg_ed_mass(s, s->slot[id]);
    mtot += m;
    for (int a = 0; a < s->dim; a++) mean[a] += m * kick_gauss(s, k, id, a);
  }
  for (int a = 0; a < s->dim; a++) mean[a] /= mtot;
  for (long id = 0; id < s->n; id++) {
    long i = s->slot[id];
    double m = wg_ed_mass(s, i), work = 0;
    advance(s, i, s->now);
    for (int a = 0; a < s->dim; a++) {
      double dv = amp * (kick_gauss(s, k, id, a) - mean[a]);
      work += m * dv * (s->p[i].v[a] + 0.5 * dv);
      s->p[i].v[a] += dv;
    }
    wg_ksum_add(&s->ledger.injected_noise, work);
  }
  predict_everything(s);
  return WG_OK;
}

int wg_ed_advance(wg_ed *s, double t_stop)
{
  if (!s->shear && !s->noise) return advance_events(s, t_stop);
  for (;;) { /* up to each time the field switches or the particles are kicked, then on */
    double t_switch = !s->shear ? INFINITY
                      : s->sheared ? s->shear->t_off
                      : s->now < s->shear->t_on ? s->shear->t_on : INFINITY;
    double t_kick = s->noise ? next_kick_time(s) : INFINITY;
    double t_next = t_kick < t_switch ? t_kick : t_switch;
    if (!(t_next <= t_stop)) return advance_events(s, t_stop);
    int st = advance_events(s, t_next);
    if (st == WG_OK) st = t_kick < t_switch ? noise_kick(s) : switch_field(s, !s->sheared);
    if (st != WG_OK) return st;
  }
}

/* Apply new[k] = old[order[k]] in place, cycle by cycle; done[] is scratch (n bytes). */
static void permute(void *base, size_t size, long n, const int32_t *order, uint8_t *done)
{
  char *a = base, tmp[128]; /* holds one element: at most a row of 16 bonds */
  memset(done, 0, (size_t)n);
  for (long k = 0; k < n; k++) {
    if (done[k] || order[k] == k) continue;
    memcpy(tmp, a + (size_t)k * size, size);
    long j = k;
    for (;;) {
      long src = order[j];
      done[j] = 1;
      if (src == k) {
        memcpy(a + (size_t)j * size, tmp, size);
        break;
      }
      memcpy(a + (size_t)j * size, a + (size_t)src * size, size);
      j = src;
    }
  }
}

/* Renumber the slots in the order of the cells (a counting sort, stable, so an ordered
   state stays as it is).  Every per-particle array moves along, in place; bond partners are
   translated.  The scratch (9 bytes per particle and one word per cell) is taken here,
   outside the event loop. */
static int renumber_by_cell(wg_ed *s)
{
  long n = s->n;
  int fail = 0;
  long *start = zalloc((size_t)s->cells.ncell + 1, sizeof *start, &fail);
  int32_t *order = zalloc((size_t)n, sizeof *order, &fail);  /* order[new] = old */
  uint8_t *done = zalloc((size_t)n, 1, &fail);
  if (fail) {
    free(start); free(order); free(done);
    return wg_error(WG_ENOMEM, "engine", "no memory to renumber %ld particles", n);
  }
  for (long i = 0; i < n; i++) start[wg_cells_locate(&s->cells, s->p[i].r) + 1]++;
  for (long c = 0; c < s->cells.ncell; c++) start[c + 1] += start[c];
  for (long i = 0; i < n; i++) order[start[wg_cells_locate(&s->cells, s->p[i].r)]++] = (int32_t)i;
  free(start);
  if (s->wet) /* bond partners by identity while slots move */
    for (long k = 0; k < n; k++)
      for (int m = 0; m < s->nbond[k]; m++) {
        int32_t *b = &s->bond[(size_t)k * s->bond_cap + m];
        *b = s->id[*b];
      }
  permute(s->p, sizeof *s->p, n, order, done);
  permute(s->id, sizeof *s->id, n, order, done);
  if (s->mass) permute(s->mass, sizeof *s->mass, n, order, done);
  if (s->t_last) permute(s->t_last, sizeof *s->t_last, n, order, done);
  if (s->riding) permute(s->riding, sizeof *s->riding, n, order, done);
  if (s->wet) {
    permute(s->nbond, sizeof *s->nbond, n, order, done);
    permute(s->bond, sizeof *s->bond * (size_t)s->bond_cap, n, order, done);
  }
  for (long k = 0; k < n; k++) s->slot[s->id[k]] = (int32_t)k;
  if (s->wet)
    for (long k = 0; k < n; k++)
      for (int m = 0; m < s->nbond[k]; m++) {
        int32_t *b = &s->bond[(size_t)k * s->bond_cap + m];
        *b = s->slot[*b];
      }
  free(order);
  free(done);
  return WG_OK;
}

int wg_ed_synchronize(wg_ed *s)
{
  for (long i = 0; i < s->n; i++) {
    advance(s, i, s->now);
    wrap_into_box(s, s->p[i].r);
    s->ev[i].count = 0;
  }
  int st = renumber_by_cell(s);
  if (st != WG_OK) return st;
  wg_cells_rebuild(&s->cells, s->n, s->p[0].r, sizeof(wg_particle) / sizeof(double));
  if (s->listed) {
    wg_nlist_clear(&s->nl, s->n);
    for (long i = 0; i < s->n; i++)
      for (int k = 0; k < 3; k++) s->nl.centre[3 * i + k] = k < s->dim ? s->p[i].r[k] : 0;
    for (long i = 0; i < s->n; i++) {
      st = list_neighbours(s, i, 1, NULL, 0, NULL, NULL);
      if (st != WG_OK) return st;
    }
  }
  if (s->sheared)
    for (long i = 0; i < s->n; i++) s->bin[i] = wg_shear_bin_of(s->shear, s->p[i].r[0]);
  predict_everything(s);
  s->watch_at = s->watch_at > s->since_sync ? s->watch_at - s->since_sync : 0;
  s->since_sync = 0;
  set_check_at(s);
  return WG_OK;
}

/* ---------- energy ---------- */

void wg_ed_energy(const wg_ed *s, double *kinetic, double *potential)
{
  double ek = 0, ep = 0;
  for (long i = 0; i < s->n; i++) {
    double r[3], v[3];
    wg_ed_position_at(s, i, s->now, r, v);
    double m = wg_ed_mass(s, i);
    ek += 0.5 * m * dot(v, v, s->dim);
    ep += m * s->g * r[s->up];
  }
  *kinetic = ek;
  *potential = ep;
}

double wg_ed_ledger_residual(wg_ed *s)
{
  double ek, ep;
  wg_ed_energy(s, &ek, &ep);
  const wg_ledger *l = &s->ledger;
  double in = wg_ed_wall_work(s) + wg_ed_field_work(s) + wg_ksum_value(&l->injected_noise);
  double out = wg_ksum_value(&l->dissipated_coll) + wg_ksum_value(&l->dissipated_wall) +
               wg_ksum_value(&l->dissipated_rupt);
  double level = ek + fabs(ep);
  if (level > s->ledger.scale) s->ledger.scale = level;
  double scale = s->ledger.scale > in + out ? s->ledger.scale : in + out;
  if (scale <= 0) return 0;
  return fabs(ek + ep - l->e0 - in + out) / scale;
}

/* ---------- set-up ---------- */

static int setup_common(wg_ed *s, const wg_scene *sc, long n)
{
  memset(s, 0, sizeof *s);
  s->sc = sc;
  s->dim = sc->dim;
  s->up = sc->dim - 1;
  s->n = n;
  s->g = sc->gravity;
  s->eps = sc->eps;
  s->eps_wall = sc->eps_wall;
  s->tc = sc->tc;
  s->grazing_angle = sc->grazing_angle;
  s->noise = sc->noise;
  s->noise_dt = sc->noise_dt;
  s->wet = sc->s_crit > 0 && sc->e_cb > 0;
  s->s_crit = s->wet ? sc->s_crit : 0;
  s->e_cb = s->wet ? sc->e_cb : 0;
  s->bond_cap = s->dim == 2 ? BOND_CAP_2D : BOND_CAP_3D;
  s->box[0] = sc->lx;
  if (s->dim == 3) s->box[1] = sc->ly;
  s->box[s->up] = sc->height;
  s->periodic[0] = 1;
  if (s->dim == 3) s->periodic[1] = 1;
  s->periodic[s->up] = sc->container == WG_CONTAINER_PERIODIC;
  s->nwalls = wg_scene_walled(sc) ? 2 : 0;
  s->inelastic = s->eps < 1 || (s->nwalls && s->eps_wall < 1);
  if (s->nwalls) {
    s->wall[0] = (wg_wall){0.0, sc->amplitude, sc->omega, +1};
    s->wall[1] = (wg_wall){sc->height, sc->amplitude, sc->omega, -1};
    double push = s->g + sc->amplitude * sc->omega * sc->omega;
    s->wall_min_speed = push * (s->tc > 0 ? s->tc : WALL_MIN_TIME);
  }

  int fail = 0;
  s->p = zalloc((size_t)n, sizeof *s->p, &fail);
  s->id = zalloc((size_t)n, sizeof *s->id, &fail);
  s->slot = zalloc((size_t)n, sizeof *s->slot, &fail);
  s->ev = zalloc((size_t)n, sizeof *s->ev, &fail);
  s->key = zalloc((size_t)n, sizeof *s->key, &fail);
  if (sc->mass_scaling) s->mass = zalloc((size_t)n, sizeof *s->mass, &fail);
  if (s->inelastic) s->t_last = zalloc((size_t)n, sizeof *s->t_last, &fail);
  if (sc->rest_speed > 0 && s->nwalls && s->g > 0) {
    s->rest_speed = sc->rest_speed;
    s->riding = zalloc((size_t)n, sizeof *s->riding, &fail);
  }
  if (sc->shear_force != 0) {
    s->shear = zalloc(1, sizeof *s->shear, &fail);
    s->bin = zalloc((size_t)n, sizeof *s->bin, &fail);
    /* the force acts along y in 3D and along the second axis in 2D (see shear.h) */
    if (!fail && wg_shear_init(s->shear, sc->shear_force, sc->shear_bins, sc->lx, sc->shear_on,
                               sc->shear_off, 1) != WG_OK)
      fail = 1;
  }
  if (sc->shell > 0) {
    s->listed = 1;
    if (wg_nlist_alloc(&s->nl, s->dim, n, sc->shell) != WG_OK) fail = 1;
  }
  if (s->wet) {
    s->bond = zalloc((size_t)n * s->bond_cap, sizeof *s->bond, &fail);
    s->nbond = zalloc((size_t)n, sizeof *s->nbond, &fail);
  }
  if (fail) {
    wg_ed_free(s);
    return wg_error(WG_ENOMEM, "engine", "cannot allocate the state of %ld particles", n);
  }
  for (long i = 0; i < n; i++) s->id[i] = s->slot[i] = (int32_t)i;
  s->sync_interval = 16ULL * (unsigned long long)n;
  s->check_at = s->sync_interval;
  if (s->t_last)
    for (long i = 0; i < n; i++) s->t_last[i] = -INFINITY;
  s->cells.head = NULL;
  int st = wg_evqueue_alloc(&s->queue, n, s->key);
  if (st != WG_OK) {
    wg_ed_free(s);
    return st;
  }
  return WG_OK;
}

/* Cells: wider than the largest diameter plus the bridge range; the vertical grid of a
   shaker spans everything the walls sweep. */
static int setup_cells(wg_ed *s)
{
  double dmax = 0;
  for (long i = 0; i < s->n; i++)
    if (2 * s->p[i].radius > dmax) dmax = 2 * s->p[i].radius;
  double lo[3] = {0, 0, 0}, len[3] = {s->box[0], s->box[1], s->box[2]};
  if (s->listed) s->nl.r_max = 0.5 * dmax;
  double range = dmax + s->s_crit + (s->listed ? s->nl.shell : 0);
  if (s->nwalls) {
    lo[s->up] = -s->wall[0].A;
    len[s->up] = s->box[s->up] + 2 * s->wall[0].A;
  } else {
    /* A dilute periodic gas (free cooling, thesis Fig. 2.6: phi = 0.006) would get hundreds of
       empty cells per particle, bytes and cell crossings for nothing: cells hold at least one
       particle in CELLS_PER_PARTICLE on average.  Denser gases keep cells one range wide. */
    double volume = 1, widest = INFINITY; /* a periodic axis keeps 3 cells */
    for (int k = 0; k < s->dim; k++) {
      volume *= len[k];
      widest = fmin(widest, len[k] / 3);
    }
    double w = fmin(pow(volume / (CELLS_PER_PARTICLE * (double)s->n), 1.0 / s->dim), widest);
    if (w > range) range = w;
  }
  int st = wg_cells_alloc(&s->cells, s->dim, lo, len, s->periodic, range, s->n);
  /* resting grains make no events (and so no synchronisations): without turn_back a grain
     falling onto them after its apex could pass through them unseen */
  s->cells.turn_back = s->riding != NULL;
  if (st == WG_OK)
    s->cell_images = s->cells.images_exact && !(s->g > 0 && s->periodic[s->up]);
  s->gather = s->n >= GATHER_MIN_N;
  return st;
}

int wg_ed_alloc_empty(wg_ed *s, const wg_scene *sc, long n)
{
  return setup_common(s, sc, n);
}

int wg_ed_start(wg_ed *s, double t0)
{
  int st = setup_cells(s);
  if (st != WG_OK) return st;
  s->now = t0;
  s->sheared = wg_shear_active(s->shear, t0);
  if (s->noise) s->counts.kicks = kicks_by(s, t0);
  st = wg_ed_synchronize(s);
  if (st != WG_OK) return st;
  double ek, ep;
  wg_ed_energy(s, &ek, &ep);
  s->ledger.e0 = ek + ep;
  s->ledger.scale = ek + fabs(ep);
  return WG_OK;
}

/* With init_from: the bridges of the run file's last snapshot (slots are identities until
   wg_ed_start renumbers them). */
static int restore_bonds(wg_ed *s, const wg_scene *sc)
{
  int32_t *pairs;
  long nb;
  int st = wg_init_bonds(sc, &pairs, &nb);
  if (st != WG_OK || !nb) return st;
  if (!s->wet) st = wg_error(WG_EINVAL, sc->init_from, "init_from: bridges in the run file, but this scene is dry");
  for (long k = 0; st == WG_OK && k < nb; k++) {
    int32_t i = pairs[2 * k], j = pairs[2 * k + 1];
    if (s->nbond[i] >= s->bond_cap || s->nbond[j] >= s->bond_cap) {
      st = wg_error(WG_EINVAL, sc->init_from, "init_from: particle with more than %d bridges", s->bond_cap);
      break;
    }
    s->bond[(size_t)i * s->bond_cap + s->nbond[i]++] = j;
    s->bond[(size_t)j * s->bond_cap + s->nbond[j]++] = i;
  }
  free(pairs);
  return st;
}

int wg_ed_alloc(wg_ed *s, const wg_scene *sc)
{
  int st = setup_common(s, sc, sc->n);
  if (st == WG_OK) st = wg_init_state(sc, s->p, s->mass);
  if (st == WG_OK && sc->init_from[0]) st = restore_bonds(s, sc);
  if (st == WG_OK) st = wg_ed_start(s, 0.0);
  if (st != WG_OK) wg_ed_free(s);
  return st;
}

int wg_ed_alloc_state(wg_ed *s, const wg_scene *sc, long n, const double *r, const double *v,
                      const double *radius, const double *mass, double t0)
{
  int st = setup_common(s, sc, n);
  if (st != WG_OK) return st;
  for (long i = 0; i < n; i++) {
    for (int k = 0; k < s->dim; k++) {
      s->p[i].r[k] = r[i * s->dim + k];
      s->p[i].v[k] = v[i * s->dim + k];
    }
    s->p[i].t = t0;
    s->p[i].radius = radius[i];
    if (s->mass) s->mass[i] = mass ? mass[i] : 1.0;
  }
  st = wg_ed_start(s, t0);
  if (st != WG_OK) wg_ed_free(s);
  return st;
}

size_t wg_ed_bytes(const wg_ed *s)
{
  size_t n = (size_t)s->n;
  size_t per = sizeof *s->p + sizeof *s->ev + sizeof *s->key + 3 * sizeof(int32_t) /* cell lists */ +
               2 * sizeof(int32_t) /* id, slot */;
  size_t bytes = n * per + wg_evqueue_bytes(&s->queue) +
                 (size_t)s->cells.ncell * sizeof(int32_t);
  if (s->mass) bytes += n * sizeof *s->mass;
  if (s->t_last) bytes += n * sizeof *s->t_last;
  if (s->riding) bytes += n * sizeof *s->riding;
  if (s->wet) bytes += n * ((size_t)s->bond_cap * sizeof *s->bond + sizeof *s->nbond);
  if (s->shear) bytes += n * sizeof *s->bin + (size_t)s->shear->nbins * sizeof(double);
  if (s->listed) bytes += wg_nlist_bytes(&s->nl, s->n);
  return bytes;
}

void wg_ed_free(wg_ed *s)
{
  free(s->p); free(s->id); free(s->slot); free(s->ev); free(s->key);
  free(s->mass); free(s->t_last); free(s->riding); free(s->bond); free(s->nbond); free(s->bin);
  if (s->shear) wg_shear_free(s->shear);
  free(s->shear);
  wg_cells_free(&s->cells);
  if (s->listed) wg_nlist_free(&s->nl);
  wg_evqueue_free(&s->queue);
  memset(s, 0, sizeof *s);
}
