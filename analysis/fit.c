/* wetgran-fit: least-squares fits of the forms the thesis draws through its data, with
   GSL's nonlinear least squares (trust region, Levenberg-Marquardt).  Reads a TSV table,
   prints key, value, error rows (errors from the covariance matrix scaled by the reduced
   chi^2, i.e. from the scatter of the data).
     critical:  y = a (xc - x)^beta  for x < xc   (order parameter near a transition, Fig. 3.31)
     line:      y = a + b x                       (transition energies against E_cb, Fig. 3.5)
     prop:      y = b x                           (the same through the origin: gsl_fit_mul)
     melt:      y = l0 ln(1 / (1 - (x - xm)/(xc - xm)))  for xm < x < xc, 0 below xm, capped
                at C (the number of layers) and C from xc on (fluidization depth, Fig. 4.4) */
#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run_open.h"
#include "wg_args.h"

#define MAX_COLS 64
#define MAX_ITER 500
#define XTOL 1e-10
#define GTOL 1e-10
#define FTOL 0.0

typedef struct data {
  size_t n;
  double *x, *y;
  double cap; /* melt: the largest value the model takes */
} data;

/* critical: p = (a, xc, beta) */
static int critical_f(const gsl_vector *p, void *d_, gsl_vector *r)
{
  const data *d = d_;
  double a = gsl_vector_get(p, 0), xc = gsl_vector_get(p, 1), b = gsl_vector_get(p, 2);
  for (size_t i = 0; i < d->n; i++) {
    double u = xc - d->x[i];
    double model = u > 0 ? a * pow(u, b) : 0;
    gsl_vector_set(r, i, model - d->y[i]);
  }
  return GSL_SUCCESS;
}

static int critical_df(const gsl_vector *p, void *d_, gsl_matrix *J)
{
  const data *d = d_;
  double a = gsl_vector_get(p, 0), xc = gsl_vector_get(p, 1), b = gsl_vector_get(p, 2);
  for (size_t i = 0; i < d->n; i++) {
    double u = xc - d->x[i];
    double ub = u > 0 ? pow(u, b) : 0;
    gsl_matrix_set(J, i, 0, ub);
    gsl_matrix_set(J, i, 1, u > 0 ? a * b * ub / u : 0);
    gsl_matrix_set(J, i, 2, u > 0 ? a * ub * log(u) : 0);
  }
  return GSL_SUCCESS;
}

static int line_f(const gsl_vector *p, void *d_, gsl_vector *r)
{
  const data *d = d_;
  for (size_t i = 0; i < d->n; i++)
    gsl_vector_set(r, i, gsl_vector_get(p, 0) + gsl_vector_get(p, 1) * d->x[i] - d->y[i]);
  return GSL_SUCCESS;
}

static int line_df(const gsl_vector *p, void *d_, gsl_matrix *J)
{
  (void)p;
  const data *d = d_;
  for (size_t i = 0; i < d->n; i++) {
    gsl_matrix_set(J, i, 0, 1);
    gsl_matrix_set(J, i, 1, d->x[i]);
  }
  return GSL_SUCCESS;
}

/* melt: p = (l0, xm, xc).  With u = (x - xm)/(xc - xm), ln(1/(1 - u)) = ln(xc - xm) - ln(xc - x),
   so the derivatives are closed forms; below xm and where the cap holds they vanish. */
static double melt_model(double l0, double xm, double xc, double cap, double x, int *capped)
{
  *capped = 1;
  if (x <= xm) return 0;
  if (x >= xc || xc <= xm) return cap;
  double y = l0 * (log(xc - xm) - log(xc - x));
  if (y >= cap) return cap;
  *capped = 0;
  return y;
}

static int melt_f(const gsl_vector *p, void *d_, gsl_vector *r)
{
  const data *d = d_;
  double l0 = gsl_vector_get(p, 0), xm = gsl_vector_get(p, 1), xc = gsl_vector_get(p, 2);
  int capped;
  for (size_t i = 0; i < d->n; i++)
    gsl_vector_set(r, i, melt_model(l0, xm, xc, d->cap, d->x[i], &capped) - d->y[i]);
  return GSL_SUCCESS;
}

static int melt_df(const gsl_vector *p, void *d_, gsl_matrix *J)
{
  const data *d = d_;
  double l0 = gsl_vector_get(p, 0), xm = gsl_vector_get(p, 1), xc = gsl_vector_get(p, 2);
  for (size_t i = 0; i < d->n; i++) {
    int capped;
    double x = d->x[i];
    melt_model(l0, xm, xc, d->cap, x, &capped);
    int live = !capped; /* x > xm, below the cap */
    gsl_matrix_set(J, i, 0, live ? log(xc - xm) - log(xc - x) : 0);
    gsl_matrix_set(J, i, 1, live ? -l0 / (xc - xm) : 0);
    gsl_matrix_set(J, i, 2, live ? l0 * (1 / (xc - xm) - 1 / (xc - x)) : 0);
  }
  return GSL_SUCCESS;
}

/* melt's start: the least sum of squares on a grid of xm, xc (over and beyond the range of x)
   and l0 (0.02 to 20, logarithmic); the model is piecewise, so a local fit needs a start in the
   right piece. */
static void melt_start(const data *d, double start[3])
{
  double xlo = d->x[0], xhi = d->x[0], best = INFINITY;
  for (size_t i = 0; i < d->n; i++) {
    if (d->x[i] < xlo) xlo = d->x[i];
    if (d->x[i] > xhi) xhi = d->x[i];
  }
  double span = xhi - xlo > 0 ? xhi - xlo : 1;
  const int nx = 80, nl = 60;
  for (int a = 0; a <= nx; a++) {
    double xm = xlo - 0.25 * span + 1.25 * span * a / nx;
    for (int b = 1; b <= nx; b++) {
      double xc = xm + 1.5 * span * b / nx;
      for (int c = 0; c < nl; c++) {
        double l0 = 0.02 * pow(1000.0, (double)c / (nl - 1)), s = 0;
        int capped;
        for (size_t i = 0; i < d->n && s < best; i++) {
          double r = melt_model(l0, xm, xc, d->cap, d->x[i], &capped) - d->y[i];
          s += r * r;
        }
        if (s < best) {
          best = s;
          start[0] = l0;
          start[1] = xm;
          start[2] = xc;
        }
      }
    }
  }
}

/* Columns xname, yname of a table (wg_table_read_xy, strictly), keeping the rows with
   xmin <= x <= xmax and finite values. */
static int read_table(const char *path, const char *xname, const char *yname, double xmin,
                      double xmax, data *d)
{
  wg_xy t;
  if (wg_table_read_xy(path, xname, yname, 1, &t)) return 1;
  d->n = 0, d->x = t.x, d->y = t.y;
  for (size_t i = 0; i < t.n; i++)
    if (isfinite(t.x[i]) && isfinite(t.y[i]) && t.x[i] >= xmin && t.x[i] <= xmax)
      d->x[d->n] = t.x[i], d->y[d->n++] = t.y[i];
  return 0;
}

static void usage(FILE *out)
{
  fprintf(out,
          "Usage: wetgran-fit --model critical|line|prop|melt --x COL --y COL [--xmin X]\n"
          "                   [--xmax X] [--prefix P] [--guess a,xc,beta] [--cap C] TABLE|-\n"
          "Least-squares fit (GSL trust-region Levenberg-Marquardt) of column y against x:\n"
          "  critical  y = a (xc - x)^beta for x < xc, 0 beyond (Fig. 3.31)\n"
          "  line      y = a + b x (Fig. 3.5)\n"
          "  prop      y = b x, a line through the origin (Fig. 3.5: E* as a slope)\n"
          "  melt      y = l0 ln(1 / (1 - (x - xm) / (xc - xm))) for xm < x < xc, 0 for x <= xm,\n"
          "            never above C (--cap; default the largest y) and C for x >= xc: the\n"
          "            fluidization depth of Fig. 4.4, C the number of layers; started from\n"
          "            the best point of a grid in (l0, xm, xc) unless --guess l0,xm,xc\n"
          "Prints 'key value error' rows: P_a, P_xc, P_beta (or P_a, P_b; or P_b; or P_l0,\n"
          "P_xm, P_xc), P_n (points) and\n"
          "P_chi2_dof; errors are the covariance errors scaled by sqrt(chi^2/dof).\n");
}

int main(int argc, char **argv)
{
  const char *model = NULL, *xname = NULL, *yname = NULL, *path = NULL, *prefix = "fit";
  double xmin = -INFINITY, xmax = INFINITY, guess[3] = {NAN, NAN, NAN}, cap = NAN;
  for (int a = 1; a < argc; a++) {
    const char *o = argv[a];
    if (!strcmp(o, "-h") || !strcmp(o, "--help")) {
      usage(stdout);
      return 0;
    }
    if (a + 1 < argc && !strcmp(o, "--model")) model = argv[++a];
    else if (a + 1 < argc && !strcmp(o, "--x")) xname = argv[++a];
    else if (a + 1 < argc && !strcmp(o, "--y")) yname = argv[++a];
    else if (a + 1 < argc && (!strcmp(o, "--xmin") || !strcmp(o, "--xmax") || !strcmp(o, "--cap"))) {
      if (wg_arg_double(o, argv[++a], !strcmp(o, "--xmin") ? &xmin : !strcmp(o, "--xmax") ? &xmax : &cap) != WG_OK)
        return 2;
    } else if (a + 1 < argc && !strcmp(o, "--prefix")) prefix = argv[++a];
    else if (a + 1 < argc && !strcmp(o, "--guess")) {
      /* up to three comma-separated numbers, each read whole */
      char buf[256], *save = NULL;
      int k = 0;
      snprintf(buf, sizeof buf, "%s", argv[++a]);
      for (char *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save), k++)
        if (k >= 3 || wg_arg_double("--guess", tok, &guess[k]) != WG_OK) {
          if (k >= 3) fprintf(stderr, "wetgran-fit: option --guess: '%s': more than three numbers\n", argv[a]);
          return 2;
        }
    }
    else if (o[0] == '-' && o[1]) {
      fprintf(stderr, "wetgran-fit: unknown or incomplete option '%s' (see --help)\n", o);
      return 2;
    } else path = o;
  }
  int critical = model && !strcmp(model, "critical"), linear = model && !strcmp(model, "line");
  int prop = model && !strcmp(model, "prop"), melt = model && !strcmp(model, "melt");
  if ((!critical && !linear && !prop && !melt) || !xname || !yname || !path) {
    usage(stderr);
    return 2;
  }
  data d;
  if (read_table(path, xname, yname, xmin, xmax, &d)) return 1;
  if (prop) { /* linear least squares: the slope's variance from the scatter about the fit */
    if (d.n < 2) {
      fprintf(stderr, "wetgran-fit: %s: %zu usable points, need at least 2\n", path, d.n);
      return 1;
    }
    double b, cov, sumsq;
    gsl_fit_mul(d.x, 1, d.y, 1, d.n, &b, &cov, &sumsq);
    printf("key\tvalue\terror\n%s_b\t%.6g\t%.3g\n", prefix, b, sqrt(cov));
    printf("%s_n\t%zu\tnan\n%s_chi2_dof\t%.4g\tnan\n", prefix, d.n, prefix, sumsq / (double)(d.n - 1));
    free(d.x);
    free(d.y);
    return 0;
  }
  size_t p = critical || melt ? 3 : 2;
  if (d.n <= p) {
    fprintf(stderr, "wetgran-fit: %s: %zu usable points, need more than %zu\n", path, d.n, p);
    return 1;
  }
  double start[3];
  if (critical) {
    double xhi = d.x[0], ymax = 0;
    for (size_t i = 0; i < d.n; i++) {
      if (d.x[i] > xhi) xhi = d.x[i];
      if (d.y[i] > ymax) ymax = d.y[i];
    }
    start[0] = isfinite(guess[0]) ? guess[0] : ymax;
    start[1] = isfinite(guess[1]) ? guess[1] : xhi * 1.05;
    start[2] = isfinite(guess[2]) ? guess[2] : 0.5;
  } else if (melt) {
    d.cap = cap;
    if (!isfinite(cap))
      for (size_t i = 0; i < d.n; i++)
        if (i == 0 || d.y[i] > d.cap) d.cap = d.y[i];
    if (isfinite(guess[0]) && isfinite(guess[1]) && isfinite(guess[2]))
      for (int k = 0; k < 3; k++) start[k] = guess[k];
    else melt_start(&d, start);
  } else {
    start[0] = 0;
    start[1] = 0;
  }
  gsl_set_error_handler_off();
  gsl_multifit_nlinear_fdf fdf = {critical ? critical_f : melt ? melt_f : line_f,
                                  critical ? critical_df : melt ? melt_df : line_df,
                                  NULL, d.n, p, &d, 0, 0, 0};
  gsl_multifit_nlinear_parameters fp = gsl_multifit_nlinear_default_parameters();
  gsl_multifit_nlinear_workspace *w =
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &fp, d.n, p);
  gsl_vector_view x0 = gsl_vector_view_array(start, p);
  int info, st = gsl_multifit_nlinear_init(&x0.vector, &fdf, w);
  if (st == GSL_SUCCESS)
    st = gsl_multifit_nlinear_driver(MAX_ITER, XTOL, GTOL, FTOL, NULL, NULL, &info, w);
  gsl_matrix *cov = gsl_matrix_alloc(p, p);
  gsl_matrix *J = gsl_multifit_nlinear_jac(w);
  gsl_multifit_nlinear_covar(J, 0.0, cov);
  double chi2;
  gsl_blas_ddot(gsl_multifit_nlinear_residual(w), gsl_multifit_nlinear_residual(w), &chi2);
  double dof = (double)(d.n - p), scale = sqrt(chi2 / dof > 0 ? chi2 / dof : 0);
  const char *names[3][3] = {{"a", "b", ""}, {"a", "xc", "beta"}, {"l0", "xm", "xc"}};
  int kind = melt ? 2 : critical;
  if (st != GSL_SUCCESS)
    fprintf(stderr, "wetgran-fit: %s: the fit did not converge (%s)\n", path, gsl_strerror(st));
  printf("key\tvalue\terror\n");
  for (size_t k = 0; k < p; k++)
    printf("%s_%s\t%.6g\t%.3g\n", prefix, names[kind][k], gsl_vector_get(w->x, k),
           scale * sqrt(gsl_matrix_get(cov, k, k)));
  printf("%s_n\t%zu\tnan\n%s_chi2_dof\t%.4g\tnan\n", prefix, d.n, prefix, chi2 / dof);
  gsl_matrix_free(cov);
  gsl_multifit_nlinear_free(w);
  free(d.x);
  free(d.y);
  return st == GSL_SUCCESS ? 0 : 1;
}
