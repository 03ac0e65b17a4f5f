/* Exact particle–wall contact times for a sinusoidally moving flat wall (thesis App. B).

   The thesis finds the root of Eq. (B.7) by scanning the gap on a grid of step t_min
   (App. B.3) and replaces that scan by look-up tables (App. B.4).  Here the root is found
   exactly instead, using the structure of the gap
       gap(tau)   = h0 + h1 tau + h2 tau^2 - a sin(theta),      theta = theta0 + omega tau,
       gap'(tau)  = h1 + 2 h2 tau - a omega cos(theta),
       gap''(tau) = 2 h2 + a omega^2 sin(theta),
   with h0 = side (z0 - c) - R, h1 = side v0, h2 = -side g / 2, a = side A  (Eq. B.7 in the
   frame of the wall's mean position, oriented towards the particle).

   1. gap'' vanishes only where sin(theta) = g / (A omega^2) = 1/Gamma: twice per period,
      in closed form.  Between two such critical phases ("a piece") gap'' has one sign, so
      gap' is monotonic and the gap is convex or concave.
   2. A piece in which gap' keeps its sign is monotonic: it holds a closing root iff
      gap(start) > 0 >= gap(end).  A concave piece whose gap' goes + to - (a maximum inside)
      holds one iff gap(end) <= 0.  A convex piece whose gap' goes - to + (a minimum inside)
      is first tested with the two end tangents (a rigorous lower bound of a convex gap);
      only if that bound is not positive is the zero of gap' found, and the gap there tells
      whether the particle reaches the wall.  In every case the bracket holds exactly one
      crossing from > 0 to <= 0, found by safeguarded Newton–bisection to round-off.
   3. The wall's reach (App. B.3.3.1, line I of Fig. B.2) is the slab swept by the wall; the
      gap is provably positive while the particle is outside it.  The reach function
          q(tau) = side (z(tau) - c) - R - A = gap(tau) - A (1 - side sin(theta)) <= gap(tau)
      is a quadratic, so the windows inside the reach are known in closed form.  Inside a
      window that lasts a full period the wall reaches its extreme, where gap = q <= 0, so a
      contact is certain within one period of entering (the thesis' argument for n_max,
      Eq. B.9): no search ever needs to run longer than one period past an entry.

   Overlap rule (App. B.5.6): gap(0) <= 0 and closing -> contact at tau = 0.  Overlapping
   and opening: the search waits until the gap is positive again and reports the next
   closing crossing.  Should the overlapping particle turn round (gap' becomes negative)
   before the gap is positive again, the overlap rule applies at that instant: the contact
   is reported there (the alternative would let the particle pass through the wall).

   Every loop has a bound stated where it is written.  No global mutable state. */
#include "wall.h"

#include <float.h>
#include <math.h>

#define WG_PI 3.14159265358979323846264338327950288
#define WG_TWO_PI 6.28318530717958647692528676655900577

/* ---- tolerances --------------------------------------------------------------------- */

/* The root bracket is accepted once it is at most this many ulps of tau wide. */
#define ROOT_BRACKET_ULPS 4.0
/* A Newton step shorter than this many ulps of tau ends the iteration (converged). */
#define NEWTON_STOP_ULPS 4.0
/* Newton steps are accepted only if at most this fraction of the step before last. */
#define NEWTON_MIN_SHRINK 0.5
/* A bisection is forced when the bracket has not halved within this many iterations, so
   the bracket halves at least every NEWTON_RUN_MAX + 1 iterations. */
#define NEWTON_RUN_MAX 8
/* Halvings that take any double bracket down to ROOT_BRACKET_ULPS ulps: the exponent range
   plus the mantissa (about 2100).  Times (NEWTON_RUN_MAX + 1) this bounds the iteration
   count; the cap is therefore unreachable and its failure return a pure safety net. */
#define ROOT_MAX_HALVINGS (DBL_MAX_EXP - DBL_MIN_EXP + DBL_MANT_DIG + 4)
#define ROOT_MAX_ITER ((NEWTON_RUN_MAX + 1) * ROOT_MAX_HALVINGS)
/* Relative round-off of one gap evaluation, in units of the size of its terms; a lower
   bound on the gap must exceed this to prove a piece free of contacts. */
#define GAP_ROUNDOFF_REL (64.0 * DBL_EPSILON)
/* A particle this close (relative to the height scale) to entering the reach counts as
   inside: keeps callers that propagate to an entry time from re-entering forever. */
#define REACH_SNAP_REL 1e-10
/* Windows inside the reach that never end are searched this many periods past their
   start (a contact is certain within one period of it, see 3. above). */
#define REACH_SEARCH_PERIODS 2.0

/* ---- the gap model ------------------------------------------------------------------ */

typedef struct gap_model {
  double h0, h1, h2;    /* particle part of the gap: h0 + h1 tau + h2 tau^2 */
  double a;             /* side * A */
  double omega;         /* angular frequency */
  double theta0;        /* omega t0 reduced to [0, 2 pi) */
  double period;        /* T_driv = 2 pi / omega (infinite for a static wall) */
  double crit[2];       /* critical phases in [0, 2 pi): gap'' = 0 (or period start) */
  int ncrit;            /* 2, or 1 when Gamma < 1 (no critical phase) */
  int is_static;        /* A == 0 or omega == 0: gap is a quadratic */
  double height_scale;  /* |z0| + |c| + R + A: magnitude of the heights involved */
  wg_wall_stats *st;    /* may be NULL */
} gap_model;

typedef struct gap_value {
  double gap, slope, curv; /* gap, gap', gap'' */
} gap_value;

/* omega t reduced to [0, 2 pi) once, so that theta0 + omega tau keeps full precision. */
static double reduced_phase(double omega, double t)
{
  double theta = fmod(omega * t, WG_TWO_PI);
  if (theta < 0.0) theta += WG_TWO_PI;
  if (theta >= WG_TWO_PI) theta = 0.0; /* -tiny + 2 pi rounded up */
  return theta;
}

/* The particle's part of the model (no trigonometry); model_phase adds the wall's phase. */
static void model_particle(gap_model *m, const wg_wall *w, const wg_ballistic *p,
                           wg_wall_stats *st)
{
  double side = w->side >= 0 ? 1.0 : -1.0;
  m->h0 = side * (p->z0 - w->c) - p->R;
  m->h1 = side * p->v0;
  m->h2 = -side * p->g / 2.0;
  m->a = side * w->A;
  m->omega = w->omega;
  m->st = st;
  m->height_scale = fabs(p->z0) + fabs(w->c) + p->R + fabs(w->A);
  m->is_static = !(w->A != 0.0 && w->omega > 0.0);
  if (m->is_static) {
    /* Wall frozen at c (A = 0, or no motion): gap = h0 + h1 tau + h2 tau^2. */
    m->a = 0.0;
    m->omega = 0.0;
    m->theta0 = 0.0;
    m->period = INFINITY;
    m->ncrit = 0;
  }
}

static void model_phase(gap_model *m, const wg_wall *w, const wg_ballistic *p)
{
  if (m->is_static) return;
  m->theta0 = reduced_phase(w->omega, p->t0);
  m->period = WG_TWO_PI / w->omega;
  /* gap'' = side (-g + A omega^2 sin theta) = 0  <=>  sin theta = g / (A omega^2) = 1/Gamma */
  double inv_gamma = p->g / (fabs(w->A) * w->omega * w->omega);
  if (fabs(inv_gamma) <= 1.0) {
    double alpha = asin(inv_gamma), beta = WG_PI - alpha;
    if (alpha < 0.0) alpha += WG_TWO_PI;
    m->crit[0] = alpha < beta ? alpha : beta;
    m->crit[1] = alpha < beta ? beta : alpha;
    m->ncrit = 2;
  } else {
    /* Gamma < 1: gap'' never vanishes, gap' is monotonic everywhere; the period
       boundaries serve as piece boundaries. */
    m->crit[0] = 0.0;
    m->ncrit = 1;
  }
}

static void model_init(gap_model *m, const wg_wall *w, const wg_ballistic *p,
                       wg_wall_stats *st)
{
  model_particle(m, w, p, st);
  model_phase(m, w, p);
}

/* gap, gap', gap'' at tau (Eq. B.7 and its derivatives). */
static gap_value gap_at(const gap_model *m, double tau)
{
  gap_value v;
  double theta = m->theta0 + m->omega * tau;
  double s = sin(theta), c = cos(theta);
  v.gap = m->h0 + tau * (m->h1 + m->h2 * tau) - m->a * s;
  v.slope = m->h1 + 2.0 * m->h2 * tau - m->a * m->omega * c;
  v.curv = 2.0 * m->h2 + m->a * m->omega * m->omega * s;
  if (m->st) m->st->evaluations++;
  return v;
}

/* Size of the terms summed in gap(tau): its round-off is a few ulps of this. */
static double gap_term_scale(const gap_model *m, double tau)
{
  return fabs(m->h0) + fabs(m->h1) * tau + fabs(m->h2) * tau * tau + fabs(m->a) + 1e-300;
}

/* The gap at tau = 0 is clear of the wall when it exceeds its own round-off.  A particle
   that has just been reflected sits at gap ~ 0 +- round-off; treating it as still in
   contact (not armed) keeps the search from finding the contact it has just left. */
static int clear_of_wall(const gap_model *m, gap_value v0)
{
  return v0.gap > GAP_ROUNDOFF_REL * gap_term_scale(m, 0.0);
}

/* Overlap rule (App. B.5.6): overlapping and approaching.  Approaching includes a
   particle moving with the wall (gap' = 0) that is being pushed into it (gap'' < 0). */
static int is_closing(gap_value v)
{
  return v.slope < 0.0 || (v.slope == 0.0 && v.curv < 0.0);
}

/* Spacing of doubles at x, to within a factor 2 from above (eps |x| >= ulp(x)). */
static double ulp_of(double x)
{
  double u = DBL_EPSILON * fabs(x);
  return u > DBL_TRUE_MIN ? u : DBL_TRUE_MIN;
}

/* ---- safeguarded Newton–bisection (Press et al. rtsafe, with a halving guarantee) ---- */

enum { ROOT_OF_GAP, ROOT_OF_SLOPE };

/* Zero of gap (which = ROOT_OF_GAP, Newton with gap') or of gap' (ROOT_OF_SLOPE, Newton
   with gap'') in [lo, hi], given f(lo) != 0 and f(hi) of the other sign or 0.  The
   bracket always keeps f(lo) on its initial side and f(hi) on the other, so it converges
   to a sign change; for the gap with f(lo) > 0 >= f(hi) the returned point is on the
   closing side to within the tolerances.
   Termination: every iteration either bisects or takes a Newton step inside the bracket;
   a bisection is forced whenever the bracket has not halved in NEWTON_RUN_MAX iterations,
   so the width halves at least every NEWTON_RUN_MAX + 1 iterations and reaches
   ROOT_BRACKET_ULPS ulps (always > 2 ulps, so a midpoint is strictly inside) within
   ROOT_MAX_ITER iterations.  Returns WG_OK, or WG_EFAIL with *root = hi if the cap is hit. */
static int bracketed_root(const gap_model *m, int which, double lo, double hi, double f_lo,
                          double f_hi, double *root)
{
  double sgn = f_lo > 0.0 ? 1.0 : -1.0; /* work with F = sgn f: F(lo) > 0 >= F(hi) */
  double F_lo = sgn * f_lo, F_hi = sgn * f_hi;
  double x, step = hi - lo, step_before = hi - lo, width_ref = hi - lo;
  int since_halved = 0;
  if (F_hi == 0.0) {
    *root = hi;
    return WG_OK;
  }
  /* First iterate: regula falsi from the end values (inside the bracket). */
  x = lo + (hi - lo) * (F_lo / (F_lo - F_hi));
  if (!(x > lo && x < hi)) x = lo + 0.5 * (hi - lo);
  for (int iter = 0; iter < ROOT_MAX_ITER; iter++) {
    gap_value v = gap_at(m, x);
    double F = sgn * (which == ROOT_OF_GAP ? v.gap : v.slope);
    double dF = sgn * (which == ROOT_OF_GAP ? v.slope : v.curv);
    if (F == 0.0) {
      *root = x;
      return WG_OK;
    }
    if (F > 0.0) lo = x;
    else hi = x;
    double width = hi - lo;
    if (width <= ROOT_BRACKET_ULPS * ulp_of(fabs(lo) > fabs(hi) ? lo : hi)) {
      *root = hi;
      return WG_OK;
    }
    if (width <= 0.5 * width_ref) {
      width_ref = width;
      since_halved = 0;
    } else {
      since_halved++;
    }
    double newton = dF != 0.0 ? -F / dF : NAN; /* Newton step, Eq. (B.8) */
    if (fabs(newton) <= NEWTON_STOP_ULPS * ulp_of(x) && x + newton >= lo &&
        x + newton <= hi) {
      *root = x + newton; /* converged to round-off */
      return WG_OK;
    }
    /* Accept the Newton step if it stays inside the bracket and is at most half the
       step before last (Press et al.'s rtsafe test), and the bracket has halved lately. */
    int accept = since_halved < NEWTON_RUN_MAX && x + newton > lo && x + newton < hi &&
                 fabs(newton) <= NEWTON_MIN_SHRINK * fabs(step_before);
    step_before = step;
    if (accept) {
      step = newton;
      x += newton;
    } else { /* bisection */
      step = 0.5 * width;
      x = lo + step;
      width_ref = width; /* the bisection at least halves it */
      since_halved = 0;
    }
  }
  *root = hi;
  return WG_EFAIL;
}

/* ---- static wall: the gap is a quadratic --------------------------------------------- */

/* Real roots of a2 x^2 + a1 x + a0 (a2 != 0), sorted, with the cancellation-free formula
   q = -(a1 + sign(a1) sqrt(D)) / 2, x = q / a2, a0 / q.  Returns the number (0 or 2;
   a double root is returned twice). */
static int quadratic_roots(double a2, double a1, double a0, double r[2])
{
  double disc = a1 * a1 - 4.0 * a2 * a0;
  if (disc < 0.0) return 0;
  double q = -0.5 * (a1 + copysign(sqrt(disc), a1));
  if (q == 0.0) { /* a1 = 0 and a0 = 0 */
    r[0] = r[1] = 0.0;
    return 2;
  }
  double x1 = q / a2, x2 = a0 / q;
  r[0] = x1 < x2 ? x1 : x2;
  r[1] = x1 < x2 ? x2 : x1;
  return 2;
}

/* First closing root in [0, inf) of gap = h0 + h1 tau + h2 tau^2, with the overlap rule.
   Closed form, no iteration.  Returns 1 and *tau, or 0. */
static int static_first_root(const gap_model *m, double *tau)
{
  double h0 = m->h0, h1 = m->h1, h2 = m->h2, r[2];
  if (m->st) m->st->evaluations++;
  if (h0 <= 0.0) {
    if (h1 < 0.0 || (h1 == 0.0 && h2 < 0.0)) { /* overlapping and closing */
      *tau = 0.0;
      return 1;
    }
    if (!(h2 < 0.0)) return 0; /* opening for ever */
    /* Opening, then pulled back (floor under gravity): closes at the larger root if
       the gap becomes positive, else the overlapping particle turns round at the vertex. */
    if (quadratic_roots(h2, h1, h0, r) == 2 && r[1] > r[0]) {
      *tau = r[1];
    } else {
      *tau = -h1 / (2.0 * h2);
    }
    return 1;
  }
  if (h2 == 0.0) { /* linear gap */
    if (h1 < 0.0) {
      *tau = -h0 / h1;
      return 1;
    }
    return 0;
  }
  if (quadratic_roots(h2, h1, h0, r) == 0) return 0;
  if (h2 < 0.0) { /* roots of opposite sign: the positive one closes */
    *tau = r[1];
    return 1;
  }
  if (h1 < 0.0) { /* h2 > 0: both roots positive, the first one closes */
    *tau = r[0];
    return 1;
  }
  return 0;
}

/* ---- the wall's reach ---------------------------------------------------------------- */

typedef struct window {
  double start, end; /* end may be INFINITY */
} window;

/* Windows of tau >= 0 in which the particle is within the wall's reach, i.e. where
   q(tau) = (h0 - A) + h1 tau + h2 tau^2 <= 0 (App. B.3.3.1), in time order (at most 2).
   Outside them gap >= q > 0.  A particle just about to enter (q(0) within the snap
   tolerance and not moving away, or q(0) <= 0) has its first window start at 0;
   *entry_exact receives the unsnapped start. */
static int reach_windows(const gap_model *m, window win[2], double *entry_exact)
{
  double q0 = m->h0 - fabs(m->a), q1 = m->h1, q2 = m->h2, r[2];
  int n = 0;
  if (q2 < 0.0) { /* floor under gravity: outside the reach only between the roots */
    if (quadratic_roots(q2, q1, q0, r) == 2 && r[0] < r[1] && r[1] >= 0.0) {
      if (r[0] >= 0.0) win[n++] = (window){0.0, r[0]};
      win[n++] = (window){r[1], INFINITY};
    } else {
      win[n++] = (window){0.0, INFINITY};
    }
  } else if (q2 > 0.0) { /* lid under gravity: inside only between the roots */
    if (quadratic_roots(q2, q1, q0, r) == 2 && r[1] >= 0.0)
      win[n++] = (window){r[0] > 0.0 ? r[0] : 0.0, r[1]};
  } else if (q1 > 0.0) { /* no gravity, moving away from the wall */
    double root = -q0 / q1;
    if (root >= 0.0) win[n++] = (window){0.0, root};
  } else if (q1 < 0.0) { /* no gravity, moving towards the wall */
    double root = -q0 / q1;
    win[n++] = (window){root > 0.0 ? root : 0.0, INFINITY};
  } else if (q0 <= 0.0) { /* at rest inside */
    win[n++] = (window){0.0, INFINITY};
  }
  *entry_exact = n > 0 ? win[0].start : 0.0;
  if (n > 0 && win[0].start > 0.0 && q0 <= REACH_SNAP_REL * m->height_scale &&
      (q1 <= 0.0 || q0 <= 0.0))
    win[0].start = 0.0;
  return n;
}

/* ---- walking the pieces -------------------------------------------------------------- */

/* Time of the first piece boundary (critical phase) strictly after tau.
   Loop bound: the start index is at most ncrit positions before the answer. */
static double next_boundary(const gap_model *m, double tau)
{
  double theta = m->theta0 + m->omega * tau;
  double k = floor(theta / WG_TWO_PI) - 1.0;
  for (int j = 0; j < 3 * m->ncrit + 3; j++) {
    double phase = m->crit[j % m->ncrit] + WG_TWO_PI * (k + (double)(j / m->ncrit));
    double t = (phase - m->theta0) / m->omega;
    if (t > tau) return t;
  }
  return tau + m->period / (double)(m->ncrit + 1); /* not reached: phases are < 2 pi apart */
}

/* Search [ta, tb] (tb finite) piece by piece for the first closing crossing; v_start is
   the gap at ta if already known (else NULL).  *armed says
   whether the gap has been positive since the search began (else the particle is still in
   an initial overlap).  Returns 1 with *tau, 0 if none, or -WG_EFAIL.
   Termination: tau advances to the next critical phase (strictly later) or to tb on every
   pass, so there are at most ncrit (omega (tb - ta) / 2 pi + 2) passes. */
static int walk_pieces(const gap_model *m, double ta, double tb, const gap_value *v_start,
                       int *armed, double *tau)
{
  double a = ta;
  gap_value va = v_start ? *v_start : gap_at(m, a);
  if (*armed && va.gap <= 0.0) { /* crossed exactly at a window's start */
    *tau = a;
    return 1;
  }
  while (a < tb) {
    double b = next_boundary(m, a);
    if (b > tb) b = tb;
    gap_value vb = gap_at(m, b);
    double root;
    int rc = WG_OK;
    if (m->st) m->st->pieces++;

    if (!*armed) {
      /* Still in the initial overlap, gap(a) <= 0: the particle was opening so far. */
      if (va.slope < 0.0 || (va.slope == 0.0 && vb.slope < 0.0)) {
        *tau = a; /* closing again while overlapping: overlap rule (App. B.5.6) */
        return 1;
      }
      if (vb.slope >= 0.0) { /* gap increasing through the piece */
        if (vb.gap > 0.0) *armed = 1;
      } else { /* concave, maximum inside: turn round there */
        rc = bracketed_root(m, ROOT_OF_SLOPE, a, b, va.slope, vb.slope, &root);
        gap_value vc = gap_at(m, root);
        if (vc.gap <= 0.0) {
          *tau = root; /* turned round before separating: overlap rule */
          return rc == WG_OK ? 1 : -WG_EFAIL;
        }
        *armed = 1;
        if (vb.gap <= 0.0) {
          rc = bracketed_root(m, ROOT_OF_GAP, root, b, vc.gap, vb.gap, tau);
          return rc == WG_OK ? 1 : -WG_EFAIL;
        }
      }
    } else if (va.slope < 0.0 && vb.slope > 0.0) {
      /* Convex piece with a minimum inside (gap' increasing from - to +). */
      if (vb.gap <= 0.0) {
        rc = bracketed_root(m, ROOT_OF_GAP, a, b, va.gap, vb.gap, tau);
        return rc == WG_OK ? 1 : -WG_EFAIL;
      }
      /* Both ends positive.  A convex gap lies above both end tangents, hence above the
         height at which they intersect: if that is positive the piece is free. */
      double tx = (vb.gap - va.gap - vb.slope * (b - a)) / (va.slope - vb.slope);
      double lower = va.gap + va.slope * tx;
      if (!(lower > GAP_ROUNDOFF_REL * gap_term_scale(m, b))) {
        rc = bracketed_root(m, ROOT_OF_SLOPE, a, b, va.slope, vb.slope, &root);
        gap_value vc = gap_at(m, root);
        if (vc.gap <= 0.0) { /* the particle reaches the wall before the minimum */
          int rc2 = bracketed_root(m, ROOT_OF_GAP, a, root, va.gap, vc.gap, tau);
          return rc == WG_OK && rc2 == WG_OK ? 1 : -WG_EFAIL;
        }
      }
    } else if (vb.gap <= 0.0) {
      /* Monotonic piece, or concave with a maximum inside: {gap > 0} is an initial
         segment [a, root) of the piece, so the crossing in [a, b] is unique. */
      rc = bracketed_root(m, ROOT_OF_GAP, a, b, va.gap, vb.gap, tau);
      return rc == WG_OK ? 1 : -WG_EFAIL;
    }
    if (rc != WG_OK) return -WG_EFAIL;
    a = b;
    va = vb;
  }
  return 0;
}

/* ---- public interface ---------------------------------------------------------------- */

double wg_wall_position(const wg_wall *w, double t)
{
  if (w->A == 0.0 || !(w->omega > 0.0)) return w->c;
  return w->c + w->A * sin(reduced_phase(w->omega, t));
}

double wg_wall_velocity(const wg_wall *w, double t)
{
  if (w->A == 0.0 || !(w->omega > 0.0)) return 0.0;
  return w->A * w->omega * cos(reduced_phase(w->omega, t));
}

/* Acceleration of the wall at absolute time t. */
double wg_wall_acceleration(const wg_wall *w, double t)
{
  if (w->A == 0.0 || !(w->omega > 0.0)) return 0.0;
  return -w->A * w->omega * w->omega * sin(reduced_phase(w->omega, t));
}

/* The first time after t at which the wall's phase is theta (mod 2 pi): t itself counts only
   when strictly later phases are meant, i.e. never (a phase equal to now is a full period
   ahead). */
static double next_phase_time(const wg_wall *w, double t, double theta)
{
  double d = theta - reduced_phase(w->omega, t);
  if (d <= 0.0) d += WG_TWO_PI;
  return t + d / w->omega;
}

double wg_wall_lift_off_time(const wg_wall *w, double g, double t)
{
  if (w->A == 0.0 || !(w->omega > 0.0) || w->side < 0) return INFINITY;
  double inv_gamma = g / (w->A * w->omega * w->omega);
  if (!(inv_gamma < 1.0)) return INFINITY; /* Gamma <= 1: the floor never falls faster than g */
  return next_phase_time(w, t, asin(inv_gamma)); /* a_w = -g, falling: sin rising through 1/Gamma */
}

double wg_wall_level_time(const wg_wall *w, double t, double level, int rising)
{
  if (w->A == 0.0 || !(w->omega > 0.0)) return INFINITY;
  double s = (level - w->c) / w->A;
  if (!(fabs(s) <= 1.0)) return INFINITY;
  double theta = asin(s); /* the rising passage; the falling one is at pi - theta */
  if (!rising) theta = WG_PI - theta;
  if (theta < 0.0) theta += WG_TWO_PI;
  return next_phase_time(w, t, theta);
}

/* Reports a failed root search (unreachable by the iteration bound above) and keeps the
   conservative estimate: the bracket end on the closing side. */
static int report_failure(const char *where)
{
  wg_error(WG_EFAIL, where, "root bracket did not converge within %d iterations",
           ROOT_MAX_ITER);
  return 1;
}

int wg_wall_first_root(const wg_wall *w, const wg_ballistic *p, double tau_max, double *tau,
                       wg_wall_stats *st)
{
  gap_model m;
  window win[2];
  double entry;
  if (st) st->calls++;
  if (!(tau_max >= 0.0)) return 0;
  model_init(&m, w, p, st);
  if (m.is_static) {
    double t;
    if (static_first_root(&m, &t) && t <= tau_max) {
      *tau = t;
      return 1;
    }
    return 0;
  }
  gap_value v0 = gap_at(&m, 0.0);
  if (v0.gap <= 0.0 && is_closing(v0)) {
    *tau = 0.0;
    return 1;
  }
  int armed = clear_of_wall(&m, v0);
  int n = reach_windows(&m, win, &entry);
  /* At most two windows; outside them gap >= q > 0, so the gap is positive on entry. */
  for (int i = 0; i < n; i++) {
    double s = win[i].start, e = win[i].end;
    if (s > tau_max) break;
    if (i > 0) armed = 1;
    if (isinf(e)) e = (i == 0 ? entry : s) + REACH_SEARCH_PERIODS * m.period;
    if (e > tau_max) e = tau_max;
    int rc = walk_pieces(&m, s, e, s == 0.0 ? &v0 : NULL, &armed, tau);
    if (rc < 0) return report_failure("wg_wall_first_root");
    if (rc > 0) return 1;
  }
  return 0;
}

wg_wall_outcome wg_wall_next_event(const wg_wall *w, const wg_ballistic *p, double *tau,
                                   wg_wall_stats *st)
{
  gap_model m;
  window win[2];
  double entry;
  if (st) st->calls++;
  model_particle(&m, w, p, st);
  if (m.is_static) /* the reach is the wall itself: entering it is the contact */
    return static_first_root(&m, tau) ? WG_WALL_HIT : WG_WALL_NONE;
  if (m.h0 - fabs(m.a) > 0.0) {
    /* Outside the reach now (so gap > 0, no contact at tau = 0): the answer is the reach's
       entry time or none, a quadratic's root; most calls end here, without the phase's
       trigonometry. */
    int n = reach_windows(&m, win, &entry);
    if (n == 0) return WG_WALL_NONE;
    if (win[0].start > 0.0) {
      *tau = win[0].start;
      return WG_WALL_ENTER;
    }
  }
  model_phase(&m, w, p);
  gap_value v0 = gap_at(&m, 0.0);
  if (v0.gap <= 0.0 && is_closing(v0)) {
    *tau = 0.0;
    return WG_WALL_HIT;
  }
  int armed = clear_of_wall(&m, v0);
  int n = reach_windows(&m, win, &entry);
  if (n == 0) return WG_WALL_NONE;
  if (win[0].start > 0.0) { /* outside the reach: only the analytic entry time */
    *tau = win[0].start;
    return WG_WALL_ENTER;
  }
  /* Inside: a contact is certain within one period of the entry if the particle stays
     inside, so the exact search never runs past that or the exit time. */
  double end = entry + m.period;
  if (win[0].end < end) end = win[0].end;
  int rc = walk_pieces(&m, 0.0, end, &v0, &armed, tau);
  if (rc < 0) {
    report_failure("wg_wall_next_event");
    return WG_WALL_HIT;
  }
  if (rc > 0) return WG_WALL_HIT;
  if (end < win[0].end) {
    /* Still inside after a full period without a crossing: only possible when round-off
       hides a grazing touch at the wall's extreme.  Ask to be called again then. */
    *tau = end;
    return WG_WALL_ENTER;
  }
  if (n > 1) {
    *tau = win[1].start;
    return WG_WALL_ENTER;
  }
  return WG_WALL_NONE;
}

int wg_wall_first_root_scan(const wg_wall *w, const wg_ballistic *p, double dt_scan,
                            double tau_max, double *tau, wg_wall_stats *st)
{
  gap_model m;
  if (st) st->calls++;
  if (!(dt_scan > 0.0) || !(tau_max >= 0.0) || !(tau_max / dt_scan < 0x1p52)) {
    wg_error(WG_EINVAL, "wg_wall_first_root_scan", "need dt_scan > 0 and finite tau_max");
    return 0;
  }
  model_init(&m, w, p, st);
  gap_value v = gap_at(&m, 0.0);
  if (v.gap <= 0.0 && is_closing(v)) { /* overlap rule (App. B.5.6) */
    *tau = 0.0;
    return 1;
  }
  int armed = v.gap > 0.0; /* overlapping and opening: wait until separated */
  double t_prev = 0.0, g_prev = v.gap;
  /* App. B.3.2: test tau = k t_min, k = 1, 2, ... for a change of sign.
     Loop bound: k <= tau_max / dt_scan + 1 < 2^52, checked above. */
  for (double k = 1.0;; k += 1.0) {
    double t = k * dt_scan;
    if (t > tau_max) break;
    v = gap_at(&m, t);
    if (armed && g_prev > 0.0 && v.gap <= 0.0) {
      if (bracketed_root(&m, ROOT_OF_GAP, t_prev, t, g_prev, v.gap, tau) != WG_OK)
        return report_failure("wg_wall_first_root_scan");
      return 1;
    }
    if (v.gap > 0.0) armed = 1;
    t_prev = t;
    g_prev = v.gap;
  }
  return 0;
}
