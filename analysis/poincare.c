/* wetgran-poincare: Poincare sections of a limit cycle and their return map (thesis Sec. 8.4,
   following Lorenz 1963): the section is the maximum of a series (E_perp by default) during each
   cycle; the return map pairs each cycle's maximum with the next one's, pooled over the files
   given (seeds); its fixed points are where the map crosses the diagonal, stable where the
   map's slope there has |slope| <= 1.  Modes, each writing a tab-separated table:
     section  per file and cycle: the time and value of the cycle's maximum
     map      the pairs (x_n, x_n+1) of all files
     fixed    the fixed points: x* and the slope with errors, stable or unstable
   Input: run files of wetgran-run (the series /observables/<column>) or tab-separated tables
   with a header line (wetgran-series output; "-" reads stdin).

   Cycles: the series is smoothed by a running mean of --smooth samples (odd; default 1, none),
   then its maxima and minima are taken with hysteresis (a maximum counts once the series has
   fallen --prominence below it, a minimum once it has risen as much; default a tenth of the
   smoothed series' 10-90 percentile range, and at least eight times its noise, so that noise
   makes no cycles).  A cycle runs from one minimum to the next (the first, without a minimum
   before it, is dropped); its section value is the smoothed series' largest value inside it
   (the raw series' largest sample would be biased up by the noise; a running mean of K samples
   lowers a smooth peak by about its curvature times K^2 dt^2 / 24).  Fewer than --min-cycles
   cycles (default 5) is no limit cycle: the tool says so and exits 1 rather than draw a map
   from noise. */
#include <gsl/gsl_fit.h>
#include <gsl/gsl_multifit.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "extrema.h"
#include "io_h5.h"
#include "run_open.h"
#include "wg_args.h"

#define PROG "wetgran-poincare"

typedef struct options {
  const char *column, *time;
  long smooth, min_cycles, bins;
  double prominence; /* 0: automatic */
  double from;
} options;

typedef struct series {
  long n;
  double *t, *x;
} series;

static void series_free(series *s) { free(s->t), free(s->x), s->n = 0; }

/* A run file's /observables/<column>/{time,value}. */
static int load_h5(const char *file, const options *o, series *s)
{
  hid_t f = wg_run_open(file);
  if (f < 0) return 1;
  char pv[256], pt[256];
  snprintf(pv, sizeof pv, "/observables/%s/value", o->column);
  snprintf(pt, sizeof pt, "/observables/%s/time", o->column);
  int rank, rc = 0;
  hsize_t d[8];
  if (!wg_h5_exists(f, pv) || wg_h5_dims(f, pv, &rank, d) != WG_OK || rank != 1) {
    fprintf(stderr, PROG ": %s: no series '%s' in this run (wetgran-series --help lists them)\n",
            file, o->column);
    wg_h5_close(f);
    return 1;
  }
  s->n = (long)d[0];
  s->t = malloc(sizeof(double) * (s->n ? s->n : 1)), s->x = malloc(sizeof(double) * (s->n ? s->n : 1));
  if (!s->t || !s->x || wg_h5_read(f, pt, H5T_NATIVE_DOUBLE, s->t) ||
      wg_h5_read(f, pv, H5T_NATIVE_DOUBLE, s->x)) {
    fprintf(stderr, PROG ": %s: cannot read the series '%s'\n", file, o->column);
    rc = 1;
  }
  wg_h5_close(f);
  return rc;
}

/* A table: the time and value columns by name (rows without a time are skipped). */
static int load_table(const char *file, const options *o, series *s)
{
  wg_xy t;
  if (wg_table_read_xy(file, o->time, o->column, 0, &t)) return 1;
  s->t = t.x, s->x = t.y, s->n = 0;
  for (size_t i = 0; i < t.n; i++)
    if (isfinite(t.x[i])) s->t[s->n] = t.x[i], s->x[s->n++] = t.y[i];
  return 0;
}

static int load(const char *file, const options *o, series *s)
{
  memset(s, 0, sizeof *s);
  int h5 = wg_input_is_h5(file);
  if (h5 < 0) return 1;
  int rc = h5 ? load_h5(file, o, s) : load_table(file, o, s);
  if (rc) series_free(s);
  return rc;
}

/* The cycles' maxima of one series from t >= from: times and values to mt[], mx[] (room n);
   returns their number, or -1 when there is no memory. */
static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static long section(const series *s, const options *o, double *mt, double *mx)
{
  long n = s->n, h = o->smooth / 2, m = 0;
  double *y = malloc(sizeof(double) * (n ? n : 1));
  long *idx = malloc(sizeof(long) * (n ? n : 1));
  int *kind = malloc(sizeof(int) * (n ? n : 1));
  if (!y || !idx || !kind) {
    free(y), free(idx), free(kind);
    return -1;
  }
  for (long i = 0; i < n; i++) { /* running mean over the window inside the series */
    double a = 0;
    long c = 0;
    for (long j = i - h; j <= i + h; j++)
      if (j >= 0 && j < n && isfinite(s->x[j])) a += s->x[j], c++;
    y[i] = s->t[i] >= o->from && c ? a / c : NAN;
  }
  /* default prominence: a tenth of the smoothed series' range, and at least eight times its
     noise (the raw series' from second differences, which a smooth signal sampled finely
     hardly has: median-based, over sqrt(K)) */
  double swing = o->prominence;
  if (!(swing > 0)) {
    double *d = malloc(sizeof(double) * (n ? n : 1));
    long nd = 0;
    for (long i = 1; d && i + 1 < n; i++)
      if (isfinite(s->x[i + 1]) && isfinite(s->x[i]) && isfinite(s->x[i - 1]))
        d[nd++] = fabs(s->x[i + 1] - 2 * s->x[i] + s->x[i - 1]);
    double noise = 0;
    if (nd > 0) {
      qsort(d, (size_t)nd, sizeof(double), cmp_double);
      noise = d[nd / 2] / (0.6745 * sqrt(6.0)) / sqrt((double)o->smooth); /* MAD of N(0, 6 s^2) */
    }
    free(d);
    swing = fmax(wg_auto_swing(y, n, 0.1, 0), 8 * noise);
  }
  long k = swing > 0 ? wg_turning_points(y, n, swing, idx, kind) : 0;
  /* turning points alternate, and the maximum between two minima is the largest value of
     the smoothed series between them (the hysteresis tracks it until the fall) */
  for (long j = 0; j + 2 < k; j++)
    if (kind[j] == -1) mt[m] = s->t[idx[j + 1]], mx[m++] = y[idx[j + 1]];
  free(y), free(idx), free(kind);
  return m;
}

typedef struct pairs {
  long n;
  double *x, *y;
} pairs;

static int cmp_pair_x(const void *a, const void *b)
{
  const double *p = a, *q = b;
  return (p[0] > q[0]) - (p[0] < q[0]);
}

/* Every file's section, printed (mode section) or gathered into pairs. */
static int sections(const options *o, int nfile, char **files, int print, pairs *pr)
{
  long cap = 0;
  pr->n = 0, pr->x = pr->y = NULL;
  if (print) printf("file\tcycle\tt\tmax\n");
  for (int r = 0; r < nfile; r++) {
    series s;
    if (load(files[r], o, &s)) return 1;
    double *mt = malloc(sizeof(double) * (s.n ? s.n : 1)), *mx = malloc(sizeof(double) * (s.n ? s.n : 1));
    long m = mt && mx ? section(&s, o, mt, mx) : -1;
    if (m < 0) {
      fprintf(stderr, PROG ": no memory\n");
      return 1;
    }
    if (m < o->min_cycles) {
      fprintf(stderr, PROG ": %s: %ld cycle(s) of '%s' from t = %g on (need %ld): no limit cycle "
              "to cut; --prominence, --smooth or --min-cycles change what counts\n", files[r], m,
              o->column, o->from, o->min_cycles);
      free(mt), free(mx), series_free(&s);
      return 1;
    }
    for (long j = 0; j < m; j++) {
      if (print) printf("%s\t%ld\t%.10g\t%.10g\n", files[r], j, mt[j], mx[j]);
      if (j + 1 < m) {
        if (pr->n == cap) {
          cap = cap ? 2 * cap : 256;
          pr->x = realloc(pr->x, sizeof(double) * cap), pr->y = realloc(pr->y, sizeof(double) * cap);
          if (!pr->x || !pr->y) return 1;
        }
        pr->x[pr->n] = mx[j], pr->y[pr->n++] = mx[j + 1];
      }
    }
    free(mt), free(mx), series_free(&s);
  }
  return 0;
}

/* Fixed points: the pairs sorted by x_n in bins of equal count; where the bins' mean of
   x_n+1 - x_n changes sign between neighbours, a parabola fitted to the points of the two bins
   (GSL; a unimodal map is locally one, and a straight line would bias x* and the slope on a
   curved map) gives x* where it meets the diagonal and the slope there, with errors; a
   straight line instead where the curvature is within twice its error (a noise cloud round
   a stable point). */
static int mode_fixed(const options *o, const pairs *pr)
{
  long n = pr->n, nb = o->bins > 0 ? o->bins : (long)fmax(2, round(cbrt((double)n)));
  printf("x_star\tx_star_err\tslope\tslope_err\tstability\tpoints\n");
  if (n < 4) return 0;
  double *p = malloc(sizeof(double) * 2 * n);
  double *bx = calloc((size_t)nb, sizeof(double)), *bd = calloc((size_t)nb, sizeof(double));
  if (!p || !bx || !bd) return 1;
  for (long i = 0; i < n; i++) p[2 * i] = pr->x[i], p[2 * i + 1] = pr->y[i];
  qsort(p, (size_t)n, 2 * sizeof(double), cmp_pair_x);
  for (long b = 0; b < nb; b++) {
    long lo = b * n / nb, hi = (b + 1) * n / nb;
    for (long i = lo; i < hi; i++) bx[b] += p[2 * i], bd[b] += p[2 * i + 1] - p[2 * i];
    bx[b] /= (hi - lo), bd[b] /= (hi - lo);
  }
  long found = 0;
  for (long b = 0; b + 1 < nb; b++) {
    if ((bd[b] > 0) == (bd[b + 1] > 0)) continue;
    long lo = b * n / nb, hi = (b + 2) * n / nb, k = hi - lo;
    double *x = malloc(sizeof(double) * k), *y = malloc(sizeof(double) * k);
    for (long i = 0; i < k; i++) x[i] = p[2 * (lo + i)], y[i] = p[2 * (lo + i) + 1];
    /* x_next = c0 + c1 x + c2 x^2 about the crossing (x measured from the bins' mean, so the
       three columns stay well conditioned); x* = x0 + u where the parabola meets the
       diagonal nearest the crossing, the slope c1 + 2 c2 u there; errors by propagating the
       fit's covariance */
    double x0 = 0.5 * (bx[b] + bx[b + 1]), c[3], cv[9];
    gsl_matrix *X = gsl_matrix_alloc((size_t)k, 3), *C = gsl_matrix_alloc(3, 3);
    gsl_vector *Y = gsl_vector_alloc((size_t)k), *cc = gsl_vector_alloc(3);
    gsl_multifit_linear_workspace *w = gsl_multifit_linear_alloc((size_t)k, 3);
    for (long i = 0; i < k; i++) {
      double u = x[i] - x0;
      gsl_matrix_set(X, (size_t)i, 0, 1), gsl_matrix_set(X, (size_t)i, 1, u);
      gsl_matrix_set(X, (size_t)i, 2, u * u), gsl_vector_set(Y, (size_t)i, y[i]);
    }
    double chisq;
    gsl_multifit_linear(X, Y, cc, C, &chisq, w);
    for (int q = 0; q < 3; q++) c[q] = gsl_vector_get(cc, (size_t)q);
    for (int q = 0; q < 9; q++) cv[q] = gsl_matrix_get(C, (size_t)(q / 3), (size_t)(q % 3));
    if (!(fabs(c[2]) > 2 * sqrt(cv[8]))) { /* no curvature above the scatter: a straight line */
      double c00, c01, c11, ss;
      for (long i = 0; i < k; i++) x[i] -= x0;
      gsl_fit_linear(x, 1, y, 1, (size_t)k, &c[0], &c[1], &c00, &c01, &c11, &ss);
      c[2] = 0;
      double lin[9] = {c00, c01, 0, c01, c11, 0, 0, 0, 0};
      memcpy(cv, lin, sizeof lin);
    }
    gsl_matrix_free(X), gsl_matrix_free(C), gsl_vector_free(Y), gsl_vector_free(cc);
    gsl_multifit_linear_free(w);
    /* on the diagonal x_next = x0 + u: g(u) = (c0 - x0) + (c1 - 1) u + c2 u^2 = 0, the root
       nearest the crossing (the cancellation-free form of the quadratic's roots) */
    double A = c[2], B = c[1] - 1, C0 = c[0] - x0, u;
    if (fabs(A) < 1e-12 * fabs(B)) u = -C0 / B;
    else {
      double disc = B * B - 4 * A * C0;
      if (disc < 0) disc = 0;
      double q = -0.5 * (B + (B < 0 ? -1 : 1) * sqrt(disc));
      double r1 = q / A, r2 = q != 0 ? C0 / q : r1;
      u = fabs(r1) < fabs(r2) ? r1 : r2;
    }
    double slope = c[1] + 2 * c[2] * u, gp = B + 2 * A * u;
    /* du = -(dc0 + u dc1 + u^2 dc2) / g'(u); dslope = dc1 + 2 u dc2 + 2 c2 du */
    double ju[3] = {-1 / gp, -u / gp, -u * u / gp};
    double js[3] = {2 * c[2] * ju[0], 1 + 2 * c[2] * ju[1], 2 * u + 2 * c[2] * ju[2]};
    double vu = 0, vs = 0;
    for (int q = 0; q < 3; q++)
      for (int r = 0; r < 3; r++) vu += ju[q] * ju[r] * cv[3 * q + r], vs += js[q] * js[r] * cv[3 * q + r];
    printf("%.6g\t%.3g\t%.4g\t%.3g\t%s\t%ld\n", x0 + u, sqrt(fmax(0, vu)), slope, sqrt(fmax(0, vs)),
           fabs(slope) <= 1 ? "stable" : "unstable", k);
    found++;
    free(x), free(y);
  }
  if (!found)
    fprintf(stderr, PROG ": the return map does not cross the diagonal (%ld pairs in %ld bins)\n", n, nb);
  free(p), free(bx), free(bd);
  return 0;
}

static void usage(FILE *out)
{
  fprintf(out,
    "Usage: " PROG " MODE [options] RUN.h5|TABLE ... (\"-\": a table on stdin)\n"
    "Poincare sections of a limit cycle (thesis Sec. 8.4): the maximum of a series during each\n"
    "cycle, the return map of consecutive maxima pooled over the files (seeds), its fixed\n"
    "points.  Run files: the series /observables/COLUMN; tables: a header line, tab-separated\n"
    "(wetgran-series output).  Tab-separated tables on stdout.\n"
    "Modes:\n"
    "  section   file, cycle, t, max: each cycle's largest sample\n"
    "  map       x_n, x_next: consecutive maxima of every file\n"
    "  fixed     x_star, x_star_err, slope, slope_err, stability, points: where the return\n"
    "            map crosses the diagonal (bins of equal count along x_n; a parabola fitted\n"
    "            to the two bins around each change of sign of x_next - x_n, GSL); stable\n"
    "            when |slope| <= 1\n"
    "Options:\n"
    "  --column NAME     the series (default e_perp)\n"
    "  --time NAME       a table's time column (default time)\n"
    "  --from T          cycles from time T on (default 0)\n"
    "  --smooth K        running mean over K samples (odd) before the cycles are found (default 1)\n"
    "  --prominence P    a maximum counts once the series has fallen P below it, a minimum once\n"
    "                    it has risen P (default: a tenth of the smoothed series' 10-90\n"
    "                    percentile range, at least eight times its noise as estimated from\n"
    "                    second differences)\n"
    "  --min-cycles K    fewer cycles in a file is no limit cycle: exit 1 (default 5)\n"
    "  --bins K          fixed: bins along x_n (default the cube root of the pairs, at least 2:\n"
    "                    wide enough that noise does not fake crossings of the diagonal)\n"
    "A cycle runs from one minimum of the smoothed series to the next; its value is the\n"
    "smoothed series' largest value within it.\n");
}

int main(int argc, char **argv)
{
  if (argc < 2 || !strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
    usage(argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const char *mode = argv[1];
  options o = {.column = "e_perp", .time = "time", .smooth = 1, .min_cycles = 5, .bins = 0,
               .prominence = 0, .from = -INFINITY};
  int i = 2;
  for (; i < argc && argv[i][0] == '-' && argv[i][1] == '-'; i++) {
    const char *a = argv[i];
    if (!strcmp(a, "--help")) {
      usage(stdout);
      return 0;
    }
    if (i + 1 >= argc) {
      fprintf(stderr, PROG ": option %s needs a value\n", a);
      return 2;
    }
    const char *v = argv[++i];
    if (!strcmp(a, "--column")) o.column = v;
    else if (!strcmp(a, "--time")) o.time = v;
    else if (!strcmp(a, "--from")) { if (wg_arg_double(a, v, &o.from)) return 2; }
    else if (!strcmp(a, "--prominence")) { if (wg_arg_double(a, v, &o.prominence)) return 2; }
    else if (!strcmp(a, "--smooth")) { if (wg_arg_long(a, v, &o.smooth)) return 2; }
    else if (!strcmp(a, "--min-cycles")) { if (wg_arg_long(a, v, &o.min_cycles)) return 2; }
    else if (!strcmp(a, "--bins")) { if (wg_arg_long(a, v, &o.bins)) return 2; }
    else {
      fprintf(stderr, PROG ": unknown option %s (see --help)\n", a);
      return 2;
    }
  }
  if (o.smooth < 1 || o.smooth % 2 == 0 || o.min_cycles < 2 || o.bins < 0 || o.prominence < 0) {
    fprintf(stderr, PROG ": need an odd --smooth >= 1, --min-cycles >= 2, --bins >= 0, --prominence >= 0\n");
    return 2;
  }
  if (i >= argc) {
    fprintf(stderr, PROG ": no input files (see --help)\n");
    return 2;
  }
  int section_mode = !strcmp(mode, "section");
  if (!section_mode && strcmp(mode, "map") && strcmp(mode, "fixed")) {
    fprintf(stderr, PROG ": unknown mode '%s' (section, map, fixed)\n", mode);
    return 2;
  }
  pairs pr;
  if (sections(&o, argc - i, argv + i, section_mode, &pr)) return 1;
  int rc = 0;
  if (!strcmp(mode, "map")) {
    printf("x_n\tx_next\n");
    for (long k = 0; k < pr.n; k++) printf("%.10g\t%.10g\n", pr.x[k], pr.y[k]);
  } else if (!strcmp(mode, "fixed")) rc = mode_fixed(&o, &pr);
  free(pr.x), free(pr.y);
  return rc;
}
