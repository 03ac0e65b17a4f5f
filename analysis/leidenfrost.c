/* wetgran-leidenfrost: the granular Leidenfrost plug of thesis Ch. 6, from a run's height maps
   (wetgran-run height_bins > 0: packing fraction, number density and T_g in slabs across the
   height, averaged over the lateral plane).  Modes, each writing a tab-separated table:
     map          the height-time map of the packing fraction (Figs. 6.3b, 6.6, 6.10)
     interface    per frame: the plug's lower interface h_I (where phi first reaches phi_c
                  from below, 0.51 as the thesis), its top, the grains below and above it
     oscillation  per run: turning points of h_I, the plug period T_p and omega_p = 2 pi / T_p
                  with errors, the cushion height h0 and its grains, Eq. 6.5's omega_p, the
                  rms excursion eps_h (Fig. 6.15), the gas above the plug and the sound speed
     profiles     phi(z) averaged over the frames of the top and of the bottom turning points
                  (Fig. 6.4)
     bubbling     the onset of bubbling (a hole in the plug's lateral maps) and the plug's
                  height then, against Eq. 6.33's L_c = pi h_p (Fig. 6.13)
   The plug in a frame is the run of slabs with phi >= phi_c around the densest slab; a frame
   whose densest slab stays below phi_c has no plug (nan). */
#include <gsl/gsl_fit.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "extrema.h"
#include "io_h5.h"
#include "plug.h"
#include "run_open.h"
#include "wg_args.h"

#define PROG "wetgran-leidenfrost"
#define PHI_GAS 0.1 /* a slab of a dilute gas: phi below this */

typedef struct options {
  double phi_c;      /* interface density */
  double from, to;   /* time window [sqrt(d/g)] */
  double swing;      /* a turning point counts once h_I has moved this far back [d]; 0: auto */
  double hole;       /* bubbling: a column below this share of the mean grains */
  double last;       /* profiles: only the last this many tops and bottoms (0: all) */
} options;

/* One run's height maps. */
typedef struct hmaps {
  int dim, nb;
  long nf, n;
  double z0, w, area;        /* first slab's bottom, slab width, lateral area (2D: length) */
  double t_driv, e_cb, estar, gamma, g, v_bead;
  double *t, *phi, *num, *temp; /* nf, nf x nb each */
} hmaps;

static void hmaps_free(hmaps *h)
{
  free(h->t), free(h->phi), free(h->num), free(h->temp);
  memset(h, 0, sizeof *h);
}

static int load(const char *file, hmaps *h)
{
  memset(h, 0, sizeof *h);
  hid_t f = wg_run_open(file);
  if (f < 0) return 1;
  static const char *grp = "/observables/heights";
  if (!wg_h5_exists(f, "/observables/heights/packing_fraction/value")) {
    fprintf(stderr, PROG ": %s: no height maps in this run (run it with height_bins > 0)\n", file);
    wg_h5_close(f);
    return 1;
  }
  double dim, n, lx, ly = 1, span;
  int has_num = 0;
  int rc = wg_run_param(f, file, "dim", &dim, 1) | wg_run_param(f, file, "n", &n, 1) |
           wg_run_param(f, file, "lx", &lx, 1) | (dim == 3 ? wg_run_param(f, file, "ly", &ly, 1) : 0);
  wg_run_param(f, file, "t_driv", &h->t_driv, 0), wg_run_param(f, file, "e_cb", &h->e_cb, 0);
  wg_run_param(f, file, "estar", &h->estar, 0), wg_run_param(f, file, "gamma", &h->gamma, 0);
  if (wg_run_param(f, file, "gravity", &h->g, 0), !(h->g > 0)) h->g = 1; /* wetgran-run's default */
  int rank;
  hsize_t d[8];
  if (!rc && (wg_h5_dims(f, "/observables/heights/packing_fraction/value", &rank, d) != WG_OK ||
              rank != 2 || wg_h5_read_attr_double(f, grp, "z0", &h->z0) != WG_OK ||
              wg_h5_read_attr_double(f, grp, "span", &span) != WG_OK)) {
    fprintf(stderr, PROG ": %s: damaged height maps\n", file);
    rc = 1;
  }
  if (!rc) {
    h->dim = (int)dim, h->n = (long)n, h->nf = (long)d[0], h->nb = (int)d[1];
    h->w = span / h->nb, h->area = lx * ly;
    size_t c = (size_t)h->nf * (size_t)h->nb;
    h->t = malloc(sizeof(double) * (h->nf ? h->nf : 1));
    h->phi = malloc(sizeof(double) * (c ? c : 1));
    h->num = malloc(sizeof(double) * (c ? c : 1));
    h->temp = malloc(sizeof(double) * (c ? c : 1));
    if (!h->t || !h->phi || !h->num || !h->temp) {
      fprintf(stderr, PROG ": %s: no memory for %ld frames\n", file, h->nf);
      rc = 1;
    } else if (wg_h5_read(f, "/observables/heights/packing_fraction/time", H5T_NATIVE_DOUBLE, h->t) ||
               wg_h5_read(f, "/observables/heights/packing_fraction/value", H5T_NATIVE_DOUBLE, h->phi) ||
               (has_num = wg_h5_exists(f, "/observables/heights/number_density/value") &&
                wg_h5_read(f, "/observables/heights/number_density/value", H5T_NATIVE_DOUBLE, h->num)) ||
               (wg_h5_exists(f, "/observables/heights/temperature/value") &&
                wg_h5_read(f, "/observables/heights/temperature/value", H5T_NATIVE_DOUBLE, h->temp))) {
      fprintf(stderr, PROG ": %s: cannot read the height maps\n", file);
      rc = 1;
    } else {
      has_num = wg_h5_exists(f, "/observables/heights/number_density/value");
      if (!wg_h5_exists(f, "/observables/heights/temperature/value"))
        for (size_t i = 0; i < c; i++) h->temp[i] = NAN;
    }
  }
  wg_h5_close(f);
  if (!rc && h->nf > 0) { /* a grain's mean volume: the first frame's total over N */
    double v = 0;
    for (int k = 0; k < h->nb; k++) v += h->phi[k];
    h->v_bead = v * h->w * h->area / (double)h->n;
    if (!has_num) /* a record keeping only the packing fraction: grains by volume */
      for (size_t i = 0; i < (size_t)h->nf * h->nb; i++) h->num[i] = h->phi[i] / h->v_bead;
  }
  if (rc) hmaps_free(h);
  return rc;
}

static double periods(const hmaps *h, double t) { return h->t_driv > 0 ? t / h->t_driv : NAN; }

/* The plug of frame i: its lower and upper interfaces (linear between slab centres where phi
   crosses phi_c), grains below and above them, mean phi inside.  0 when there is none. */
typedef struct plug {
  double h_i, h_top, n_below, phi;
  double n_above;          /* grains above the top in slabs of a dilute gas (phi < PHI_GAS) */
  double t_below, t_above; /* T_g of the dilute gas below h_I and above the top (count-weighted) */
} plug;

static double zc(const hmaps *h, int k) { return h->z0 + (k + 0.5) * h->w; }

static int find_plug(const hmaps *h, long i, double phi_c, plug *p)
{
  const double *f = h->phi + (size_t)i * h->nb, *num = h->num + (size_t)i * h->nb,
               *tg = h->temp + (size_t)i * h->nb;
  int m = 0;
  for (int k = 1; k < h->nb; k++)
    if (f[k] > f[m]) m = k;
  *p = (plug){NAN, NAN, NAN, NAN, NAN, NAN, NAN};
  if (f[m] < phi_c) return 0;
  int lo = m, hi = m;
  while (lo > 0 && f[lo - 1] >= phi_c) lo--;
  while (hi < h->nb - 1 && f[hi + 1] >= phi_c) hi++;
  p->h_i = lo > 0 ? zc(h, lo - 1) + h->w * (phi_c - f[lo - 1]) / (f[lo] - f[lo - 1]) : zc(h, 0);
  p->h_top = hi < h->nb - 1 ? zc(h, hi) + h->w * (f[hi] - phi_c) / (f[hi] - f[hi + 1])
                            : zc(h, h->nb - 1);
  double below = 0, above = 0, phis = 0, tb = 0, ta = 0, wb = 0, wa = 0;
  for (int k = 0; k < h->nb; k++) {
    /* grains whose centre is in slab k, the slab cut by an interface shared pro rata */
    double c = num[k] * h->w * h->area, e = h->z0 + k * h->w;
    double fb = fmin(1, fmax(0, (p->h_i - e) / h->w)), fa = fmin(1, fmax(0, (e + h->w - p->h_top) / h->w));
    if (f[k] >= PHI_GAS) fa = 0; /* above the plug: its dilute gas only, not its loose top */
    below += fb * c, above += fa * c;
    if (f[k] >= PHI_GAS) fb = 0;
    if (isfinite(tg[k])) tb += fb * c * tg[k], ta += fa * c * tg[k], wb += fb * c, wa += fa * c;
  }
  for (int k = lo; k <= hi; k++) phis += f[k];
  p->n_below = below, p->n_above = above, p->phi = phis / (hi - lo + 1);
  p->t_below = wb > 0 ? tb / wb : NAN, p->t_above = wa > 0 ? ta / wa : NAN;
  return 1;
}

static int in_window(const options *o, double t) { return t >= o->from && t <= o->to; }

static int mode_map(const options *o, int nfile, char **files)
{
  printf("file\tt\tperiods\tz\tphi\tphi_rel\tnumber_density\ttemperature_ecb\n");
  for (int r = 0; r < nfile; r++) {
    hmaps h;
    if (load(files[r], &h)) return 1;
    double phi_max = h.dim == 3 ? 0.7405 : 0.9069; /* close packing: the thesis's scale */
    for (long i = 0; i < h.nf; i++) {
      if (!in_window(o, h.t[i])) continue;
      for (int k = 0; k < h.nb; k++) {
        size_t c = (size_t)i * h.nb + k;
        printf("%s\t%.10g\t%.10g\t%.10g\t%.6g\t%.6g\t%.6g\t%.6g\n", files[r], h.t[i],
               periods(&h, h.t[i]), zc(&h, k), h.phi[c], h.phi[c] / phi_max, h.num[c],
               h.e_cb > 0 ? h.temp[c] / h.e_cb : NAN);
      }
      printf("\n");
    }
    hmaps_free(&h);
  }
  return 0;
}

/* The frames of a run's window: h_I per frame and the turning points. */
typedef struct track {
  long n, m;          /* frames in the window, turning points */
  long *frame;        /* window frame k -> frame index */
  double *hi;
  plug *p;
  long *tp;           /* turning points, as window frame indices */
  int *kind;
  double swing;       /* the hysteresis used */
} track;

static void track_free(track *tr)
{
  free(tr->frame), free(tr->hi), free(tr->p), free(tr->tp), free(tr->kind);
}

static int track_run(const hmaps *h, const options *o, track *tr)
{
  memset(tr, 0, sizeof *tr);
  size_t cap = (size_t)(h->nf ? h->nf : 1);
  tr->frame = malloc(sizeof(long) * cap), tr->hi = malloc(sizeof(double) * cap);
  tr->p = malloc(sizeof(plug) * cap), tr->tp = malloc(sizeof(long) * cap);
  tr->kind = malloc(sizeof(int) * cap);
  if (!tr->frame || !tr->hi || !tr->p || !tr->tp || !tr->kind) return 1;
  for (long i = 0; i < h->nf; i++) {
    if (!in_window(o, h->t[i])) continue;
    find_plug(h, i, o->phi_c, &tr->p[tr->n]);
    tr->hi[tr->n] = tr->p[tr->n].h_i;
    tr->frame[tr->n++] = i;
  }
  /* default swing: the interface jitters by a few d while the plug sits on its cushion */
  tr->swing = o->swing > 0 ? o->swing : wg_auto_swing(tr->hi, tr->n, 0.3, 2);
  tr->m = wg_turning_points(tr->hi, tr->n, tr->swing, tr->tp, tr->kind);
  return 0;
}

static int mode_interface(const options *o, int nfile, char **files)
{
  printf("file\tt\tperiods\th_i\th_top\th_p\tn_below\tn_above\tphi_plug\tturning\n");
  for (int r = 0; r < nfile; r++) {
    hmaps h;
    track tr;
    if (load(files[r], &h)) return 1;
    if (track_run(&h, o, &tr)) return 1;
    for (long j = 0, k = 0; j < tr.n; j++) {
      const plug *p = &tr.p[j];
      long i = tr.frame[j];
      int turn = k < tr.m && tr.tp[k] == j ? tr.kind[k++] : 0;
      printf("%s\t%.10g\t%.10g\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%d\n", files[r], h.t[i],
             periods(&h, h.t[i]), p->h_i, p->h_top, p->h_top - p->h_i, p->n_below, p->n_above,
             p->phi, turn);
    }
    track_free(&tr);
    hmaps_free(&h);
  }
  return 0;
}

static double mean_of(const double *x, long n, double *sd)
{
  double s = 0, s2 = 0;
  long c = 0;
  for (long i = 0; i < n; i++) {
    double v = x[i];
    if (isfinite(v)) s += v, s2 += v * v, c++;
  }
  double m = c ? s / c : NAN;
  if (sd) *sd = c > 1 ? sqrt(fmax(0, (s2 - c * m * m) / (c - 1))) : NAN;
  return m;
}

static int mode_oscillation(const options *o, int nfile, char **files)
{
  printf("file\testar\tgamma\tframes\tturning_points\tt_p\tt_p_err\tomega_p\tomega_p_err\th0\t"
         "h0_err\tn_gas\tomega_theory\tomega_ratio\tomega_ratio_err\tamplitude\tamplitude_cv\t"
         "eps_rms\th_p\tphi_plug\tabove_fraction\tv_sound_below\tv_sound_above\n");
  for (int r = 0; r < nfile; r++) {
    hmaps h;
    track tr;
    if (load(files[r], &h)) return 1;
    if (track_run(&h, o, &tr)) {
      fprintf(stderr, PROG ": no memory\n");
      return 1;
    }
    long n = tr.n, m = tr.m;
    /* T_p: turning-point times against their index, t_k = t_0 + k T_p / 2 (GSL's fit; its
       slope error from the scatter about the line) */
    double tp = NAN, tp_err = NAN;
    if (m >= 3) {
      double *k = malloc(sizeof(double) * m), *t = malloc(sizeof(double) * m);
      for (long j = 0; j < m; j++) k[j] = (double)j, t[j] = h.t[tr.frame[tr.tp[j]]];
      double c0, c1, c00, c01, c11, ss;
      gsl_fit_linear(k, 1, t, 1, (size_t)m, &c0, &c1, &c00, &c01, &c11, &ss);
      tp = 2 * c1, tp_err = 2 * sqrt(c11);
      free(k), free(t);
    }
    /* the window's statistics over whole cycles: from the first turning point to the last */
    long a = m >= 2 ? tr.tp[0] : 0, b = m >= 2 ? tr.tp[m - 1] : n - 1;
    long nw = b >= a ? b - a + 1 : 0;
    double sd_h0, h0 = mean_of(tr.hi + a, nw, &sd_h0);
    double cycles = isfinite(tp) && tp > 0 && nw > 1 ? (h.t[tr.frame[b]] - h.t[tr.frame[a]]) / tp : 0;
    double h0_err = cycles >= 1 ? sd_h0 / sqrt(cycles) : NAN;
    double ngas = 0, hp = 0, phip = 0, above = 0, tb = 0, ta = 0, eps2 = 0;
    long cp = 0, cb = 0, ca = 0;
    for (long j = a; j < a + nw; j++) {
      const plug *p = &tr.p[j];
      if (!isfinite(p->h_i)) continue;
      hp += p->h_top - p->h_i, phip += p->phi, above += p->n_above, ngas += p->n_below, cp++;
      eps2 += (p->h_i - h0) * (p->h_i - h0) / (h0 * h0);
      if (isfinite(p->t_below)) tb += p->t_below, cb++;
      if (isfinite(p->t_above) && p->n_above >= 1) ta += p->t_above, ca++;
    }
    ngas = cp ? ngas / cp : NAN, hp = cp ? hp / cp : NAN, phip = cp ? phip / cp : NAN, above = cp ? above / cp : NAN;
    double eps_rms = cp ? sqrt(eps2 / cp) : NAN;
    /* Eq. 6.5: omega_p^2 = kappa g / h0 (1 + V_ex / (A_g h0)), V_ex = 4 N V_bead,
       kappa = (D + 2) / D (5/3 in 3D) */
    double kappa = (h.dim + 2.0) / h.dim;
    double vex = 4 * ngas * h.v_bead;
    double om_th = sqrt(wg_plug_omega2(kappa, h.g, h0, vex, h.area));
    double om = 2 * M_PI / tp, om_err = 2 * M_PI * tp_err / (tp * tp);
    /* its error from h0's: omega_th ~ h0^(-1/2) at least (more with the excluded volume) */
    double rel_th = isfinite(h0_err) ? 0.5 * h0_err / h0 : NAN;
    double ratio = om / om_th;
    double ratio_err = ratio * sqrt(pow(om_err / om, 2) + (isfinite(rel_th) ? rel_th * rel_th : 0));
    /* amplitude: each top minus the bottoms beside it, half of it */
    double amp = NAN, amp_cv = NAN;
    if (m >= 2) {
      double *d = malloc(sizeof(double) * m);
      for (long j = 1; j < m; j++) d[j - 1] = 0.5 * fabs(tr.hi[tr.tp[j]] - tr.hi[tr.tp[j - 1]]);
      double sd;
      amp = mean_of(d, m - 1, &sd);
      amp_cv = sd / amp;
      free(d);
    }
    /* the adiabatic sound speed of the gas, sqrt(kappa T / m) with m = 1, in d / T_driv */
    double vb = cb ? sqrt(kappa * tb / cb) * h.t_driv : NAN, va = ca ? sqrt(kappa * ta / ca) * h.t_driv : NAN;
    printf("%s\t%.6g\t%.6g\t%ld\t%ld\t%.6g\t%.3g\t%.6g\t%.3g\t%.6g\t%.3g\t%.6g\t%.6g\t%.6g\t%.3g\t"
           "%.6g\t%.3g\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\n",
           files[r], h.estar, h.gamma, n, m, tp, tp_err, om, om_err, h0, h0_err, ngas, om_th,
           ratio, ratio_err, amp, amp_cv, eps_rms, hp, phip, above / (double)h.n, vb, va);
    if (m < 3)
      fprintf(stderr, PROG ": %s: %ld turning points of h_I in the window (need 3 for a period; "
              "swing %g d)\n", files[r], m, tr.swing);
    track_free(&tr);
    hmaps_free(&h);
  }
  return 0;
}

/* The lateral maps' number density (/observables/maps, map_bins > 0): nf frames of nc cells. */
static int load_columns(const char *file, double **t, double **n, long *nf, long *nc, double *lx)
{
  hid_t f = wg_run_open(file);
  if (f < 0) return 1;
  int rank, rc = 0;
  hsize_t d[8];
  if (!wg_h5_exists(f, "/observables/maps/number_density/value") ||
      wg_h5_dims(f, "/observables/maps/number_density/value", &rank, d) != WG_OK || rank < 2) {
    fprintf(stderr, PROG ": %s: no lateral maps in this run (bubbling needs map_bins > 0)\n", file);
    wg_h5_close(f);
    return 1;
  }
  *nf = (long)d[0], *nc = (long)d[1] * (rank == 3 ? (long)d[2] : 1);
  *t = malloc(sizeof(double) * (*nf ? *nf : 1));
  *n = malloc(sizeof(double) * (size_t)(*nf ? *nf : 1) * (size_t)*nc);
  if (!*t || !*n || wg_run_param(f, file, "lx", lx, 1) ||
      wg_h5_read(f, "/observables/maps/number_density/time", H5T_NATIVE_DOUBLE, *t) ||
      wg_h5_read(f, "/observables/maps/number_density/value", H5T_NATIVE_DOUBLE, *n)) {
    fprintf(stderr, PROG ": %s: cannot read the lateral maps\n", file);
    rc = 1;
  }
  wg_h5_close(f);
  return rc;
}

/* Bubbling (Sec. 6.5.2, Fig. 6.13): a gas bubble rising through the plug leaves a column of the
   lateral maps with far fewer grains than the mean.  Per run: the first lateral-map frame from
   --from on whose emptiest column holds less than --hole of the mean (the onset), the plug's
   height h_p there (mean over the height-map frames of that window), and L / (pi h_p) against
   Eq. 6.33's 1; without an onset, the least h_p the plug reached (stable down to it). */
static int mode_bubbling(const options *o, int nfile, char **files)
{
  printf("file\testar\tl\tframes\tonset_t\tonset_periods\tmin_column\th_p\tl_over_pi_hp\th_p_min\n");
  for (int r = 0; r < nfile; r++) {
    hmaps h;
    track tr;
    double *t, *n, lx;
    long nf, nc;
    if (load(files[r], &h) || load_columns(files[r], &t, &n, &nf, &nc, &lx)) return 1;
    if (track_run(&h, o, &tr)) return 1;
    double window = nf > 1 ? t[1] - t[0] : INFINITY, onset = NAN, least = NAN;
    long used = 0;
    for (long i = 0; i < nf && !isfinite(onset); i++) {
      if (!in_window(o, t[i])) continue;
      double mean = 0, lo = INFINITY;
      for (long c = 0; c < nc; c++) mean += n[i * nc + c], lo = fmin(lo, n[i * nc + c]);
      mean /= nc, used++;
      double rel = mean > 0 ? lo / mean : NAN;
      if (!isfinite(least) || rel < least) least = rel;
      if (rel < o->hole) onset = t[i], least = rel;
    }
    double hp = 0, hp_min = NAN;
    long k = 0;
    for (long j = 0; j < tr.n; j++) {
      const plug *p = &tr.p[j];
      double tj = h.t[tr.frame[j]], pj = p->h_top - p->h_i;
      if (!isfinite(pj)) continue;
      if (!isfinite(hp_min) || pj < hp_min) hp_min = pj;
      if (isfinite(onset) && fabs(tj - onset) <= 0.5 * window) hp += pj, k++;
    }
    hp = k ? hp / k : NAN;
    printf("%s\t%.6g\t%.6g\t%ld\t%.6g\t%.6g\t%.4g\t%.6g\t%.4g\t%.6g\n", files[r], h.estar, lx,
           used, onset, periods(&h, onset), least, hp, lx / (M_PI * hp), hp_min);
    free(t), free(n);
    track_free(&tr);
    hmaps_free(&h);
  }
  return 0;
}

static int mode_profiles(const options *o, int nfile, char **files)
{
  printf("file\tz\tphi_top\tphi_bottom\ttops\tbottoms\n");
  for (int r = 0; r < nfile; r++) {
    hmaps h;
    track tr;
    if (load(files[r], &h)) return 1;
    if (track_run(&h, o, &tr)) return 1;
    double *top = calloc((size_t)h.nb, sizeof(double)), *bot = calloc((size_t)h.nb, sizeof(double));
    long nt = 0, nb = 0;
    /* the last --last tops and as many bottoms (all with 0) */
    long j0 = o->last > 0 && 2 * o->last < tr.m ? tr.m - 2 * o->last : 0;
    for (long j = j0; j < tr.m; j++) {
      const double *f = h.phi + (size_t)tr.frame[tr.tp[j]] * h.nb;
      double *acc = tr.kind[j] > 0 ? top : bot;
      for (int k = 0; k < h.nb; k++) acc[k] += f[k];
      if (tr.kind[j] > 0) nt++;
      else nb++;
    }
    for (int k = 0; k < h.nb; k++)
      printf("%s\t%.6g\t%.6g\t%.6g\t%ld\t%ld\n", files[r], zc(&h, k), nt ? top[k] / nt : NAN,
             nb ? bot[k] / nb : NAN, nt, nb);
    free(top), free(bot);
    track_free(&tr);
    hmaps_free(&h);
  }
  return 0;
}

static void usage(FILE *out)
{
  fprintf(out,
    "Usage: " PROG " MODE [options] RUN.h5 ...\n"
    "The granular Leidenfrost plug (thesis Ch. 6) from the height maps of event-driven runs\n"
    "(wetgran-run height_bins > 0, dt_height).  Tab-separated tables on stdout.\n"
    "Modes:\n"
    "  map          height-time map: per frame and slab t, periods (t/T_driv), z [d], phi,\n"
    "               phi_rel = phi/phi_max (0.7405 in 3D, 0.9069 in 2D), number density, T_g/E_cb;\n"
    "               a blank line after each frame (gnuplot's pm3d/image)\n"
    "  interface    per frame: h_i (the plug's lower interface, where phi reaches phi_c),\n"
    "               h_top, h_p = h_top - h_i, grains with centre below h_i and in the gas\n"
    "               above h_top, the plug's mean phi, and turning: 1 at a top turning point\n"
    "               of h_i, -1 at a bottom one, else 0 (as oscillation finds them)\n"
    "  oscillation  per run, over the window: turning points of h_i, the plug period t_p\n"
    "               (turning-point times against their index, a line of slope t_p/2: GSL's\n"
    "               fit and its error) and omega_p = 2 pi/t_p; h0 = mean h_i (error: its sd\n"
    "               over sqrt(cycles)); n_gas = mean grains below h_i; omega_theory from\n"
    "               Eq. 6.5 with kappa = (D+2)/D, V_ex = 4 n_gas V_bead, A_g the base; their\n"
    "               ratio; the mean half swing and its coefficient of variation (the\n"
    "               modulation of Fig. 6.6); eps_rms = rms (h_i - h0)/h0 (Fig. 6.15); the\n"
    "               plug's height h_p and phi; the fraction of grains in the gas above it\n"
    "               (slabs above h_top with phi < 0.1); the adiabatic sound speed\n"
    "               sqrt(kappa T_g/m) of the dilute gas (phi < 0.1) below and above the plug,\n"
    "               in d/T_driv\n"
    "  profiles     phi(z) averaged over the frames of the top and of the bottom turning\n"
    "               points (Fig. 6.4; --last K: the last K of each)\n"
    "  bubbling     runs with lateral maps too (map_bins): the first lateral-map frame whose\n"
    "               emptiest column holds less than --hole of the mean grains (a gas bubble\n"
    "               through the plug, Fig. 6.12), the plug's height h_p then and L/(pi h_p)\n"
    "               against Eq. 6.33's 1 (Fig. 6.13); else the least h_p reached\n"
    "Options:\n"
    "  --phi-c X       interface density (default 0.51, as the thesis)\n"
    "  --from T        first frame time [sqrt(d/g)] (default 0)\n"
    "  --to T          last frame time (default: the run's end)\n"
    "  --min-swing D   a turning point counts once h_i has moved D back (default: 30 %% of\n"
    "                  h_i's 10-90 percentile range over the window, at least 2 d)\n"
    "  --hole X        bubbling: a column with less than X of the mean grains (default 0.5)\n"
    "  --last K        profiles: the last K top and K bottom turning points only (the thesis\n"
    "                  averages eight consecutive ones; default 0: all in the window)\n");
}

int main(int argc, char **argv)
{
  if (argc < 2 || !strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
    usage(argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const char *mode = argv[1];
  options o = {.phi_c = 0.51, .from = 0, .to = INFINITY, .swing = 0, .hole = 0.5};
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
    double *dst = !strcmp(a, "--phi-c") ? &o.phi_c : !strcmp(a, "--from") ? &o.from
                : !strcmp(a, "--to") ? &o.to : !strcmp(a, "--min-swing") ? &o.swing
                : !strcmp(a, "--hole") ? &o.hole : !strcmp(a, "--last") ? &o.last : NULL;
    if (!dst) {
      fprintf(stderr, PROG ": unknown option %s (see --help)\n", a);
      return 2;
    }
    if (wg_arg_double(a, argv[++i], dst)) return 2;
  }
  if (!(o.phi_c > 0 && o.phi_c < 1) || !(o.swing >= 0) || !(o.to >= o.from) ||
      !(o.hole > 0 && o.hole < 1) || !(o.last >= 0 && o.last == floor(o.last))) {
    fprintf(stderr, PROG ": need 0 < --phi-c < 1, --min-swing >= 0, --to >= --from, 0 < --hole < 1 "
            "and a whole --last >= 0\n");
    return 2;
  }
  if (i >= argc) {
    fprintf(stderr, PROG ": no run files (see --help)\n");
    return 2;
  }
  int nfile = argc - i;
  char **files = argv + i;
  if (!strcmp(mode, "map")) return mode_map(&o, nfile, files);
  if (!strcmp(mode, "interface")) return mode_interface(&o, nfile, files);
  if (!strcmp(mode, "oscillation")) return mode_oscillation(&o, nfile, files);
  if (!strcmp(mode, "profiles")) return mode_profiles(&o, nfile, files);
  if (!strcmp(mode, "bubbling")) return mode_bubbling(&o, nfile, files);
  fprintf(stderr, PROG ": unknown mode '%s' (map, interface, oscillation, profiles, bubbling)\n", mode);
  return 2;
}
