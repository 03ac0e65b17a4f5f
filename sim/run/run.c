/* A run of either engine with its observers, checkpoints and run file.  The observers see
   the particles through a few accessors (particle(), bond_counts()); the engines differ only
   in the time-series columns they fill, their checkpoint state and their summary line. */
#include "run.h"

#include <errno.h>
#include <gsl/gsl_version.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include "io_h5.h"

#ifndef WG_CFLAGS
#define WG_CFLAGS "unknown"
#endif

/* Columns of the time series, in storage order: each becomes /observables/<name>. */
typedef struct series_column {
  const char *name, *unit, *description;
  int only;              /* ONLY_ED / ONLY_TD: written for one engine; 0: both */
  const char *td_description; /* the time-driven engine's meaning, where it differs */
} series_column;

enum { ONLY_ED = 1, ONLY_TD = 2, ONLY_SHEAR = 4 /* event-driven, with a shear field */,
       ONLY_NOISE = 8 /* event-driven, with the random force */ };

enum {
  COL_TIME, COL_KINETIC, COL_POTENTIAL, COL_INJ_WALL, COL_DIS_COLL, COL_DIS_WALL, COL_DIS_RUPT,
  COL_RESIDUAL, COL_TG, COL_BRIDGES, COL_COLLISIONS, COL_CAPTURES, COL_RUPTURES,
  COL_REFLECTIONS, COL_WALL_HITS, COL_WALL_ENTERS, COL_CELL_CROSSINGS, COL_STEPS, COL_REBUILDS,
  COL_FIELD_WORK, COL_E_PAR, COL_E_PERP, COL_INJ_NOISE, COL_A2, COL_A2_FREE, COL_TG_FREE,
  /* last: older checkpoints have fewer columns */
  NCOL
};
/* checkpoints hold NCOL columns, or NCOL - OLD_COLS up to NCOL - 1 when written before the
   last columns existed (field_work; e_par and e_perp; the random force's four) */
#define OLD_COLS 7

static const series_column columns[NCOL] = {
    {"time", "tau", "simulated time of the sample", 0, NULL},
    {"kinetic_energy", "m d+2 tau-2", "total kinetic energy, sum of m v^2 / 2", 0,
     "total kinetic energy, sum of m v^2 / 2 (with friction: plus I w^2 / 2)"},
    {"potential_energy", "m d+2 tau-2", "total potential energy in gravity, sum of m g z (z = 0 at the floor's mean position)", 0,
     "potential energy: gravity (sum of m g z, z = 0 at the floor's mean position) + elastic energy of the overlaps (and of the tangential springs) + bond energy (F_B gap, or Eq. 2.9 integrated)"},
    {"injected_wall", "m d+2 tau-2", "work done on the particles by the moving walls since t = 0", 0, NULL},
    {"dissipated_collisions", "m d+2 tau-2", "energy lost in inelastic particle collisions since t = 0 (Eq. 2.6)", 0,
     "energy lost in the dashpots of particle contacts since t = 0 (with friction: and in their tangential forces)"},
    {"dissipated_wall", "m d+2 tau-2", "energy lost in inelastic wall collisions since t = 0", 0,
     "energy lost in the dashpots of wall contacts since t = 0 (with friction: and in their tangential forces)"},
    {"dissipated_ruptures", "m d+2 tau-2", "energy taken by capillary bridge ruptures since t = 0, E_cb each", 0,
     "bond energy taken by ruptures (minus that given by captures at an overlap) since t = 0"},
    {"ledger_residual", "1", "|E(t) - E(0) - injected + dissipated| / energy scale of the run", 0, NULL},
    {"temperature", "m d+2 tau-2", "granular temperature T_g = sum m |v - V_cm|^2 / (N D) (Eq. 3.2)", 0, NULL},
    {"bridges", "1", "number of capillary bridges", 0, NULL},
    {"collisions", "1", "particle-particle collisions since t = 0", 0,
     "particle-particle contacts begun since t = 0"},
    {"captures", "1", "capillary bridges formed since t = 0", 0, NULL},
    {"ruptures", "1", "capillary bridges ruptured since t = 0", 0, NULL},
    {"reflections", "1", "bonded pairs reflected at gap s_crit since t = 0", ONLY_ED, NULL},
    {"wall_hits", "1", "particle-wall collisions since t = 0", 0, "particle-wall contacts begun since t = 0"},
    {"wall_enters", "1", "entries into a wall's reach (exact wall solver calls) since t = 0", ONLY_ED, NULL},
    {"cell_crossings", "1", "cell crossings (bookkeeping events) since t = 0", ONLY_ED, NULL},
    {"steps", "1", "time steps since t = 0", ONLY_TD, NULL},
    {"list_rebuilds", "1", "neighbour-list rebuilds since t = 0", ONLY_TD, NULL},
    {"field_work", "m d+2 tau-2", "work done on the particles by the shear field since t = 0 (its bins' forces times the displacements along them)", ONLY_SHEAR, NULL},
    {"e_par", "m d+2 tau-2", "kinetic energy per particle along the shear force, sum of m v_f^2 / 2 over N (thesis Ch. 8: E_par)", ONLY_SHEAR, NULL},
    {"e_perp", "m d+2 tau-2", "kinetic energy per particle across the shear force in its plane (along x, where the force varies), sum of m v_x^2 / 2 over N (thesis Ch. 8: E_perp)", ONLY_SHEAR, NULL},
    {"injected_noise", "m d+2 tau-2", "work done on the particles by the random force's kicks since t = 0", ONLY_NOISE, NULL},
    {"a2", "1", "Sonine coefficient of the velocity distribution, a_2 = D/(D+2) <u^4>/<u^2>^2 - 1 over the velocities u relative to the centre of mass (thesis Eq. A.32)", ONLY_NOISE, NULL},
    {"a2_free", "1", "a_2 of the particles without a bridge (the free grains of the kinetic theory, App. A; = a2 when dry)", ONLY_NOISE, NULL},
    {"temperature_free", "m d+2 tau-2", "granular temperature of the particles without a bridge, sum m |v - V_cm|^2 / (N_free D)", ONLY_NOISE, NULL},
};

static int is_td(const wg_run *run) { return run->sc->engine == WG_ENGINE_TD; }
static int column_used(const wg_run *run, int c)
{
  if (columns[c].only == ONLY_SHEAR) return !is_td(run) && run->sc->shear_force != 0;
  if (columns[c].only == ONLY_NOISE) return !is_td(run) && run->sc->noise != 0;
  return !columns[c].only || columns[c].only == (is_td(run) ? ONLY_TD : ONLY_ED);
}

static double wall_clock(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

unsigned long long wg_run_events(const wg_run *run)
{
  if (is_td(run)) return run->td.contacts + run->td.ruptures + run->td.wall_contacts;
  const wg_counts *c = &run->ed.counts;
  return c->collisions + c->ruptures + c->reflections + c->wall_hits;
}

/* ---------- the engines seen by the observers ---------- */

static double run_now(const wg_run *run) { return is_td(run) ? run->td.t : run->ed.now; }

/* Storage index of particle id (the event-driven engine keeps particles in cell order). */
static long slot_of(const wg_run *run, long id) { return is_td(run) ? id : run->ed.slot[id]; }

/* Particle at storage index k now: position (wrapped into the periodic box), velocity, radius
   and mass. */
static void particle(const wg_run *run, long k, double *r, double *v, double *radius, double *mass)
{
  if (!is_td(run)) {
    const wg_ed *s = &run->ed;
    wg_ed_position_at(s, k, s->now, r, v);
    *radius = s->p[k].radius;
    *mass = wg_ed_mass(s, k);
    return;
  }
  const wg_td *s = &run->td;
  for (int a = 0; a < 3; a++) {
    r[a] = s->r[3 * k + a];
    v[a] = s->v[3 * k + a];
    if (a < s->par.dim && s->par.periodic[a]) r[a] -= s->par.box[a] * floor(r[a] / s->par.box[a]);
  }
  *radius = s->radius[k];
  *mass = s->mass ? s->mass[k] : 1.0;
}

/* Angular velocity components per particle in a snapshot: 1 (2D) or 3 (3D) with friction,
   else 0. */
static int spin_components(const wg_run *run)
{
  if (!is_td(run) || !run->td.rot) return 0;
  return run->sc->dim == 2 ? 1 : 3;
}

/* Bridges per particle (storage order), NULL when dry. */
static const uint8_t *bond_counts(wg_run *run)
{
  if (!is_td(run)) return run->ed.wet ? run->ed.nbond : NULL;
  const wg_td *s = &run->td;
  if (s->par.f_b <= 0 || !run->nbond) return NULL;
  memset(run->nbond, 0, (size_t)s->n);
  for (long k = 0; k < s->npair; k++)
    if (s->pair[k].bonded) {
      run->nbond[s->pair[k].i]++;
      run->nbond[s->pair[k].j]++;
    }
  return run->nbond;
}

/* ---------- observers ---------- */

static double temperature(const wg_run *run)
{
  double msum = 0, mv[3] = {0, 0, 0}, mv2 = 0;
  int dim = run->sc->dim;
  long n = run->sc->n;
  for (long i = 0; i < n; i++) {
    double r[3], v[3], rad, m;
    particle(run, i, r, v, &rad, &m);
    msum += m;
    for (int k = 0; k < dim; k++) {
      mv[k] += m * v[k];
      mv2 += m * v[k] * v[k];
    }
  }
  double cm2 = 0;
  for (int k = 0; k < dim; k++) cm2 += mv[k] * mv[k];
  return (mv2 - cm2 / msum) / (double)(n * dim); /* Eq. 3.2 */
}

/* The velocity distribution's a_2 (Eq. A.32: the fourth moment against a Gaussian's) of every
   particle and of those without a bridge, and the latter's temperature; velocities relative
   to the centre of mass of all, in one pass after it. */
static void velocity_moments(wg_run *run, double *a2_all, double *a2_free, double *t_free)
{
  int dim = run->sc->dim;
  long n = run->sc->n, nfree = 0;
  const uint8_t *nb = bond_counts(run);
  double msum = 0, mv[3] = {0, 0, 0}, u2 = 0, u4 = 0, f2 = 0, f4 = 0, mf2 = 0;
  for (long i = 0; i < n; i++) {
    double r[3], v[3], rad, m;
    particle(run, i, r, v, &rad, &m);
    msum += m;
    for (int k = 0; k < dim; k++) mv[k] += m * v[k];
  }
  for (long i = 0; i < n; i++) {
    double r[3], v[3], rad, m, w = 0;
    particle(run, i, r, v, &rad, &m);
    for (int k = 0; k < dim; k++) w += (v[k] - mv[k] / msum) * (v[k] - mv[k] / msum);
    u2 += w;
    u4 += w * w;
    if (nb && nb[i]) continue;
    mf2 += m * w;
    f2 += w;
    f4 += w * w;
    nfree++;
  }
  double c = (double)dim / (dim + 2);
  *a2_all = u2 > 0 ? c * (u4 / n) / ((u2 / n) * (u2 / n)) - 1 : NAN;
  *a2_free = f2 > 0 ? c * (f4 / nfree) / ((f2 / nfree) * (f2 / nfree)) - 1 : NAN;
  *t_free = nfree ? mf2 / (double)(nfree * dim) : NAN;
}

static int sample_series(wg_run *run)
{
  if (run->rows == run->cap) {
    size_t cap = run->cap ? 2 * run->cap : 1024;
    double *p = realloc(run->series, sizeof *p * cap * NCOL);
    if (!p) return wg_error(WG_ENOMEM, "time series", "cannot grow to %zu rows", cap);
    run->series = p;
    run->cap = cap;
  }
  double *row = run->series + run->rows * NCOL;
  memset(row, 0, sizeof *row * NCOL);
  row[COL_TG] = temperature(run);
  if (is_td(run)) {
    const wg_td *s = &run->td;
    double ek, ep;
    wg_td_energy(s, &ek, &ep);
    row[COL_TIME] = s->t;
    row[COL_KINETIC] = ek;
    row[COL_POTENTIAL] = ep;
    row[COL_INJ_WALL] = wg_ksum_value(&s->injected_wall);
    row[COL_DIS_COLL] = wg_ksum_value(&s->dissipated);
    row[COL_DIS_WALL] = wg_ksum_value(&s->dissipated_wall);
    row[COL_DIS_RUPT] = wg_ksum_value(&s->dissipated_rupt);
    row[COL_RESIDUAL] = wg_td_ledger_residual(s);
    row[COL_BRIDGES] = (double)wg_td_bond_total(s);
    row[COL_COLLISIONS] = (double)s->contacts;
    row[COL_CAPTURES] = (double)s->captures;
    row[COL_RUPTURES] = (double)s->ruptures;
    row[COL_WALL_HITS] = (double)s->wall_contacts;
    row[COL_STEPS] = (double)s->steps;
    row[COL_REBUILDS] = (double)s->rebuilds;
    run->rows++;
    return WG_OK;
  }
  wg_ed *s = &run->ed;
  double ek, ep;
  wg_ed_energy(s, &ek, &ep);
  row[COL_TIME] = s->now;
  row[COL_KINETIC] = ek;
  row[COL_POTENTIAL] = ep;
  row[COL_INJ_WALL] = wg_ed_wall_work(s);
  row[COL_DIS_COLL] = wg_ksum_value(&s->ledger.dissipated_coll);
  row[COL_DIS_WALL] = wg_ksum_value(&s->ledger.dissipated_wall);
  row[COL_DIS_RUPT] = wg_ksum_value(&s->ledger.dissipated_rupt);
  row[COL_RESIDUAL] = wg_ed_ledger_residual(s);
  row[COL_BRIDGES] = (double)wg_ed_bond_total(s);
  row[COL_COLLISIONS] = (double)s->counts.collisions;
  row[COL_CAPTURES] = (double)s->counts.captures;
  row[COL_RUPTURES] = (double)s->counts.ruptures;
  row[COL_REFLECTIONS] = (double)s->counts.reflections;
  row[COL_WALL_HITS] = (double)s->counts.wall_hits;
  row[COL_WALL_ENTERS] = (double)s->counts.wall_enters;
  row[COL_CELL_CROSSINGS] = (double)s->counts.cell_crossings;
  row[COL_FIELD_WORK] = wg_ed_field_work(s);
  if (s->noise) {
    row[COL_INJ_NOISE] = wg_ksum_value(&s->ledger.injected_noise);
    velocity_moments(run, &row[COL_A2], &row[COL_A2_FREE], &row[COL_TG_FREE]);
  }
  if (s->shear) { /* Ch. 8's order parameters */
    double par = 0, perp = 0;
    for (long i = 0; i < s->n; i++) {
      double r[3], v[3], m = wg_ed_mass(s, i);
      wg_ed_position_at(s, i, s->now, r, v);
      par += 0.5 * m * v[s->shear->axis] * v[s->shear->axis];
      perp += 0.5 * m * v[0] * v[0];
    }
    row[COL_E_PAR] = par / (double)s->n;
    row[COL_E_PERP] = perp / (double)s->n;
  }
  run->rows++;
  return WG_OK;
}

static int profile_alloc(wg_profile *pr, int bins)
{
  pr->bins = bins;
  pr->samples = 0;
  return wg_cellsums_alloc(&pr->sums, (size_t)(bins > 0 ? bins : 1), 1);
}

/* One sample of the lateral profiles: every particle adds to the bin of its x coordinate;
   a bridge counts half in the bin of each of its particles. */
static void sample_profile(wg_run *run)
{
  wg_profile *pr = &run->prof;
  int dim = run->sc->dim;
  double width = run->sc->lx / pr->bins;
  double unit_volume = dim == 2 ? M_PI : 4 * M_PI / 3; /* times radius^dim */
  const uint8_t *nbond = bond_counts(run);
  for (long i = 0; i < run->sc->n; i++) {
    double r[3], v[3], radius, m;
    particle(run, i, r, v, &radius, &m);
    int b = (int)(r[0] / width);
    if (b >= pr->bins) b = pr->bins - 1;
    if (b < 0) b = 0;
    wg_cellsums_add(&pr->sums, (size_t)b, dim, v, m, unit_volume * pow(radius, dim),
                    nbond ? nbond[i] : 0);
  }
  pr->samples++;
}

/* One sample of the lateral or height maps (maps.h): every particle with its bridges. */
static int sample_map(wg_run *run, wg_map *map)
{
  const uint8_t *nbond = bond_counts(run);
  for (long i = 0; i < run->sc->n; i++) {
    double r[3], v[3], radius, m;
    particle(run, i, r, v, &radius, &m);
    wg_map_add(map, r, v, m, radius, nbond ? nbond[i] : 0);
  }
  return wg_map_end_sample(map);
}

/* Snapshot record in the scratch file: positions, velocities (n x dim doubles each),
   bridge counts (n bytes), bridge pairs i < j (2 x int32 each). */
static int write_frame(wg_run *run)
{
  long n = run->sc->n;
  int dim = run->sc->dim;
  long long nb = 0;
  size_t bytes = 0;
  for (int what = 0; what < 2; what++) /* positions, then velocities */
    for (long id = 0; id < n; id++) {
      double r[3], v[3], radius, m;
      particle(run, slot_of(run, id), r, v, &radius, &m);
      bytes += fwrite(what ? v : r, sizeof(double), (size_t)dim, run->frames) * sizeof(double);
    }
  int nw = spin_components(run);
  for (long id = 0; nw && id < n; id++)
    bytes += fwrite(&run->td.w[3 * id + 3 - nw], sizeof(double), (size_t)nw, run->frames) * sizeof(double);
  const uint8_t *nbond = bond_counts(run);
  for (long id = 0; id < n; id++) {
    uint8_t c = nbond ? nbond[slot_of(run, id)] : 0;
    bytes += fwrite(&c, 1, 1, run->frames);
  }
  if (nbond && is_td(run)) {
    const wg_td *s = &run->td;
    for (long k = 0; k < s->npair; k++)
      if (s->pair[k].bonded) {
        int32_t pair[2] = {s->pair[k].i, s->pair[k].j};
        bytes += fwrite(pair, sizeof(int32_t), 2, run->frames) * sizeof(int32_t);
        nb++;
      }
  } else if (nbond) {
    const wg_ed *s = &run->ed;
    for (long id = 0; id < s->n; id++) {
      long i = s->slot[id];
      for (int k = 0; k < s->nbond[i]; k++) {
        int32_t pair[2] = {(int32_t)id, s->id[s->bond[(size_t)i * s->bond_cap + k]]};
        if (pair[1] < id) continue;
        bytes += fwrite(pair, sizeof(int32_t), 2, run->frames) * sizeof(int32_t);
        nb++;
      }
    }
  }
  size_t expect = (size_t)n * ((2 * dim + nw) * sizeof(double) + 1) + (size_t)nb * 8;
  if (bytes != expect || fflush(run->frames) != 0)
    return wg_error(WG_EIO, run->frames_path, "cannot write snapshot %ld: %s", run->nframes,
                    strerror(errno));
  double *ft = realloc(run->frame_time, sizeof(double) * (size_t)(run->nframes + 1));
  long long *fb = realloc(run->frame_bonds, sizeof(long long) * (size_t)(run->nframes + 1));
  if (ft) run->frame_time = ft;
  if (fb) run->frame_bonds = fb;
  if (!ft || !fb) return wg_error(WG_ENOMEM, "snapshots", "cannot grow the frame index");
  run->frame_time[run->nframes] = run_now(run);
  run->frame_bonds[run->nframes] = nb;
  run->nframes++;
  run->frames_bytes += (long long)expect;
  return WG_OK;
}

/* ---------- checkpoints ---------- */

static char *scene_fingerprint(const wg_scene *sc);

/* The event-driven engine's state, after wg_ed_synchronize(). */
static int ckpt_write_ed(wg_run *run, hid_t f)
{
  wg_ed *s = &run->ed;
  int st = WG_OK;
  long n = s->n;
  double *buf = malloc(sizeof(double) * (size_t)n * 3);
  if (!buf) return wg_error(WG_ENOMEM, "checkpoint", "no memory");
  hsize_t d2[2] = {(hsize_t)n, 3}, d1[1] = {(hsize_t)n};
  for (long i = 0; i < n; i++) memcpy(buf + 3 * i, s->p[i].r, sizeof(double) * 3);
  st |= wg_h5_write(f, "state/r", H5T_NATIVE_DOUBLE, 2, d2, buf, "d", "positions at time now");
  for (long i = 0; i < n; i++) memcpy(buf + 3 * i, s->p[i].v, sizeof(double) * 3);
  st |= wg_h5_write(f, "state/v", H5T_NATIVE_DOUBLE, 2, d2, buf, "d tau-1", "velocities");
  for (long i = 0; i < n; i++) buf[i] = s->p[i].radius;
  st |= wg_h5_write(f, "state/radius", H5T_NATIVE_DOUBLE, 1, d1, buf, "d", "radii");
  st |= wg_h5_write(f, "state/id", H5T_NATIVE_INT32, 1, d1, s->id, "1", "identity of the particle in each slot");
  free(buf);
  if (s->mass) st |= wg_h5_write(f, "state/mass", H5T_NATIVE_DOUBLE, 1, d1, s->mass, "m", "masses");
  if (s->t_last)
    st |= wg_h5_write(f, "state/t_last", H5T_NATIVE_DOUBLE, 1, d1, s->t_last, "tau",
                      "time of each particle's last collision (TC model)");
  if (s->riding) {
    st |= wg_h5_write(f, "state/riding", H5T_NATIVE_UINT8, 1, d1, s->riding, "1",
                      "1 while the particle rests on the floor (rest_speed)");
    unsigned long long rc[2] = {s->counts.rests, s->counts.lift_offs};
    hsize_t d2c[1] = {2};
    st |= wg_h5_write(f, "run/rest_counts", H5T_NATIVE_ULLONG, 1, d2c, rc, "1",
                      "floor contacts come to rest, lift-offs");
  }
  if (s->wet) {
    hsize_t db[1] = {(hsize_t)n * (hsize_t)s->bond_cap};
    st |= wg_h5_write(f, "state/nbond", H5T_NATIVE_UINT8, 1, d1, s->nbond, "1", "bridges per particle");
    st |= wg_h5_write(f, "state/bond", H5T_NATIVE_INT32, 1, db, s->bond, "1", "bridge partners, bond_cap per particle");
  }
  unsigned long long counts[10] = {s->counts.collisions, s->counts.captures, s->counts.ruptures,
                                  s->counts.reflections, s->counts.wall_hits, s->counts.wall_enters,
                                  s->counts.cell_crossings, s->counts.stale, s->counts.rigid,
                                   s->counts.grazing};
  hsize_t d8[1] = {10};
  st |= wg_h5_write(f, "run/counts", H5T_NATIVE_ULLONG, 1, d8, counts, "1", "event counts");
  double ledger[10] = {s->ledger.injected_wall.s, s->ledger.injected_wall.c,
                       s->ledger.dissipated_coll.s, s->ledger.dissipated_coll.c,
                       s->ledger.dissipated_wall.s, s->ledger.dissipated_wall.c,
                       s->ledger.dissipated_rupt.s, s->ledger.dissipated_rupt.c,
                       s->ledger.e0, s->ledger.scale};
  hsize_t d10[1] = {10};
  st |= wg_h5_write(f, "run/ledger", H5T_NATIVE_DOUBLE, 1, d10, ledger, "m d+2 tau-2", "ledger sums");
  if (s->shear) {
    double field[3] = {s->ledger.injected_field.s, s->ledger.injected_field.c,
                       (double)s->counts.bin_crossings};
    hsize_t d3f[1] = {3};
    st |= wg_h5_write(f, "run/field", H5T_NATIVE_DOUBLE, 1, d3f, field, "m d+2 tau-2, 1",
                      "shear field's work (sum, compensation), bin crossings");
  }
  if (s->noise) {
    double noise[2] = {s->ledger.injected_noise.s, s->ledger.injected_noise.c};
    hsize_t d2n[1] = {2};
    st |= wg_h5_write(f, "run/noise", H5T_NATIVE_DOUBLE, 1, d2n, noise, "m d+2 tau-2",
                      "random force's work (sum, compensation)");
  }
  unsigned long long ws[3] = {s->wall_stats.calls, s->wall_stats.pieces, s->wall_stats.evaluations};
  hsize_t d3[1] = {3};
  st |= wg_h5_write(f, "run/wall_stats", H5T_NATIVE_ULLONG, 1, d3, ws, "1", "wall solver work");
  st |= wg_h5_attr_double(f, ".", "now", s->now);
  return st;
}

/* The time-driven engine's counters and ledger scalars, in checkpoint order. */
enum { TD_NCOUNT = 6, TD_NLEDGER = 15 };
static unsigned long long *td_count(wg_td *s, int k)
{
  unsigned long long *c[TD_NCOUNT] = {&s->steps, &s->rebuilds, &s->captures, &s->ruptures,
                                      &s->contacts, &s->wall_contacts};
  return c[k];
}
static double *td_ledger(wg_td *s, int k)
{
  double *l[TD_NLEDGER] = {&s->injected_wall.s, &s->injected_wall.c, &s->dissipated.s,
                           &s->dissipated.c, &s->dissipated_wall.s, &s->dissipated_wall.c,
                           &s->dissipated_rupt.s, &s->dissipated_rupt.c, &s->e0, &s->u_contact,
                           &s->u_bond, &s->p_wall, &s->p_diss, &s->p_diss_wall, &s->t0};
  return l[k];
}

/* The time-driven engine's state between two steps, complete (forces, neighbour list with
   its pair states, positions at the last build) so that a resumed run takes exactly the
   steps the uninterrupted one takes. */
static int ckpt_write_td(wg_run *run, hid_t f)
{
  const wg_td *s = &run->td;
  int st = WG_OK;
  long n = s->n, np = s->npair;
  hsize_t d2[2] = {(hsize_t)n, 3}, d1[1] = {(hsize_t)n}, dp[2] = {(hsize_t)np, 2};
  st |= wg_h5_write(f, "state/r", H5T_NATIVE_DOUBLE, 2, d2, s->r, "d", "positions");
  st |= wg_h5_write(f, "state/v", H5T_NATIVE_DOUBLE, 2, d2, s->v, "d tau-1", "velocities");
  st |= wg_h5_write(f, "state/f", H5T_NATIVE_DOUBLE, 2, d2, s->f, "m g", "forces");
  st |= wg_h5_write(f, "state/r_built", H5T_NATIVE_DOUBLE, 2, d2, s->r_built, "d", "positions at the last list build");
  if (s->gear) {
    hsize_t dg[2] = {(hsize_t)n, 12};
    st |= wg_h5_write(f, "state/gear", H5T_NATIVE_DOUBLE, 2, dg, s->gear, "d",
                      "Gear's scaled derivatives dt^k/k! d^k r/dt^k, k = 2..5, per axis");
  }
  if (s->gear_w) {
    hsize_t dg[2] = {(hsize_t)n, 12};
    st |= wg_h5_write(f, "state/gear_w", H5T_NATIVE_DOUBLE, 2, dg, s->gear_w, "1",
                      "Gear's scaled derivatives dt^k/k! d^k w/dt^k, k = 1..4, per axis");
  }
  if (s->rot) {
    hsize_t dw[2] = {2 * (hsize_t)n, 4};
    st |= wg_h5_write(f, "state/w", H5T_NATIVE_DOUBLE, 2, d2, s->w, "tau-1", "angular velocities");
    st |= wg_h5_write(f, "state/torque", H5T_NATIVE_DOUBLE, 2, d2, s->tq, "m d+2 tau-2", "torques");
    st |= wg_h5_write(f, "state/wall_spring", H5T_NATIVE_DOUBLE, 2, dw, s->wall_spring, "d, m g / d",
                      "tangential springs on the walls (2 i + wall): extension, stiffness");
    if (np) {
      hsize_t ds[2] = {(hsize_t)np, 4};
      st |= wg_h5_write(f, "state/pair_spring", H5T_NATIVE_DOUBLE, 2, ds, s->spring, "d, m g / d",
                        "tangential springs of the neighbour pairs: extension, stiffness");
    }
  }
  st |= wg_h5_write(f, "state/radius", H5T_NATIVE_DOUBLE, 1, d1, s->radius, "d", "radii");
  if (s->mass) st |= wg_h5_write(f, "state/mass", H5T_NATIVE_DOUBLE, 1, d1, s->mass, "m", "masses");
  st |= wg_h5_write(f, "state/wall_touch", H5T_NATIVE_UINT8, 1, d1, s->wall_touch, "1", "wall contacts (bit per wall)");
  int32_t *ij = malloc(sizeof *ij * 2 * (size_t)(np ? np : 1));
  uint8_t *flags = malloc(2 * (size_t)(np ? np : 1));
  if (!ij || !flags) st = WG_ENOMEM;
  for (long k = 0; st == WG_OK && k < np; k++) {
    ij[2 * k] = s->pair[k].i;
    ij[2 * k + 1] = s->pair[k].j;
    flags[2 * k] = s->pair[k].bonded;
    flags[2 * k + 1] = s->pair[k].touching;
  }
  if (st == WG_OK) {
    st |= wg_h5_write(f, "state/pair", H5T_NATIVE_INT32, 2, dp, ij, "1", "neighbour list, in order");
    st |= wg_h5_write(f, "state/pair_state", H5T_NATIVE_UINT8, 2, dp, flags, "1", "bonded, touching");
  }
  free(ij);
  free(flags);
  unsigned long long counts[TD_NCOUNT];
  double ledger[TD_NLEDGER];
  for (int k = 0; k < TD_NCOUNT; k++) counts[k] = *td_count((wg_td *)s, k);
  for (int k = 0; k < TD_NLEDGER; k++) ledger[k] = *td_ledger((wg_td *)s, k);
  hsize_t d6[1] = {TD_NCOUNT}, d15[1] = {TD_NLEDGER};
  st |= wg_h5_write(f, "run/td_counts", H5T_NATIVE_ULLONG, 1, d6, counts, "1", "steps, rebuilds, captures, ruptures, contacts, wall contacts");
  st |= wg_h5_write(f, "run/td_ledger", H5T_NATIVE_DOUBLE, 1, d15, ledger, "m d+2 tau-2", "ledger sums, energies and powers, t0");
  st |= wg_h5_attr_double(f, ".", "now", s->t);
  return st;
}

/* What the observers need to continue: time series, profile sums, the frame index and the
   sampling counters. */
static int ckpt_write_observers(wg_run *run, hid_t f)
{
  int st = WG_OK;
  hsize_t ds[2] = {run->rows, NCOL};
  st |= wg_h5_write(f, "run/series", H5T_NATIVE_DOUBLE, 2, ds, run->series, "-", "time series rows");
  st |= wg_cellsums_checkpoint_write(&run->prof.sums, f, "run/prof_");
  hsize_t df[1] = {(hsize_t)run->nframes};
  if (run->nframes) {
    st |= wg_h5_write(f, "run/frame_time", H5T_NATIVE_DOUBLE, 1, df, run->frame_time, "tau", "frame times");
    st |= wg_h5_write(f, "run/frame_bonds", H5T_NATIVE_LLONG, 1, df, run->frame_bonds, "1", "bridges per frame");
  }
  st |= wg_map_checkpoint_write(&run->map, f);
  st |= wg_map_checkpoint_write(&run->heights, f);
  long long k[7] = {run->k_series, run->k_snapshot, run->k_profile, run->k_checkpoint,
                    run->prof.samples, run->nframes, run->frames_bytes};
  hsize_t d7[1] = {7};
  st |= wg_h5_write(f, "run/counters", H5T_NATIVE_LLONG, 1, d7, k, "1", "sampling counters");
  st |= wg_h5_attr_double(f, ".", "wall_s", wall_clock() - run->wall_start + run->wall_resumed);
  st |= wg_h5_attr_llong(f, ".", "n", run->sc->n);
  char *fp = scene_fingerprint(run->sc);
  st |= fp ? wg_h5_attr_string(f, ".", "scene", fp) : WG_ENOMEM;
  free(fp);
  return st;
}

static int checkpoint_write(wg_run *run)
{
  char tmp[4200];
  snprintf(tmp, sizeof tmp, "%s.tmp", run->ckpt_path);
  hid_t f = wg_h5_create(tmp);
  if (f < 0) return WG_EIO;
  int st = is_td(run) ? ckpt_write_td(run, f) : ckpt_write_ed(run, f);
  if (st == WG_OK) st = ckpt_write_observers(run, f);
  wg_h5_close(f);
  if (st != WG_OK) return wg_error(WG_EIO, tmp, "checkpoint not written");
  if (rename(tmp, run->ckpt_path) != 0)
    return wg_error(WG_EIO, run->ckpt_path, "cannot rename checkpoint: %s", strerror(errno));
  return WG_OK;
}

static int read_into(hid_t f, const char *ckpt, const char *path, hid_t type, void *buf, hsize_t expect)
{
  int rank;
  hsize_t dims[8];
  if (wg_h5_dims(f, path, &rank, dims) != WG_OK) return WG_EIO;
  hsize_t total = 1;
  for (int k = 0; k < rank; k++) total *= dims[k];
  if (total != expect)
    return wg_error(WG_EIO, ckpt, "dataset %s has %llu values, expected %llu", path,
                    (unsigned long long)total, (unsigned long long)expect);
  return wg_h5_read(f, path, type, buf);
}

static int ckpt_load_ed(wg_run *run, hid_t f, long n, double now)
{
  const char *ck = run->ckpt_path;
  wg_ed *s = &run->ed;
  int st = wg_ed_alloc_empty(s, run->sc, n);
  if (st != WG_OK) return st;
  double *buf = malloc(sizeof(double) * (size_t)n * 3);
  if (!buf) return wg_error(WG_ENOMEM, "checkpoint", "no memory");
  st = read_into(f, ck, "state/r", H5T_NATIVE_DOUBLE, buf, (hsize_t)n * 3);
  for (long i = 0; st == WG_OK && i < n; i++) memcpy(s->p[i].r, buf + 3 * i, sizeof(double) * 3);
  if (st == WG_OK) st = read_into(f, ck, "state/v", H5T_NATIVE_DOUBLE, buf, (hsize_t)n * 3);
  for (long i = 0; st == WG_OK && i < n; i++) memcpy(s->p[i].v, buf + 3 * i, sizeof(double) * 3);
  if (st == WG_OK) st = read_into(f, ck, "state/radius", H5T_NATIVE_DOUBLE, buf, (hsize_t)n);
  for (long i = 0; st == WG_OK && i < n; i++) {
    s->p[i].radius = buf[i];
    s->p[i].t = now;
  }
  free(buf);
  if (st == WG_OK) st = read_into(f, ck, "state/id", H5T_NATIVE_INT32, s->id, (hsize_t)n);
  for (long i = 0; st == WG_OK && i < n; i++) {
    if (s->id[i] < 0 || s->id[i] >= n) st = WG_EIO;
    else s->slot[s->id[i]] = (int32_t)i;
  }
  if (st == WG_OK && s->mass) st = read_into(f, ck, "state/mass", H5T_NATIVE_DOUBLE, s->mass, (hsize_t)n);
  if (st == WG_OK && s->t_last) st = read_into(f, ck, "state/t_last", H5T_NATIVE_DOUBLE, s->t_last, (hsize_t)n);
  unsigned long long rc[2] = {0, 0};
  if (st == WG_OK && s->riding) {
    st = read_into(f, ck, "state/riding", H5T_NATIVE_UINT8, s->riding, (hsize_t)n);
    if (st == WG_OK) st = read_into(f, ck, "run/rest_counts", H5T_NATIVE_ULLONG, rc, 2);
  }
  if (st == WG_OK && s->wet) {
    st = read_into(f, ck, "state/nbond", H5T_NATIVE_UINT8, s->nbond, (hsize_t)n);
    if (st == WG_OK)
      st = read_into(f, ck, "state/bond", H5T_NATIVE_INT32, s->bond, (hsize_t)n * (hsize_t)s->bond_cap);
  }
  unsigned long long counts[10], ws[3];
  double ledger[10];
  if (st == WG_OK) st = read_into(f, ck, "run/counts", H5T_NATIVE_ULLONG, counts, 10);
  if (st == WG_OK) st = read_into(f, ck, "run/ledger", H5T_NATIVE_DOUBLE, ledger, 10);
  if (st == WG_OK) st = read_into(f, ck, "run/wall_stats", H5T_NATIVE_ULLONG, ws, 3);
  double field[3] = {0, 0, 0};
  if (st == WG_OK && s->shear) st = read_into(f, ck, "run/field", H5T_NATIVE_DOUBLE, field, 3);
  double noise[2] = {0, 0};
  if (st == WG_OK && s->noise) st = read_into(f, ck, "run/noise", H5T_NATIVE_DOUBLE, noise, 2);
  if (st != WG_OK) return st;
  s->counts = (wg_counts){counts[0], counts[1], counts[2], counts[3], counts[4], counts[5], counts[6], counts[7], counts[8],
               counts[9], (unsigned long long)field[2], rc[0], rc[1],
               0 /* kicks: a function of the time, set by wg_ed_start */};
  s->wall_stats = (wg_wall_stats){ws[0], ws[1], ws[2]};
  st = wg_ed_start(s, now);
  if (st != WG_OK) return st;
  s->ledger = (wg_ledger){.injected_wall = {ledger[0], ledger[1]},
                          .dissipated_coll = {ledger[2], ledger[3]},
                          .dissipated_wall = {ledger[4], ledger[5]},
                          .dissipated_rupt = {ledger[6], ledger[7]},
                          .injected_field = {field[0], field[1]},
                          .injected_noise = {noise[0], noise[1]}, .e0 = ledger[8],
                          .scale = ledger[9]};
  return WG_OK;
}

static int ckpt_load_td(wg_run *run, hid_t f, long n)
{
  const char *ck = run->ckpt_path;
  wg_td *s = &run->td;
  wg_td_params par;
  wg_td_params_from_scene(run->sc, &par);
  size_t n3 = 3 * (size_t)n;
  double *r = malloc(sizeof *r * n3), *v = malloc(sizeof *v * n3), *rad = malloc(sizeof *rad * (size_t)n);
  double *mass = run->sc->mass_scaling ? malloc(sizeof *mass * (size_t)n) : NULL;
  int st = (!r || !v || !rad || (run->sc->mass_scaling && !mass)) ? WG_ENOMEM : WG_OK;
  double ledger[TD_NLEDGER];
  unsigned long long counts[TD_NCOUNT];
  if (st == WG_OK) st = read_into(f, ck, "state/r", H5T_NATIVE_DOUBLE, r, n3);
  if (st == WG_OK) st = read_into(f, ck, "state/v", H5T_NATIVE_DOUBLE, v, n3);
  if (st == WG_OK) st = read_into(f, ck, "state/radius", H5T_NATIVE_DOUBLE, rad, (hsize_t)n);
  if (st == WG_OK && mass) st = read_into(f, ck, "state/mass", H5T_NATIVE_DOUBLE, mass, (hsize_t)n);
  if (st == WG_OK) st = read_into(f, ck, "run/td_ledger", H5T_NATIVE_DOUBLE, ledger, TD_NLEDGER);
  if (st == WG_OK) st = read_into(f, ck, "run/td_counts", H5T_NATIVE_ULLONG, counts, TD_NCOUNT);
  /* set up at t0, then overwrite everything the set-up recomputed */
  if (st == WG_OK) st = wg_td_alloc_state(s, &par, n, r, v, rad, mass, ledger[14]);
  free(v);
  free(rad);
  free(mass);
  if (st == WG_OK) memcpy(s->r, r, sizeof *r * n3); /* the set-up wrapped them */
  free(r);
  if (st == WG_OK) st = read_into(f, ck, "state/f", H5T_NATIVE_DOUBLE, s->f, n3);
  if (st == WG_OK) st = read_into(f, ck, "state/r_built", H5T_NATIVE_DOUBLE, s->r_built, n3);
  if (st == WG_OK && s->gear) st = read_into(f, ck, "state/gear", H5T_NATIVE_DOUBLE, s->gear, 4 * n3);
  if (st == WG_OK && s->gear_w) st = read_into(f, ck, "state/gear_w", H5T_NATIVE_DOUBLE, s->gear_w, 4 * n3);
  if (st == WG_OK) st = read_into(f, ck, "state/wall_touch", H5T_NATIVE_UINT8, s->wall_touch, (hsize_t)n);
  int rank;
  hsize_t dims[8] = {0};
  if (st == WG_OK) st = wg_h5_dims(f, "state/pair", &rank, dims);
  long np = (long)dims[0];
  int32_t *ij = NULL;
  uint8_t *flags = NULL;
  if (st == WG_OK) {
    ij = malloc(sizeof *ij * 2 * (size_t)(np ? np : 1));
    flags = malloc(2 * (size_t)(np ? np : 1));
    if (np > s->pair_cap) {
      wg_td_pair *p = realloc(s->pair, sizeof *p * (size_t)np);
      if (p) {
        s->pair = p;
        s->pair_cap = np;
      } else {
        st = WG_ENOMEM;
      }
    }
    if (!ij || !flags) st = WG_ENOMEM;
  }
  if (st == WG_OK && np) st = read_into(f, ck, "state/pair", H5T_NATIVE_INT32, ij, 2 * (hsize_t)np);
  if (st == WG_OK && np) st = read_into(f, ck, "state/pair_state", H5T_NATIVE_UINT8, flags, 2 * (hsize_t)np);
  for (long k = 0; st == WG_OK && k < np; k++) {
    if (ij[2 * k] < 0 || ij[2 * k] >= n || ij[2 * k + 1] < 0 || ij[2 * k + 1] >= n) st = WG_EIO;
    s->pair[k] = (wg_td_pair){.i = ij[2 * k], .j = ij[2 * k + 1], .bonded = flags[2 * k],
                              .touching = flags[2 * k + 1]};
  }
  free(ij);
  free(flags);
  if (st == WG_OK && s->rot) {
    wg_spring *sp = realloc(s->spring, sizeof *sp * (size_t)(s->pair_cap ? s->pair_cap : 1));
    if (!sp) return WG_ENOMEM;
    s->spring = sp;
    st = read_into(f, ck, "state/w", H5T_NATIVE_DOUBLE, s->w, n3);
    if (st == WG_OK) st = read_into(f, ck, "state/torque", H5T_NATIVE_DOUBLE, s->tq, n3);
    if (st == WG_OK) st = read_into(f, ck, "state/wall_spring", H5T_NATIVE_DOUBLE, s->wall_spring, 8 * (hsize_t)n);
    if (st == WG_OK && np) st = read_into(f, ck, "state/pair_spring", H5T_NATIVE_DOUBLE, s->spring, 4 * (hsize_t)np);
  }
  if (st != WG_OK) return st;
  s->npair = np;
  for (int k = 0; k < TD_NCOUNT; k++) *td_count(s, k) = counts[k];
  for (int k = 0; k < TD_NLEDGER; k++) *td_ledger(s, k) = ledger[k];
  s->t = s->t0 + (double)s->steps * s->par.dt;
  return WG_OK;
}

static int ckpt_load_observers(wg_run *run, hid_t f)
{
  const char *ck = run->ckpt_path;
  long long k[7];
  int st = read_into(f, ck, "run/counters", H5T_NATIVE_LLONG, k, 7);
  int rank;
  hsize_t dims[8] = {0};
  if (st == WG_OK) st = wg_h5_dims(f, "run/series", &rank, dims);
  if (st == WG_OK && (rank != 2 || dims[1] > NCOL || dims[1] < NCOL - OLD_COLS)) st = WG_EIO;
  if (st == WG_OK) {
    size_t width = dims[1];
    run->rows = run->cap = dims[0];
    run->series = calloc((dims[0] ? dims[0] : 1) * NCOL, sizeof(double));
    if (!run->series) st = WG_ENOMEM;
    else if (dims[0]) st = read_into(f, ck, "run/series", H5T_NATIVE_DOUBLE, run->series, dims[0] * width);
    for (size_t r = dims[0]; st == WG_OK && width < NCOL && r-- > 0;) /* spread the rows out */
      for (size_t c = NCOL; c-- > 0;)
        run->series[r * NCOL + c] = c < width ? run->series[r * width + c] : 0;
  }
  if (st == WG_OK) st = wg_cellsums_checkpoint_read(&run->prof.sums, f, ck, "run/prof_");
  if (st == WG_OK && k[5] > 0) {
    run->frame_time = malloc(sizeof(double) * (size_t)k[5]);
    run->frame_bonds = malloc(sizeof(long long) * (size_t)k[5]);
    if (!run->frame_time || !run->frame_bonds) st = WG_ENOMEM;
    if (st == WG_OK) st = read_into(f, ck, "run/frame_time", H5T_NATIVE_DOUBLE, run->frame_time, (hsize_t)k[5]);
    if (st == WG_OK) st = read_into(f, ck, "run/frame_bonds", H5T_NATIVE_LLONG, run->frame_bonds, (hsize_t)k[5]);
  }
  if (st == WG_OK) st = wg_map_checkpoint_read(&run->map, f, ck);
  if (st == WG_OK) st = wg_map_checkpoint_read(&run->heights, f, ck);
  if (st != WG_OK) return st;
  run->k_series = k[0];
  run->k_snapshot = k[1];
  run->k_profile = k[2];
  run->k_checkpoint = k[3];
  run->prof.samples = (long)k[4];
  run->nframes = (long)k[5];
  run->frames_bytes = k[6];
  return WG_OK;
}

static int checkpoint_load(wg_run *run)
{
  const char *ck = run->ckpt_path;
  hid_t f = wg_h5_open_read(ck);
  if (f < 0) return WG_EIO;
  long long n;
  double now, wall_s;
  int st = wg_h5_read_attr_llong(f, ".", "n", &n);
  st |= wg_h5_read_attr_double(f, ".", "now", &now);
  st |= wg_h5_read_attr_double(f, ".", "wall_s", &wall_s);
  if (st != WG_OK || n != run->sc->n) {
    wg_h5_close(f);
    return wg_error(WG_EIO, ck, "checkpoint does not match the scene (n = %lld); rerun with --fresh", n);
  }
  st = is_td(run) ? ckpt_load_td(run, f, (long)n) : ckpt_load_ed(run, f, (long)n, now);
  if (st == WG_OK) st = ckpt_load_observers(run, f);
  wg_h5_close(f);
  if (st != WG_OK) return wg_error(WG_EIO, ck, "cannot read the checkpoint; rerun with --fresh");
  run->wall_resumed = wall_s;
  /* the snapshot scratch file continues exactly after the checkpoint's last frame */
  if (truncate(run->frames_path, (off_t)run->frames_bytes) != 0)
    return wg_error(WG_EIO, run->frames_path, "cannot resume the snapshot file: %s", strerror(errno));
  run->frames = fopen(run->frames_path, "ab");
  if (!run->frames) return wg_error(WG_EIO, run->frames_path, "cannot open: %s", strerror(errno));
  return WG_OK;
}

/* ---------- the run file ---------- */

/* The run's one sampling clock (layout 2): every instant at which something is recorded
   (a time-series sample or a snapshot), sorted and without repeats; an instant's step is its
   index.  Rebuilt from the recorded times at the end, so a resumed run gets the same steps. */
typedef struct run_clock {
  double *t;
  size_t n;
} run_clock;

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static int clock_build(const wg_run *run, run_clock *c)
{
  size_t n = run->rows + (size_t)run->nframes + (size_t)run->map.nframes +
             (size_t)run->heights.nframes, k = 0;
  c->n = 0;
  if (!(c->t = malloc(sizeof(double) * (n ? n : 1))))
    return wg_error(WG_ENOMEM, "run file", "no memory for the sampling clock");
  for (size_t r = 0; r < run->rows; r++) c->t[k++] = run->series[r * NCOL + COL_TIME];
  for (long i = 0; i < run->nframes; i++) c->t[k++] = run->frame_time[i];
  for (long i = 0; i < run->map.nframes; i++) c->t[k++] = run->map.time[i];
  for (long i = 0; i < run->heights.nframes; i++) c->t[k++] = run->heights.time[i];
  qsort(c->t, n, sizeof(double), cmp_double);
  for (size_t i = 0; i < n; i++)
    if (c->n == 0 || c->t[i] != c->t[c->n - 1]) c->t[c->n++] = c->t[i];
  return WG_OK;
}

/* Step of recorded time t (always on the clock, which holds every recorded time). */
static long long clock_step(const run_clock *c, double t)
{
  size_t lo = 0, hi = c->n;
  while (hi - lo > 1) {
    size_t mid = lo + (hi - lo) / 2;
    if (c->t[mid] <= t) lo = mid;
    else hi = mid;
  }
  return (long long)lo;
}

static long long clock_step_of(const void *clock, double t) { return clock_step(clock, t); }

typedef struct text_buf {
  char *s;
  size_t len, cap;
} text_buf;

static int text_append(void *user, const char *key, const char *value, const char *unit,
                       const char *description)
{
  text_buf *t = user;
  if (wg_scene_key_is_advisory(key)) return WG_OK; /* resumes with another stall_rate */
  (void)unit;
  (void)description;
  size_t need = strlen(key) + strlen(value) + 4;
  if (t->len + need >= t->cap) {
    size_t cap = 2 * (t->cap + need);
    char *p = realloc(t->s, cap);
    if (!p) return WG_ENOMEM;
    t->s = p;
    t->cap = cap;
  }
  t->len += (size_t)sprintf(t->s + t->len, "%s = %s\n", key, value);
  return WG_OK;
}

/* All parameters as "key = value" lines: identifies the configuration of a checkpoint. */
static char *scene_fingerprint(const wg_scene *sc)
{
  text_buf t = {NULL, 0, 0};
  if (wg_scene_visit(sc, text_append, &t) != WG_OK) {
    free(t.s);
    return NULL;
  }
  return t.s;
}

/* One parameter, typed (layout 2): the text the scene visitor gives is exact ("%.17g" for
   reals), so converting it back loses nothing. */
static int parameter_attr(void *user, const char *key, const char *value, const char *unit,
                          const char *description)
{
  hid_t g = *(hid_t *)user;
  (void)unit;
  (void)description;
  switch (wg_scene_key_kind(key)) {
  case WG_KEY_REAL: return wg_h5_attr_double(g, ".", key, strtod(value, NULL));
  case WG_KEY_INT: return wg_h5_attr_llong(g, ".", key, strtoll(value, NULL, 10));
  case WG_KEY_UINT: return wg_h5_attr_ullong(g, ".", key, strtoull(value, NULL, 10));
  case WG_KEY_WORD: break;
  }
  return wg_h5_attr_string(g, ".", key, value);
}

static int write_parameters(wg_run *run, hid_t f)
{
  hid_t g = wg_h5_group(f, "/parameters");
  if (g < 0) return WG_EIO;
  int st = wg_scene_visit(run->sc, parameter_attr, &g);
  H5Gclose(g);
  return st;
}

static int write_provenance(wg_run *run, hid_t f, double wall_s)
{
  unsigned maj, min, rel;
  char buf[128];
  H5get_libversion(&maj, &min, &rel);
  snprintf(buf, sizeof buf, "%u.%u.%u", maj, min, rel);
  int st = WG_OK;
  hid_t g = wg_h5_group(f, "/provenance");
  if (g < 0) return WG_EIO;
  st |= wg_h5_attr_string(g, ".", "wetgran_version", wg_version());
  st |= wg_h5_attr_string(g, ".", "compiler", __VERSION__);
  st |= wg_h5_attr_string(g, ".", "cflags", WG_CFLAGS);
  st |= wg_h5_attr_string(g, ".", "hdf5_version", buf);
  st |= wg_h5_attr_string(g, ".", "gsl_version", gsl_version);
  st |= wg_h5_attr_string(g, ".", "command_line", run->opt.command_line ? run->opt.command_line : "");
  st |= wg_h5_attr_string(g, ".", "scene_file", run->sc->source);
  st |= wg_h5_attr_string(g, ".", "scene_text", run->opt.scene_text ? run->opt.scene_text : "");
  st |= wg_h5_attr_llong(g, ".", "seed", (long long)run->sc->seed);
  st |= wg_h5_attr_string(g, ".", "rng", "GSL mt19937 (gsl_rng_set with the seed); diameters, then Gaussian velocities");
  H5Gclose(g);

  hid_t v = wg_h5_group(f, "/provenance/volatile");
  if (v < 0) return WG_EIO;
  char host[64] = "", date[64] = "";
  double events = (double)wg_run_events(run);
  if (run->opt.no_volatile) {
    wall_s = 0;
    events = 0;
  } else {
    gethostname(host, sizeof host - 1);
    time_t now = time(NULL);
    strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
  }
  st |= wg_h5_attr_double(v, ".", "wall_s", wall_s);
  st |= wg_h5_attr_double(v, ".", "events_per_s", wall_s > 0 ? events / wall_s : 0);
  st |= wg_h5_attr_string_fixed(v, ".", "host", host, 64);
  st |= wg_h5_attr_string_fixed(v, ".", "date", date, 64);
  H5Gclose(v);
  return st;
}

static int write_series(wg_run *run, hid_t f, const run_clock *clk)
{
  int st = WG_OK;
  double *col = malloc(sizeof(double) * (run->rows ? run->rows : 1));
  long long *step = malloc(sizeof(long long) * (run->rows ? run->rows : 1));
  if (!col || !step) {
    free(col);
    free(step);
    return wg_error(WG_ENOMEM, "run file", "no memory for the time series");
  }
  for (size_t r = 0; r < run->rows; r++) step[r] = clock_step(clk, run->series[r * NCOL + COL_TIME]);
  for (int c = 1; c < NCOL && st == WG_OK; c++) {
    if (!column_used(run, c)) continue;
    char path[160];
    hsize_t dims[1] = {run->rows};
    const char *desc = is_td(run) && columns[c].td_description ? columns[c].td_description
                                                                : columns[c].description;
    for (size_t r = 0; r < run->rows; r++) col[r] = run->series[r * NCOL + c];
    snprintf(path, sizeof path, "/observables/%s/value", columns[c].name);
    st |= wg_h5_write(f, path, H5T_NATIVE_DOUBLE, 1, dims, col, columns[c].unit, desc);
    for (size_t r = 0; r < run->rows; r++) col[r] = run->series[r * NCOL + COL_TIME];
    snprintf(path, sizeof path, "/observables/%s/time", columns[c].name);
    st |= wg_h5_write(f, path, H5T_NATIVE_DOUBLE, 1, dims, col, columns[COL_TIME].unit, columns[COL_TIME].description);
    snprintf(path, sizeof path, "/observables/%s/step", columns[c].name);
    st |= wg_h5_write(f, path, H5T_NATIVE_LLONG, 1, dims, step, "1", WG_H5_STEP_MEANING);
  }
  free(col);
  free(step);
  return st;
}

static int write_profiles(wg_run *run, hid_t f)
{
  const wg_profile *pr = &run->prof;
  const wg_scene *sc = run->sc;
  int dim = sc->dim;
  if (pr->bins <= 0) return WG_OK;
  int b = pr->bins;
  double width = sc->lx / b;
  double cross = dim == 3 ? sc->ly : 1; /* lateral extent across x */
  double height = sc->height;
  double *x = malloc(sizeof(double) * 5 * (size_t)b);
  if (!x) return wg_error(WG_ENOMEM, "run file", "no memory for profiles");
  double *nd = x + b, *pf = x + 2 * b, *tg = x + 3 * b, *ncb = x + 4 * b;
  double samples = pr->samples > 0 ? (double)pr->samples : NAN;
  for (int k = 0; k < b; k++) {
    x[k] = (k + 0.5) * width;
    nd[k] = pr->sums.count[k] / (samples * width * cross);
    pf[k] = pr->sums.volume[k] / (samples * width * cross * height);
    tg[k] = wg_cellsums_temperature(&pr->sums, (size_t)k, dim);
    ncb[k] = pr->sums.bridges[k] / (samples * width * cross);
  }
  hsize_t dims[1] = {(hsize_t)b};
  const char *per_area = dim == 3 ? "d-2" : "d-1";
  int st = WG_OK;
  st |= wg_h5_write(f, "/observables/profiles/x", H5T_NATIVE_DOUBLE, 1, dims, x, "d", "centre of each lateral bin along x");
  st |= wg_h5_write(f, "/observables/profiles/number_density", H5T_NATIVE_DOUBLE, 1, dims, nd,
                    per_area, "time-averaged particles per lateral area (projected along gravity)");
  st |= wg_h5_write(f, "/observables/profiles/packing_fraction", H5T_NATIVE_DOUBLE, 1, dims, pf, "1",
                    "time-averaged area (2D) or volume (3D) fraction of the bin's column between floor and lid");
  st |= wg_h5_write(f, "/observables/profiles/temperature", H5T_NATIVE_DOUBLE, 1, dims, tg, "m d+2 tau-2",
                    "granular temperature in the bin: sum m |v - V_bin|^2 / (count D), sums over all samples");
  st |= wg_h5_write(f, "/observables/profiles/bridge_density", H5T_NATIVE_DOUBLE, 1, dims, ncb,
                    per_area, "time-averaged capillary bridges per lateral area, n_cb (half a bridge per particle end)");
  st |= wg_h5_attr_double(f, "/observables/profiles", "t_start", run->sc->profile_start);
  st |= wg_h5_attr_llong(f, "/observables/profiles", "samples", pr->samples);
  st |= wg_h5_attr_double(f, "/observables/profiles", "e_cb", run->sc->e_cb);
  free(x);
  return st;
}

/* Copy the snapshot frames from the scratch file into H5MD elements (angular velocities
   only with friction). */
static int write_frames(wg_run *run, hid_t f, const run_clock *clk)
{
  long n = run->sc->n;
  int dim = run->sc->dim, st = WG_OK;
  if (fflush(run->frames) != 0) return wg_error(WG_EIO, run->frames_path, "cannot flush");
  FILE *in = fopen(run->frames_path, "rb");
  if (!in) return wg_error(WG_EIO, run->frames_path, "cannot reopen: %s", strerror(errno));
  wg_h5md_element pos, vel, nbr, spin;
  int nw = spin_components(run);
  hsize_t fd[2] = {(hsize_t)n, (hsize_t)dim}, fb[1] = {(hsize_t)n}, fw[2] = {(hsize_t)n, (hsize_t)nw};
  hsize_t F = (hsize_t)run->nframes;
  if (nw)
    st |= wg_h5md_element_create(f, "/particles/all/angular_velocity", H5T_NATIVE_DOUBLE, nw == 1 ? 1 : 2,
                                 fw, F, "tau-1", nw == 1 ? "angular velocities (about z)" : "angular velocities", &spin);
  st |= wg_h5md_element_create(f, "/particles/all/position", H5T_NATIVE_DOUBLE, 2, fd, F, "d",
                               "particle centres in the lab frame, wrapped into the box along periodic axes", &pos);
  st |= wg_h5md_element_create(f, "/particles/all/velocity", H5T_NATIVE_DOUBLE, 2, fd, F, "d tau-1",
                               "particle velocities", &vel);
  st |= wg_h5md_element_create(f, "/particles/all/bridge_count", H5T_NATIVE_UINT8, 1, fb, F, "1",
                               "number of capillary bridges of each particle", &nbr);
  long long total_bonds = 0;
  for (long k = 0; k < run->nframes; k++) total_bonds += run->frame_bonds[k];
  hsize_t bd[2] = {(hsize_t)total_bonds, 2}, od[1] = {F + 1};
  hid_t pairs = wg_h5_dataset_create(f, "/bridges/pairs", H5T_NATIVE_INT32, 2, bd, "1",
                                     "bridged pairs (i < j) of all snapshots, concatenated");
  long long *offset = malloc(sizeof(long long) * (F + 1));
  double *buf = malloc(sizeof(double) * (size_t)n * (size_t)dim);
  uint8_t *cnt = malloc((size_t)n);
  int32_t *pb = NULL;
  if (pairs < 0 || !offset || !buf || !cnt) st = WG_EIO;
  long long row = 0;
  for (long k = 0; k < run->nframes && st == WG_OK; k++) {
    double t = run->frame_time[k];
    long long step = clock_step(clk, t);
    if (fread(buf, sizeof(double), (size_t)n * dim, in) != (size_t)n * dim) st = WG_EIO;
    if (st == WG_OK) st = wg_h5md_element_write(&pos, step, t, buf);
    if (st == WG_OK && fread(buf, sizeof(double), (size_t)n * dim, in) != (size_t)n * dim) st = WG_EIO;
    if (st == WG_OK) st = wg_h5md_element_write(&vel, step, t, buf);
    if (st == WG_OK && nw && fread(buf, sizeof(double), (size_t)n * nw, in) != (size_t)n * nw) st = WG_EIO;
    if (st == WG_OK && nw) st = wg_h5md_element_write(&spin, step, t, buf);
    if (st == WG_OK && fread(cnt, 1, (size_t)n, in) != (size_t)n) st = WG_EIO;
    if (st == WG_OK) st = wg_h5md_element_write(&nbr, step, t, cnt);
    long long nb = run->frame_bonds[k];
    offset[k] = row;
    if (st == WG_OK && nb > 0) {
      int32_t *p = realloc(pb, sizeof(int32_t) * 2 * (size_t)nb);
      if (!p) st = WG_ENOMEM;
      else pb = p;
      if (st == WG_OK && fread(pb, sizeof(int32_t), 2 * (size_t)nb, in) != 2 * (size_t)nb) st = WG_EIO;
      if (st == WG_OK) st = wg_h5_write_rows(pairs, H5T_NATIVE_INT32, (hsize_t)row, (hsize_t)nb, pb);
      row += nb;
    }
  }
  if (offset) offset[F] = row;
  if (st == WG_OK)
    st = wg_h5_write(f, "/bridges/offset", H5T_NATIVE_LLONG, 1, od, offset, "1",
                     "snapshot k's bridges are rows offset[k] .. offset[k+1]-1 of pairs");
  hsize_t tdims[1] = {F};
  if (st == WG_OK)
    st = wg_h5_write(f, "/bridges/time", H5T_NATIVE_DOUBLE, 1, tdims, run->frame_time, "tau",
                     "time of each snapshot (as /particles/all/position/time)");
  long long *steps = malloc(sizeof(long long) * (F ? F : 1));
  if (!steps) st = WG_ENOMEM;
  for (hsize_t k = 0; st == WG_OK && k < F; k++) steps[k] = clock_step(clk, run->frame_time[k]);
  if (st == WG_OK)
    st = wg_h5_write(f, "/bridges/step", H5T_NATIVE_LLONG, 1, tdims, steps, "1",
                     "step of each snapshot (as /particles/all/position/step)");
  free(steps);
  wg_h5md_element_close(&pos);
  wg_h5md_element_close(&vel);
  wg_h5md_element_close(&nbr);
  if (nw) wg_h5md_element_close(&spin);
  if (pairs >= 0) H5Dclose(pairs);
  free(offset);
  free(buf);
  free(cnt);
  free(pb);
  fclose(in);
  if (st != WG_OK) return wg_error(WG_EIO, run->frames_path, "cannot copy the snapshots into the run file");
  return WG_OK;
}

static int write_summary(wg_run *run, hid_t f)
{
  hid_t g = wg_h5_group(f, "/summary");
  if (g < 0) return WG_EIO;
  int st = WG_OK;
  double residual = run->rows ? run->series[(run->rows - 1) * NCOL + COL_RESIDUAL] : 0;
  st |= wg_h5_attr_llong(g, ".", "events", (long long)wg_run_events(run));
  st |= wg_h5_attr_double(g, ".", "sim_time", run_now(run));
  st |= wg_h5_attr_double(g, ".", "ledger_residual", residual);
  if (is_td(run)) {
    const wg_td *s = &run->td;
    st |= wg_h5_attr_llong(g, ".", "steps", (long long)s->steps);
    st |= wg_h5_attr_llong(g, ".", "contacts", (long long)s->contacts);
    st |= wg_h5_attr_llong(g, ".", "wall_contacts", (long long)s->wall_contacts);
    st |= wg_h5_attr_llong(g, ".", "list_rebuilds", (long long)s->rebuilds);
  } else {
    const wg_ed *s = &run->ed;
    st |= wg_h5_attr_llong(g, ".", "collisions", (long long)s->counts.collisions);
    st |= wg_h5_attr_llong(g, ".", "cell_crossings", (long long)s->counts.cell_crossings);
    st |= wg_h5_attr_llong(g, ".", "wall_enters", (long long)s->counts.wall_enters);
    st |= wg_h5_attr_llong(g, ".", "stale_predictions", (long long)s->counts.stale);
    st |= wg_h5_attr_llong(g, ".", "rigid_collisions", (long long)s->counts.rigid);
    st |= wg_h5_attr_llong(g, ".", "grazing_reflections", (long long)s->counts.grazing);
    if (s->riding) {
      st |= wg_h5_attr_llong(g, ".", "rests", (long long)s->counts.rests);
      st |= wg_h5_attr_llong(g, ".", "lift_offs", (long long)s->counts.lift_offs);
    }
  }
  H5Gclose(g);
  return st;
}

/* Floor and lid heights in the lab frame at every instant of the clock (the engines' own
   wall law, wall.h: floor c = 0, lid c = height, both c + A sin(w t)). */
static int write_walls(wg_run *run, hid_t f, const run_clock *clk)
{
  const wg_scene *sc = run->sc;
  if (!wg_scene_walled(sc)) return WG_OK;
  double omega = sc->omega > 0 ? sc->omega : 1; /* as the engines: A = 0 then */
  const wg_wall wall[2] = {{0.0, sc->amplitude, omega, +1}, {sc->height, sc->amplitude, omega, -1}};
  const char *name[2] = {"floor", "lid"};
  const char *desc[2] = {"height of the floor in the lab frame, A sin(omega t + phase)",
                         "height of the lid in the lab frame, height + A sin(omega t + phase)"};
  hsize_t n = clk->n;
  double *z = malloc(sizeof(double) * (n ? n : 1));
  long long *step = malloc(sizeof(long long) * (n ? n : 1));
  int st = !z || !step ? wg_error(WG_ENOMEM, "run file", "no memory for the walls") : WG_OK;
  for (hsize_t k = 0; st == WG_OK && k < n; k++) step[k] = (long long)k;
  for (int w = 0; w < 2 && st == WG_OK; w++) {
    char path[64], p[80];
    snprintf(path, sizeof path, "/observables/walls/%s", name[w]);
    for (hsize_t k = 0; k < n; k++) z[k] = wg_wall_position(&wall[w], clk->t[k]);
    snprintf(p, sizeof p, "%s/value", path);
    st |= wg_h5_write(f, p, H5T_NATIVE_DOUBLE, 1, &n, z, "d", desc[w]);
    snprintf(p, sizeof p, "%s/time", path);
    st |= wg_h5_write(f, p, H5T_NATIVE_DOUBLE, 1, &n, clk->t, "tau", columns[COL_TIME].description);
    snprintf(p, sizeof p, "%s/step", path);
    st |= wg_h5_write(f, p, H5T_NATIVE_LLONG, 1, &n, step, "1", WG_H5_STEP_MEANING);
    st |= wg_h5_attr_double(f, path, "mean", wall[w].c);
    st |= wg_h5_attr_double(f, path, "amplitude", sc->amplitude);
    st |= wg_h5_attr_double(f, path, "omega", sc->omega);
    st |= wg_h5_attr_double(f, path, "phase", 0.0);
  }
  free(z);
  free(step);
  return st;
}

/* The units module: wetgran's units are the mean diameter, the mass and sqrt(d/g). */
static int write_units(hid_t f)
{
  const char *sym[3] = {"d", "m", "tau"};
  const char *meaning[3] = {
      "length: the mean particle diameter",
      "mass: the mass of a particle of diameter d (every particle's mass with mass = unit)",
      "time: sqrt(d/g), g the acceleration of gravity (also the unit of gravity = 1 when the scene has none)"};
  return wg_h5md_units(f, "wetgran", 3, sym, meaning);
}

static int write_run_file(wg_run *run, double wall_s)
{
  const wg_scene *sc = run->sc;
  long n = sc->n;
  int dim = sc->dim;
  hid_t f = wg_h5_create(run->tmp_path);
  if (f < 0) return WG_EIO;
  int st = WG_OK;
  st |= wg_h5md_header(f, "wetgran", "wetgran-run", wg_version());
  const char *bound[3] = {"periodic", "periodic", "periodic"};
  if (wg_scene_walled(sc)) bound[dim - 1] = "none";
  double edges[3] = {sc->lx, dim == 3 ? sc->ly : sc->height, sc->height};
  st |= wg_h5md_box(f, "all", dim, edges, bound);
  st |= write_units(f);
  st |= wg_h5_attr_string(f, "/particles/all/box", "z_frame",
                          sc->container == WG_CONTAINER_SHAKER
                              ? "positions are in the lab frame: the floor is at z = A sin(omega t) and the lid at "
                                "z = height + A sin(omega t) (/observables/walls); the last edge is the "
                                "floor-to-lid distance height"
                          : sc->container == WG_CONTAINER_BOX
                              ? "positions are in the box frame: the floor is at z = 0 and the lid at z = height, "
                                "both at rest; the lateral axes periodic, 0 <= x < edge"
                              : "positions are in the box frame, every axis periodic: 0 <= x < edge");
  st |= wg_h5_attr_string(f, "/particles/all", "step_meaning", WG_H5_STEP_MEANING);
  double *buf = malloc(sizeof(double) * (size_t)n), *dia = malloc(sizeof(double) * (size_t)n);
  if (!buf || !dia) st = WG_ENOMEM;
  hsize_t d1[1] = {(hsize_t)n};
  for (long id = 0; st == WG_OK && id < n; id++) {
    double r[3], v[3], radius;
    particle(run, slot_of(run, id), r, v, &radius, buf + id);
    dia[id] = 2 * radius;
  }
  if (st == WG_OK) st = wg_h5_write(f, "/particles/all/diameter", H5T_NATIVE_DOUBLE, 1, d1, dia, "d", "particle diameters");
  if (st == WG_OK) st = wg_h5_write(f, "/particles/all/mass", H5T_NATIVE_DOUBLE, 1, d1, buf, "m", "particle masses");
  long long *id = malloc(sizeof(long long) * (size_t)n);
  int *species = calloc((size_t)n, sizeof(int));
  if (!id || !species) st = WG_ENOMEM;
  for (long i = 0; st == WG_OK && i < n; i++) id[i] = i;
  if (st == WG_OK)
    st = wg_h5_write(f, "/particles/all/id", H5T_NATIVE_LLONG, 1, d1, id, "1",
                     "particle identity: row i of every per-particle dataset is particle i");
  if (st == WG_OK)
    st = wg_h5_write(f, "/particles/all/species", H5T_NATIVE_INT, 1, d1, species, "1",
                     "particle species: 0 for all (one granular material; sizes in diameter)");
  free(id);
  free(species);
  free(buf);
  free(dia);
  run_clock clk = {NULL, 0};
  if (st == WG_OK) st = clock_build(run, &clk);
  if (st == WG_OK) st = write_frames(run, f, &clk);
  if (st == WG_OK) st = write_series(run, f, &clk);
  if (st == WG_OK) st = write_walls(run, f, &clk);
  if (st == WG_OK) st = wg_map_write(&run->map, f, clock_step_of, &clk);
  if (st == WG_OK) st = wg_map_write(&run->heights, f, clock_step_of, &clk);
  if (st == WG_OK) st = wg_h5_attr_string(f, "/observables", "step_meaning", WG_H5_STEP_MEANING);
  free(clk.t);
  if (st == WG_OK) st = write_profiles(run, f);
  if (st == WG_OK) st = write_parameters(run, f);
  if (st == WG_OK) st = write_provenance(run, f, wall_s);
  if (st == WG_OK) st = write_summary(run, f);
  if (wg_h5_close(f) != WG_OK) st = WG_EIO;
  if (st != WG_OK) return wg_error(WG_EIO, run->tmp_path, "run file not completed; nothing renamed");
  if (rename(run->tmp_path, run->opt.out_path) != 0)
    return wg_error(WG_EIO, run->opt.out_path, "cannot rename from %s: %s", run->tmp_path, strerror(errno));
  return WG_OK;
}

/* ---------- driver ---------- */

int wg_run_init(wg_run *run, wg_scene *sc, const wg_run_options *opt)
{
  memset(run, 0, sizeof *run);
  run->sc = sc;
  run->opt = *opt;
  snprintf(run->tmp_path, sizeof run->tmp_path, "%s.tmp", opt->out_path);
  snprintf(run->ckpt_path, sizeof run->ckpt_path, "%s.ckpt", opt->out_path);
  snprintf(run->frames_path, sizeof run->frames_path, "%s.frames", opt->out_path);
  int st = profile_alloc(&run->prof, sc->profile_bins);
  if (st == WG_OK)
    st = wg_map_init(&run->map, sc->map_bins, sc->map_bins_y, sc->dim, sc->lx, sc->ly,
                     sc->map_start, sc->dt_map, sc->map_samples);
  if (st == WG_OK)
    st = wg_map_init_height(&run->heights, sc->height_bins, sc->dim, sc->lx, sc->ly,
                            -sc->amplitude, sc->height + 2 * sc->amplitude, sc->height_start,
                            sc->dt_height, sc->height_samples);
  if (st != WG_OK) return st;
  if (is_td(run) && sc->s_crit > 0 && !(run->nbond = malloc((size_t)sc->n)))
    return wg_error(WG_ENOMEM, "run", "no memory for %ld bridge counts", sc->n);
  run->wall_start = wall_clock();
  if (!opt->fresh && access(run->ckpt_path, R_OK) == 0) {
    char *want = scene_fingerprint(sc), have[1 << 15] = "";
    hid_t f = wg_h5_open_read(run->ckpt_path);
    if (f >= 0) {
      wg_h5_read_attr_string(f, ".", "scene", have, sizeof have);
      wg_h5_close(f);
    }
    int same = want && wg_scene_same_configuration(want, have);
    free(want);
    if (!same)
      return wg_error(WG_EINVAL, run->ckpt_path,
                      "a checkpoint of a different configuration exists; remove it or run with --fresh");
    st = checkpoint_load(run);
    if (st != WG_OK) return st;
    run->resumed = 1;
    if (opt->progress || opt->log_every > 0)
      fprintf(stderr, "resuming from %s at t = %g\n", run->ckpt_path, run_now(run));
    return WG_OK;
  }
  st = is_td(run) ? wg_td_alloc(&run->td, sc) : wg_ed_alloc(&run->ed, sc);
  if (st != WG_OK) return st;
  run->frames = fopen(run->frames_path, "wb");
  if (!run->frames) return wg_error(WG_EIO, run->frames_path, "cannot create: %s", strerror(errno));
  return WG_OK;
}

static double next_time(const wg_run *run, int *what)
{
  const wg_scene *sc = run->sc;
  double t = sc->t_end;
  *what = 0;
  double ts = run->k_series * sc->dt_series;
  if (ts < t) t = ts;
  if (sc->dt_snapshot > 0) {
    double tf = run->k_snapshot * sc->dt_snapshot;
    if (tf < t) t = tf;
  }
  if (sc->profile_bins > 0) {
    double tp = sc->profile_start + run->k_profile * sc->dt_profile;
    if (tp < t) t = tp;
  }
  double tm = wg_map_next_time(&run->map);
  if (tm < t) t = tm;
  double th = wg_map_next_time(&run->heights);
  if (th < t) t = th;
  if (sc->dt_checkpoint > 0) {
    double tc = run->k_checkpoint * sc->dt_checkpoint;
    if (tc < t) t = tc;
  }
  return t;
}

/* ---------- what the user sees while it runs ---------- */

/* Work done so far: physical events (ed) or particle-steps (td). */
static double work_done(const wg_run *run)
{
  return is_td(run) ? (double)run->td.steps * (double)run->td.n : (double)wg_run_events(run);
}

static void watch_start(wg_run *run)
{
  wg_run_watch *w = &run->watch;
  double now = wall_clock(), t = run_now(run);
  *w = (wg_run_watch){.wall0 = now, .t0 = t, .line_wall = now, .log_wall = now, .log_t = t,
                      .log_work = work_done(run), .stall_wall = now, .stall_t = t};
  if (!is_td(run)) w->stall_events = wg_run_events(run);
}

/* A duration for people: seconds, minutes or hours. */
static void format_duration(char *buf, size_t size, double s)
{
  if (!(s < 1e12)) snprintf(buf, size, "unknown");
  else if (s < 600) snprintf(buf, size, "%.0f s", s);
  else if (s < 18000) snprintf(buf, size, "%.0f min", s / 60);
  else snprintf(buf, size, "%.1f h", s / 3600);
}

/* On a terminal, a line redrawn in place once a second; in a batch log (stderr not a
   terminal), a line every log_every seconds with the pace since the previous one. */
static void report(wg_run *run)
{
  wg_run_watch *w = &run->watch;
  double now = wall_clock(), t = run_now(run), t_end = run->sc->t_end;
  if (run->opt.progress && now - w->line_wall >= 1.0) {
    w->line_wall = now;
    w->line_shown = 1;
    double el = now - run->wall_start;
    if (is_td(run))
      fprintf(stderr, "\rt = %.6g / %g (%3.0f%%)  steps %llu  %.3g particle-steps/s   ", t,
              t_end, 100 * t / t_end, run->td.steps,
              el > 0 ? (double)run->td.steps * (double)run->td.n / el : 0);
    else
      fprintf(stderr, "\rt = %.6g / %g (%3.0f%%)  events %llu  %.3g events/s   ", t, t_end,
              100 * t / t_end, wg_run_events(run), el > 0 ? (double)wg_run_events(run) / el : 0);
  }
  if (run->opt.log_every > 0 && now - w->log_wall >= run->opt.log_every) {
    double work = work_done(run), span = now - w->log_wall, dt = t - w->log_t;
    char wall[32], eta[32];
    format_duration(wall, sizeof wall, now - w->wall0 + run->wall_resumed);
    format_duration(eta, sizeof eta, dt > 0 ? (t_end - t) * span / dt : INFINITY);
    fprintf(stderr, "progress: t = %.2f / %g (%.0f%%), %.3g %s/s, wall %s, ETA %s\n", t, t_end,
            100 * t / t_end, (work - w->log_work) / span,
            is_td(run) ? "particle-steps" : "events", wall, eta);
    fflush(stderr);
    w->log_wall = now;
    w->log_t = t;
    w->log_work = work;
  }
}

/* The stall watch (event-driven engine): physical events per particle and unit simulated
   time, over windows of at least a wall second.  The archived campaigns average 1.4 to 143
   (at most 197 over one time unit); a bed at rest on a floor shaken at Gamma ~ 1, or an
   inelastic collapse, makes thousands, and the run crawls.  Warns once (stall_action = warn)
   or stops (stop).  Only reads the state. */
static int stall_check(wg_run *run)
{
  wg_run_watch *w = &run->watch;
  const wg_scene *sc = run->sc;
  if (is_td(run) || sc->stall_rate <= 0 || w->stall_warned) return WG_OK;
  double now = wall_clock();
  if (now - w->stall_wall < 1.0) return WG_OK;
  double t = run->ed.now, dt = t - w->stall_t, span = now - w->stall_wall;
  unsigned long long ev = wg_run_events(run);
  double dev = (double)(ev - w->stall_events);
  double rate = dt > 0 ? dev / ((double)sc->n * dt) : dev > 0 ? INFINITY : 0;
  w->stall_wall = now;
  w->stall_t = t;
  w->stall_events = ev;
  if (!(rate > sc->stall_rate)) return WG_OK;
  w->stall_warned = 1;
  int stop = sc->stall_action == WG_STALL_STOP;
  int shaker = sc->container == WG_CONTAINER_SHAKER;
  char more[32];
  format_duration(more, sizeof more, dt > 0 ? (sc->t_end - t) * span / dt : INFINITY);
  if (w->line_shown) fputc('\n', stderr);
  w->line_shown = 0;
  fprintf(stderr,
          "wetgran-run: %s: t = %g: %.3g physical events per particle and unit time (stall_rate "
          "= %g; the thesis's shaken beds and gases make 1.4 to 150): at this pace the run "
          "needs about %s more.\n"
          "  Likely cause: inelastic collapse (eps < 1: a larger tc helps)%s.\n"
          "  What to do: raise tc%s, or use the time-driven engine (engine = td), which costs the "
          "same per time unit whatever the bed does.  ",
          stop ? "error" : "warning", t, rate, sc->stall_rate, more,
          shaker ? " or a bed resting on a slowly shaken floor (Gamma near or below 1)" : "",
          shaker ? ", Gamma or E*" : "");
  if (shaker && sc->engine == WG_ENGINE_ED && sc->rest_speed == 0)
    fprintf(stderr, "Grains resting on the floor: rest_speed (e.g. 0.01 with eps_wall < 1; "
            "docs/engines.md) lets them ride it instead of bouncing.  ");
  if (!stop) {
    fprintf(stderr, "Going on (stall_action = stop would stop here).\n");
    return WG_OK;
  }
  if (access(run->ckpt_path, F_OK) == 0)
    fprintf(stderr, "Stopped (stall_action = stop): no run file; %s resumes it (e.g. with "
            "stall_rate=0).\n", run->ckpt_path);
  else
    fprintf(stderr, "Stopped (stall_action = stop): no run file.\n");
  return WG_ERANGE;
}

/* Called by the event-driven engine every WG_ED_WATCH_EVENTS events, between two sampling
   times: reads counters and the clock, nothing else. */
static int ed_watch(void *user)
{
  wg_run *run = user;
  int st = stall_check(run);
  if (st == WG_OK) report(run);
  return st;
}

static void print_summary(wg_run *run, double wall_s)
{
  double residual = run->rows ? run->series[(run->rows - 1) * NCOL + COL_RESIDUAL] : 0;
  unsigned long long ev = wg_run_events(run);
  struct rusage ru;
  getrusage(RUSAGE_SELF, &ru);
  if (is_td(run)) {
    const wg_td *s = &run->td;
    double ps = (double)s->steps * (double)s->n;
    fprintf(stderr,
            "summary: engine=td steps=%llu events=%llu sim_time=%.10g wall_s=%.3f"
            " particle_steps_per_s=%.4g events_per_s=%.4g ledger_residual=%.3g contacts=%llu"
            " wall_contacts=%llu ruptures=%llu list_rebuilds=%llu peak_rss_kb=%ld"
            " engine_bytes_per_particle=%.0f\n",
            s->steps, ev, s->t, wall_s, wall_s > 0 ? ps / wall_s : 0,
            wall_s > 0 ? (double)ev / wall_s : 0, residual, s->contacts, s->wall_contacts,
            s->ruptures, s->rebuilds, ru.ru_maxrss, wg_td_bytes_per_particle(s));
    return;
  }
  const wg_ed *s = &run->ed;
  fprintf(stderr,
          "summary: events=%llu sim_time=%.10g wall_s=%.3f events_per_s=%.4g ledger_residual=%.3g"
          " cell_crossings=%llu wall_enters=%llu rigid_collisions=%llu grazing_reflections=%llu"
          " peak_rss_kb=%ld"
          " engine_bytes_per_particle=%.0f\n",
          ev, s->now, wall_s, wall_s > 0 ? (double)ev / wall_s : 0, residual,
          s->counts.cell_crossings, s->counts.wall_enters, s->counts.rigid, s->counts.grazing, ru.ru_maxrss,
          (double)wg_ed_bytes(s) / (double)s->n);
}

int wg_run_execute(wg_run *run)
{
  wg_scene *sc = run->sc;
  watch_start(run);
  if (!is_td(run)) wg_ed_set_watch(&run->ed, ed_watch, run);
  if (run->k_checkpoint == 0) run->k_checkpoint = 1;
  int st = WG_OK;
  for (;;) {
    int what;
    double t = next_time(run, &what);
    st = is_td(run) ? wg_td_advance(&run->td, t) : wg_ed_advance(&run->ed, t);
    if (st != WG_OK) break;
    int final = t >= sc->t_end;
    if (run->k_series * sc->dt_series <= t || final) {
      st = sample_series(run);
      run->k_series++;
      while (run->k_series * sc->dt_series <= t) run->k_series++;
    }
    if (st == WG_OK && sc->profile_bins > 0 && sc->profile_start + run->k_profile * sc->dt_profile <= t) {
      sample_profile(run);
      run->k_profile++;
    }
    if (st == WG_OK && wg_map_next_time(&run->map) <= t) st = sample_map(run, &run->map);
    if (st == WG_OK && wg_map_next_time(&run->heights) <= t) st = sample_map(run, &run->heights);
    if (st == WG_OK && ((sc->dt_snapshot > 0 && run->k_snapshot * sc->dt_snapshot <= t) || final)) {
      if (!(final && run->nframes > 0 && run->frame_time[run->nframes - 1] == run_now(run)))
        st = write_frame(run);
      if (sc->dt_snapshot > 0)
        while (run->k_snapshot * sc->dt_snapshot <= t) run->k_snapshot++;
    }
    if (st != WG_OK || final) break;
    if (sc->dt_checkpoint > 0 && run->k_checkpoint * sc->dt_checkpoint <= t) {
      while (run->k_checkpoint * sc->dt_checkpoint <= t) run->k_checkpoint++;
      if (!is_td(run)) st = wg_ed_synchronize(&run->ed);
      if (st == WG_OK) st = checkpoint_write(run);
      if (st != WG_OK) break;
      if (run->opt.abort_after_checkpoint > 0 &&
          run->k_checkpoint - 1 >= run->opt.abort_after_checkpoint) {
        fprintf(stderr, "wetgran-run: stopping after checkpoint at t = %g as asked\n", run_now(run));
        return WG_ESTOPPED;
      }
    }
    report(run);
  }
  if (run->opt.progress) fprintf(stderr, "\n");
  if (!is_td(run)) wg_ed_set_watch(&run->ed, NULL, NULL);
  if (st != WG_OK) {
    if (run->watch.stall_warned && access(run->ckpt_path, F_OK) != 0) {
      fclose(run->frames); /* nothing to resume: the snapshots so far go too */
      run->frames = NULL;
      remove(run->frames_path);
    }
    return st;
  }
  double wall_s = wall_clock() - run->wall_start + run->wall_resumed;
  st = write_run_file(run, wall_s);
  if (st != WG_OK) return st;
  fclose(run->frames);
  run->frames = NULL;
  remove(run->frames_path);
  remove(run->ckpt_path);
  print_summary(run, wall_s);
  return WG_OK;
}

void wg_run_free(wg_run *run)
{
  if (run->frames) fclose(run->frames);
  if (is_td(run)) wg_td_free(&run->td);
  else wg_ed_free(&run->ed);
  free(run->nbond);
  free(run->series);
  free(run->frame_time);
  free(run->frame_bonds);
  wg_cellsums_free(&run->prof.sums);
  wg_map_free(&run->map);
  wg_map_free(&run->heights);
  memset(run, 0, sizeof *run);
}
