/* wetgran-orderparam: order parameters and phase label of shaken runs (thesis App. 3.A).
   One row per run file: the stationary T_g / E_cb with its error, the lateral contrasts
   Delta n_cb and Delta n_area (Eq. 3.3), the temperatures of the densest and most dilute
   parts, and a label s, f, g, sfc, sgc or fgc.  --calibrate derives the label thresholds
   from the runs given (Otsu's criterion on their distributions). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io_h5.h"
#include "run_open.h"

#define BLOCKS 10            /* blocks for the error of time averages */
#define DRIFT_SIGMAS 3.0     /* a window drifting by more than this many errors ... */
#define DRIFT_REL 0.05       /* ... and by more than 5 % is not stationary, */
#define DRIFT_GROSS 0.5      /* nor is one whose halves differ by more than half */
#define QUINTILE 0.2         /* densest / most dilute fraction of the bins */
#define MSER_BATCH 5         /* MSER-5: the warm-up rule works on means of 5 samples */
#define WARMUP_IN_WINDOW 0.1 /* a window may begin this fraction of its length before the
                                warm-up's end: so short a tail of it barely moves the mean */

typedef struct thresholds {
  double t_sf;   /* T_g / E_cb below which a region is solid */
  double t_fg;   /* T_g / E_cb above which a region is a gas */
  double dn;     /* contrast above which phases coexist: Delta n_cb (wet) or Delta n_area
                    (dry), or with 'relative' Delta n_area over the largest packing fraction */
  int relative;  /* --relative-contrast */
} thresholds;

/* Defaults, used without --calibrate: the order of magnitude of the cuts that --calibrate
   finds on the elastic 2D sweep of experiments/fig3_4a (fluid below ~10 E_cb, gas above;
   coexistence when n_cb varies by more than ~1 bridge per d).  A solid is a state whose
   random motion is small against E_cb (App. 3.A.1.1): below 1e-2 E_cb. */
static const thresholds default_thresholds = {1e-2, 12.0, 1.0, 0};
/* --relative-contrast without --calibrate: a dilute region below half the densest one's
   packing fraction (the full fig3_4a and fig3_9 sweeps: homogeneous below 0.47, coexisting
   above 0.60) */
#define DEFAULT_RELATIVE_DN 0.5

typedef struct row {
  const char *file;
  double gamma, estar, estar_d, e_cb, eps, s_crit;
  double t0, t1, drift;
  double t_settle;  /* where T_g's warm-up ends (MSER-5), NAN: not within the run's first half */
  int stationary;
  double tg, tg_err, tg_dense, tg_dilute, dn_cb, dn_area;
  double rel_contrast; /* Delta n_area over the largest packing fraction of the profile */
  int has_profiles;
  double t_fg;   /* the fluid-gas cut of this run's scan (--per-scan), NAN: the global one */
  double tg_chain; /* the median T_g / E_cb of its chain (--per-scan, scan_chains), NAN: none */
  char label[4];
} row;

/* The parameter key of the run (a number, or a number as text in old files); a missing one is
   added to 'missing' (reported by the caller, in one line for all of them). */
static int param(hid_t f, const char *key, double *v, char *missing, size_t len)
{
  if (H5Aexists_by_name(f, "/parameters", key, H5P_DEFAULT) <= 0) {
    size_t k = strlen(missing);
    snprintf(missing + k, len - k, "%s%s", k ? ", " : "", key);
    return WG_EINVAL;
  }
  return wg_h5_read_param_double(f, key, v);
}

static double *read_1d(hid_t f, const char *path, const char *name, size_t *n)
{
  int rank;
  hsize_t dims[8];
  if (wg_h5_dims(f, name, &rank, dims) != WG_OK) return NULL;
  *n = dims[0];
  double *x = malloc(sizeof *x * (dims[0] ? dims[0] : 1));
  if (x && wg_h5_read(f, name, H5T_NATIVE_DOUBLE, x) != WG_OK) {
    free(x);
    x = NULL;
  }
  if (!x) wg_error(WG_EIO, path, "cannot read %s", name);
  return x;
}

/* Mean of v over samples with t in [t0, t1], its error from BLOCKS block means, and the
   means of the first and second half of the window. */
static void window_mean(const double *t, const double *v, size_t n, double t0, double t1,
                        double *mean, double *err, double *first, double *second)
{
  size_t a = 0, b;
  while (a < n && t[a] < t0) a++;
  b = a;
  while (b < n && t[b] <= t1) b++;
  size_t m = b - a;
  *mean = *err = *first = *second = NAN;
  if (m == 0) return;
  double s = 0;
  for (size_t k = a; k < b; k++) s += v[k];
  *mean = s / m;
  double h1 = 0, h2 = 0;
  for (size_t k = a; k < a + m / 2; k++) h1 += v[k];
  for (size_t k = a + m / 2; k < b; k++) h2 += v[k];
  *first = m / 2 ? h1 / (m / 2) : *mean;
  *second = h2 / (m - m / 2);
  if (m < 2 * BLOCKS) return;
  double bm[BLOCKS], bs = 0, bs2 = 0;
  size_t len = m / BLOCKS;
  for (int k = 0; k < BLOCKS; k++) {
    double x = 0;
    for (size_t j = 0; j < len; j++) x += v[a + k * len + j];
    bm[k] = x / len;
    bs += bm[k];
    bs2 += bm[k] * bm[k];
  }
  double var = (bs2 - bs * bs / BLOCKS) / (BLOCKS - 1);
  *err = var > 0 ? sqrt(var / BLOCKS) : 0;
}

/* The end of the warm-up of a series (MSER-5; White, Simulation 69, 323 (1997)): over the
   means z_j of batches of MSER_BATCH samples, the truncation d that minimises the squared
   standard error of the truncated mean, sum_{j>=d} (z_j - zbar_d)^2 / (m - d)^2, searched over
   the first half of the batches.  A minimum at the end of that half means the series has not
   settled (still relaxing or drifting); NAN then.  Returns the time of the first sample kept. */
static double mser_settle(const double *t, const double *v, size_t n)
{
  size_t m = n / MSER_BATCH;
  if (m < 4) return NAN;
  double *z = malloc(sizeof *z * m);
  if (!z) return NAN;
  for (size_t j = 0; j < m; j++) {
    double x = 0;
    for (size_t k = 0; k < MSER_BATCH; k++) x += v[j * MSER_BATCH + k];
    z[j] = x / MSER_BATCH;
  }
  /* suffix sums, from the end backwards: S1 = sum z, S2 = sum z^2 over j >= d */
  size_t half = m / 2, best = 0;
  double s1 = 0, s2 = 0, best_se = INFINITY;
  for (size_t j = m; j-- > half + 1;) {
    s1 += z[j];
    s2 += z[j] * z[j];
  }
  for (size_t d = half + 1; d-- > 0;) {
    s1 += z[d];
    s2 += z[d] * z[d];
    double k = (double)(m - d);
    double se = (s2 - s1 * s1 / k) / (k * k);
    if (se <= best_se) {
      best_se = se;
      best = d;
    }
  }
  free(z);
  return best >= half ? NAN : t[best * MSER_BATCH];
}

/* Average of y over the bins whose key lies in the top (top = 1) or bottom quintile. */
static double quintile_mean(const double *key, const double *y, size_t n, int top)
{
  double *sorted = malloc(sizeof *sorted * n);
  if (!sorted) return NAN;
  memcpy(sorted, key, sizeof *sorted * n);
  for (size_t i = 1; i < n; i++) /* insertion sort: n is a few hundred bins */
    for (size_t j = i; j > 0 && sorted[j - 1] > sorted[j]; j--) {
      double x = sorted[j];
      sorted[j] = sorted[j - 1];
      sorted[j - 1] = x;
    }
  size_t k = (size_t)(QUINTILE * n);
  if (k < 1) k = 1;
  double cut = top ? sorted[n - k] : sorted[k - 1];
  free(sorted);
  double s = 0;
  int c = 0;
  for (size_t i = 0; i < n; i++)
    if ((top && key[i] >= cut) || (!top && key[i] <= cut)) {
      if (isfinite(y[i])) {
        s += y[i];
        c++;
      }
    }
  return c ? s / c : NAN;
}

static double range_of(const double *x, size_t n)
{
  double lo = INFINITY, hi = -INFINITY;
  for (size_t i = 0; i < n; i++) {
    if (x[i] < lo) lo = x[i];
    if (x[i] > hi) hi = x[i];
  }
  return n ? hi - lo : NAN;
}

static double max_of(const double *x, size_t n)
{
  double hi = -INFINITY;
  for (size_t i = 0; i < n; i++)
    if (x[i] > hi) hi = x[i];
  return n ? hi : NAN;
}

/* The contrast the labels cut: Eq. 3.3's Delta n_cb (wet) or Delta n_area (dry), or with
   th->relative Delta n_area over the profile's largest packing fraction.  A dilute region
   beside a dense one makes that ratio large however dense the dense part is and however
   many bridges it holds, while a homogeneous state's ratio is its noise, small even for a
   dilute gas (the packing fraction is well sampled where bridges are rare).  Delta n_cb
   itself grows with the bridge density of the dense part: in the full fig3_9 sweep solids
   at Gamma = 1.2 reach 1.9 from noise while the inelastic coexistence at Gamma >= 8 starts
   at 2.0 and that of Gamma = 1.2 at 8, so no one cut of Delta n_cb tells them apart; the
   ratio lies below 0.45 (homogeneous) or above 0.69 (coexisting) there, below 0.10 or
   above 0.64 over the 129 runs of the full fig3_4a sweep. */
static double contrast(const row *r, const thresholds *th)
{
  if (th->relative) return r->rel_contrast;
  return r->e_cb > 0 ? r->dn_cb : r->dn_area;
}

static int measure(const char *path, row *r)
{
  memset(r, 0, sizeof *r);
  r->t_fg = r->tg_chain = NAN;
  r->file = path;
  hid_t f = wg_run_open(path);
  if (f < 0) return WG_EIO;
  int st = WG_OK;
  double t_end, profile_start;
  char missing[256] = "";
  if (!wg_h5_exists(f, "/parameters")) snprintf(missing, sizeof missing, "the group /parameters");
  else {
    st |= param(f, "gamma", &r->gamma, missing, sizeof missing);
    st |= param(f, "estar", &r->estar, missing, sizeof missing);
    st |= param(f, "estar_d", &r->estar_d, missing, sizeof missing);
    st |= param(f, "e_cb", &r->e_cb, missing, sizeof missing);
    st |= param(f, "eps", &r->eps, missing, sizeof missing);
    st |= param(f, "s_crit", &r->s_crit, missing, sizeof missing);
    st |= param(f, "t_end", &t_end, missing, sizeof missing);
    st |= param(f, "profile_start", &profile_start, missing, sizeof missing);
  }
  if (missing[0]) {
    wg_h5_close(f);
    return wg_error(WG_EINVAL, path, "not a shaker run of wetgran-run (no parameter %s)", missing);
  }
  if (st != WG_OK || !wg_h5_exists(f, "/observables/temperature/value")) {
    wg_h5_close(f);
    return st != WG_OK ? st : wg_error(WG_EINVAL, path, "no T_g series (/observables/temperature missing)");
  }
  size_t n, nv;
  double *t = read_1d(f, path, "/observables/temperature/time", &n);
  double *v = read_1d(f, path, "/observables/temperature/value", &nv);
  if (!t || !v || n != nv) {
    free(t);
    free(v);
    wg_h5_close(f);
    return WG_EIO;
  }
  r->t0 = profile_start;
  r->t1 = t_end;
  double first, second;
  window_mean(t, v, n, r->t0, r->t1, &r->tg, &r->tg_err, &first, &second);
  r->t_settle = mser_settle(t, v, n);
  free(t);
  free(v);
  double scale = r->e_cb > 0 ? r->e_cb : 1;
  r->tg /= scale;
  r->tg_err /= scale;
  double half_err = isfinite(r->tg_err) ? r->tg_err * sqrt(2.0) * scale : 0;
  r->drift = (second - first) / (0.5 * (first + second));
  int drifting = (fabs(second - first) > DRIFT_SIGMAS * half_err && fabs(r->drift) > DRIFT_REL) ||
                 fabs(r->drift) > DRIFT_GROSS;
  /* the window must also lie in the stationary part: after the warm-up has ended */
  r->stationary = !drifting && isfinite(r->t_settle) &&
                  r->t_settle <= r->t0 + WARMUP_IN_WINDOW * (r->t1 - r->t0);

  r->has_profiles = wg_h5_exists(f, "/observables/profiles/x");
  r->tg_dense = r->tg_dilute = r->dn_cb = r->dn_area = r->rel_contrast = NAN;
  if (r->has_profiles) {
    size_t b1, b2, b3;
    double *pf = read_1d(f, path, "/observables/profiles/packing_fraction", &b1);
    double *tb = read_1d(f, path, "/observables/profiles/temperature", &b2);
    double *nc = read_1d(f, path, "/observables/profiles/bridge_density", &b3);
    if (pf && tb && nc && b1 == b2 && b2 == b3) {
      r->dn_cb = range_of(nc, b3);     /* Eq. 3.3 */
      r->dn_area = range_of(pf, b1);
      double top = max_of(pf, b1);
      r->rel_contrast = top > 0 ? r->dn_area / top : 0;
      r->tg_dense = quintile_mean(pf, tb, b1, 1) / scale;
      r->tg_dilute = quintile_mean(pf, tb, b1, 0) / scale;
    } else {
      st = WG_EIO;
    }
    free(pf);
    free(tb);
    free(nc);
  }
  wg_h5_close(f);
  return st;
}

static const char *region(double tg, double t_fg, const thresholds *th)
{
  return tg < th->t_sf ? "s" : tg > t_fg ? "g" : "f";
}

/* Homogeneous: the whole sample's T_g decides.  Coexisting (contrast above dn): the densest
   and the most dilute fifth of the lateral bins are classified separately. */
static void label(row *r, const thresholds *th)
{
  double t_fg = isfinite(r->t_fg) ? r->t_fg : th->t_fg;
  if (!r->has_profiles) { /* no contrasts: homogeneous or coexisting cannot be told */
    snprintf(r->label, sizeof r->label, "n/a");
    return;
  }
  if (r->has_profiles && contrast(r, th) > th->dn) {
    const char *a = region(r->tg_dense, t_fg, th), *b = region(r->tg_dilute, t_fg, th);
    if (strcmp(a, b) != 0) {
      snprintf(r->label, sizeof r->label, "%s%sc", a, b);
      return;
    }
  }
  if (isfinite(r->tg_chain) && !(r->tg < th->t_sf)) { /* scan_chains */
    snprintf(r->label, sizeof r->label, "%s", region(r->tg_chain, t_fg, th));
    return;
  }
  snprintf(r->label, sizeof r->label, "%s", region(r->tg, t_fg, th));
}

/* Otsu: the cut of sorted x[0..n-1] into classes [0, k) and [k, n) with the largest
   between-class variance; returns the midpoint between x[k-1] and x[k]. */
static double otsu_two(const double *x, size_t n)
{
  double best = -1, cut = NAN, total = 0;
  for (size_t i = 0; i < n; i++) total += x[i];
  double left = 0;
  for (size_t k = 1; k < n; k++) {
    left += x[k - 1];
    double m1 = left / k, m2 = (total - left) / (n - k);
    double between = (double)k * (n - k) * (m1 - m2) * (m1 - m2);
    if (between > best && x[k] > x[k - 1]) {
      best = between;
      cut = 0.5 * (x[k - 1] + x[k]);
    }
  }
  return cut;
}

/* Otsu's cut moved to the widest gap between neighbouring sorted values that lies between
   the two classes' means (a natural break).  Otsu alone follows the classes' masses: a tail
   of runs near one transition (fluids at E* just below the f-fgc line, whose dilute part is
   already somewhat hotter) pulls it into that tail, while the widest empty interval between
   the classes is where the sweep really separates. */
static double widest_gap_cut(const double *x, size_t n, double otsu)
{
  size_t k = 0;
  while (k < n && x[k] < otsu) k++;
  if (k == 0 || k == n) return otsu;
  double lo = 0, hi = 0;
  for (size_t i = 0; i < k; i++) lo += x[i];
  for (size_t i = k; i < n; i++) hi += x[i];
  lo /= k;
  hi /= n - k;
  double best = x[k] - x[k - 1], cut = otsu;
  for (size_t i = 0; i + 1 < n; i++)
    if (x[i] >= lo && x[i + 1] <= hi && x[i + 1] - x[i] > best) {
      best = x[i + 1] - x[i];
      cut = 0.5 * (x[i] + x[i + 1]);
    }
  return cut;
}

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static double mean_of(const double *x, size_t n)
{
  double s = 0;
  for (size_t i = 0; i < n; i++) s += x[i];
  return n ? s / n : NAN;
}

/* The relative contrast's cut: the middle of the empty interval of the sweep's sorted
   contrasts x[0..n-1] that holds 1/2, a dilute part half as dense as the dense one.  The
   sweeps' contrasts form two classes, homogeneous (below 0.18 over the 117 runs of the full
   fig3_9 sweep, below 0.10 over the 129 of fig3_4a) and coexisting (above 0.55 and 0.64),
   with a sparse tail between them: fluids just before the f-fgc line whose dilute part is
   somewhat hotter (0.27-0.47 in fig3_9).  Otsu's cut and the widest gap between the class
   means fall on either side of that tail as a sweep fills (0.41 and 0.53 at 60 runs of
   fig3_9, 0.23 at 117); the empty interval around 1/2 (0.47-0.55, 0.10-0.64) does not move. */
#define HALF_DENSITY 0.5
static double half_density_cut(const double *x, size_t n)
{
  double lo = 0, hi = 1;
  for (size_t i = 0; i < n; i++) {
    if (x[i] <= HALF_DENSITY && x[i] > lo) lo = x[i];
    if (x[i] > HALF_DENSITY && x[i] < hi) hi = x[i];
  }
  return 0.5 * (lo + hi);
}

/* Thresholds from the runs (a sweep):
   1. dn: Otsu's two-class cut of the lateral contrasts (homogeneous | coexisting), moved
      to the widest gap between the two classes' means (widest_gap_cut); with
      --relative-contrast the middle of the empty interval around 1/2 (half_density_cut).
   2. t_fg: Otsu's cut of log10(T_g/E_cb) over the homogeneous runs: the jump between fluid
      and gas (Fig. 3.28b).
   3. t_sf: Otsu's cut within the colder class, kept only if its two sub-classes differ by
      more than SOLID_DECADES in mean log T (a solid is far colder than a fluid); otherwise
      the sweep holds no solid and the default stays.
   Each step reports the classes it found on stderr, so the choice can be checked.  A threshold
   given on the command line (bit in 'given': 1 t_sf, 2 t_fg, 4 dn) is kept and used by the
   later steps.  With LOG_CONTRAST the contrasts are cut on a log scale: a scan through a
   coexistence band whose contrasts span decades (Fig. 3.17), where the linear cut would
   follow the largest values only. */
#define SOLID_DECADES 1.0
/* Otsu's two classes of log T_g must lie more than this apart to be fluid and gas: the full
   archived sweeps separate by 1.05-2.93 decades, the rows of fig3_10 by 0.60-0.63, while seven
   fluids at T_g/E_cb 0.59-1.15 (one phase) split into classes 0.2 decades apart */
#define ONE_PHASE_DECADES 0.5
#define MIN_RUNS_CONTRAST 4 /* fewer runs cannot show two classes of contrast */
enum { GIVEN_T_SF = 1, GIVEN_T_FG = 2, GIVEN_DN = 4, LOG_CONTRAST = 8 };
static void calibrate(const row *rows, size_t n, thresholds *th, int given)
{
  double *lt = malloc(sizeof *lt * n), *dn = malloc(sizeof *dn * n);
  size_t nt = 0, nd = 0;
  if (!lt || !dn) {
    free(lt);
    free(dn);
    return;
  }
  for (size_t i = 0; i < n; i++) {
    double c = contrast(&rows[i], th);
    if (isfinite(c) && (!(given & LOG_CONTRAST) || c > 0)) dn[nd++] = (given & LOG_CONTRAST) ? log10(c) : c;
  }
  if (nd >= MIN_RUNS_CONTRAST && !(given & GIVEN_DN)) {
    qsort(dn, nd, sizeof *dn, cmp_double);
    double c = th->relative ? half_density_cut(dn, nd) : otsu_two(dn, nd);
    if (isfinite(c) && !th->relative) c = widest_gap_cut(dn, nd, c);
    if (isfinite(c)) th->dn = (given & LOG_CONTRAST) ? pow(10, c) : c;
  }
  for (size_t i = 0; i < n; i++) {
    double c = contrast(&rows[i], th);
    if (rows[i].has_profiles && rows[i].tg > 0 && !(c > th->dn)) lt[nt++] = log10(rows[i].tg);
  }
  qsort(lt, nt, sizeof *lt, cmp_double);
  double cut = nt >= 2 ? otsu_two(lt, nt) : NAN;
  if (isfinite(cut) && !(given & GIVEN_T_FG)) {
    /* Otsu always finds two classes; they are fluid and gas only if T_g jumps between them */
    size_t k = 0;
    while (k < nt && lt[k] < cut) k++;
    double apart = mean_of(lt + k, nt - k) - mean_of(lt, k);
    if (!(apart > ONE_PHASE_DECADES)) {
      double med = nt % 2 ? lt[nt / 2] : 0.5 * (lt[nt / 2 - 1] + lt[nt / 2]);
      int gas = med > log10(th->t_fg);
      /* no boundary is drawn: the given or default t_fg stays if all lie on one side of it,
         else it moves half a decade beyond the hottest (fluid) or the coldest (gas) run */
      if (!gas && lt[nt - 1] >= log10(th->t_fg)) th->t_fg = pow(10, lt[nt - 1] + ONE_PHASE_DECADES);
      if (gas && lt[0] <= log10(th->t_fg)) th->t_fg = pow(10, lt[0] - ONE_PHASE_DECADES);
      fprintf(stderr, "calibrate: contrast cut dn = %.4g; the %zu homogeneous runs are not separated "
              "into fluid and gas (T_g %.4g-%.4g %s; Otsu's classes %.3g decades apart, not more "
              "than %g): one phase, %s (t_fg = %.4g)\n", th->dn, nt, pow(10, lt[0]),
              pow(10, lt[nt - 1]), rows[0].e_cb > 0 ? "E_cb" : "m g d", apart, ONE_PHASE_DECADES,
              gas ? "gas" : "fluid", th->t_fg);
      cut = NAN;
    }
  }
  if (isfinite(cut) && (given & GIVEN_T_FG)) {
    fprintf(stderr, "calibrate: contrast cut dn = %.4g; t_fg = %.4g and t_sf = %.4g %s\n", th->dn,
            th->t_fg, th->t_sf, (given & GIVEN_T_SF) ? "as given" : "(t_fg as given)");
  } else if (isfinite(cut)) {
    th->t_fg = pow(10, cut);
    size_t k = 0;
    while (k < nt && lt[k] < cut) k++;
    fprintf(stderr, "calibrate: contrast cut dn = %.4g; homogeneous runs: %zu below T_g/E_cb = %.4g "
            "(mean log10 %.3f), %zu above (mean log10 %.3f)\n", th->dn, k, th->t_fg,
            mean_of(lt, k), nt - k, mean_of(lt + k, nt - k));
    double sub = k >= 2 ? otsu_two(lt, k) : NAN;
    if (isfinite(sub)) {
      size_t j = 0;
      while (j < k && lt[j] < sub) j++;
      double gap = mean_of(lt + j, k - j) - mean_of(lt, j);
      if (gap > SOLID_DECADES && !(given & GIVEN_T_SF)) th->t_sf = pow(10, sub);
      fprintf(stderr, "calibrate: colder class splits at %.4g into means %.3g decades apart: %s\n",
              pow(10, sub), gap, gap > SOLID_DECADES ? "solid and fluid" : "no solid in this sweep");
    }
  }
  free(lt);
  free(dn);
}

/* The fluid-gas cut per scan (--per-scan).  The thesis reads the fluid-gas transition as the
   jump of T_g along a scan in E* at fixed Gamma (Fig. 3.28b).  One cut for a whole sweep fails
   when the gas temperature itself moves by decades with Gamma (T_g/E_cb of the gas is ~50 at
   Gamma = 10 and ~2000 at 80 for F_B = 16 mg): Otsu then splits cool gases from hot ones.  So
   each scan -- the runs sharing Gamma, E_cb, eps and s_crit -- gets its own cut of log T_g
   among its samples: the homogeneous runs' T_g and, from each coexisting run, the densest and
   the most dilute fifth's T_g (one fluid and one gas sample at that Gamma); samples below t_sf
   (solids) are left out.  With fluid-gas coexistence in the scan the cut lies in the widest
   gap between neighbouring samples within fluid_gas_interval(): the coexisting runs show both
   phases at this Gamma, and the homogeneous gases can be decades hotter than their dilute
   parts (6000-90000 E_cb against 140-420 at F_B = m g), so a cut between classes of all
   samples could fall among gases.  Else it is Otsu's cut, kept when the samples either side
   lie more than JUMP_DECADES apart (a jump, not a spread).  A scan without a cut (all fluid
   or all gas) takes the cut of the nearest scan in log Gamma with the same E_cb, eps and
   s_crit, and else the global cut. */
/* 0.5: more than a fluid's T_g grows when E* doubles (0.42 decades at F_B = 4 mg, quick
   fig3_4a); the elastic scans jump by 0.6-2 decades, those at eps = 0.96 by 0.4-0.65. */
#define JUMP_DECADES 0.5
/* The dense and the dilute parts of coexisting runs show both phases at this Gamma, so a gap
   between them needs less: 0.4 decades (inelastic quick scans, fig3_9 at Gamma = 8 and 15:
   0.41-0.45 from the dense parts to the dilute ones). */
#define JUMP_COEX_DECADES 0.4
static int same_scan(const row *a, const row *b)
{
  return a->gamma == b->gamma && a->e_cb == b->e_cb && a->eps == b->eps && a->s_crit == b->s_crit;
}

static int same_family(const row *a, const row *b)
{
  return a->e_cb == b->e_cb && a->eps == b->eps && a->s_crit == b->s_crit;
}

/* The interval of log T_g that a scan's fluid-gas cut must lie in: above the dense (fluid)
   parts and below the dilute (gas) parts of its coexisting runs.  A run whose contrast is a
   density variation within one phase breaks it: at Gamma = 8, E* = 4.5 (full fig3_9) a gas
   with dense part 26 E_cb and dilute part 93, hotter than the dilute parts of the coexistence
   at E* = 1.8-2.7 (20-27; their dense parts 2.8-4.4).  While the hottest dense part is not
   below the coldest dilute part, the one of these two runs whose parts differ less in T_g is
   left out.  Returns 0 if no coexisting run is left. */
static int fluid_gas_interval(const row *rows, size_t n, size_t scan, const thresholds *th, double *fluid,
                              double *gas)
{
  char *out = calloc(n ? n : 1, 1);
  if (!out) return 0;
  for (;;) {
    size_t hot = n, cold = n;
    for (size_t j = 0; j < n; j++) {
      const row *r = &rows[j];
      if (out[j] || !same_scan(r, &rows[scan]) || !r->has_profiles || !(contrast(r, th) > th->dn) ||
          !(r->tg_dense > th->t_sf))
        continue;
      if (hot == n || r->tg_dense > rows[hot].tg_dense) hot = j;
      if (cold == n || r->tg_dilute < rows[cold].tg_dilute) cold = j;
    }
    if (hot == n) {
      free(out);
      return 0;
    }
    if (rows[hot].tg_dense < rows[cold].tg_dilute) {
      *fluid = log10(rows[hot].tg_dense);
      *gas = log10(rows[cold].tg_dilute);
      free(out);
      return 1;
    }
    double r_hot = rows[hot].tg_dilute / rows[hot].tg_dense, r_cold = rows[cold].tg_dilute / rows[cold].tg_dense;
    out[r_hot < r_cold ? hot : cold] = 1;
  }
}

static void calibrate_per_scan(row *rows, size_t n, const thresholds *th, int report)
{
  double *lt = malloc(sizeof *lt * 3 * (n ? n : 1));
  double *cut = malloc(sizeof *cut * (n ? n : 1)), *jump = malloc(sizeof *jump * (n ? n : 1));
  if (!lt || !cut || !jump) {
    free(lt);
    free(cut);
    free(jump);
    return;
  }
  for (size_t i = 0; i < n; i++) { /* cut[i]: the own cut of run i's scan, NAN if none */
    cut[i] = jump[i] = NAN;
    size_t first = 0;
    while (!same_scan(&rows[first], &rows[i])) first++;
    if (first < i) {
      cut[i] = cut[first];
      jump[i] = jump[first];
      continue;
    }
    size_t m = 0;
    for (size_t j = i; j < n; j++) {
      const row *r = &rows[j];
      if (!same_scan(r, &rows[i]) || !r->has_profiles) continue;
      double t[2] = {r->tg, NAN};
      if (r->has_profiles && contrast(r, th) > th->dn) {
        t[0] = r->tg_dense;
        t[1] = r->tg_dilute;
      }
      for (int k = 0; k < 2; k++)
        if (t[k] > th->t_sf) lt[m++] = log10(t[k]);
    }
    qsort(lt, m, sizeof *lt, cmp_double);
    double fluid, gas, c = NAN, need = JUMP_DECADES;
    size_t k = 0;
    if (fluid_gas_interval(rows, n, i, th, &fluid, &gas)) {
      /* the widest gap between neighbouring samples within [fluid, gas] */
      double best = -1;
      for (size_t a = 0; a + 1 < m; a++)
        if (lt[a] >= fluid && lt[a + 1] <= gas && lt[a + 1] - lt[a] > best) {
          best = lt[a + 1] - lt[a];
          c = 0.5 * (lt[a] + lt[a + 1]);
          k = a + 1;
        }
      need = JUMP_COEX_DECADES;
    } else {
      c = m >= 2 ? otsu_two(lt, m) : NAN;
      while (k < m && lt[k] < c) k++;
    }
    if (isfinite(c) && k > 0 && k < m) jump[i] = lt[k] - lt[k - 1];
    if (jump[i] > need) cut[i] = c;
  }
  for (size_t i = 0; i < n; i++) {
    rows[i].t_fg = isfinite(cut[i]) ? pow(10, cut[i]) : NAN;
    double best = INFINITY;
    for (size_t j = 0; !isfinite(cut[i]) && j < n; j++) {
      double d = fabs(log(rows[j].gamma / rows[i].gamma));
      if (isfinite(cut[j]) && same_family(&rows[i], &rows[j]) && d < best) {
        best = d;
        rows[i].t_fg = pow(10, cut[j]);
      }
    }
    size_t first = 0;
    while (!same_scan(&rows[first], &rows[i])) first++;
    if (first == i && report)
      fprintf(stderr, "calibrate: scan Gamma = %g, E_cb = %g, eps = %g, s_crit = %g: t_fg = %.4g (%s; "
              "its cut lies in a gap of %.2f decades)\n",
              rows[i].gamma, rows[i].e_cb, rows[i].eps, rows[i].s_crit,
              isfinite(rows[i].t_fg) ? rows[i].t_fg : th->t_fg,
              isfinite(cut[i]) ? "its own jump" : isfinite(rows[i].t_fg) ? "nearest scan's" : "global", jump[i]);
  }
  free(lt);
  free(cut);
  free(jump);
}

/* A phase changes along a scan only where T_g jumps (Fig. 3.28b).  The homogeneous runs of a
   scan that follow each other in E* with no coexisting or solid run between them and with
   T_g changing by at most JUMP_COEX_DECADES from one to the next form a chain: one phase, its
   label decided by the chain's median log T_g.  A scan without a cut of its own takes its
   neighbour's, and that cut can fall inside a chain whose T_g drifts with E*: at Gamma = 5 of
   the full fig3_4b sweep the gases right of the coexistence cool steadily from 12.5 E_cb at
   E* = 1.3 to 7.4 at E* = 5 (no step above 0.1 decades), and the cut 8.9 of Gamma = 3 called
   the last of them fluid. */
static int by_estar(const void *a, const void *b, void *rows_)
{
  const row *rows = rows_;
  double x = rows[*(const size_t *)a].estar, y = rows[*(const size_t *)b].estar;
  return (x > y) - (x < y);
}

static void scan_chains(row *rows, size_t n, const thresholds *th)
{
  size_t *idx = malloc(sizeof *idx * (n ? n : 1));
  double *lt = malloc(sizeof *lt * (n ? n : 1));
  if (!idx || !lt) {
    free(idx);
    free(lt);
    return;
  }
  for (size_t i = 0; i < n; i++) {
    size_t first = 0;
    while (!same_scan(&rows[first], &rows[i])) first++;
    if (first < i) continue;
    size_t m = 0;
    for (size_t j = i; j < n; j++)
      if (same_scan(&rows[j], &rows[i])) idx[m++] = j;
    qsort_r(idx, m, sizeof *idx, by_estar, rows);
    for (size_t a = 0; a < m;) {
      const row *r = &rows[idx[a]];
      if (!r->has_profiles || contrast(r, th) > th->dn || !(r->tg > th->t_sf)) {
        a++;
        continue;
      }
      size_t b = a + 1;
      while (b < m) {
        const row *q = &rows[idx[b]];
        if (!q->has_profiles || contrast(q, th) > th->dn || !(q->tg > th->t_sf) ||
            fabs(log10(q->tg) - log10(rows[idx[b - 1]].tg)) > JUMP_COEX_DECADES)
          break;
        b++;
      }
      for (size_t k = a; k < b; k++) lt[k - a] = log10(rows[idx[k]].tg);
      qsort(lt, b - a, sizeof *lt, cmp_double);
      size_t h = (b - a) / 2;
      double med = (b - a) % 2 ? lt[h] : 0.5 * (lt[h - 1] + lt[h]);
      for (size_t k = a; k < b; k++) rows[idx[k]].tg_chain = pow(10, med);
      a = b;
    }
  }
  free(idx);
  free(lt);
}

/* With --per-scan the colder class is the homogeneous runs below their own scan's t_fg, not
   below the global cut: the global cut moves with the hottest gases of a sweep (18.5 E_cb over
   118 runs of the full fig3_4a sweep, 29.6 over 125), and a cut that leaves the cool gases of
   Gamma = 2 (16-28 E_cb) in the colder class makes Otsu split gas from fluid and call the
   fluid solid.  The solid split of calibrate() is redone on this class: t_sf is Otsu's cut
   if the two sub-classes lie more than SOLID_DECADES apart, else t_sf_none.  The scans' cuts
   are found before it without a solid cut (the global one may lie among fluids) and redone
   after it, as they leave out the samples below t_sf. */
static void calibrate_solid_per_scan(const row *rows, size_t n, thresholds *th, double t_sf_none)
{
  double *lt = malloc(sizeof *lt * (n ? n : 1));
  size_t k = 0;
  if (!lt) return;
  for (size_t i = 0; i < n; i++) {
    const row *r = &rows[i];
    double c = contrast(r, th);
    double t_fg = isfinite(r->t_fg) ? r->t_fg : th->t_fg;
    if (r->has_profiles && r->tg > 0 && !(c > th->dn) && r->tg < t_fg) lt[k++] = log10(r->tg);
  }
  qsort(lt, k, sizeof *lt, cmp_double);
  double sub = k >= 2 ? otsu_two(lt, k) : NAN, t_sf = t_sf_none, gap = NAN;
  if (isfinite(sub)) {
    size_t j = 0;
    while (j < k && lt[j] < sub) j++;
    gap = mean_of(lt + j, k - j) - mean_of(lt, j);
    if (gap > SOLID_DECADES) t_sf = pow(10, sub);
    fprintf(stderr, "calibrate: colder class of the scans (%zu homogeneous runs below their scan's "
            "t_fg; replaces the split above) splits at %.4g into means %.3g decades apart: %s\n",
            k, pow(10, sub), gap, gap > SOLID_DECADES ? "solid and fluid" : "no solid in this sweep");
  }
  free(lt);
  th->t_sf = t_sf;
}

/* Inflection point of T_g along a scan in E* (Fig. 3.29): the middle of the segment over
   which log10 T_g rises most steeply against log10 E*; the error is half that segment.
   With inelastic collisions T_g has no jump between fluid and gas, and the thesis takes
   this point as the boundary (App. 3.A.1.2). */
/* The scan variable of --inflection: E* (Fig. 3.29) or Gamma (the s-f line of Fig. 3.11). */
static double scan_x(const row *r, int along_gamma) { return along_gamma ? r->gamma : r->estar; }

static int inflection(const row *rows, size_t n, int along_gamma)
{
  const char *name = along_gamma ? "gamma" : "estar";
  size_t *order = malloc(sizeof *order * n);
  if (!order) return WG_ENOMEM;
  size_t m = 0;
  for (size_t i = 0; i < n; i++)
    if (rows[i].tg > 0 && scan_x(&rows[i], along_gamma) > 0) order[m++] = i;
  for (size_t i = 1; i < m; i++) /* by the scan variable, a few dozen runs */
    for (size_t j = i; j > 0 && scan_x(&rows[order[j - 1]], along_gamma) > scan_x(&rows[order[j]], along_gamma); j--) {
      size_t t = order[j];
      order[j] = order[j - 1];
      order[j - 1] = t;
    }
  double best = -INFINITY, lo = NAN, hi = NAN;
  for (size_t k = 1; k < m; k++) {
    double xa = scan_x(&rows[order[k - 1]], along_gamma), xb = scan_x(&rows[order[k]], along_gamma);
    if (xb == xa) continue;
    double slope = (log10(rows[order[k]].tg) - log10(rows[order[k - 1]].tg)) / (log10(xb) - log10(xa));
    if (slope > best) {
      best = slope;
      lo = xa;
      hi = xb;
    }
  }
  free(order);
  if (!isfinite(lo))
    return wg_error(WG_EINVAL, "wetgran-orderparam", "--inflection needs runs at two values of %s at least", name);
  double mid = sqrt(lo * hi);
  printf("key\tvalue\terror\n");
  printf("inflection_%s\t%.6g\t%.3g\n", name, mid, 0.5 * (hi - lo));
  printf("inflection_slope\t%.4g\tnan\n", best);
  return WG_OK;
}

/* The table as an HDF5 file: one dataset per column, with units and descriptions. */
static int write_h5(const char *path, const row *rows, size_t n, const thresholds *th, int wet)
{
  const char *tu = wet ? "E_cb" : "m g d";
  char tmp[4200];
  snprintf(tmp, sizeof tmp, "%s.tmp", path);
  hid_t f = wg_h5_create(tmp);
  if (f < 0) return WG_EIO;
  double *v = malloc(sizeof *v * (n ? n : 1));
  if (!v) {
    wg_h5_close(f);
    return WG_ENOMEM;
  }
  struct { const char *name, *unit, *desc; size_t off; } cols[] = {
      {"gamma", "1", "Gamma = A w^2 / g", offsetof(row, gamma)},
      {"estar", "1", "E* = m (A w)^2 / (2 E_cb)", offsetof(row, estar)},
      {"estar_d", "1", "E*_d = (A w)^2 / (2 g d)", offsetof(row, estar_d)},
      {"e_cb", "m g d", "capillary bridge energy", offsetof(row, e_cb)},
      {"eps", "1", "restitution", offsetof(row, eps)},
      {"t0", "sqrt(d/g)", "start of the averaging window", offsetof(row, t0)},
      {"t1", "sqrt(d/g)", "end of the averaging window", offsetof(row, t1)},
      {"drift", "1", "relative difference of the window's halves", offsetof(row, drift)},
      {wet ? "tg_ecb" : "tg_mgd", tu, "mean T_g over the window", offsetof(row, tg)},
      {wet ? "tg_ecb_err" : "tg_mgd_err", tu, "error of the mean T_g from block means", offsetof(row, tg_err)},
      {wet ? "tg_dense_ecb" : "tg_dense_mgd", tu, "T_g of the densest fifth of the bins", offsetof(row, tg_dense)},
      {wet ? "tg_dilute_ecb" : "tg_dilute_mgd", tu, "T_g of the most dilute fifth of the bins", offsetof(row, tg_dilute)},
      {"dn_cb", "d^-(D-1)", "Eq. 3.3: max - min of the bridge density", offsetof(row, dn_cb)},
      {"dn_area", "1", "max - min of the packing fraction", offsetof(row, dn_area)},
      {"rel_contrast", "1", "dn_area over the largest packing fraction of the profile", offsetof(row, rel_contrast)},
      {"t_fg", tu, "fluid-gas cut of the run's scan (--per-scan; NaN: the global one)", offsetof(row, t_fg)},
      {"tg_chain", tu, "median T_g of the run's chain, which decides fluid or gas (--per-scan; NaN: none)", offsetof(row, tg_chain)},
      {"t_settle", "sqrt(d/g)", "end of T_g's warm-up (MSER-5; NaN: not settled within the run's first half)", offsetof(row, t_settle)},
  };
  hsize_t dims[1] = {n};
  int st = WG_OK;
  for (size_t c = 0; c < sizeof cols / sizeof *cols && st == WG_OK; c++) {
    for (size_t i = 0; i < n; i++) v[i] = *(const double *)((const char *)&rows[i] + cols[c].off);
    char name[64];
    snprintf(name, sizeof name, "/orderparam/%s", cols[c].name);
    st = wg_h5_write(f, name, H5T_NATIVE_DOUBLE, 1, dims, v, cols[c].unit, cols[c].desc);
  }
  int *iv = malloc(sizeof *iv * (n ? n : 1));
  for (size_t i = 0; iv && i < n; i++) iv[i] = rows[i].stationary;
  if (st == WG_OK && iv)
    st = wg_h5_write(f, "/orderparam/stationary", H5T_NATIVE_INT, 1, dims, iv, "1", "1 if the window is stationary");
  free(iv);
  const char **lab = malloc(sizeof *lab * (n ? n : 1)), **file = malloc(sizeof *file * (n ? n : 1));
  for (size_t i = 0; lab && file && i < n; i++) {
    lab[i] = rows[i].label;
    file[i] = rows[i].file;
  }
  if (st == WG_OK && lab && file && n > 0) {
    st |= wg_h5_attr_strings(f, "/orderparam", "label", (int)n, lab);
    st |= wg_h5_attr_strings(f, "/orderparam", "file", (int)n, file);
  }
  free(lab);
  free(file);
  double t[3] = {th->t_sf, th->t_fg, th->dn};
  if (st == WG_OK) st = wg_h5_attr_doubles(f, "/orderparam", "thresholds_tsf_tfg_dn", 3, t);
  free(v);
  if (wg_h5_close(f) != WG_OK) st = WG_EIO;
  if (st != WG_OK) return wg_error(WG_EIO, tmp, "order parameters not written");
  if (rename(tmp, path) != 0) return wg_error(WG_EIO, path, "cannot rename from %s", tmp);
  return WG_OK;
}

static void usage(FILE *out)
{
  fprintf(out,
          "Usage: wetgran-orderparam [options] RUN.h5 ...\n"
          "Order parameters of shaken runs (thesis App. 3.A), one tab-separated row per run:\n"
          "  gamma estar estar_d e_cb eps   parameters of the run\n"
          "  t0 t1                          averaging window: [profile_start, t_end]\n"
          "  stationary drift               1 if the window lies in the run's stationary part:\n"
          "                                 after T_g's warm-up (MSER-5 over the whole series;\n"
          "                                 the window may start up to %g %% of its length early;\n"
          "                                 a run whose warm-up does not end within its first\n"
          "                                 half never became stationary), and its two halves\n"
          "                                 differ by at most %g errors or %g %%, and by at most\n"
          "                                 %g %% (drift: their relative difference).  Where the\n"
          "                                 warm-up ends goes to stderr for runs that fail, and\n"
          "                                 for every run to --h5 (/orderparam/t_settle)\n"
          "  tg_ecb tg_ecb_err              mean T_g (Eq. 3.2) / E_cb over the window and its\n"
          "                                 error from %d block means (a table of dry runs,\n"
          "                                 E_cb = 0: tg_mgd tg_mgd_err, in m g d; wet and dry\n"
          "                                 runs are not mixed in one table)\n"
          "  tg_dense_ecb tg_dilute_ecb     T_g / E_cb of the densest and most dilute fifth of\n"
          "                                 the lateral bins (dry: tg_dense_mgd tg_dilute_mgd)\n"
          "  dn_cb dn_area                  Eq. 3.3: max - min of the bridge density n_cb\n"
          "                                 [1/d^(D-1)] and of the packing fraction\n"
          "  rel_contrast                   dn_area over the profile's largest packing fraction\n"
          "  label                          s, f, g, sfc, sgc or fgc (see below); n/a for a run\n"
          "                                 without profiles (profile_bins = 0): it is named on\n"
          "                                 stderr and the exit status is 1\n"
          "Labels: a region is solid below T_g/E_cb = t_sf, a gas above t_fg, fluid between;\n"
          "phases coexist when dn_cb (wet) or dn_area (dry) exceeds dn (with\n"
          "--relative-contrast: when rel_contrast does), and then the densest and most dilute\n"
          "fifths are labelled separately.\n"
          "Options:\n"
          "  --t-sf X --t-fg Y --dn Z   thresholds (defaults %g, %g, %g)\n"
          "  --calibrate                derive the thresholds from the runs given, a sweep:\n"
          "                             Otsu's cut of the contrasts, moved to the widest gap\n"
          "                             between the two classes' means, gives dn (relative:\n"
          "                             the middle of the empty interval around 1/2); Otsu's cut of\n"
          "                             log T_g over the homogeneous runs gives t_fg; a further\n"
          "                             cut of the colder class gives t_sf if its halves lie\n"
          "                             more than a decade apart.  The classes found go to\n"
          "                             stderr, the thresholds to a '#' line before the table;\n"
          "                             thresholds also given as options are kept.  Otsu's\n"
          "                             classes of log T_g are fluid and gas only if their\n"
          "                             means lie more than %g decades apart; else the\n"
          "                             homogeneous runs are one phase (said on stderr) and\n"
          "                             t_fg stays (or moves %g decades past the hottest\n"
          "                             fluid or the coldest gas if it would split them)\n"
          "  --log-contrast             with --calibrate: Otsu's cut of log10 of the contrasts,\n"
          "                             for a scan whose contrasts span decades\n"
          "  --relative-contrast        cut rel_contrast instead of dn_cb / dn_area (dn default\n"
          "                             %g): for sweeps whose coexistence is weak in places and\n"
          "                             strong in others (the bridges of the dense part vary\n"
          "                             with eps, Gamma, E_cb), where one cut of dn_cb falls\n"
          "                             between weak and strong coexistence\n"
          "  --per-scan                 with --calibrate: a fluid-gas cut t_fg per scan (runs\n"
          "                             sharing Gamma, E_cb, eps, s_crit): in log T_g over its\n"
          "                             homogeneous runs and the dense and dilute parts of its\n"
          "                             coexisting runs, the widest gap between their dense\n"
          "                             and their dilute parts, kept if wider than %g decades\n"
          "                             (without coexistence Otsu's cut, kept where T_g jumps\n"
          "                             by more than %g decades); else the nearest scan's in\n"
          "                             log Gamma, else the global cut.  For sweeps over Gamma,\n"
          "                             where the gas's T_g/E_cb moves by decades.  The solid cut t_sf is\n"
          "                             then redone on the homogeneous runs below their own\n"
          "                             scan's t_fg.  The homogeneous runs of a scan that follow\n"
          "                             each other in E* without coexistence between them and\n"
          "                             with T_g changing by at most %g decades per step are one\n"
          "                             phase (a chain): labelled by its median T_g\n"
          "  --tg-only                  T_g only, for runs without profiles: no label ('-'),\n"
          "                             no contrasts (nan), exit status 0\n"
          "  --h5 FILE                  also write the table to FILE (HDF5: /orderparam/<column>,\n"
          "                             labels and file names as attributes)\n"
          "  --inflection               instead of the table: the E* where log T_g rises most\n"
          "                             steeply along the runs given (a scan in E*), as\n"
          "                             key/value/error rows (inelastic f-g boundary, Fig. 3.29)\n"
          "  --along estar|gamma        the scan variable of --inflection (default estar; gamma:\n"
          "                             the s-f line of Fig. 3.11, a scan in Gamma at fixed E*)\n",
          100 * WARMUP_IN_WINDOW, DRIFT_SIGMAS, 100 * DRIFT_REL, 100 * DRIFT_GROSS, BLOCKS, default_thresholds.t_sf,
          default_thresholds.t_fg, default_thresholds.dn, ONE_PHASE_DECADES, ONE_PHASE_DECADES, DEFAULT_RELATIVE_DN, JUMP_COEX_DECADES, JUMP_DECADES,
          JUMP_COEX_DECADES);
}

static int parse_double(const char *opt, const char *s, double *v)
{
  char *end;
  *v = strtod(s, &end);
  if (end == s || *end || !(*v >= 0))
    return wg_error(WG_EINVAL, "wetgran-orderparam", "option %s: '%s' is not a number >= 0", opt, s);
  return WG_OK;
}

int main(int argc, char **argv)
{
  thresholds th = default_thresholds;
  int do_calibrate = 0, do_inflection = 0, per_scan = 0, given = 0, along_gamma = 0, tg_only = 0;
  const char *h5_out = NULL;
  const char **files = calloc((size_t)argc, sizeof *files);
  size_t nf = 0;
  for (int a = 1; a < argc; a++) {
    const char *o = argv[a];
    if (!strcmp(o, "-h") || !strcmp(o, "--help")) {
      usage(stdout);
      free(files);
      return 0;
    }
    if (!strcmp(o, "--calibrate")) do_calibrate = 1;
    else if (!strcmp(o, "--log-contrast")) given |= LOG_CONTRAST;
    else if (!strcmp(o, "--relative-contrast")) th.relative = 1;
    else if (!strcmp(o, "--per-scan")) per_scan = 1;
    else if (!strcmp(o, "--tg-only")) tg_only = 1;
    else if (!strcmp(o, "--inflection")) do_inflection = 1;
    else if (!strcmp(o, "--along") && a + 1 < argc) {
      const char *v = argv[++a];
      if (strcmp(v, "estar") && strcmp(v, "gamma")) {
        fprintf(stderr, "wetgran-orderparam: --along: '%s' is not estar or gamma\n", v);
        free(files);
        return 2;
      }
      along_gamma = !strcmp(v, "gamma");
    }
    else if (!strcmp(o, "--h5") && a + 1 < argc) h5_out = argv[++a];
    else if ((!strcmp(o, "--t-sf") || !strcmp(o, "--t-fg") || !strcmp(o, "--dn")) && a + 1 < argc) {
      double *dst = !strcmp(o, "--t-sf") ? &th.t_sf : !strcmp(o, "--t-fg") ? &th.t_fg : &th.dn;
      given |= !strcmp(o, "--t-sf") ? GIVEN_T_SF : !strcmp(o, "--t-fg") ? GIVEN_T_FG : GIVEN_DN;
      if (parse_double(o, argv[++a], dst) != WG_OK) {
        free(files);
        return 2;
      }
    } else if (o[0] == '-') {
      fprintf(stderr, "wetgran-orderparam: unknown option '%s' (see --help)\n", o);
      free(files);
      return 2;
    } else {
      files[nf++] = o;
    }
  }
  if (nf == 0) {
    usage(stderr);
    free(files);
    return 2;
  }
  if (tg_only && (do_calibrate || do_inflection || h5_out)) {
    fprintf(stderr, "wetgran-orderparam: --tg-only goes without --calibrate, --inflection and --h5\n");
    free(files);
    return 2;
  }
  if (th.relative && !(given & GIVEN_DN)) th.dn = DEFAULT_RELATIVE_DN;
  wg_h5_quiet();
  row *rows = calloc(nf, sizeof *rows);
  int st = rows ? WG_OK : WG_ENOMEM;
  for (size_t i = 0; i < nf && st == WG_OK; i++) st = measure(files[i], &rows[i]);
  /* T_g is divided by E_cb in wet runs only: one table, one unit */
  size_t wet = 0, dry = 0;
  for (size_t i = 0; i < nf && st == WG_OK; i++) {
    if (rows[i].e_cb > 0) wet = i + 1;
    else dry = i + 1;
  }
  if (wet && dry) {
    fprintf(stderr, "wetgran-orderparam: %s is wet (E_cb = %g, T_g in E_cb) and %s dry (E_cb = 0, T_g "
            "in m g d): give wet and dry runs in separate tables\n", rows[wet - 1].file,
            rows[wet - 1].e_cb, rows[dry - 1].file);
    free(rows);
    free(files);
    return 2;
  }
  const char *u = wet ? "ecb" : "mgd";
  if (st == WG_OK && do_inflection) {
    st = inflection(rows, nf, along_gamma);
  } else if (st == WG_OK) {
    if (do_calibrate) {
      double t_sf_none = th.t_sf;
      calibrate(rows, nf, &th, given);
      if (per_scan && !(given & GIVEN_T_FG)) {
        int redo = !(given & GIVEN_T_SF);
        if (redo) { /* fluid-gas cuts without a solid first: the global t_sf may be a fluid */
          thresholds no_solid = th;
          no_solid.t_sf = t_sf_none;
          calibrate_per_scan(rows, nf, &no_solid, 0);
          calibrate_solid_per_scan(rows, nf, &th, t_sf_none);
        }
        calibrate_per_scan(rows, nf, &th, 1);
        scan_chains(rows, nf, &th);
      }
      printf("# thresholds from %zu runs: t_sf\t%.6g\tt_fg\t%.6g\tdn\t%.6g\tcontrast\t%s\n", nf, th.t_sf,
             th.t_fg, th.dn, th.relative ? "relative" : "absolute");
    }
    printf("file\tgamma\testar\testar_d\te_cb\teps\tt0\tt1\tstationary\tdrift\ttg_%s\ttg_%s_err\t"
           "tg_dense_%s\ttg_dilute_%s\tdn_cb\tdn_area\trel_contrast\tlabel\n", u, u, u, u);
    for (size_t i = 0; i < nf; i++) {
      row *r = &rows[i];
      label(r, &th);
      if (tg_only) snprintf(r->label, sizeof r->label, "-");
      else if (!r->has_profiles) {
        fprintf(stderr, "wetgran-orderparam: %s: no profiles (profile_bins = 0), so no contrasts: "
                "label n/a (--tg-only for T_g alone)\n", r->file);
        st = WG_EINVAL;
      }
      if (!r->stationary) {
        if (!isfinite(r->t_settle))
          fprintf(stderr, "wetgran-orderparam: %s: never became stationary: T_g still settling at half "
                  "the run (MSER-5; window [%g, %g] drifts by %.0f %%)\n", r->file, r->t0, r->t1, 100 * r->drift);
        else if (r->t_settle > r->t0)
          fprintf(stderr, "wetgran-orderparam: %s: not stationary in [%g, %g]: T_g settles only at t = %g "
                  "(drift %.0f %%)\n", r->file, r->t0, r->t1, r->t_settle, 100 * r->drift);
        else
          fprintf(stderr, "wetgran-orderparam: %s: not stationary in [%g, %g] (T_g drifts by %.0f %%)\n",
                  r->file, r->t0, r->t1, 100 * r->drift);
      }
      printf("%s\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%d\t%.3g\t%.6g\t%.3g\t%.6g\t%.6g\t%.6g\t%.6g\t%.4g\t%s\n",
             r->file, r->gamma, r->estar, r->estar_d, r->e_cb, r->eps, r->t0, r->t1, r->stationary,
             r->drift, r->tg, r->tg_err, r->tg_dense, r->tg_dilute, r->dn_cb, r->dn_area,
             r->rel_contrast, r->label);
    }
    if (h5_out && write_h5(h5_out, rows, nf, &th, wet != 0) != WG_OK) st = WG_EIO;
  }
  free(rows);
  free(files);
  return st == WG_OK ? 0 : 1;
}
