/* wetgran-theory: the thesis's analytic models, evaluated with GSL, as one tool.
     wetgran-theory MODEL [key=value ...]     key/value rows (header "key\tvalue")
     wetgran-theory MODEL key=start:stop:step [key=value ...]
                                              a curve: the ranged key, then every output, as
                                              columns, one row per point
   Models (thesis equation numbers):
     ffgc         Eq. 3.1: critical E* of the f-fgc transition, with n_Kn(D) and n_c(eps, n_L)
     solid-fluid  Eq. 4.9-4.15: force balance of a shaken column; surface melting (Fig. 4.4)
     shapes       Sec. 5.2: drop/strip window, the pinched-strip saddle (Eq. 5.1), Eq. 5.2
     interface    Eq. 5.9, 5.10, 5.13: interfacial energy and relaxation of a deformed strip
     plug         Eq. 6.5-6.33: Leidenfrost plug oscillation, its instabilities, L_c, Delta T_c
     chain        Eq. 7.3-7.9: chain of bridged grains in a cosine shear field
     a2           Eq. A.59, A.60: Sonine coefficient a_2 of a driven wet granular gas
   Each model is a table of keys (name, offset in its parameter struct, default, meaning), a
   table of outputs (name, meaning) and an evaluation function; help text, parsing and
   printing all come from the tables.  Units: d = m = g = 1, k_B = 1.  Where a printed
   equation has a typo, the comment at the model says what was derived instead and which of
   the thesis's numbers the corrected form reproduces. */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_poly.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_ellint.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plug.h"

#define MAX_OUT 48          /* outputs of one model */
#define MAX_POINTS 1000000  /* points of one curve */
#define ROOT_TOL 1e-13      /* relative tolerance of root finding and minimisation */
#define ODE_TOL 1e-12       /* absolute and relative tolerance of the chain's ODE */

typedef struct wg_theory_key {
  const char *name;
  size_t offset;   /* of the double in the model's parameter struct */
  double def;      /* NAN: not given (see the key's text for what is used instead) */
  const char *doc;
} wg_theory_key;

typedef struct wg_theory_field {
  const char *name;
  const char *doc;
} wg_theory_field;

struct wg_theory_model;

typedef struct wg_theory_result {
  const struct wg_theory_model *model;
  double value[MAX_OUT];
  int set[MAX_OUT];
  char err[512];
} wg_theory_result;

typedef struct wg_theory_model {
  const char *name;
  const char *summary;
  const wg_theory_key *keys;
  size_t nkeys;
  const wg_theory_field *outputs;
  size_t nout;
  int (*eval)(const void *params, wg_theory_result *r);
} wg_theory_model;

/* Sets output `name`; a name missing from the model's table is a programming error. */
static void put(wg_theory_result *r, const char *name, double v)
{
  for (size_t k = 0; k < r->model->nout; k++)
    if (!strcmp(r->model->outputs[k].name, name)) {
      r->value[k] = v;
      r->set[k] = 1;
      return;
    }
  fprintf(stderr, "wetgran-theory: internal error: model %s has no output '%s'\n", r->model->name, name);
  abort();
}

/* A value outside the model's domain: the message names the key and its value. */
static int domain_error(wg_theory_result *r, const char *key, double v, const char *fmt, ...)
{
  int n = snprintf(r->err, sizeof r->err, "%s = %g: ", key, v);
  va_list ap;
  va_start(ap, fmt);
  if (n > 0 && (size_t)n < sizeof r->err) vsnprintf(r->err + n, sizeof r->err - (size_t)n, fmt, ap);
  va_end(ap);
  return 1;
}

#define KEY(type, field, def, doc) {#field, offsetof(type, field), def, doc}

/* ------------------------------------------------------------------------------------------
   ffgc: Eq. 3.1, the f-fgc line of shaken wet grains.  Energy injected at the floor reaches
   the top layer as E_inj eps^(2 n_c) after n_c collisions (Sec. 3.3.2.3); the top layer
   evaporates when that exceeds one bridge per kissing neighbour:
     E*_f-fgc(D, eps, n_L) = n_Kn(D) E0* / eps^(2 n_c(eps, n_L)),  E0* = 1/6,
     n_c(eps, n_L) = A1 exp(A2 eps) + n_L - 1  (fit of Fig. 3.16b: A1 = 7.3e-3, A2 = 6.95),
   n_Kn = 2, 6, 12, 24 in 1-4 dimensions (Musin 2008).  At eps = 1 the number of collisions
   drops out: E* = n_Kn/6 = 1 (2D), 2 (3D). */
typedef struct ffgc_params {
  double dim, eps, nl, nc, a1, a2, e0;
} ffgc_params;

static const wg_theory_key ffgc_keys[] = {
    KEY(ffgc_params, dim, 2, "dimension D (1, 2, 3 or 4)"),
    KEY(ffgc_params, eps, 1, "coefficient of restitution, 0 < eps <= 1"),
    KEY(ffgc_params, nl, 3, "number of particle layers n_L (>= 1)"),
    KEY(ffgc_params, nc, NAN, "collisions per wall collision n_c; not given: the fit of Fig. 3.16b"),
    KEY(ffgc_params, a1, 7.3e-3, "A1 of the n_c fit (Fig. 3.16b)"),
    KEY(ffgc_params, a2, 6.95, "A2 of the n_c fit (Fig. 3.16b)"),
    KEY(ffgc_params, e0, 1.0 / 6.0, "E0* of Eq. 3.1"),
};

static const wg_theory_field ffgc_outputs[] = {
    {"n_kn", "kissing number n_Kn(D)"},
    {"n_ilc", "intra-layer collisions n_L - 1, the lower bound of n_c (Fig. 3.16b)"},
    {"n_c", "collisions per wall collision n_c = A1 exp(A2 eps) + n_L - 1 (or the given nc)"},
    {"estar", "E*_f-fgc = n_Kn E0* / eps^(2 n_c) (Eq. 3.1)"},
};

static double wg_theory_ffgc_kissing(int dim)
{
  static const double kissing[] = {0, 2, 6, 12, 24};
  return kissing[dim];
}

static double wg_theory_ffgc_nc(double eps, double nl, double a1, double a2)
{
  return a1 * exp(a2 * eps) + nl - 1; /* Fig. 3.16b */
}

static double wg_theory_ffgc_estar(double n_kn, double e0, double eps, double nc)
{
  return n_kn * e0 / pow(eps, 2 * nc); /* Eq. 3.1 */
}

static int ffgc_eval(const void *params, wg_theory_result *r)
{
  const ffgc_params *p = params;
  if (p->dim != floor(p->dim) || p->dim < 1 || p->dim > 4)
    return domain_error(r, "dim", p->dim, "Eq. 3.1 needs a kissing number: dimension 1, 2, 3 or 4");
  if (!(p->eps > 0 && p->eps <= 1)) return domain_error(r, "eps", p->eps, "must lie in (0, 1]");
  if (!(p->nl >= 1)) return domain_error(r, "nl", p->nl, "needs at least one layer");
  if (!isnan(p->nc) && !(p->nc >= 0)) return domain_error(r, "nc", p->nc, "must be >= 0");
  double n_kn = wg_theory_ffgc_kissing((int)p->dim);
  double nc = isnan(p->nc) ? wg_theory_ffgc_nc(p->eps, p->nl, p->a1, p->a2) : p->nc;
  put(r, "n_kn", n_kn);
  put(r, "n_ilc", p->nl - 1);
  put(r, "n_c", nc);
  put(r, "estar", wg_theory_ffgc_estar(n_kn, p->e0, p->eps, nc));
  return 0;
}

/* ------------------------------------------------------------------------------------------
   solid-fluid: Ch. 4, the force balance of a column of M layers on a floor shaken at its peak
   acceleration Gamma (Eq. 4.8): F_B/mg + 1 - h = f k_B T_g/(mg l_m) + M (Gamma - 1).
     Eq. 4.9   l_m(h) = (f T_g/mg) / (F_B/mg + M (1 - Gamma) - h + 1)  (inf where the
               denominator is <= 0: nothing holds the layer down)
     Eq. 4.10  Gamma_M = (1/M) ((F_B - f T_g/s_crit)/mg + 1)   top layer starts to melt
     Eq. 4.11  h_c(Gamma) = M (1 + Gamma_M - Gamma)             layers above h_c are fluid
     Eq. 4.12  T_g < (E_cb + mg s_crit)/f                       i.e. Gamma_M > 0
     Eq. 4.13  Gamma_C = 1 + Gamma_M - 1/M                      complete fluidization, h_c = 1
     Eq. 4.14  Gamma_C > 1 - 1/M
     Eq. 4.15  Gamma_C = 1 + F_B (1 - E*)/(M mg)                with f T_g = E_kin = E* E_cb
   E_cb = F_B s_crit.  Unless tg is given, f T_g = E* E_cb (the text before Eq. 4.15), so that
   Eq. 4.13 and Eq. 4.15 coincide.
   Surface melting (Fig. 4.4), the number of fluid layers l_s against Gamma:
     linear (red line, Eq. 4.11)  l_s = (M - 1)(Gamma - Gamma_M)/(Gamma_C - Gamma_M)
     fit form (black line)        l_s = l0 ln(1/(1 - (Gamma - Gamma_M)/(Gamma_C - Gamma_M)))
   both 0 for Gamma <= Gamma_M and M (every layer fluid) for Gamma >= Gamma_C; the fit form is
   never above M (the convention of wetgran-fit --model melt).  The caption writes
   l_s = h_c - M; the number of fluid layers is M - h_c = M (Gamma - Gamma_M), which is the
   caption's red line when Gamma_C is that of Eq. 4.13.  Fig. 4.4 uses fitted Gamma_M = 1.16
   and Gamma_C = 2.65 (keys gm, gc), not Eq. 4.10/4.13. */
typedef struct sf_params {
  double M, fb, scrit, estar, tg, f, gamma, h, l0, gm, gc;
} sf_params;

static const wg_theory_key sf_keys[] = {
    KEY(sf_params, M, 3, "number of layers M"),
    KEY(sf_params, fb, 4, "bridge force F_B/mg"),
    KEY(sf_params, scrit, 0.036, "rupture distance s_crit/d"),
    KEY(sf_params, estar, 0.4, "driving energy E* = m(A omega)^2/(2 E_cb)"),
    KEY(sf_params, tg, NAN, "granular temperature T_g; not given: f T_g = E* E_cb (Eq. 4.15)"),
    KEY(sf_params, f, 2, "degrees of freedom f (2 for disks, 3 for spheres)"),
    KEY(sf_params, gamma, 1.5, "peak acceleration Gamma = A omega^2/g"),
    KEY(sf_params, h, 1, "layer h of l_m (1 = bottom, M = top)"),
    KEY(sf_params, l0, 1.27, "l0 of the surface-melting fit form (Fig. 4.4)"),
    KEY(sf_params, gm, NAN, "Gamma_M of the surface-melting forms; not given: Eq. 4.10"),
    KEY(sf_params, gc, NAN, "Gamma_C of the surface-melting forms; not given: Eq. 4.13"),
};

static const wg_theory_field sf_outputs[] = {
    {"ecb", "bridge energy E_cb = F_B s_crit"},
    {"ftg", "f k_B T_g used"},
    {"l_m", "mean free path of layer h at Gamma (Eq. 4.9)"},
    {"gamma_m", "Gamma_M: the top layer melts above it (Eq. 4.10)"},
    {"h_c", "critical height h_c(Gamma) (Eq. 4.11)"},
    {"tg_max", "largest T_g with Gamma_M > 0 (Eq. 4.12)"},
    {"gamma_c", "Gamma_C of complete fluidization (Eq. 4.13)"},
    {"gamma_c_min", "lower bound of Gamma_C, 1 - 1/M (Eq. 4.14)"},
    {"gamma_c_415", "Gamma_C = 1 + F_B (1 - E*)/(M mg) (Eq. 4.15)"},
    {"l_s_lin", "fluid layers, linear form (Eq. 4.11, Fig. 4.4 red)"},
    {"l_s_log", "fluid layers, fit form l0 ln(1/(1 - u)) (Fig. 4.4 black)"},
};

static double wg_theory_sf_mean_free_path(double ftg, double fb, double M, double gamma, double h)
{
  double hold = fb + M * (1 - gamma) - h + 1; /* Eq. 4.9 */
  return hold > 0 ? ftg / hold : INFINITY;
}

static double wg_theory_sf_gamma_m(double ftg, double fb, double scrit, double M)
{
  return (fb - ftg / scrit + 1) / M; /* Eq. 4.10 */
}

/* Fluid layers at gamma between gm and gc: linear (Eq. 4.11) or the fit form of Fig. 4.4. */
static double wg_theory_sf_melt_depth(int logarithmic, double M, double l0, double gm, double gc,
                                      double gamma)
{
  if (gamma <= gm) return 0;
  if (gamma >= gc) return M;
  double u = (gamma - gm) / (gc - gm);
  double ls = logarithmic ? l0 * log(1 / (1 - u)) : (M - 1) * u;
  return ls < M ? ls : M;
}

static int sf_eval(const void *params, wg_theory_result *r)
{
  const sf_params *p = params;
  if (!(p->M >= 1)) return domain_error(r, "M", p->M, "needs at least one layer");
  if (!(p->fb >= 0)) return domain_error(r, "fb", p->fb, "must be >= 0");
  if (!(p->scrit > 0)) return domain_error(r, "scrit", p->scrit, "must be > 0");
  if (!(p->f > 0)) return domain_error(r, "f", p->f, "must be > 0");
  if (!(p->estar >= 0)) return domain_error(r, "estar", p->estar, "must be >= 0");
  if (!isnan(p->tg) && !(p->tg >= 0)) return domain_error(r, "tg", p->tg, "must be >= 0");
  if (!(p->gamma >= 0)) return domain_error(r, "gamma", p->gamma, "must be >= 0");
  if (!(p->h >= 1)) return domain_error(r, "h", p->h, "layers are counted from 1");
  if (!(p->l0 > 0)) return domain_error(r, "l0", p->l0, "must be > 0");
  double ecb = p->fb * p->scrit;
  double ftg = isnan(p->tg) ? p->estar * ecb : p->f * p->tg;
  double gamma_m = wg_theory_sf_gamma_m(ftg, p->fb, p->scrit, p->M);
  double gamma_c = 1 + gamma_m - 1 / p->M; /* Eq. 4.13 */
  double gm = isnan(p->gm) ? gamma_m : p->gm, gc = isnan(p->gc) ? gamma_c : p->gc;
  if (!(gc > gm))
    return domain_error(r, isnan(p->gc) ? "gm" : "gc", isnan(p->gc) ? gm : gc,
                        "surface melting needs Gamma_C > Gamma_M (here %g, %g)", gc, gm);
  put(r, "ecb", ecb);
  put(r, "ftg", ftg);
  put(r, "l_m", wg_theory_sf_mean_free_path(ftg, p->fb, p->M, p->gamma, p->h));
  put(r, "gamma_m", gamma_m);
  put(r, "h_c", p->M * (1 + gamma_m - p->gamma)); /* Eq. 4.11 */
  put(r, "tg_max", (ecb + p->scrit) / p->f);      /* Eq. 4.12 */
  put(r, "gamma_c", gamma_c);
  put(r, "gamma_c_min", 1 - 1 / p->M);                       /* Eq. 4.14 */
  put(r, "gamma_c_415", 1 + p->fb * (1 - p->estar) / p->M); /* Eq. 4.15 */
  put(r, "l_s_lin", wg_theory_sf_melt_depth(0, p->M, p->l0, gm, gc, p->gamma));
  put(r, "l_s_log", wg_theory_sf_melt_depth(1, p->M, p->l0, gm, gc, p->gamma));
  return 0;
}

/* ------------------------------------------------------------------------------------------
   shapes: Sec. 5.2, the shape of a coexisting minority phase of area fraction a on the
   periodic L x L square (lengths in units of L).  A drop of area a has the interface length
   2 sqrt(pi a), a strip 2 (two straight interfaces); they are equal at a = 1/pi, so the strip
   is favoured for 1/pi <= a_g <= 1 - 1/pi (the minority phase is the gas below 1/2, the fluid
   above).
   The saddle between drop and strip (Leung and Zia 1990; Eq. 5.1): the 'pinched strip', a
   lens of two circular arcs of equal radius spanning one period L and touching itself at the
   periodic images of its tips.  Arcs of half-angle theta (radius R = L/(2 sin theta)) enclose
   the area (theta - sin theta cos theta)/(2 sin^2 theta) L^2 and have the length
   2 theta/sin theta L: for given area a (a <= pi/4, the circle of diameter L touching itself)
   theta follows by root finding, and the excess length over the strip is
   (1/2) da - 1 = theta/sin theta - 1.  Equal arcs are the constrained minimum (equal pressure
   on both sides); at a = 1/pi this gives 0.13485, while Eq. 5.1 quotes Leung and Zia's
   0.1346... (J. Phys. A 23, 4593 (1990)), 2.5e-4 lower: the construction above does not pin
   down their last digits, so both are printed, the quoted number as excess_lz.
   Eq. 5.2: the excess length of a drop of the measured critical area a_D/S (Fig. 5.2c) over
   the strip, sqrt(pi a_D/S) - 1, with the error propagated from that of a_D/S. */
typedef struct shapes_params {
  double ag, ads, ads_err;
} shapes_params;

static const wg_theory_key shapes_keys[] = {
    KEY(shapes_params, ag, 0.25, "area fraction of the gas a_g, 0 < a_g < 1"),
    KEY(shapes_params, ads, 0.413, "measured area a_D/S of the drop-to-strip transition (Fig. 5.2c)"),
    KEY(shapes_params, ads_err, 0.013, "error of a_D/S"),
};

static const wg_theory_field shapes_outputs[] = {
    {"ag_lo", "lower edge of the strip window, 1/pi"},
    {"ag_hi", "upper edge of the strip window, 1 - 1/pi"},
    {"shape", "shape of least interface at a_g: 1 gas drop (I), 2 strip (II), 3 fluid drop (III)"},
    {"len_drop", "interface length of a drop of the minority phase, 2 sqrt(pi min(a_g, 1 - a_g))"},
    {"len_strip", "interface length of the strip, 2"},
    {"len_lens", "interface length of the pinched-strip lens enclosing the minority area"},
    {"excess_lens", "(1/2) da - 1 of the lens at a = 1/pi (Eq. 5.1, computed)"},
    {"excess_lz", "(1/2) da - 1 as quoted from Leung and Zia 1990 (Eq. 5.1): 0.1346"},
    {"excess_52", "sqrt(pi a_D/S) - 1 (Eq. 5.2)"},
    {"excess_52_err", "its error, sqrt(pi/a_D/S) err(a_D/S)/2"},
};

#define LEUNG_ZIA_EXCESS 0.1346 /* Eq. 5.1, quoted from Leung and Zia 1990 */

static double lens_area(double theta, void *target)
{
  double s = sin(theta);
  return (theta - s * cos(theta)) / (2 * s * s) - *(double *)target;
}

/* Half-angle of the lens of area a (0 < a <= pi/4); NAN above pi/4. */
static double wg_theory_shapes_lens_angle(double a)
{
  if (a > M_PI_4) return NAN;
  if (a == M_PI_4) return M_PI_2;
  gsl_function F = {lens_area, &a};
  gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  gsl_root_fsolver_set(s, &F, 1e-9, M_PI_2); /* area ~ theta/3 near 0: bracketed for a > 1e-9/3 */
  double lo = 1e-9, hi = M_PI_2;
  for (int it = 0; it < 200; it++) {
    gsl_root_fsolver_iterate(s);
    lo = gsl_root_fsolver_x_lower(s);
    hi = gsl_root_fsolver_x_upper(s);
    if (gsl_root_test_interval(lo, hi, 0, ROOT_TOL) == GSL_SUCCESS) break;
  }
  gsl_root_fsolver_free(s);
  return 0.5 * (lo + hi);
}

static double wg_theory_shapes_lens_excess(double a)
{
  double theta = wg_theory_shapes_lens_angle(a);
  return theta / sin(theta) - 1;
}

static int shapes_eval(const void *params, wg_theory_result *r)
{
  const shapes_params *p = params;
  if (!(p->ag > 0 && p->ag < 1)) return domain_error(r, "ag", p->ag, "must lie in (0, 1)");
  if (!(p->ads > 0 && p->ads < 1)) return domain_error(r, "ads", p->ads, "must lie in (0, 1)");
  if (!(p->ads_err >= 0)) return domain_error(r, "ads_err", p->ads_err, "must be >= 0");
  if (!(p->ag >= 1e-8 && p->ag <= 1 - 1e-8))
    return domain_error(r, "ag", p->ag, "too close to 0 or 1 for the lens");
  double lo = 1 / M_PI, hi = 1 - 1 / M_PI, minority = p->ag < 0.5 ? p->ag : 1 - p->ag;
  put(r, "ag_lo", lo);
  put(r, "ag_hi", hi);
  put(r, "shape", p->ag < lo ? 1 : p->ag <= hi ? 2 : 3);
  put(r, "len_drop", 2 * sqrt(M_PI * minority));
  put(r, "len_strip", 2);
  put(r, "len_lens", 2 * (wg_theory_shapes_lens_excess(minority) + 1));
  put(r, "excess_lens", wg_theory_shapes_lens_excess(1 / M_PI));
  put(r, "excess_lz", LEUNG_ZIA_EXCESS);
  put(r, "excess_52", sqrt(M_PI * p->ads) - 1); /* Eq. 5.2 */
  put(r, "excess_52_err", 0.5 * sqrt(M_PI / p->ads) * p->ads_err);
  return 0;
}

/* ------------------------------------------------------------------------------------------
   interface: Sec. 5.3, a fluid strip deformed by the shear field F_smax cos(2 pi x/L_x).
     Eq. 5.6   H_V = N_p F_smax A~_d / 2                (gain of potential energy)
     Eq. 5.8   H_sigma = 2 pi^2 sigma A~_d^2            (two interfaces)
     Eq. 5.9   sigma = N_p F_smax / ((2 pi)^2 A~_d)     (H_V = H_sigma; A~_d = A_d/L_x)
     Eq. 5.10  sigma/gamma = (pi/6) n_cb d s_crit n^(-1/3)   (cutting a lattice of bridges)
     Eq. 5.13  A~_d(t) = A~_e0 exp(-(2 pi)^2 sigma mu_f t)
   and, inverting Eq. 5.13 for a fitted decay rate k, mu_f = k/((2 pi)^2 sigma).  sigma is in
   the units of F_smax (both A~_d and the interface length are in units of L_x, which
   cancel); keys without a default give nan in the outputs that use them. */
typedef struct iface_params {
  double np, fsmax, ad, ncb, n, scrit, d, a0, sigma, mu, t, rate;
} iface_params;

static const wg_theory_key iface_keys[] = {
    KEY(iface_params, np, NAN, "particles in the fluid phase N_p"),
    KEY(iface_params, fsmax, NAN, "largest shear force F_smax"),
    KEY(iface_params, ad, NAN, "deformation amplitude A~_d = A_d/L_x"),
    KEY(iface_params, ncb, NAN, "bridge number density n_cb of the fluid [1/d^3]"),
    KEY(iface_params, n, NAN, "particle number density n of the fluid [1/d^3]"),
    KEY(iface_params, scrit, 0.0625, "rupture distance s_crit/d"),
    KEY(iface_params, d, 1, "particle diameter d"),
    KEY(iface_params, a0, NAN, "initial amplitude A~_e0 of the relaxation (Eq. 5.13)"),
    KEY(iface_params, sigma, NAN, "interfacial energy for Eq. 5.13; not given: Eq. 5.9"),
    KEY(iface_params, mu, NAN, "mobility mu_f"),
    KEY(iface_params, t, 0, "time t of Eq. 5.13"),
    KEY(iface_params, rate, NAN, "fitted decay rate k of A~_d(t) (gives mu_f)"),
};

static const wg_theory_field iface_outputs[] = {
    {"h_v", "H_V = N_p F_smax A~_d / 2 (Eq. 5.6)"},
    {"sigma", "sigma = N_p F_smax / ((2 pi)^2 A~_d) (Eq. 5.9)"},
    {"h_sigma", "H_sigma = 2 pi^2 sigma A~_d^2 (Eq. 5.8)"},
    {"sigma_gamma", "sigma/gamma = (pi/6) n_cb d s_crit n^(-1/3) (Eq. 5.10)"},
    {"ad_t", "A~_d(t) = A~_e0 exp(-(2 pi)^2 sigma mu_f t) (Eq. 5.13)"},
    {"mu_f", "mu_f = k / ((2 pi)^2 sigma) from the decay rate (Eq. 5.13)"},
};

static int iface_eval(const void *params, wg_theory_result *r)
{
  const iface_params *p = params;
  if (!isnan(p->ad) && !(p->ad > 0)) return domain_error(r, "ad", p->ad, "must be > 0");
  if (!isnan(p->n) && !(p->n > 0)) return domain_error(r, "n", p->n, "must be > 0");
  if (!isnan(p->np) && !(p->np >= 0)) return domain_error(r, "np", p->np, "must be >= 0");
  if (!isnan(p->ncb) && !(p->ncb >= 0)) return domain_error(r, "ncb", p->ncb, "must be >= 0");
  if (!(p->scrit > 0)) return domain_error(r, "scrit", p->scrit, "must be > 0");
  if (!(p->d > 0)) return domain_error(r, "d", p->d, "must be > 0");
  const double k2 = 4 * M_PI * M_PI;
  double sigma59 = p->np * p->fsmax / (k2 * p->ad); /* Eq. 5.9 */
  double sigma = isnan(p->sigma) ? sigma59 : p->sigma;
  put(r, "h_v", 0.5 * p->np * p->fsmax * p->ad);                  /* Eq. 5.6 */
  put(r, "sigma", sigma59);
  put(r, "h_sigma", 2 * M_PI * M_PI * sigma59 * p->ad * p->ad);   /* Eq. 5.8 */
  put(r, "sigma_gamma", M_PI / 6 * p->ncb * p->d * p->scrit * cbrt(1 / p->n)); /* Eq. 5.10 */
  put(r, "ad_t", p->a0 * exp(-k2 * sigma * p->mu * p->t));       /* Eq. 5.13 */
  put(r, "mu_f", p->rate / (k2 * sigma));
  return 0;
}

/* ------------------------------------------------------------------------------------------
   plug: Ch. 6, the granular Leidenfrost plug on its gas cushion (units of time sqrt(d/g)).
     Eq. 6.5   omega_p = sqrt(kappa g/h0 (1 + V_ex/(A_g h0))), V_ex = 4 N V_bead; the
               isothermal sqrt(g/h0) and adiabatic sqrt(kappa g/h0) ideal-gas limits too.
               Eq. 6.5 is the first order in V_ex/V of p (V - V_ex)^kappa = const, whose
               exact linearisation is omega_p^2 = kappa g/h0 / (1 - V_ex/V) (omega_p_vdw).
     Eq. 6.10  Lambda (Lambda^2 + B Lambda + 1) = 0: Lambda_0 = 0 and (Eq. 6.11)
               Lambda_pm = -B/2 +- sqrt(B^2/4 - 1); B = nu/omega_p, Lambda = lambda/omega_p.
     Eq. 6.15  (Lambda^2 + 1)(Lambda + B) - B + A = 0, i.e. Lambda^3 + B Lambda^2 + Lambda + A
               = 0, with the temperature gradient A of Eq. 6.16; A = B is undamped (+-i).
     Eq. 6.21  (lambda^2 + Omega^2)(lambda + b) = (omega_p^2/kappa)(kappa b - theta) with
               b = nu + beta Q^2, Omega^2 = omega_p^2 - omega_1^2 (1 - Q^2), omega_1^2 = g/h_p;
               its largest real part is growth_621.  Scaled by Omega (Omega^2 > 0) it is
     Eq. 6.22  (Lambda^2 + 1)(Lambda + B) + (omega_p^2/Omega^2)(theta/(kappa Omega) - B) = 0,
               B = b/Omega, or Eq. 6.24: Lambda (Lambda^2 + B Lambda + 1) = C with
               C = alpha B - theta (1 + alpha)/(kappa Omega), alpha = omega_p^2/Omega^2 - 1
               (Eq. 6.25 is this with omega_p^2/omega_1^2 = kappa h_p/h0, i.e. without
               excluded volume).
     Eq. 6.23  theta_c = kappa (nu + beta Q^2)  (oscillatory instability)
     Eq. 6.26  theta_RT = alpha/(1 + alpha) theta_c  (Rayleigh-Taylor, C = 0)
               = (nu + beta Q^2) h0 (1 - Q^2)/h_p for n = 0: kappa cancels.
     Eq. 6.27  the width L_c at which theta_RT = theta for the largest mode Q = 2 pi l/L_c,
               solving the quadratic in Q^2 of Eq. 6.26 (n = 0):
                 L_c = sqrt(2) pi l sqrt((h0 (nu - beta) + sqrt(h0 (h0 (beta + nu)^2
                       - 4 h_p beta theta))) / (h0 nu - h_p theta)).
               The thesis prints the prefactor as sqrt(2 pi l), which is not a length and
               misses its own limit Eq. 6.28/6.31 (L_c -> 2 pi l as h_p -> 0); sqrt(2) pi l
               meets both, and the test checks theta_RT(2 pi l/L_c) = theta.
     Eq. 6.28  L_c = 2 pi l + pi l theta h_p/(h0 (beta + nu)) + O(h_p^2)
     Eq. 6.31  L_c = 2 pi l;  Eq. 6.33  L_c = pi h_p  (with h_p = 2 l, Eq. 6.32)
     Eq. 6.29  Delta T_c = 2 kappa H/(3 k_B);  Eq. 6.30  Delta T_c = (10/9) Z_b E_cb, which is
               Eq. 6.29 at kappa = 5/3 with H = Z_b E_cb (the default of H). */
typedef struct plug_params {
  double h0, n, area, vbead, kappa, B, A, hp, Q, nu, beta, theta, l, zb, ecb, H;
} plug_params;

static const wg_theory_key plug_keys[] = {
    KEY(plug_params, h0, 10, "mean height h0 of the gas cushion"),
    KEY(plug_params, n, 0, "particles N in the gas (excluded volume of Eq. 6.5)"),
    KEY(plug_params, area, 625, "cross section A_g of the tube"),
    KEY(plug_params, vbead, M_PI / 6, "volume of one bead V_bead (pi d^3/6)"),
    KEY(plug_params, kappa, 5.0 / 3.0, "adiabatic index kappa"),
    KEY(plug_params, B, 1, "exchange frequency B = nu/omega_p of Eq. 6.10, 6.15"),
    KEY(plug_params, A, 0, "temperature gradient A of Eq. 6.15 (Eq. 6.16)"),
    KEY(plug_params, hp, 10, "height h_p of the plug"),
    KEY(plug_params, Q, 0, "wave number Q = q l of Eq. 6.21-6.26"),
    KEY(plug_params, nu, 0.1, "exchange frequency nu of Eq. 6.21-6.28"),
    KEY(plug_params, beta, 0.05, "lateral flow rate beta = p0 h0^2/(12 eta l^2)"),
    KEY(plug_params, theta, 0, "temperature gradient theta (Eq. 6.14)"),
    KEY(plug_params, l, 1, "capillary length l"),
    KEY(plug_params, zb, 6, "coordination number Z_b at the plug's interface"),
    KEY(plug_params, ecb, 1, "bridge energy E_cb"),
    KEY(plug_params, H, NAN, "energy of evaporation H; not given: Z_b E_cb"),
};

static const wg_theory_field plug_outputs[] = {
    {"v_ex", "excluded volume V_ex = 4 N V_bead"},
    {"omega_p", "plug frequency (Eq. 6.5)"},
    {"omega_p_iso", "isothermal ideal gas, sqrt(g/h0)"},
    {"omega_p_ad", "adiabatic ideal gas, sqrt(kappa g/h0)"},
    {"omega_p_vdw", "exact linearisation of p (V - V_ex)^kappa = const"},
    {"t_p", "period 2 pi/omega_p"},
    {"lam610_p_re", "Lambda_+ of Eq. 6.11, real part"},
    {"lam610_p_im", "Lambda_+ of Eq. 6.11, imaginary part"},
    {"lam610_m_re", "Lambda_- of Eq. 6.11, real part"},
    {"lam610_m_im", "Lambda_- of Eq. 6.11, imaginary part"},
    {"lam615_1_re", "roots of Eq. 6.15 by decreasing real (then imaginary) part: 1, real part"},
    {"lam615_1_im", "root 1, imaginary part"},
    {"lam615_2_re", "root 2, real part"},
    {"lam615_2_im", "root 2, imaginary part"},
    {"lam615_3_re", "root 3, real part"},
    {"lam615_3_im", "root 3, imaginary part"},
    {"omega_1", "omega_1 = sqrt(g/h_p)"},
    {"omega2", "Omega^2 = omega_p^2 - omega_1^2 (1 - Q^2)"},
    {"alpha", "alpha = omega_p^2/Omega^2 - 1 (Eq. 6.25)"},
    {"B_622", "B = (nu + beta Q^2)/Omega (Eq. 6.22; nan if Omega^2 <= 0)"},
    {"C_624", "C = alpha B - theta (1 + alpha)/(kappa Omega) (Eq. 6.24; nan if Omega^2 <= 0)"},
    {"lam622_1_re", "roots Lambda of Eq. 6.22, ordered as for Eq. 6.15: 1, real part"},
    {"lam622_1_im", "root 1, imaginary part"},
    {"lam622_2_re", "root 2, real part"},
    {"lam622_2_im", "root 2, imaginary part"},
    {"lam622_3_re", "root 3, real part"},
    {"lam622_3_im", "root 3, imaginary part"},
    {"growth_621", "largest real part of the roots lambda of Eq. 6.21 [1/time]"},
    {"theta_c", "theta_c = kappa (nu + beta Q^2) (Eq. 6.23)"},
    {"theta_rt", "theta_RT = alpha/(1 + alpha) theta_c (Eq. 6.26)"},
    {"lc_627", "critical width L_c (Eq. 6.27, prefactor corrected; nan without solution)"},
    {"lc_628", "L_c to first order in h_p (Eq. 6.28)"},
    {"lc_631", "L_c = 2 pi l (Eq. 6.31)"},
    {"lc_633", "L_c = pi h_p (Eq. 6.33)"},
    {"dtc_629", "Delta T_c = 2 kappa H/3 (Eq. 6.29)"},
    {"dtc_630", "Delta T_c = (10/9) Z_b E_cb (Eq. 6.30)"},
};

/* Roots of x^3 + c2 x^2 + c1 x + c0, ordered by decreasing real part, then imaginary part. */
static int wg_theory_cubic_roots(double c2, double c1, double c0, double re[3], double im[3])
{
  double coef[4] = {c0, c1, c2, 1}, z[6];
  gsl_poly_complex_workspace *w = gsl_poly_complex_workspace_alloc(4);
  int st = gsl_poly_complex_solve(coef, 4, w, z);
  gsl_poly_complex_workspace_free(w);
  for (int k = 0; k < 3; k++) {
    re[k] = st == GSL_SUCCESS ? z[2 * k] : NAN;
    im[k] = st == GSL_SUCCESS ? z[2 * k + 1] : NAN;
  }
  for (int a = 0; a < 3; a++) /* three elements: exchange sort */
    for (int b = a + 1; b < 3; b++)
      if (re[b] > re[a] || (re[b] == re[a] && im[b] > im[a])) {
        double t = re[a];
        re[a] = re[b];
        re[b] = t;
        t = im[a];
        im[a] = im[b];
        im[b] = t;
      }
  return st;
}

/* Eq. 6.27 with the prefactor sqrt(2) pi l (see the model's comment); NAN without a real,
   positive solution. */
static double wg_theory_plug_lc(double l, double h0, double hp, double nu, double beta, double theta)
{
  double disc = h0 * (h0 * (beta + nu) * (beta + nu) - 4 * hp * beta * theta);
  double den = h0 * nu - hp * theta;
  if (disc < 0 || den <= 0) return NAN;
  double x = (h0 * (nu - beta) + sqrt(disc)) / den;
  return x > 0 ? M_SQRT2 * M_PI * l * sqrt(x) : NAN;
}

static int plug_eval(const void *params, wg_theory_result *r)
{
  const plug_params *p = params;
  if (!(p->h0 > 0)) return domain_error(r, "h0", p->h0, "must be > 0");
  if (!(p->area > 0)) return domain_error(r, "area", p->area, "must be > 0");
  if (!(p->n >= 0)) return domain_error(r, "n", p->n, "must be >= 0");
  if (!(p->vbead >= 0)) return domain_error(r, "vbead", p->vbead, "must be >= 0");
  if (!(p->kappa > 0)) return domain_error(r, "kappa", p->kappa, "must be > 0");
  if (!(p->hp > 0)) return domain_error(r, "hp", p->hp, "must be > 0");
  if (!(p->l > 0)) return domain_error(r, "l", p->l, "must be > 0");
  if (!(p->nu >= 0)) return domain_error(r, "nu", p->nu, "must be >= 0");
  if (!(p->beta >= 0)) return domain_error(r, "beta", p->beta, "must be >= 0");
  double v_ex = 4 * p->n * p->vbead, vol = p->area * p->h0;
  if (!(v_ex < vol))
    return domain_error(r, "n", p->n, "excluded volume %g fills the cushion's volume %g", v_ex, vol);
  double wad2 = p->kappa / p->h0;
  double wp2 = wg_plug_omega2(p->kappa, 1, p->h0, v_ex, p->area);
  put(r, "v_ex", v_ex);
  put(r, "omega_p", sqrt(wp2));
  put(r, "omega_p_iso", sqrt(1 / p->h0));
  put(r, "omega_p_ad", sqrt(wad2));
  put(r, "omega_p_vdw", sqrt(wad2 / (1 - v_ex / vol)));
  put(r, "t_p", 2 * M_PI / sqrt(wp2));

  double disc = p->B * p->B / 4 - 1; /* Eq. 6.11 */
  double sq = sqrt(fabs(disc));
  put(r, "lam610_p_re", -p->B / 2 + (disc >= 0 ? sq : 0));
  put(r, "lam610_p_im", disc >= 0 ? 0 : sq);
  put(r, "lam610_m_re", -p->B / 2 - (disc >= 0 ? sq : 0));
  put(r, "lam610_m_im", disc >= 0 ? 0 : -sq);

  double re[3], im[3];
  static const char *const n615[3][2] = {{"lam615_1_re", "lam615_1_im"}, {"lam615_2_re", "lam615_2_im"},
                                         {"lam615_3_re", "lam615_3_im"}};
  static const char *const n622[3][2] = {{"lam622_1_re", "lam622_1_im"}, {"lam622_2_re", "lam622_2_im"},
                                         {"lam622_3_re", "lam622_3_im"}};
  wg_theory_cubic_roots(p->B, 1, p->A, re, im); /* Eq. 6.15 */
  for (int k = 0; k < 3; k++) {
    put(r, n615[k][0], re[k]);
    put(r, n615[k][1], im[k]);
  }

  double q2 = p->Q * p->Q, b = p->nu + p->beta * q2;
  double w1sq = 1 / p->hp, omega2 = wp2 - w1sq * (1 - q2);
  double alpha = wp2 / omega2 - 1; /* Eq. 6.25 */
  double theta_c = p->kappa * b;   /* Eq. 6.23 */
  put(r, "omega_1", sqrt(w1sq));
  put(r, "omega2", omega2);
  put(r, "alpha", alpha);
  put(r, "theta_c", theta_c);
  put(r, "theta_rt", alpha / (1 + alpha) * theta_c); /* Eq. 6.26 */
  if (omega2 > 0) {
    double om = sqrt(omega2), B = b / om;
    double C = alpha * B - p->theta * (1 + alpha) / (p->kappa * om); /* Eq. 6.24 */
    put(r, "B_622", B);
    put(r, "C_624", C);
    wg_theory_cubic_roots(B, 1, -C, re, im); /* Eq. 6.22 as Lambda^3 + B Lambda^2 + Lambda - C */
  } else {
    put(r, "B_622", NAN);
    put(r, "C_624", NAN);
    for (int k = 0; k < 3; k++) re[k] = im[k] = NAN;
  }
  for (int k = 0; k < 3; k++) {
    put(r, n622[k][0], re[k]);
    put(r, n622[k][1], im[k]);
  }
  /* Eq. 6.21 unscaled: lambda^3 + b lambda^2 + Omega^2 lambda + Omega^2 b - omega_p^2 (b - theta/kappa) */
  wg_theory_cubic_roots(b, omega2, omega2 * b - wp2 * (b - p->theta / p->kappa), re, im);
  put(r, "growth_621", re[0]);

  put(r, "lc_627", wg_theory_plug_lc(p->l, p->h0, p->hp, p->nu, p->beta, p->theta));
  put(r, "lc_628", 2 * M_PI * p->l + M_PI * p->l * p->theta * p->hp / (p->h0 * (p->beta + p->nu)));
  put(r, "lc_631", 2 * M_PI * p->l);
  put(r, "lc_633", M_PI * p->hp);
  double H = isnan(p->H) ? p->zb * p->ecb : p->H;
  put(r, "dtc_629", 2 * p->kappa * H / 3);
  put(r, "dtc_630", 10.0 / 9.0 * p->zb * p->ecb);
  return 0;
}

/* ------------------------------------------------------------------------------------------
   chain: Ch. 7, a chain of bridged grains (mass m/d per length) across the shear field
   F_smax cos(2 pi x~), x~ = x/L_x, held at x~ = -1/4, 1/4 (the black grains of Fig. 7.1).
   Full problem (Eq. 7.3-7.5): minimise int_{-1/4}^{1/4} (y~ cos(2 pi x~) + lambda~) ds~; the
   Euler-Lagrange equation of G = (y~ c + lambda~) sqrt(1 + y~'^2), c = cos(2 pi x~),
   s = sin(2 pi x~), is
       y~'' = (1 + y~'^2) (c + 2 pi y~ y~' s) / (y~ c + lambda~),
   solved by shooting (GSL rk8pd, Brent): y~(0) = -A~, y~'(0) = 0 (symmetry), A~ such that
   y~(1/4) = 0; of the two branches the smaller amplitude is taken (scan upwards from
   A~ = 0), the one drawn in Fig. 7.2.  Its deviation from the cosine -A~ cos(2 pi x~) of the
   same depth is max |y~_cos - y~|/|y~| over 0 < x~ <= 1/4 (at 1/4 the ratio of the slopes).
   Cosine approximation (Eq. 7.6-7.8), a = 2 pi A~, with the complete elliptic integrals
   K(m), E(m) of parameter m = -a^2 (for GSL's modulus form: K(-a^2) = K(k)/sqrt(1 + a^2),
   E(-a^2) = sqrt(1 + a^2) E(k), k = a/sqrt(1 + a^2)).  Integrating Eq. 7.1 and 7.2 over
   -1/4 <= x~ <= 1/4:
       E~_pot = -[(1 + a^2) K + (a^2 - 1) E] / (6 pi^2 a)
       l~_half = E/pi                                      (Eq. 7.7)
       F~_chain = -(dE~/dA~)/(dl~/dA~) = [(2 a^2 + 1) E - (1 + a^2) K] / (6 pi a (E - K))
   Printed Eq. 7.6 is a sum of four terms, which with the transformations above is
   2 [(1 + a^2) K + (a^2 - 1) E]: it lacks the factor -1/(12 pi^2 a).  F~_chain equals the
   tension at x~ = +-1/4 in units of F_smax L_x/d, i.e. the Lagrange multiplier: at
   lambda~ = 0.4 the shooting gives A~ = 0.07384 and F~_chain(0.07384) = 0.398.  Its minimum
   gives A~_opt = 0.1912, F~_cmin = 0.2709 and, over the whole system (twice Eq. 7.7),
   l~_chain = 2 E/pi = 1.2970, the thesis's numbers.  Eq. 7.9 as printed,
   F_smax L_x/(F_B d) <= 1/F~_cmin, is 3.691; the thesis's value 0.9229 is 1/(4 F~_cmin)
   (with F~_cmin rounded to 0.2709).  The factor 4 is not derived here: both are printed,
   bound (Eq. 7.9 as written) and bound_printed (the thesis's number). */
typedef struct chain_params {
  double a, lambda, x;
} chain_params;

static const wg_theory_key chain_keys[] = {
    KEY(chain_params, a, 0.1912, "chain amplitude A~_l = A_l/L_x of the cosine approximation"),
    KEY(chain_params, lambda, 0.4, "Lagrange multiplier lambda~ of the full problem (Eq. 7.3)"),
    KEY(chain_params, x, 0, "position x~ = x/L_x of the shapes y_el, y_cos"),
};

static const wg_theory_field chain_outputs[] = {
    {"e_pot", "E~_pot(A~) over -1/4 <= x~ <= 1/4 (Eq. 7.6, corrected)"},
    {"l_chain_half", "l~ over -1/4 <= x~ <= 1/4, E(-a^2)/pi (Eq. 7.7)"},
    {"l_chain", "l~ of the chain across the system, 2 E(-a^2)/pi"},
    {"f_chain", "F~_chain(A~) = F_chain d/(F_smax L_x) (Eq. 7.8)"},
    {"a_opt", "amplitude of least F~_chain"},
    {"f_cmin", "least F~_chain"},
    {"l_chain_opt", "l~_chain at a_opt (across the system)"},
    {"bound", "1/F~_cmin: Eq. 7.9 as written"},
    {"bound_printed", "1/(4 F~_cmin): the thesis's number for Eq. 7.9"},
    {"el_a", "A~ of the Euler-Lagrange shape at lambda~ (Eq. 7.4; nan: none)"},
    {"el_dev", "largest relative deviation of -A~ cos(2 pi x~) from that shape"},
    {"y_el", "Euler-Lagrange shape y~(x~)"},
    {"y_cos", "cosine shape -A~ cos(2 pi x~) of the same depth"},
};

/* K(-a^2), E(-a^2) through the imaginary-modulus transformation. */
static void wg_theory_chain_ellint(double a, double *K, double *E)
{
  double s = sqrt(1 + a * a), k = a / s;
  *K = gsl_sf_ellint_Kcomp(k, GSL_PREC_DOUBLE) / s;
  *E = gsl_sf_ellint_Ecomp(k, GSL_PREC_DOUBLE) * s;
}

static double wg_theory_chain_epot(double amp)
{
  double a = 2 * M_PI * amp, K, E;
  wg_theory_chain_ellint(a, &K, &E);
  return -((1 + a * a) * K + (a * a - 1) * E) / (6 * M_PI * M_PI * a);
}

static double wg_theory_chain_length_half(double amp)
{
  double K, E;
  wg_theory_chain_ellint(2 * M_PI * amp, &K, &E);
  return E / M_PI; /* Eq. 7.7 */
}

static double wg_theory_chain_force(double amp, void *unused)
{
  (void)unused;
  double a = 2 * M_PI * amp, K, E;
  wg_theory_chain_ellint(a, &K, &E);
  return ((2 * a * a + 1) * E - (1 + a * a) * K) / (6 * M_PI * a * (E - K)); /* Eq. 7.8 */
}

/* The amplitude of least F~_chain (Brent); F~ -> infinity at both ends. */
static double wg_theory_chain_optimum(void)
{
  gsl_function F = {wg_theory_chain_force, NULL};
  gsl_min_fminimizer *m = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
  gsl_min_fminimizer_set(m, &F, 0.2, 0.02, 1.0);
  double x = 0.2;
  for (int it = 0; it < 200; it++) {
    gsl_min_fminimizer_iterate(m);
    x = gsl_min_fminimizer_x_minimum(m);
    if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(m), gsl_min_fminimizer_x_upper(m), 0,
                              ROOT_TOL) == GSL_SUCCESS)
      break;
  }
  gsl_min_fminimizer_free(m);
  return x;
}

static int chain_rhs(double x, const double y[], double dydx[], void *par)
{
  double lambda = *(double *)par, c = cos(2 * M_PI * x), s = sin(2 * M_PI * x);
  double w = y[0] * c + lambda; /* the tension, in units of F_smax L_x/d */
  if (!(w > 0)) return GSL_EBADFUNC;
  dydx[0] = y[1];
  dydx[1] = (1 + y[1] * y[1]) * (c + 2 * M_PI * y[0] * y[1] * s) / w; /* Eq. 7.4 with Eq. 7.5 */
  return GSL_SUCCESS;
}

typedef struct chain_ode {
  gsl_odeiv2_system sys;
  gsl_odeiv2_driver *drv;
  double lambda;
} chain_ode;

static void chain_ode_init(chain_ode *o, double lambda)
{
  o->lambda = lambda;
  o->sys = (gsl_odeiv2_system){chain_rhs, NULL, 2, &o->lambda};
  o->drv = gsl_odeiv2_driver_alloc_y_new(&o->sys, gsl_odeiv2_step_rk8pd, 1e-4, ODE_TOL, ODE_TOL);
}

/* y~ and y~' at x~ = xe (0 <= xe <= 1/4) of the shape of depth amp; NAN if the tension
   vanishes on the way. */
static void chain_ode_shoot(chain_ode *o, double amp, double xe, double *y, double *yp)
{
  double t = 0, s[2] = {-amp, 0};
  gsl_odeiv2_driver_reset(o->drv);
  int st = xe > 0 ? gsl_odeiv2_driver_apply(o->drv, &t, xe, s) : GSL_SUCCESS;
  *y = st == GSL_SUCCESS ? s[0] : NAN;
  *yp = st == GSL_SUCCESS ? s[1] : NAN;
}

static double chain_miss(double amp, void *o_)
{
  double y, yp;
  chain_ode_shoot(o_, amp, 0.25, &y, &yp);
  return y;
}

static double chain_bisect(chain_ode *o, double lo, double hi)
{
  gsl_function F = {chain_miss, o};
  gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  gsl_root_fsolver_set(s, &F, lo, hi);
  for (int it = 0; it < 200; it++) {
    gsl_root_fsolver_iterate(s);
    lo = gsl_root_fsolver_x_lower(s);
    hi = gsl_root_fsolver_x_upper(s);
    if (gsl_root_test_interval(lo, hi, 0, ROOT_TOL) == GSL_SUCCESS) break;
  }
  gsl_root_fsolver_free(s);
  return 0.5 * (lo + hi);
}

/* Depth A~ of the Euler-Lagrange shape with y~(1/4) = 0, smaller branch; NAN if none.  The
   miss y~(1/4) is scanned upwards from A~ = 0 for its first sign change.  Near the least
   lambda~ that has a solution both roots can fall between two scan points: then the miss is
   minimised (Brent) around its smallest scanned value, and a negative minimum brackets the
   smaller root. */
static double wg_theory_chain_el_amplitude(chain_ode *o)
{
  const int nscan = 128;
  double lo = 1e-9 * o->lambda, flo = chain_miss(lo, o), best = INFINITY;
  int ibest = -1, last = 0;
  for (int i = 1; i < nscan && isfinite(flo); i++) {
    double hi = o->lambda * i / nscan, fhi = chain_miss(hi, o);
    if (!isfinite(fhi)) break;
    if (flo > 0 && fhi <= 0) return chain_bisect(o, lo, hi);
    if (fhi < best) {
      best = fhi;
      ibest = i;
    }
    last = i;
    lo = hi;
    flo = fhi;
  }
  if (ibest < 1 || ibest >= last) return NAN; /* no interior minimum of the miss */
  gsl_function F = {chain_miss, o};
  gsl_min_fminimizer *m = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
  double a = o->lambda * (ibest - 1) / nscan, b = o->lambda * (ibest + 1) / nscan, x = o->lambda * ibest / nscan;
  if (ibest == 1) a = 1e-9 * o->lambda;
  int st = gsl_min_fminimizer_set(m, &F, x, a, b);
  for (int it = 0; st == GSL_SUCCESS && it < 200 && chain_miss(x, o) > 0; it++) {
    gsl_min_fminimizer_iterate(m);
    x = gsl_min_fminimizer_x_minimum(m);
    if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(m), gsl_min_fminimizer_x_upper(m), 0, ROOT_TOL) ==
        GSL_SUCCESS)
      break;
  }
  gsl_min_fminimizer_free(m);
  return chain_miss(x, o) <= 0 ? chain_bisect(o, a, x) : NAN;
}

/* Largest |y_cos - y|/|y| on 0 < x~ <= 1/4; at 1/4, where both vanish, the slopes'. */
static double wg_theory_chain_el_deviation(chain_ode *o, double amp)
{
  const int n = 400;
  double t = 0, s[2] = {-amp, 0}, worst = 0;
  gsl_odeiv2_driver_reset(o->drv);
  for (int k = 1; k <= n; k++) {
    double xk = 0.25 * k / n;
    if (gsl_odeiv2_driver_apply(o->drv, &t, xk, s) != GSL_SUCCESS) return NAN;
    double dev = k < n ? fabs(-amp * cos(2 * M_PI * xk) - s[0]) / fabs(s[0])
                       : fabs(2 * M_PI * amp - s[1]) / fabs(s[1]);
    if (dev > worst) worst = dev;
  }
  return worst;
}

/* The shape at any x~: even about 0, odd about 1/4 (the field changes sign), period 1. */
static void chain_shapes_at(chain_ode *o, double amp, double x, double *y_el, double *y_cos)
{
  double u = fabs(x - floor(x + 0.5)), sign = 1, y, yp; /* u in [0, 1/2] */
  if (u > 0.25) {
    u = 0.5 - u;
    sign = -1;
  }
  chain_ode_shoot(o, amp, u, &y, &yp);
  *y_el = sign * y;
  *y_cos = -amp * cos(2 * M_PI * x);
}

static int chain_eval(const void *params, wg_theory_result *r)
{
  const chain_params *p = params;
  if (!(p->a >= 1e-6 && p->a <= 1e3)) return domain_error(r, "a", p->a, "must lie in [1e-6, 1e3]");
  if (!(p->lambda > 0)) return domain_error(r, "lambda", p->lambda, "must be > 0");
  if (!isfinite(p->x)) return domain_error(r, "x", p->x, "must be finite");
  put(r, "e_pot", wg_theory_chain_epot(p->a));
  put(r, "l_chain_half", wg_theory_chain_length_half(p->a));
  put(r, "l_chain", 2 * wg_theory_chain_length_half(p->a));
  put(r, "f_chain", wg_theory_chain_force(p->a, NULL));
  double a_opt = wg_theory_chain_optimum(), f_cmin = wg_theory_chain_force(a_opt, NULL);
  put(r, "a_opt", a_opt);
  put(r, "f_cmin", f_cmin);
  put(r, "l_chain_opt", 2 * wg_theory_chain_length_half(a_opt));
  put(r, "bound", 1 / f_cmin);
  put(r, "bound_printed", 1 / (4 * f_cmin));
  chain_ode o;
  chain_ode_init(&o, p->lambda);
  double el_a = wg_theory_chain_el_amplitude(&o), y_el = NAN, y_cos = NAN;
  put(r, "el_a", el_a);
  put(r, "el_dev", isnan(el_a) ? NAN : wg_theory_chain_el_deviation(&o, el_a));
  if (!isnan(el_a)) chain_shapes_at(&o, el_a, p->x, &y_el, &y_cos);
  put(r, "y_el", y_el);
  put(r, "y_cos", y_cos);
  gsl_odeiv2_driver_free(o.drv);
  return 0;
}

/* ------------------------------------------------------------------------------------------
   a2: App. A, the first non-trivial Sonine (Laguerre) coefficient of the velocity
   distribution of a wet granular gas driven by white noise.  eps_cb is the rule's (Eq. A.40:
   a pair's normal speed leaves as sqrt(u^2 - eps_cb v0^2)), which for the model's loss of E_cb
   is eps_cb = 4 E_cb/(m v0^2) = 2 E_cb/T_g; the printed 2 E_cb/v0^2 = E_cb/T_g would lose E_cb/2
   (docs/appendix-a.md):
     Eq. A.59  a2 = -16 (eps - 2) eps / (-128 + 16 d (8 + eps (5 + eps))
                    + eps (10 + eps (75 + (eps - 4) eps)) + Z_s),
               Z_s = 32 (d - 1) eps exp(eps/4) K1(eps/4)   (GSL's scaled K1: no overflow)
     Eq. A.60  a2 = eps/(8 (d - 1)) - 15 (8 d - 5) eps^2/(1024 (d - 1)^2) + O(eps^3)
   With eps K1(eps/4) = 4 + O(eps^2 ln eps) the expansion of A.59 gives A.60 term by term; the
   remainder is O(eps^3 ln eps) rather than O(eps^3).  At eps = 0, Z_s = 128 (d - 1), a2 = 0. */
typedef struct a2_params {
  double eps_cb, dim;
} a2_params;

static const wg_theory_key a2_keys[] = {
    KEY(a2_params, eps_cb, 0.1, "dimensionless bridge energy eps_cb = 4 E_cb/(m v0^2) = 2 E_cb/T_g (Eq. A.40's; >= 0)"),
    KEY(a2_params, dim, 2, "dimension d (>= 2)"),
};

static const wg_theory_field a2_outputs[] = {
    {"z_s", "Z_s = 32 (d - 1) eps_cb exp(eps_cb/4) K1(eps_cb/4)"},
    {"a2", "a_2 (Eq. A.59)"},
    {"a2_series", "a_2 to second order in eps_cb (Eq. A.60)"},
    {"a2_diff", "A.59 - A.60"},
};

static double wg_theory_a2_zs(double e, double d)
{
  if (e == 0) return 128 * (d - 1); /* eps K1(eps/4) -> 4 */
  return 32 * (d - 1) * e * gsl_sf_bessel_K1_scaled(e / 4);
}

static double wg_theory_a2_full(double e, double d)
{
  double den = -128 + 16 * d * (8 + e * (5 + e)) + e * (10 + e * (75 + (e - 4) * e)) + wg_theory_a2_zs(e, d);
  return -16 * (e - 2) * e / den; /* Eq. A.59 */
}

static double wg_theory_a2_series(double e, double d)
{
  return e / (8 * (d - 1)) - 15 * (8 * d - 5) * e * e / (1024 * (d - 1) * (d - 1)); /* Eq. A.60 */
}

static int a2_eval(const void *params, wg_theory_result *r)
{
  const a2_params *p = params;
  if (!(p->eps_cb >= 0 && p->eps_cb < 2800))
    return domain_error(r, "eps_cb", p->eps_cb, "must lie in [0, 2800)");
  if (!(p->dim >= 2)) return domain_error(r, "dim", p->dim, "Eq. A.60 needs d >= 2");
  double full = wg_theory_a2_full(p->eps_cb, p->dim), series = wg_theory_a2_series(p->eps_cb, p->dim);
  put(r, "z_s", wg_theory_a2_zs(p->eps_cb, p->dim));
  put(r, "a2", full);
  put(r, "a2_series", series);
  put(r, "a2_diff", full - series);
  return 0;
}

/* ------------------------------------------------------------------------------------------
   si: the streams paper's table (Waitukaitis et al. 2011, Table I and Sec. II) in SI units,
   converted to the scene keys of wetgran's units (d, m, g; time sqrt(d/g)).  The linear
   spring-dashpot of stiffness k_n with restitution e between two grains (m_eff = m/2) lasts
   t_c = sqrt(pi^2 + ln^2 e) / omega0, omega0 = sqrt(k_n / m_eff) (damped; the paper's gamma_n
   = 2 omega0 L / sqrt(pi^2 + L^2), L = -ln e), and the time-driven engine's linear law is set by
   that contact time of two unit masses (scene key t_contact), so t_contact = t_c / sqrt(d/g).
   The cohesion F_coh out to a gap l_c is the constant bridge law: f_b = F_coh / (m g),
   s_crit = l_c / d, W_coh = F_coh l_c. */
typedef struct si_params {
  double d, rho, g, k_n, e, f_coh, l_c;
} si_params;

static const wg_theory_key si_keys[] = {
    KEY(si_params, d, 200e-6, "grain diameter [m] (the paper: 100 and 200 um)"),
    KEY(si_params, rho, 2500, "density [kg/m^3] (glass; the paper prints 2.5 kg/m^3)"),
    KEY(si_params, g, 9.81, "gravity [m/s^2]"),
    KEY(si_params, k_n, 500, "normal (and tangential) stiffness [N/m]"),
    KEY(si_params, e, 0.9, "coefficient of restitution (0 < e <= 1)"),
    KEY(si_params, f_coh, 100e-9, "cohesive force F_coh [N] (the paper: 0 to 2000 nN)"),
    KEY(si_params, l_c, 100e-9, "range of the cohesion, a surface gap [m] (100 nm)"),
};

static const wg_theory_field si_outputs[] = {
    {"mass", "grain mass m [kg]"},
    {"weight", "m g [N]: the unit of force"},
    {"time_unit", "sqrt(d/g) [s]: the unit of time"},
    {"speed_unit", "sqrt(g d) [m/s]: the unit of speed"},
    {"t_c_undamped", "pi / omega0 [s], omega0 = sqrt(k_n / (m/2))"},
    {"t_c", "contact time of a pair, damped [s]"},
    {"gamma_n", "the paper's damping gamma_n [1/s] for this e"},
    {"k_scaled", "k_n d / (m g): the stiffness in wetgran's units"},
    {"t_contact", "scene key t_contact [sqrt(d/g)]"},
    {"f_b", "scene key f_b = F_coh / (m g)"},
    {"s_crit", "scene key s_crit = l_c / d"},
    {"w_coh", "W_coh = F_coh l_c [J]"},
    {"e_cb", "W_coh in m g d (the scene's E_cb)"},
};

static int si_eval(const void *params, wg_theory_result *r)
{
  const si_params *p = params;
  if (!(p->d > 0)) return domain_error(r, "d", p->d, "must be > 0");
  if (!(p->rho > 0)) return domain_error(r, "rho", p->rho, "must be > 0");
  if (!(p->g > 0)) return domain_error(r, "g", p->g, "must be > 0");
  if (!(p->k_n > 0)) return domain_error(r, "k_n", p->k_n, "must be > 0");
  if (!(p->e > 0 && p->e <= 1)) return domain_error(r, "e", p->e, "must lie in (0, 1]");
  if (!(p->f_coh >= 0)) return domain_error(r, "f_coh", p->f_coh, "must be >= 0");
  if (!(p->l_c >= 0)) return domain_error(r, "l_c", p->l_c, "must be >= 0");
  double m = p->rho * M_PI * p->d * p->d * p->d / 6, w = m * p->g, tau = sqrt(p->d / p->g);
  double omega0 = sqrt(p->k_n / (m / 2)), L = -log(p->e);
  double t_c = sqrt(M_PI * M_PI + L * L) / omega0;
  put(r, "mass", m);
  put(r, "weight", w);
  put(r, "time_unit", tau);
  put(r, "speed_unit", sqrt(p->g * p->d));
  put(r, "t_c_undamped", M_PI / omega0);
  put(r, "t_c", t_c);
  put(r, "gamma_n", 2 * omega0 * L / sqrt(M_PI * M_PI + L * L));
  put(r, "k_scaled", p->k_n * p->d / w);
  put(r, "t_contact", t_c / tau);
  put(r, "f_b", p->f_coh / w);
  put(r, "s_crit", p->l_c / p->d);
  put(r, "w_coh", p->f_coh * p->l_c);
  put(r, "e_cb", p->f_coh * p->l_c / (w * p->d));
  return 0;
}

/* ------------------------------------------------------------------------------------------
   The models, in the order of the thesis, and the command line. */
#define N_OF(a) (sizeof(a) / sizeof *(a))
#define MODEL(name, summary, k, o, eval) {name, summary, k, N_OF(k), o, N_OF(o), eval}

static const wg_theory_model models[] = {
    MODEL("ffgc", "critical E* of the f-fgc transition (Eq. 3.1, Fig. 3.16)", ffgc_keys, ffgc_outputs, ffgc_eval),
    MODEL("solid-fluid", "force balance of a shaken column: l_m, Gamma_M, h_c, Gamma_C (Eq. 4.9-4.15); "
          "surface melting (Fig. 4.4)", sf_keys, sf_outputs, sf_eval),
    MODEL("shapes", "drop/strip window, pinched-strip saddle (Eq. 5.1), excess length (Eq. 5.2)",
          shapes_keys, shapes_outputs, shapes_eval),
    MODEL("interface", "interfacial energy and relaxation of a deformed strip (Eq. 5.9, 5.10, 5.13)",
          iface_keys, iface_outputs, iface_eval),
    MODEL("plug", "Leidenfrost plug: omega_p (Eq. 6.5), roots of Eq. 6.10/6.15/6.22, theta_c, theta_RT, "
          "L_c, Delta T_c (Eq. 6.23-6.33)", plug_keys, plug_outputs, plug_eval),
    MODEL("chain", "chain in a cosine shear field: Euler-Lagrange shape (Eq. 7.3-7.5), F~_chain "
          "(Eq. 7.6-7.8), bound (Eq. 7.9)", chain_keys, chain_outputs, chain_eval),
    MODEL("a2", "Sonine coefficient a_2 of a driven wet granular gas (Eq. A.59, A.60)", a2_keys, a2_outputs, a2_eval),
    MODEL("si", "the streams paper's SI table (Waitukaitis et al. 2011) as scene keys: t_contact, f_b, "
          "s_crit", si_keys, si_outputs, si_eval),
};

typedef union wg_theory_params {
  ffgc_params ffgc;
  sf_params sf;
  shapes_params shapes;
  iface_params iface;
  plug_params plug;
  chain_params chain;
  a2_params a2;
  si_params si;
} wg_theory_params;

static double *param_slot(wg_theory_params *p, const wg_theory_key *k)
{
  return (double *)((char *)p + k->offset);
}

static void usage(FILE *out)
{
  fprintf(out,
          "Usage: wetgran-theory MODEL [key=value ...]\n"
          "       wetgran-theory MODEL key=START:STOP:STEP [key=value ...]\n"
          "       wetgran-theory MODEL --help\n"
          "The thesis's analytic models (units d = m = g = k_B = 1).  Prints 'key value' rows\n"
          "(header key, value); with one key given as START:STOP:STEP, a curve: that key and\n"
          "every output as columns, one row per point START, START + STEP, ... up to STOP\n"
          "(STEP may be negative; at most %d points).  Unknown keys, non-numbers and values\n"
          "outside a model's domain stop the tool with a message naming the argument.\n"
          "Models:\n",
          MAX_POINTS);
  for (size_t m = 0; m < N_OF(models); m++) fprintf(out, "  %-12s %s\n", models[m].name, models[m].summary);
  fprintf(out, "'wetgran-theory MODEL --help' lists a model's keys, defaults and outputs.\n");
}

static void model_usage(const wg_theory_model *m)
{
  printf("Usage: wetgran-theory %s [key=value ...]   (key=START:STOP:STEP for a curve)\n%s\nKeys (default):\n",
         m->name, m->summary);
  for (size_t k = 0; k < m->nkeys; k++) {
    char def[32];
    if (isnan(m->keys[k].def)) snprintf(def, sizeof def, "-");
    else snprintf(def, sizeof def, "%.6g", m->keys[k].def);
    printf("  %-8s %-9s %s\n", m->keys[k].name, def, m->keys[k].doc);
  }
  printf("Outputs:\n");
  for (size_t k = 0; k < m->nout; k++) printf("  %-14s %s\n", m->outputs[k].name, m->outputs[k].doc);
}

static void list_keys(const wg_theory_model *m, FILE *out)
{
  for (size_t k = 0; k < m->nkeys; k++) fprintf(out, "%s%s", k ? ", " : "", m->keys[k].name);
}

static int parse_number(const char *s, double *v)
{
  char *end;
  *v = strtod(s, &end);
  return end != s && *end == 0 && isfinite(*v);
}

/* START:STOP:STEP; returns the number of points, 0 if malformed. */
static long parse_range(const char *s, double *start, double *step)
{
  char buf[256], *c1, *c2;
  double stop;
  if (strlen(s) >= sizeof buf) return 0;
  strcpy(buf, s);
  if (!(c1 = strchr(buf, ':')) || !(c2 = strchr(c1 + 1, ':'))) return 0;
  *c1 = *c2 = 0;
  if (!parse_number(buf, start) || !parse_number(c1 + 1, &stop) || !parse_number(c2 + 1, step)) return 0;
  if (*step == 0) return *start == stop ? 1 : 0;
  double span = (stop - *start) / *step;
  if (span < -1e-9) return 0;
  double n = floor(span + 1e-9) + 1;
  return n <= MAX_POINTS ? (long)n : -1;
}

/* %.10g, but "nan" whatever the sign bit of a NaN */
static void print_value(double v)
{
  if (isnan(v)) printf("nan");
  else printf("%.10g", v);
}

static int evaluate(const wg_theory_model *m, const wg_theory_params *p, wg_theory_result *r)
{
  memset(r, 0, sizeof *r);
  r->model = m;
  if (m->eval(p, r)) return 1;
  for (size_t k = 0; k < m->nout; k++)
    if (!r->set[k]) {
      fprintf(stderr, "wetgran-theory: internal error: %s left '%s' unset\n", m->name, m->outputs[k].name);
      abort();
    }
  return 0;
}

int main(int argc, char **argv)
{
  if (argc < 2) {
    usage(stderr);
    return 2;
  }
  if (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
    usage(stdout);
    return 0;
  }
  const wg_theory_model *m = NULL;
  for (size_t k = 0; k < N_OF(models); k++)
    if (!strcmp(argv[1], models[k].name)) m = &models[k];
  if (!m) {
    fprintf(stderr, "wetgran-theory: unknown model '%s' (models:", argv[1]);
    for (size_t k = 0; k < N_OF(models); k++) fprintf(stderr, " %s", models[k].name);
    fprintf(stderr, ")\n");
    return 2;
  }
  gsl_set_error_handler_off();
  wg_theory_params p;
  memset(&p, 0, sizeof p);
  for (size_t k = 0; k < m->nkeys; k++) *param_slot(&p, &m->keys[k]) = m->keys[k].def;
  const wg_theory_key *ranged = NULL;
  double start = 0, step = 0;
  long npoints = 1;
  for (int a = 2; a < argc; a++) {
    const char *arg = argv[a];
    if (!strcmp(arg, "-h") || !strcmp(arg, "--help")) {
      model_usage(m);
      return 0;
    }
    const char *eq = strchr(arg, '=');
    if (!eq || eq == arg) {
      fprintf(stderr, "wetgran-theory: %s: argument '%s' is not key=value (see --help)\n", m->name, arg);
      return 2;
    }
    const wg_theory_key *key = NULL;
    for (size_t k = 0; k < m->nkeys; k++)
      if (strlen(m->keys[k].name) == (size_t)(eq - arg) && !strncmp(m->keys[k].name, arg, (size_t)(eq - arg)))
        key = &m->keys[k];
    if (!key) {
      fprintf(stderr, "wetgran-theory: %s: unknown key '%.*s' (keys: ", m->name, (int)(eq - arg), arg);
      list_keys(m, stderr);
      fprintf(stderr, ")\n");
      return 2;
    }
    const char *val = eq + 1;
    if (strchr(val, ':')) {
      if (ranged && ranged != key) {
        fprintf(stderr, "wetgran-theory: %s: '%s': only one key may be a range (already '%s')\n", m->name,
                arg, ranged->name);
        return 2;
      }
      npoints = parse_range(val, &start, &step);
      if (npoints <= 0) {
        fprintf(stderr, "wetgran-theory: %s: '%s': %s\n", m->name, arg,
                npoints < 0 ? "more than 1000000 points" : "not a range START:STOP:STEP reaching STOP");
        return 2;
      }
      ranged = key;
    } else {
      double v;
      if (!parse_number(val, &v)) {
        fprintf(stderr, "wetgran-theory: %s: '%s': '%s' is not a finite number\n", m->name, arg, val);
        return 2;
      }
      if (ranged == key) ranged = NULL;
      *param_slot(&p, key) = v;
    }
  }
  wg_theory_result r;
  if (!ranged) {
    if (evaluate(m, &p, &r)) {
      fprintf(stderr, "wetgran-theory: %s: %s\n", m->name, r.err);
      return 1;
    }
    printf("key\tvalue\n");
    for (size_t k = 0; k < m->nout; k++) {
      printf("%s\t", m->outputs[k].name);
      print_value(r.value[k]);
      printf("\n");
    }
    return 0;
  }
  printf("%s", ranged->name);
  for (size_t k = 0; k < m->nout; k++) printf("\t%s", m->outputs[k].name);
  printf("\n");
  for (long i = 0; i < npoints; i++) {
    double v = start + (double)i * step;
    *param_slot(&p, ranged) = v;
    if (evaluate(m, &p, &r)) {
      fflush(stdout);
      fprintf(stderr, "wetgran-theory: %s: %s\n", m->name, r.err);
      return 1;
    }
    print_value(v);
    for (size_t k = 0; k < m->nout; k++) {
      printf("\t");
      print_value(r.value[k]);
    }
    printf("\n");
  }
  return 0;
}
