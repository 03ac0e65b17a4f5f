#include "td.h"

#include "init.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static inline double td_mass(const wg_td *s, long i) { return s->mass ? s->mass[i] : 1.0; }

/* Kahan's sum, whose compensated value is s - c; wg_ksum_value reads s + c, so the
   time-driven ledger's sums are only as good as plain ones (docs/engines.md, "Where wetgran
   writes its own code"; wg_ksum_add's Neumaier sum at the next engine version). */
static void ksum_add(wg_ksum *k, double x)
{
  double y = x - k->c, t = k->s + y;
  k->c = (t - k->s) - y;
  k->s = t;
}

/* nearbyint(x) for |x| < 2^51 in the default rounding mode, without a call into libm: adding
   and taking away 1.5 2^52 rounds to an integer, half to even, as nearbyint does */
static inline double round_near(double x)
{
  const double magic = 6755399441055744.0;
  return (x + magic) - magic;
}

static inline void min_image(const wg_td *s, double *d)
{
  for (int a = 0; a < s->par.dim; a++)
    if (s->par.periodic[a]) d[a] -= s->par.box[a] * round_near(d[a] / s->par.box[a]);
}

static int cmp_pair(const void *a, const void *b)
{
  const wg_td_pair *p = a, *q = b;
  if (p->i != q->i) return p->i < q->i ? -1 : 1;
  return (p->j > q->j) - (p->j < q->j);
}

/* Attraction of a bonded pair at gap s: F_B, or Willett's law for s > 0 (Eq. 2.9). */
static double bond_force(const wg_td_params *p, double gap)
{
  double x = gap * p->willett;
  return x > 0 ? p->f_b / (1 + 1.05 * x + 2.5 * x * x) : p->f_b;
}

static double cutoff_extra(const wg_td *s) { return (s->par.f_b > 0 ? s->par.s_crit : 0) + s->par.skin; }

/* A pair with state (bond, contact) saved across a rebuild, with its old index (spring). */
typedef struct saved_pair {
  wg_td_pair p;
  long k;
} saved_pair;

static int cmp_saved(const void *a, const void *b)
{
  return cmp_pair(&((const saved_pair *)a)->p, &((const saved_pair *)b)->p);
}

/* The neighbour list from scratch: pairs closer than contact + s_crit + skin.  Periodic
   coordinates are wrapped first.  A pair's state (bond, contact, spring) carries over by
   identity. */
static int build_list(wg_td *s)
{
  int dim = s->par.dim;
  saved_pair *saved = NULL; /* every pair with state: bonded or touching */
  wg_spring *spring = NULL; /* the new list's springs (friction) */
  long nb = 0, nbond = 0;
  for (long k = 0; k < s->npair; k++) nb += s->pair[k].bonded | s->pair[k].touching;
  if (nb) {
    saved = malloc(sizeof *saved * (size_t)nb);
    if (!saved) return wg_error(WG_ENOMEM, "td", "cannot allocate %ld pair states", nb);
    nb = 0;
    for (long k = 0; k < s->npair; k++)
      if (s->pair[k].bonded | s->pair[k].touching) {
        saved[nb++] = (saved_pair){s->pair[k], k};
        nbond += s->pair[k].bonded;
      }
    qsort(saved, (size_t)nb, sizeof *saved, cmp_saved);
  }
  if (s->rot && !(spring = malloc(sizeof *spring * (size_t)(s->pair_cap ? s->pair_cap : 1)))) {
    free(saved);
    return wg_error(WG_ENOMEM, "td", "cannot allocate %ld springs", s->pair_cap);
  }
  for (long i = 0; i < s->n; i++)
    for (int a = 0; a < dim; a++)
      if (s->par.periodic[a]) s->r[3 * i + a] -= s->par.box[a] * floor(s->r[3 * i + a] / s->par.box[a]);
  wg_cells_rebuild(&s->cells, s->n, s->r, 3);
  double extra = cutoff_extra(s);
  long cells[27];
  s->npair = 0;
  for (long i = 0; i < s->n; i++) {
    int nc = wg_cells_stencil(&s->cells, s->cells.cell[i], cells);
    for (int c = 0; c < nc; c++)
      for (int32_t j = s->cells.head[cells[c]]; j >= 0; j = s->cells.next[j]) {
        if (j <= i) continue;
        double d[3] = {0, 0, 0}, d2 = 0, cut = s->radius[i] + s->radius[j] + extra;
        for (int a = 0; a < dim; a++) d[a] = s->r[3 * j + a] - s->r[3 * i + a];
        min_image(s, d);
        for (int a = 0; a < dim; a++) d2 += d[a] * d[a];
        if (d2 >= cut * cut) continue;
        if (s->npair == s->pair_cap) {
          long cap = s->pair_cap ? 2 * s->pair_cap : 8 * s->n + 16;
          wg_td_pair *p = realloc(s->pair, sizeof *p * (size_t)cap);
          wg_spring *sp = s->rot ? realloc(spring, sizeof *sp * (size_t)cap) : NULL;
          if (p) s->pair = p;
          if (sp) spring = sp;
          if (!p || (s->rot && !sp)) {
            free(saved);
            free(spring);
            return wg_error(WG_ENOMEM, "td", "cannot allocate %ld neighbour pairs", cap);
          }
          s->pair_cap = cap;
        }
        saved_pair q = {.p = {.i = (int32_t)i, .j = j, .bonded = 0, .touching = 0}, .k = -1};
        const saved_pair *old = nb ? bsearch(&q, saved, (size_t)nb, sizeof *saved, cmp_saved) : NULL;
        if (old) q = *old;
        if (s->rot) spring[s->npair] = q.k >= 0 ? s->spring[q.k] : (wg_spring){{0, 0, 0}, 0};
        s->pair[s->npair++] = q.p;
      }
  }
  if (s->rot) {
    free(s->spring);
    s->spring = spring;
  }
  /* a bonded pair is always within the cut-off (its gap <= s_crit, moves < skin): check */
  long kept = 0;
  for (long k = 0; k < s->npair; k++) kept += s->pair[k].bonded;
  free(saved);
  if (kept != nbond)
    return wg_error(WG_EFAIL, "td", "neighbour list lost %ld bonds at t = %g", nbond - kept, s->t);
  memcpy(s->r_built, s->r, sizeof *s->r * 3 * (size_t)s->n);
  s->rebuilds++;
  return WG_OK;
}

static int need_rebuild(const wg_td *s)
{
  double lim = 0.25 * s->par.skin * s->par.skin;
  for (long k = 0; k < 3 * s->n; k += 3) {
    double d2 = 0;
    for (int a = 0; a < s->par.dim; a++) {
      double d = s->r[k + a] - s->r_built[k + a];
      d2 += d * d;
    }
    if (d2 > lim) return 1;
  }
  return 0;
}

/* Forces at the current positions and the velocities vel (in Verlet: predicted at the full
   step), the bond updates they imply, and the energies and powers for the ledger.  vhalf:
   the velocities over the step just taken (Verlet's half-step ones; Gear's mean ones), which
   move the tangential springs; NULL at an evaluation that follows no step.  With friction,
   wvel and whalf are the same for the angular velocities (whalf unused when vhalf is NULL). */
static void forces(wg_td *s, const double *vel, const double *vhalf, const double *wvel,
                   const double *whalf)
{
  int dim = s->par.dim, up = s->up, wet = s->par.f_b > 0;
  memset(s->f, 0, sizeof *s->f * 3 * (size_t)s->n);
  double u_contact = 0, u_bond = 0, p_wall = 0, p_diss = 0, p_diss_wall = 0;
  double half = s->par.integrator == WG_TD_VERLET ? 0.5 : 0;
  for (long i = 0; i < s->n; i++) s->f[3 * i + up] = -s->par.g * td_mass(s, i);
  const wg_friction *fr = s->rot && s->par.fric.mu > 0 ? &s->par.fric : NULL;
  const double *wv = wvel;
  if (s->rot) memset(s->tq, 0, sizeof *s->tq * 3 * (size_t)s->n);
  for (long k = 0; k < s->npair; k++) {
    wg_td_pair *p = &s->pair[k];
    long i = p->i, j = p->j;
    double d[3] = {0, 0, 0}, dist = 0;
    for (int a = 0; a < dim; a++) d[a] = s->r[3 * j + a] - s->r[3 * i + a];
    min_image(s, d);
    for (int a = 0; a < dim; a++) dist += d[a] * d[a];
    /* most listed pairs are apart: tell them without the root (a margin of 1e-12 leaves every
       pair near contact to the exact test below, so the outcome is the same bit for bit) */
    double sum = s->radius[i] + s->radius[j];
    if (!p->bonded && !p->touching && dist > sum * sum * (1 + 1e-12)) continue;
    dist = sqrt(dist);
    double gap = dist - s->radius[i] - s->radius[j];
    if (gap > 0 && !p->bonded) {
      if (fr && p->touching) ksum_add(&s->dissipated, wg_spring_release(&s->spring[k]));
      p->touching = 0;
      continue;
    }
    double nrm[3] = {0, 0, 0}, gapdot = 0;
    for (int a = 0; a < dim; a++) {
      nrm[a] = d[a] / dist;
      gapdot += (vel[3 * j + a] - vel[3 * i + a]) * nrm[a];
    }
    if (wet) {
      /* The bond force switches on or off between two steps, and Verlet applies half of the
         last step's force: the energy booked is the bond energy less that half step's work
         (half; zero for Gear, whose corrector spreads the switch over later steps). */
      if (p->bonded && gap > s->par.s_crit) { /* rupture: the bond energy goes */
        p->bonded = 0;
        s->ruptures++;
        ksum_add(&s->dissipated_rupt, wg_td_bond_energy(&s->par, gap) -
                                          half * bond_force(&s->par, gap) * gapdot * s->par.dt);
      } else if (!p->bonded && gap < 0) { /* capture at contact */
        p->bonded = 1;
        s->captures++;
        ksum_add(&s->dissipated_rupt, -wg_td_bond_energy(&s->par, gap) +
                                          half * s->par.f_b * gapdot * s->par.dt);
      }
    }
    double fn = 0; /* along nrm on j (repulsive > 0) */
    if (gap < 0 && !p->touching) s->contacts++;
    if (fr && gap >= 0 && p->touching) ksum_add(&s->dissipated, wg_spring_release(&s->spring[k]));
    p->touching = gap < 0;
    if (gap < 0) {
      double mi = td_mass(s, i), mj = td_mass(s, j), fel, uel;
      double reff = s->radius[i] * s->radius[j] / (s->radius[i] + s->radius[j]);
      fn = wg_contact_force(&s->par.pp, -gap, -gapdot, reff, mi * mj / (mi + mj), &fel, &uel);
      u_contact += uel;
      p_diss += (fn - fel) * -gapdot;
      if (fr) { /* the tangential spring; levers R - xi/2 (notes-sheared-layering Eq. 16) */
        double kn, gn, vji[3] = {0, 0, 0}, vt[3], dvt[3], ft[3], tn[3], pw;
        double li = s->radius[i] + 0.5 * gap, lj = s->radius[j] + 0.5 * gap;
        wg_contact_stiffness(&s->par.pp, -gap, reff, mi * mj / (mi + mj), &kn, &gn);
        for (int a = 0; a < dim; a++) vji[a] = vel[3 * j + a] - vel[3 * i + a];
        wg_contact_tangential_velocity(vji, nrm, li, lj, &wv[3 * i], &wv[3 * j], vt);
        if (vhalf) {
          for (int a = 0; a < dim; a++) vji[a] = vhalf[3 * j + a] - vhalf[3 * i + a];
          wg_contact_tangential_velocity(vji, nrm, li, lj, &whalf[3 * i], &whalf[3 * j], dvt);
        }
        double du = wg_spring_update(&s->spring[k], nrm, vt, vhalf ? dvt : NULL, fr->kt_ratio * kn,
                                     fr->gt_ratio * gn, fr->mu * fmax(fn, 0), s->par.dt, ft, &pw);
        if (vhalf) ksum_add(&s->dissipated, -du);
        u_contact += s->spring[k].u;
        p_diss += pw;
        if (fr->mu_roll > 0) {
          double ii = wg_inertia(dim, mi, s->radius[i]), ij = wg_inertia(dim, mj, s->radius[j]);
          double l = 2 * li * lj / (li + lj), tr[3] = {0, 0, 0};
          p_diss += wg_rolling_resistance(nrm, l, &wv[3 * i], &wv[3 * j], fr->mu_roll * fmax(fn, 0),
                                          0.5 / (s->par.dt * l * l * (1 / ii + 1 / ij)), tr);
          for (int a = 0; a < 3; a++) {
            s->tq[3 * i + a] += tr[a];
            s->tq[3 * j + a] -= tr[a];
          }
        }
        tn[0] = nrm[1] * ft[2] - nrm[2] * ft[1];
        tn[1] = nrm[2] * ft[0] - nrm[0] * ft[2];
        tn[2] = nrm[0] * ft[1] - nrm[1] * ft[0];
        for (int a = 0; a < 3; a++) {
          s->f[3 * j + a] += ft[a];
          s->f[3 * i + a] -= ft[a];
          s->tq[3 * i + a] -= li * tn[a];
          s->tq[3 * j + a] -= lj * tn[a];
        }
      }
    }
    if (p->bonded) {
      fn -= bond_force(&s->par, gap);
      u_bond += wg_td_bond_energy(&s->par, gap);
    }
    for (int a = 0; a < dim; a++) {
      s->f[3 * j + a] += fn * nrm[a];
      s->f[3 * i + a] -= fn * nrm[a];
    }
  }
  const wg_friction *frw = s->rot && s->par.fric_wall.mu > 0 ? &s->par.fric_wall : NULL;
  for (int w = 0; w < s->par.nwalls; w++) {
    const wg_wall *wl = &s->par.wall[w];
    double zw = wg_wall_position(wl, s->t), vw = wg_wall_velocity(wl, s->t);
    uint8_t bit = (uint8_t)(1u << w), bond_bit = (uint8_t)(4u << w);
    for (long i = 0; i < s->n; i++) {
      double gap = wl->side * (s->r[3 * i + up] - zw) - s->radius[i];
      int bonded = s->wall_touch[i] & bond_bit;
      if (frw && gap >= 0 && (s->wall_touch[i] & bit))
        ksum_add(&s->dissipated_wall, wg_spring_release(&s->wall_spring[2 * i + w]));
      if (gap >= 0 && !bonded) {
        s->wall_touch[i] &= (uint8_t)~bit;
        continue;
      }
      double xidot = -wl->side * (vel[3 * i + up] - vw), fn = 0; /* fn on the particle, away from the wall */
      if (s->par.wall_bonds) { /* a bridge to the wall, as between particles */
        if (bonded && gap > s->par.s_crit) {
          s->wall_touch[i] &= (uint8_t)~bond_bit;
          bonded = 0;
          s->ruptures++;
          ksum_add(&s->dissipated_rupt, wg_td_bond_energy(&s->par, gap) +
                                            half * bond_force(&s->par, gap) * xidot * s->par.dt);
        } else if (!bonded && gap < 0) {
          s->wall_touch[i] |= bond_bit;
          bonded = 1;
          s->captures++;
          ksum_add(&s->dissipated_rupt, -wg_td_bond_energy(&s->par, gap) -
                                            half * s->par.f_b * xidot * s->par.dt);
        }
        if (bonded) {
          fn -= bond_force(&s->par, gap);
          u_bond += wg_td_bond_energy(&s->par, gap);
        }
      }
      if (gap < 0) {
        if (!(s->wall_touch[i] & bit)) s->wall_contacts++;
        s->wall_touch[i] |= bit;
        double fel, uel, fc = wg_contact_force(&s->par.pw, -gap, xidot, s->radius[i], td_mass(s, i), &fel, &uel);
        fn += fc;
        u_contact += uel;
        p_diss_wall += (fc - fel) * xidot;
        if (frw) { /* the wall as a pair partner j that does not turn; n from i to the wall */
          double kn, gn, nrm[3] = {0, 0, 0}, vji[3] = {0, 0, 0}, vt[3], dvt[3], ft[3], pw, tn[3];
          static const double still[3] = {0, 0, 0};
          double li = s->radius[i] + 0.5 * gap;
          wg_spring *sp = &s->wall_spring[2 * i + w];
          nrm[up] = -wl->side;
          for (int a = 0; a < dim; a++) vji[a] = -vel[3 * i + a];
          vji[up] += vw;
          wg_contact_stiffness(&s->par.pw, -gap, s->radius[i], td_mass(s, i), &kn, &gn);
          wg_contact_tangential_velocity(vji, nrm, li, 0, &wv[3 * i], still, vt);
          if (vhalf) { /* the wall moves only along nrm: no tangential part */
            for (int a = 0; a < dim; a++) vji[a] = -vhalf[3 * i + a];
            wg_contact_tangential_velocity(vji, nrm, li, 0, &whalf[3 * i], still, dvt);
          }
          double du = wg_spring_update(sp, nrm, vt, vhalf ? dvt : NULL, frw->kt_ratio * kn,
                                       frw->gt_ratio * gn, frw->mu * fmax(fc, 0), s->par.dt, ft, &pw);
          if (vhalf) ksum_add(&s->dissipated_wall, -du);
          u_contact += sp->u;
          p_diss_wall += pw;
          if (frw->mu_roll > 0)
            p_diss_wall += wg_rolling_resistance(nrm, li, &wv[3 * i], still, frw->mu_roll * fmax(fc, 0),
                                                 0.5 * wg_inertia(dim, td_mass(s, i), s->radius[i]) /
                                                     (s->par.dt * li * li), &s->tq[3 * i]);
          tn[0] = nrm[1] * ft[2] - nrm[2] * ft[1];
          tn[1] = nrm[2] * ft[0] - nrm[0] * ft[2];
          tn[2] = nrm[0] * ft[1] - nrm[1] * ft[0];
          for (int a = 0; a < 3; a++) {
            s->f[3 * i + a] -= ft[a];
            s->tq[3 * i + a] -= li * tn[a];
          }
        }
      } else {
        s->wall_touch[i] &= (uint8_t)~bit;
      }
      s->f[3 * i + up] += wl->side * fn;
      p_wall += wl->side * fn * vw;
    }
  }
  s->u_contact = u_contact;
  s->u_bond = u_bond;
  s->p_wall = p_wall;
  s->p_diss = p_diss;
  s->p_diss_wall = p_diss_wall;
}

/* Gear: the second derivative from the forces now (and the first of w from the torques),
   the higher ones zero. */
static void gear_start(wg_td *s)
{
  if (!s->gear) return;
  double dt = s->par.dt;
  memset(s->gear, 0, sizeof *s->gear * 12 * (size_t)s->n);
  for (long i = 0; i < s->n; i++)
    for (int a = 0; a < s->par.dim; a++)
      s->gear[12 * i + 4 * a] = 0.5 * dt * dt * s->f[3 * i + a] / td_mass(s, i);
  if (!s->gear_w) return;
  memset(s->gear_w, 0, sizeof *s->gear_w * 12 * (size_t)s->n);
  for (long i = 0; i < s->n; i++)
    for (int a = 0; a < 3; a++)
      s->gear_w[12 * i + 4 * a] = dt * s->tq[3 * i + a] / wg_inertia(s->par.dim, td_mass(s, i), s->radius[i]);
}

int wg_td_alloc_state(wg_td *s, const wg_td_params *par, long n, const double *r,
                      const double *v, const double *radius, const double *mass, double t0)
{
  memset(s, 0, sizeof *s);
  s->par = *par;
  s->up = par->dim - 1;
  s->n = n;
  s->t = s->t0 = t0;
  size_t n3 = 3 * (size_t)n;
  s->r = calloc(n3, sizeof *s->r);
  s->v = calloc(n3, sizeof *s->v);
  s->f = calloc(n3, sizeof *s->f);
  s->vp = calloc(n3, sizeof *s->vp);
  s->r_built = calloc(n3, sizeof *s->r_built);
  s->wall_touch = calloc((size_t)n, 1);
  s->radius = malloc(sizeof *s->radius * (size_t)n);
  if (mass) s->mass = malloc(sizeof *s->mass * (size_t)n);
  if (par->integrator == WG_TD_GEAR) s->gear = calloc(4 * n3, sizeof *s->gear);
  s->rot = par->fric.mu > 0 || par->fric_wall.mu > 0;
  if (s->gear && (par->fric.mu_roll > 0 || par->fric_wall.mu_roll > 0)) {
    wg_td_free(s);
    return wg_error(WG_EINVAL, "td", "rolling resistance needs the Verlet integrator");
  }
  if (s->rot) {
    if (s->gear) s->gear_w = calloc(4 * n3, sizeof *s->gear_w);
    s->w = calloc(n3, sizeof *s->w);
    s->wp = calloc(n3, sizeof *s->wp);
    s->tq = calloc(n3, sizeof *s->tq);
    s->wall_spring = calloc(2 * (size_t)n, sizeof *s->wall_spring);
  }
  if (!s->r || !s->v || !s->f || !s->vp || !s->r_built || !s->wall_touch || !s->radius ||
      (mass && !s->mass) || (par->integrator == WG_TD_GEAR && !s->gear) ||
      (s->rot && (!s->w || !s->wp || !s->tq || !s->wall_spring || (s->gear && !s->gear_w)))) {
    wg_td_free(s);
    return wg_error(WG_ENOMEM, "td", "cannot allocate %ld particles", n);
  }
  for (long i = 0; i < n; i++) {
    for (int a = 0; a < par->dim; a++) {
      s->r[3 * i + a] = r[3 * i + a];
      s->v[3 * i + a] = v[3 * i + a];
    }
    s->radius[i] = radius[i];
    if (s->radius[i] > s->r_max) s->r_max = s->radius[i];
    if (mass) s->mass[i] = mass[i];
  }
  double lo[3], len[3];
  for (int a = 0; a < 3; a++) {
    lo[a] = par->periodic[a] ? 0 : par->lo[a];
    len[a] = par->periodic[a] ? par->box[a] : par->hi[a] - par->lo[a];
  }
  int st = wg_cells_alloc(&s->cells, par->dim, lo, len, par->periodic, 2 * s->r_max + cutoff_extra(s), n);
  if (st == WG_OK) st = build_list(s);
  if (st != WG_OK) {
    wg_td_free(s);
    return st;
  }
  forces(s, s->v, NULL, s->w, NULL);
  gear_start(s);
  double k, u;
  wg_td_energy(s, &k, &u);
  s->e0 = k + u;
  memset(&s->dissipated_rupt, 0, sizeof s->dissipated_rupt); /* bonds made at t0 are in e0 */
  return WG_OK;
}

int wg_td_set_bonds(wg_td *s, const int32_t *pairs, long nb)
{
  if (s->par.f_b <= 0) return wg_error(WG_EINVAL, "td", "bridges given, but the scene is dry");
  qsort(s->pair, (size_t)s->npair, sizeof *s->pair, cmp_pair); /* a fixed order, searchable */
  for (long k = 0; k < nb; k++) {
    wg_td_pair q = {.i = pairs[2 * k] < pairs[2 * k + 1] ? pairs[2 * k] : pairs[2 * k + 1],
                    .j = pairs[2 * k] < pairs[2 * k + 1] ? pairs[2 * k + 1] : pairs[2 * k]};
    wg_td_pair *found = bsearch(&q, s->pair, (size_t)s->npair, sizeof *s->pair, cmp_pair);
    if (!found)
      return wg_error(WG_EINVAL, "td", "bridge %d-%d: the pair is not within reach of a bridge", q.i, q.j);
    found->bonded = 1;
  }
  forces(s, s->v, NULL, s->w, NULL);
  gear_start(s);
  double k, u;
  wg_td_energy(s, &k, &u);
  s->e0 = k + u;
  memset(&s->dissipated_rupt, 0, sizeof s->dissipated_rupt);
  return WG_OK;
}

int wg_td_set_angular_velocities(wg_td *s, const double *w)
{
  if (!s->rot) return wg_error(WG_EINVAL, "td", "angular velocities given, but the run has no friction");
  for (long i = 0; i < s->n; i++)
    for (int a = s->par.dim == 2 ? 2 : 0; a < 3; a++) s->w[3 * i + a] = w[3 * i + a];
  forces(s, s->v, NULL, s->w, NULL);
  gear_start(s);
  double k, u;
  wg_td_energy(s, &k, &u);
  s->e0 = k + u;
  return WG_OK;
}

void wg_td_free(wg_td *s)
{
  free(s->r);
  free(s->v);
  free(s->f);
  free(s->vp);
  free(s->gear);
  free(s->gear_w);
  free(s->r_built);
  free(s->wall_touch);
  free(s->radius);
  free(s->mass);
  free(s->pair);
  free(s->w);
  free(s->wp);
  free(s->tq);
  free(s->spring);
  free(s->wall_spring);
  if (s->cells.head) wg_cells_free(&s->cells);
  memset(s, 0, sizeof *s);
}

/* Half a kick of the angular velocities by the torques; *pred: also the prediction at the
   full step, w + dt tau / I (2D: the z axis only). */
static void rotation_kick(wg_td *s, int pred)
{
  int a0 = s->par.dim == 2 ? 2 : 0;
  for (long i = 0; i < s->n; i++) {
    double h = 0.5 * s->par.dt / wg_inertia(s->par.dim, td_mass(s, i), s->radius[i]);
    for (int a = a0; a < 3; a++) {
      s->w[3 * i + a] += h * s->tq[3 * i + a];
      if (pred) s->wp[3 * i + a] = s->w[3 * i + a] + h * s->tq[3 * i + a];
    }
  }
}

/* Velocity Verlet.  Velocity-dependent forces (dashpots) see the velocity predicted at the
   full step, v(t) + dt f(t) / m, which keeps the scheme second order in the damping; the
   ledger's powers are integrated by the trapezoid rule between force evaluations.  Angular
   velocities take the same kicks from the torques. */
static int verlet_advance(wg_td *s, double t_stop)
{
  double dt = s->par.dt;
  while (s->t < t_stop - 0.5 * dt) {
    double p_wall0 = s->p_wall, p_diss0 = s->p_diss, p_diss_wall0 = s->p_diss_wall;
    for (long i = 0; i < s->n; i++) {
      double h = 0.5 * dt / td_mass(s, i);
      for (int a = 0; a < s->par.dim; a++) {
        s->v[3 * i + a] += h * s->f[3 * i + a];
        s->r[3 * i + a] += dt * s->v[3 * i + a];
        s->vp[3 * i + a] = s->v[3 * i + a] + h * s->f[3 * i + a];
      }
    }
    if (s->rot) rotation_kick(s, 1);
    s->steps++;
    s->t = s->t0 + (double)s->steps * dt; /* no accumulated round-off */
    if (need_rebuild(s)) {
      int st = build_list(s);
      if (st != WG_OK) return st;
    }
    forces(s, s->vp, s->v, s->wp, s->w);
    for (long i = 0; i < s->n; i++) {
      double h = 0.5 * dt / td_mass(s, i);
      for (int a = 0; a < s->par.dim; a++) s->v[3 * i + a] += h * s->f[3 * i + a];
    }
    if (s->rot) rotation_kick(s, 0);
    ksum_add(&s->injected_wall, 0.5 * (p_wall0 + s->p_wall) * dt);
    ksum_add(&s->dissipated, 0.5 * (p_diss0 + s->p_diss) * dt);
    ksum_add(&s->dissipated_wall, 0.5 * (p_diss_wall0 + s->p_diss_wall) * dt);
  }
  return WG_OK;
}

/* Gear's predictor-corrector of fifth order for r'' = f(r, r')/m (six values: r and the
   scaled derivatives q_k = dt^k/k! d^k r/dt^k, k = 1..5; q_1 = dt v).  Predict by the
   Taylor series (Pascal's triangle), evaluate the forces at the predicted r and v, and
   correct every value by c_k times the misfit of q_2, with the coefficients for
   velocity-dependent forces (c_0 = 3/16; Allen and Tildesley, App. E).  With friction the
   angular velocities follow w' = tau/I the same way, five values (w and dt^k/k! d^k w/dt^k,
   k = 1..4) with the first-order coefficients; the springs move by the predicted
   displacement of the contact points, i.e. by the mean velocities over the step. */
static int gear_advance(wg_td *s, double t_stop)
{
  static const double c[6] = {3.0 / 16, 251.0 / 360, 1, 11.0 / 18, 1.0 / 6, 1.0 / 60};
  static const double cw[5] = {251.0 / 720, 1, 11.0 / 12, 1.0 / 3, 1.0 / 24};
  double dt = s->par.dt, inv_dt = 1 / dt;
  int dim = s->par.dim, a0 = dim == 2 ? 2 : 0;
  while (s->t < t_stop - 0.5 * dt) {
    double p_wall0 = s->p_wall, p_diss0 = s->p_diss, p_diss_wall0 = s->p_diss_wall;
    for (long i = 0; i < s->n; i++)
      for (int a = 0; a < dim; a++) {
        double *q = &s->gear[12 * i + 4 * a]; /* q[0..3] = q_2..q_5 */
        double q1 = dt * s->v[3 * i + a], dr = q1 + q[0] + q[1] + q[2] + q[3];
        s->r[3 * i + a] += dr;
        s->vp[3 * i + a] = dr * inv_dt;
        q1 += 2 * q[0] + 3 * q[1] + 4 * q[2] + 5 * q[3];
        q[0] += 3 * q[1] + 6 * q[2] + 10 * q[3];
        q[1] += 4 * q[2] + 10 * q[3];
        q[2] += 5 * q[3];
        s->v[3 * i + a] = q1 * inv_dt;
      }
    if (s->rot)
      for (long i = 0; i < s->n; i++)
        for (int a = a0; a < 3; a++) {
          double *q = &s->gear_w[12 * i + 4 * a], *w = &s->w[3 * i + a]; /* q[0..3]: k = 1..4 */
          s->wp[3 * i + a] = *w + q[0] / 2 + q[1] / 3 + q[2] / 4 + q[3] / 5; /* mean over the step */
          *w += q[0] + q[1] + q[2] + q[3];
          q[0] += 2 * q[1] + 3 * q[2] + 4 * q[3];
          q[1] += 3 * q[2] + 6 * q[3];
          q[2] += 4 * q[3];
        }
    s->steps++;
    s->t = s->t0 + (double)s->steps * dt;
    if (need_rebuild(s)) {
      int st = build_list(s);
      if (st != WG_OK) return st;
    }
    forces(s, s->v, s->vp, s->w, s->wp);
    for (long i = 0; i < s->n; i++) {
      double h = 0.5 * dt * dt / td_mass(s, i);
      for (int a = 0; a < dim; a++) {
        double *q = &s->gear[12 * i + 4 * a];
        double miss = h * s->f[3 * i + a] - q[0];
        s->r[3 * i + a] += c[0] * miss;
        s->v[3 * i + a] += c[1] * inv_dt * miss;
        q[0] += c[2] * miss;
        q[1] += c[3] * miss;
        q[2] += c[4] * miss;
        q[3] += c[5] * miss;
      }
    }
    if (s->rot)
      for (long i = 0; i < s->n; i++) {
        double h = dt / wg_inertia(dim, td_mass(s, i), s->radius[i]);
        for (int a = a0; a < 3; a++) {
          double *q = &s->gear_w[12 * i + 4 * a];
          double miss = h * s->tq[3 * i + a] - q[0];
          s->w[3 * i + a] += cw[0] * miss;
          for (int k = 0; k < 4; k++) q[k] += cw[k + 1] * miss;
        }
      }
    ksum_add(&s->injected_wall, 0.5 * (p_wall0 + s->p_wall) * dt);
    ksum_add(&s->dissipated, 0.5 * (p_diss0 + s->p_diss) * dt);
    ksum_add(&s->dissipated_wall, 0.5 * (p_diss_wall0 + s->p_diss_wall) * dt);
  }
  return WG_OK;
}

int wg_td_advance(wg_td *s, double t_stop)
{
  return s->gear ? gear_advance(s, t_stop) : verlet_advance(s, t_stop);
}

void wg_td_energy(const wg_td *s, double *kinetic, double *potential)
{
  double k = 0, u = 0;
  for (long i = 0; i < s->n; i++) {
    double v2 = 0;
    for (int a = 0; a < s->par.dim; a++) v2 += s->v[3 * i + a] * s->v[3 * i + a];
    k += 0.5 * td_mass(s, i) * v2;
    u += td_mass(s, i) * s->par.g * s->r[3 * i + s->up];
  }
  if (s->rot)
    for (long i = 0; i < s->n; i++) {
      const double *w = &s->w[3 * i];
      k += 0.5 * wg_inertia(s->par.dim, td_mass(s, i), s->radius[i]) * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    }
  *kinetic = k;
  *potential = u + s->u_contact + s->u_bond;
}

double wg_td_ledger_residual(const wg_td *s)
{
  double k, u;
  wg_td_energy(s, &k, &u);
  double in = s->injected_wall.s + s->injected_wall.c;
  double out = s->dissipated.s + s->dissipated.c + s->dissipated_wall.s + s->dissipated_wall.c +
               s->dissipated_rupt.s + s->dissipated_rupt.c;
  double scale = fmax(fmax(fabs(k + u), fabs(s->e0)), fmax(fabs(in), fabs(out)));
  return fabs(k + u - s->e0 - in + out) / fmax(scale, 1e-300);
}

long wg_td_bond_total(const wg_td *s)
{
  long b = 0;
  for (long k = 0; k < s->npair; k++) b += s->pair[k].bonded;
  return b;
}

double wg_td_bond_energy(const wg_td_params *p, double gap)
{
  if (gap <= 0 || p->willett <= 0) return p->f_b * gap;
  /* integral of Eq. 2.9 from 0 to gap */
  const double q = sqrt(4 * 2.5 - 1.05 * 1.05);
  double x = gap * p->willett;
  return p->f_b / p->willett * 2 / q * (atan((5 * x + 1.05) / q) - atan(1.05 / q));
}

double wg_td_bytes_per_particle(const wg_td *s)
{
  double per = 6 * 3 * sizeof(double) + 2 * sizeof(double) + 1; /* r v f vp r_built; radius mass */
  if (s->gear) per += 12 * sizeof(double);
  if (s->gear_w) per += 12 * sizeof(double);
  if (s->rot) per += 9 * sizeof(double) + 2 * sizeof(wg_spring) +
                     (double)s->pair_cap * sizeof(wg_spring) / (double)(s->n > 0 ? s->n : 1);
  return per + (double)s->pair_cap * sizeof(wg_td_pair) / (double)(s->n > 0 ? s->n : 1) +
         3 * sizeof(int32_t);
}

void wg_td_params_from_scene(const wg_scene *sc, wg_td_params *out)
{
  int dim = sc->dim, up = dim - 1;
  wg_td_params p;
  memset(&p, 0, sizeof p);
  p.dim = dim;
  p.g = sc->gravity;
  double len[3] = {sc->lx, dim == 3 ? sc->ly : sc->height, sc->height};
  for (int a = 0; a < dim; a++) {
    p.box[a] = len[a];
    p.periodic[a] = a < up || sc->container == WG_CONTAINER_PERIODIC;
  }
  if (sc->container == WG_CONTAINER_SHAKER) {
    p.nwalls = 2;
    p.wall[0] = (wg_wall){0.0, sc->amplitude, sc->omega > 0 ? sc->omega : 1, +1};
    p.wall[1] = (wg_wall){sc->height, sc->amplitude, sc->omega > 0 ? sc->omega : 1, -1};
    p.lo[up] = -sc->amplitude - 1;
    p.hi[up] = sc->height + sc->amplitude + 1;
  }
  if (sc->contact_law == WG_CONTACT_HERTZ) {
    p.pp = p.pw = wg_contact_hertz(sc->hertz_k, sc->hertz_ad);
  } else {
    p.pp = wg_contact_linear(sc->eps, sc->t_contact, 0.5);      /* two unit masses */
    p.pw = wg_contact_linear(sc->eps_wall, sc->t_contact, 1.0); /* a unit mass on a wall */
  }
  if (sc->s_crit > 0) {
    p.f_b = sc->f_b;
    p.s_crit = sc->s_crit;
    if (sc->bridge_law == 1) p.willett = sqrt(0.5 / sc->bridge_volume); /* sqrt(R/V), R = d/2 */
    p.wall_bonds = sc->wall_bridges;
  }
  p.dt = sc->dt;
  p.skin = sc->skin;
  p.integrator = sc->integrator;
  p.fric = (wg_friction){sc->mu, sc->kt_ratio, sc->gt_ratio, sc->mu_roll};
  p.fric_wall = (wg_friction){sc->mu_wall, sc->kt_ratio, sc->gt_ratio, sc->mu_roll};
  *out = p;
}

int wg_td_alloc(wg_td *s, const wg_scene *sc)
{
  wg_td_params p;
  wg_td_params_from_scene(sc, &p);
  long n = sc->n;
  wg_particle *q = malloc(sizeof *q * (size_t)n);
  double *mass = sc->mass_scaling ? malloc(sizeof *mass * (size_t)n) : NULL;
  double *r = malloc(sizeof *r * 3 * (size_t)n), *v = malloc(sizeof *v * 3 * (size_t)n);
  double *rad = malloc(sizeof *rad * (size_t)n);
  int st = (!q || !r || !v || !rad || (sc->mass_scaling && !mass))
               ? wg_error(WG_ENOMEM, "td", "cannot allocate %ld particles", n)
               : wg_init_state(sc, q, mass);
  if (st == WG_OK) {
    for (long i = 0; i < n; i++) {
      for (int a = 0; a < 3; a++) {
        r[3 * i + a] = q[i].r[a];
        v[3 * i + a] = q[i].v[a];
      }
      rad[i] = q[i].radius;
    }
    st = wg_td_alloc_state(s, &p, n, r, v, rad, mass, 0);
  }
  if (st == WG_OK && sc->init_from[0]) {
    int32_t *pairs;
    long nb;
    st = wg_init_bonds(sc, &pairs, &nb);
    if (st == WG_OK && nb) st = wg_td_set_bonds(s, pairs, nb);
    free(pairs);
    if (st != WG_OK) wg_td_free(s);
  }
  free(q);
  free(mass);
  free(r);
  free(v);
  free(rad);
  return st;
}
