/* wetgran-interface: the coexisting phases of shaken wet runs on the lateral plane (thesis
   Ch. 5).  One tool with modes; each reads run files (or records of them) and writes a
   tab-separated table to stdout.
     ag         gas fraction a_g of each run (Fig. 5.2), its phase components counted with
                periodic boundaries and, on a 2D lateral plane (3D runs), the shape class
                I (gas drop), II (strip), III (fluid drop) with the drop's equivalent radius
     field      the coarse-grained lateral field of one run: number density, bridge density,
                T_g, and the phase mask
     strip      the interfaces of a strip traced per column and fitted with a cosine (Eq. 5.4)
                -> A~_d; N_p; sigma from Eq. 5.9 and sigma/gamma; the estimate of Eq. 5.10
     relax      A~_d(t) of several seeds averaged per snapshot, exponential fit, mu_f (Eq. 5.13)
     spacetime  number and bridge density along x against time, one row per (t, x) cell
     powerfit   y = a x^beta fitted to two columns of a table (a_g = a E~*^beta, Fig. 5.2b)
     droplets   2D: fluid droplets per frame, the regimes, N_f against T_g, their spacing
     domains    3D: crystalline domains per frame, their area, N_d against t (Ostwald)
     plug       2D: the plug's centre over seeds, its mean square displacement and fit

   The phase mask: a cell is gas where T_g / E_cb lies above t_fg, solid below t_sf, fluid in
   between.  t_fg is Otsu's cut of log10(T_g / E_cb) over the cells of every run given (the
   fluid and the gas of a coexisting run are more than a decade apart, cf. Fig. 3.2), unless
   --t-fg fixes it; t_sf is orderparam's default 1e-2 (App. 3.A.1.1).  With --field density
   (or bridges) the cut is Otsu's on log10 of the number (bridge) density and the gas is the
   dilute class: number density alone cannot tell a homogeneous fluid from a homogeneous gas. */
#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_multifit.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io_h5.h"
#include "run_open.h"
#include "wg_args.h"

#define PROG "wetgran-interface"
#define T_SF_DEFAULT 1e-2     /* orderparam's solid cut (T_g / E_cb) */
#define MIN_SEPARATION 0.3    /* Otsu's classes closer than this (decades) are one phase */
#define MIN_SEPARATION_Z 0.1  /* ... for the coordination: a ratio 1.26, a bridge per grain at z = 4 */
#define MAX_COLS 64

enum field_kind { FIELD_TEMPERATURE, FIELD_DENSITY, FIELD_BRIDGES, FIELD_COORDINATION };
enum source_kind { SOURCE_AUTO, SOURCE_PROFILE, SOURCE_SNAPSHOTS, SOURCE_MAPS };
enum phase { PH_GAS = 0, PH_FLUID = 1, PH_SOLID = 2 };

typedef struct options {
  enum field_kind field;
  enum source_kind source;
  int nx, ny;             /* cells along x and y (snapshots); 0: default */
  double t0, t1;          /* averaging window (snapshots): from, to */
  double window;          /* > 0: consecutive windows of this length within [t0, t1] */
  double t_fg, t_sf;      /* NAN: from the data */
  double ef, eg;          /* --ends: E*_f-fgc, E*_fgc-g; NAN: not given */
  int ends_auto;          /* --ends auto: from the scan's own one-phase and coexisting runs */
  double fsmax;           /* strip: maximum shear force F_smax [m g] */
  double sigma;           /* relax: interfacial energy for mu_f */
  double xmin, xmax;      /* powerfit range */
  const char *xcol, *ycol;
  const char *h5;         /* ag: also write the table as HDF5 */
  double min_width;       /* droplets: narrower dense stretches are not droplets [d] */
  long min_cells;         /* domains: smaller crystalline components are not domains */
  double sp0, sp1;        /* droplets: the spacing's window; NAN: the coalescence regime */
  int tracks;             /* plug: the centres per run and frame, not the MSD */
  int smooth;             /* droplets: frames of the running median of N_f (odd) */
  int t_sf_given;         /* domains: --t-sf given (the temperature's cut) */
  int field_given;        /* --field given (domains' default is the coordination) */
} options;

/* A coarse-grained lateral field of one run: nx * ny cells (ny = 1 for a 2D run, whose
   lateral plane is the x axis).  Per cell, time averages. */
typedef struct field {
  const char *file;
  int dim, nx, ny;
  double lx, ly, height, e_cb, s_crit, f_b, gamma, estar;
  double t_from, t_to;  /* the times averaged over (profile: from its t_start, to NAN) */
  double *n;      /* particles per lateral area, d^-(D-1) */
  double *ncb;    /* bridges per lateral area */
  double *tg;     /* T_g [m g d]; NAN in a cell that never held a particle */
  double n_per_cell_particles; /* mean particles per snapshot (N) */
  unsigned char *phase;
} field;

static int usage(FILE *o, int rc)
{
  fprintf(o,
    "Usage: " PROG " MODE [options] RUN.h5 ...\n"
    "The coexisting phases of shaken wet runs on the lateral plane (thesis Ch. 5).\n"
    "Modes:\n"
    "  ag RUN.h5 ...       one row per run: gamma, estar, estar_tilde (with --ends), a_g (the\n"
    "                      gas fraction of the lateral plane: of the box length x in 2D, of\n"
    "                      the x-y area in 3D), its error (half the cells on an interface),\n"
    "                      the gas and dense components (periodic boundaries), the shape:\n"
    "                      f, g (one phase), plug (2D coexistence), I (gas drop), II (strip),\n"
    "                      III (fluid drop), the drop's equivalent radius sqrt(A/pi) [d]\n"
    "  field RUN.h5 ...    per cell of each run: file x [y] number_density bridge_density\n"
    "                      temperature temperature_ecb phase (g f s)\n"
    "  strip RUN.h5 ...    3D strip along x: both interfaces y(x) fitted with c + A cos(2 pi x/L_x)\n"
    "                      + B sin(..) (Eq. 5.4); rows key value error: ad_tilde (A~_d = A/L_x,\n"
    "                      mean of the two interfaces), n_p (particles in the fluid), with\n"
    "                      --fsmax F (F_smax [m g]): sigma = N_p F_smax / ((2 pi)^2 A~_d) (Eq. 5.9)\n"
    "                      [m g: energy per length of the interface line on the lateral plane,\n"
    "                      the thesis's normalisation], sigma_over_gamma (gamma = F_B / (pi d),\n"
    "                      Eq. 2.8, so in units of d), sigma_area_over_gamma (sigma over the box\n"
    "                      height: per area, comparable with Eq. 5.10), and eq5_10_sigma_over_gamma\n"
    "                      = (pi/6) n_cb d s_crit n^(-1/3) from the fluid's densities per volume\n"
    "                      (eq5_10_lateral_sigma_over_gamma: per lateral area, quasi-2D); with\n"
    "                      --window, a window without a strip gives ad_tilde nan, not an error\n"
    "  relax RUN.h5 ...    seeds of one relaxation: A~_d per frame (map or snapshot),\n"
    "                      averaged over the runs at equal times: rows t ad_tilde sd n; then\n"
    "                      (comment lines) the fit A~_d = A0 exp(-t/tau) over the frames in\n"
    "                      --from/--to (default all) and, with --sigma S,\n"
    "                      mu_f = 1 / ((2 pi)^2 S tau) (Eq. 5.13)\n"
    "  spacetime RUN.h5    rows t x number_density bridge_density per snapshot and x cell\n"
    "                      (gnuplot: plot F using 1:2:3 with image)\n"
    "  droplets RUN.h5 ... 2D, per frame (map or snapshot): file t periods (t/T_driv) n_f (dense\n"
    "                      stretches at least --min-width d wide, once gas stretches narrower\n"
    "                      than that are filled) n_f_smooth dense_fraction tg_ecb (mean\n"
    "                      T_g/E_cb) mean_spacing positions; then per run (comment lines) the\n"
    "                      regimes (Sec. 5.3.1: on N_f's running median over --smooth K frames\n"
    "                      (5): nucleation to its maximum t0, coalescence while it does not rise\n"
    "                      above its running minimum, to t1), the fit (smoothed N_f)\n"
    "                      N_f = c (T_g/E_cb)^(-1/2) over [t0, t1] with the free exponent beside it\n"
    "                      (Fig. 5.19), and the spacing of adjacent droplets over the smoothing\n"
    "                      window at t0 or --spacing A:B (mean, sd, median; Fig. 5.16's inset)\n"
    "  domains RUN.h5 ...  3D, per frame: file t periods n_d (crystalline domains) area_fraction\n"
    "                      mean_area [d^2]; a cell is crystalline where its coordination z =\n"
    "                      2 n_cb / n (bridges per grain) lies above the cut (Otsu's over the run's\n"
    "                      frames in --from/--to, or --t-fg Z; --field or --t-sf for T_g/E_cb < X\n"
    "                      instead); domains are its periodic\n"
    "                      4-connected components of at least --min-cells (2) cells; then the fit\n"
    "                      n_d = a (t/T_driv)^beta over --xmin < t/T_driv <= --xmax (Fig. 5.21)\n"
    "  plug RUN.h5 ...     2D seeds of one system: the plug (longest dense stretch) per frame, its\n"
    "                      interfaces placed where the log field crosses the cut, its centre their\n"
    "                      mean, unwrapped over the periodic box; rows t periods msd msd_over_lx2\n"
    "                      err n: sigma_rw(t) = <(x(t) - x(t_first))^2> over the runs; then the fit\n"
    "                      sigma_rw/L_x^2 = D_x (t/T_driv)^alpha over --xmin < t/T_driv <= --xmax\n"
    "                      with errors from the runs resampled (bootstrap; Fig. 5.24); --tracks:\n"
    "                      rows file t periods x left right instead (Fig. 5.23)\n"
    "  powerfit --x COL --y COL TABLE\n"
    "                      y = a x^beta (GSL Levenberg-Marquardt, start from the log-log line)\n"
    "                      over xmin < x <= xmax (default 0 < x <= 1): rows key value error\n"
    "                      a, beta, n (errors scaled by sqrt(chi^2/dof))\n"
    "Options:\n"
    "  --source profile|maps|snapshots  where the lateral field comes from: the run's\n"
    "                      time-averaged profile (2D runs with profile_bins; the default there\n"
    "                      without --window), its lateral maps (runs with map_bins: windows of\n"
    "                      dt_map, cells map_bins x map_bins_y; the default when present) or\n"
    "                      its particle snapshots (cells from --bins)\n"
    "  --bins NX[xNY]      cells of the snapshot grid (default: about 4 d wide)\n"
    "  --from T, --to T    averaging window over frames (default: all frames)\n"
    "  --window W          ag, field, strip: one row (set) per window [t, t + W) of snapshots\n"
    "                      from --from on (one cut pooled over every window of every run);\n"
    "                      columns t_from, t_to give the snapshots' times averaged over\n"
    "  --field temperature|density|bridges|coordination  the field the mask is cut on\n"
    "                      (default temperature; domains: coordination, bridges per grain)\n"
    "  --t-fg X            fix the gas cut (T_g/E_cb, or density) instead of Otsu's\n"
    "  --t-sf X            solid below this T_g/E_cb (default 0.01)\n"
    "  --ends EF:EG        E*_f-fgc and E*_fgc-g: estar_tilde = (E* - EF)/(EG - EF)\n"
    "  --ends auto         ag: the ends from the scan itself, each the midpoint between the\n"
    "                      last one-phase run (a_g = 0, resp. 1) and the first coexisting one\n"
    "                      (0 < a_g < 1), +- half their gap (a '# ends' line); an end the scan\n"
    "                      does not bracket is nan (and E~* with it); not with --window\n"
    "  --h5 FILE          ag: also write the table to FILE (HDF5: /ag/<column>, one value\n"
    "                      per run; /ag/file the run names; attribute threshold on /ag)\n"
    "  --fsmax F, --sigma S, --x COL, --y COL, --xmin X, --xmax X  (strip, relax, powerfit;\n"
    "                      --xmin/--xmax in driving periods for domains and plug: default all)\n"
    "  --min-width W, --spacing A:B, --smooth K (droplets), --min-cells K (domains),\n"
    "  --tracks (plug)\n"
    "Thresholds: Otsu's two-class cut of log10 of the field over the cells of every run given\n"
    "(a '# threshold' line gives it with the two classes' means; classes less than 0.3 decades\n"
    "apart are one phase, and the cut is then refused unless --t-fg is given).\n"
    "Errors name the file and the dataset; exit 1 (bad file), 2 (bad option).\n");
  return rc;
}

/* ---- reading runs ------------------------------------------------------------------------ */

static int need(hid_t f, const char *file, const char *path, const char *hint)
{
  if (wg_h5_exists(f, path)) return 0;
  fprintf(stderr, PROG ": %s: no dataset %s%s%s\n", file, path, hint ? " " : "", hint ? hint : "");
  return 1;
}

static int field_alloc(field *fd)
{
  size_t c = (size_t)fd->nx * fd->ny;
  fd->n = calloc(c, sizeof(double));
  fd->ncb = calloc(c, sizeof(double));
  fd->tg = calloc(c, sizeof(double));
  fd->phase = calloc(c, 1);
  return fd->n && fd->ncb && fd->tg && fd->phase ? 0 : 1;
}

static void field_free(field *fd)
{
  free(fd->n);
  free(fd->ncb);
  free(fd->tg);
  free(fd->phase);
}

/* The time-averaged profile along x (wetgran-run's /observables/profiles). */
static int read_profile(hid_t f, field *fd)
{
  static const char *p[] = {"/observables/profiles/x", "/observables/profiles/number_density",
                            "/observables/profiles/bridge_density",
                            "/observables/profiles/temperature"};
  for (int k = 0; k < 4; k++)
    if (need(f, fd->file, p[k], "(a run with profile_bins > 0, or use --source snapshots)")) return 1;
  int rank;
  hsize_t dims[8];
  if (wg_h5_dims(f, p[1], &rank, dims) != WG_OK) return 1;
  fd->nx = (int)dims[0];
  fd->ny = 1;
  if (fd->nx < 2 || field_alloc(fd)) {
    fprintf(stderr, PROG ": %s: %s: fewer than 2 bins\n", fd->file, p[1]);
    return 1;
  }
  if (wg_h5_read(f, p[1], H5T_NATIVE_DOUBLE, fd->n) || wg_h5_read(f, p[2], H5T_NATIVE_DOUBLE, fd->ncb) ||
      wg_h5_read(f, p[3], H5T_NATIVE_DOUBLE, fd->tg))
    return 1;
  for (int i = 0; i < fd->nx; i++)
    if (!(fd->n[i] > 0)) fd->tg[i] = NAN;
  if (H5Aexists_by_name(f, "/observables/profiles", "t_start", H5P_DEFAULT) <= 0 ||
      wg_h5_read_attr_double(f, "/observables/profiles", "t_start", &fd->t_from) != WG_OK)
    fd->t_from = NAN;
  fd->t_to = NAN;
  return 0;
}

typedef struct snaps {
  hsize_t frames, n;
  int dim;
  double *time, *mass;
} snaps;

static int snaps_open(hid_t f, const char *file, snaps *s)
{
  static const char *p[] = {"/particles/all/position/value", "/particles/all/position/time",
                            "/particles/all/velocity/value", "/particles/all/bridge_count/value",
                            "/particles/all/mass"};
  for (int k = 0; k < 5; k++)
    if (need(f, file, p[k], k == 0 ? "(a record without snapshots: set record_snapshots in the conf)" : NULL))
      return 1;
  int rank;
  hsize_t dims[8];
  if (wg_h5_dims(f, p[0], &rank, dims) != WG_OK) return 1;
  if (rank != 3 || dims[2] < 2 || dims[2] > 3) {
    fprintf(stderr, PROG ": %s: %s: not F x N x D\n", file, p[0]);
    return 1;
  }
  s->frames = dims[0];
  s->n = dims[1];
  s->dim = (int)dims[2];
  s->time = malloc(sizeof(double) * (s->frames ? s->frames : 1));
  s->mass = malloc(sizeof(double) * (s->n ? s->n : 1));
  if (!s->time || !s->mass || wg_h5_read(f, p[1], H5T_NATIVE_DOUBLE, s->time) ||
      wg_h5_read(f, p[4], H5T_NATIVE_DOUBLE, s->mass))
    return 1;
  if (s->frames == 0) {
    fprintf(stderr, PROG ": %s: %s: no snapshots\n", file, p[0]);
    return 1;
  }
  return 0;
}

/* Accumulates frame k into the sums: counts, bridge ends, and per cell the kinetic energy
   about the cell's own mean velocity (T_g per cell as in wetgran-run's profiles). */
typedef struct sums {
  double *cnt, *ends, *kin; /* per cell over frames */
  double *pm, *pv, *pv2;    /* per cell within one frame: sum m, sum m v (dim), sum m v^2 */
} sums;

static int frame_cell(const field *fd, const double *r)
{
  int ix = (int)floor(r[0] / fd->lx * fd->nx);
  ix = ((ix % fd->nx) + fd->nx) % fd->nx;
  int iy = 0;
  if (fd->ny > 1) {
    iy = (int)floor(r[1] / fd->ly * fd->ny);
    iy = ((iy % fd->ny) + fd->ny) % fd->ny;
  }
  return iy * fd->nx + ix;
}

static int add_frame(hid_t f, const field *fd, const snaps *s, hsize_t k, sums *u, double *pos,
                     double *vel, uint8_t *bc)
{
  int D = s->dim;
  if (wg_h5_read_rows(f, "/particles/all/position/value", H5T_NATIVE_DOUBLE, k, 1, pos) ||
      wg_h5_read_rows(f, "/particles/all/velocity/value", H5T_NATIVE_DOUBLE, k, 1, vel) ||
      wg_h5_read_rows(f, "/particles/all/bridge_count/value", H5T_NATIVE_UINT8, k, 1, bc))
    return 1;
  size_t c = (size_t)fd->nx * fd->ny;
  memset(u->pm, 0, sizeof(double) * c);
  memset(u->pv, 0, sizeof(double) * c * D);
  memset(u->pv2, 0, sizeof(double) * c);
  for (hsize_t i = 0; i < s->n; i++) {
    int j = frame_cell(fd, pos + i * D);
    double m = s->mass[i], v2 = 0;
    u->cnt[j] += 1;
    u->ends[j] += bc[i];
    u->pm[j] += m;
    for (int a = 0; a < D; a++) {
      u->pv[(size_t)j * D + a] += m * vel[i * D + a];
      v2 += vel[i * D + a] * vel[i * D + a];
    }
    u->pv2[j] += m * v2;
  }
  for (size_t j = 0; j < c; j++) {
    if (u->pm[j] <= 0) continue;
    double p2 = 0;
    for (int a = 0; a < D; a++) p2 += u->pv[j * D + a] * u->pv[j * D + a];
    u->kin[j] += u->pv2[j] - p2 / u->pm[j];
  }
  return 0;
}

/* The field from the snapshots with time in [t0, t1] (a single frame with k1 = k0 + 1). */
static int read_snapshots(hid_t f, field *fd, const snaps *s, hsize_t k0, hsize_t k1)
{
  size_t c = (size_t)fd->nx * fd->ny;
  int D = s->dim, rc = 0;
  sums u = {calloc(c, sizeof(double)), calloc(c, sizeof(double)), calloc(c, sizeof(double)),
            malloc(sizeof(double) * c), malloc(sizeof(double) * c * D), malloc(sizeof(double) * c)};
  double *pos = malloc(sizeof(double) * s->n * D), *vel = malloc(sizeof(double) * s->n * D);
  uint8_t *bc = malloc(s->n ? s->n : 1);
  if (!u.cnt || !u.ends || !u.kin || !u.pm || !u.pv || !u.pv2 || !pos || !vel || !bc) rc = 1;
  int used = 0;
  for (hsize_t k = k0; k < k1 && !rc; k++) {
    rc = add_frame(f, fd, s, k, &u, pos, vel, bc);
    used++;
  }
  if (!rc && used == 0) {
    fprintf(stderr, PROG ": %s: no snapshot in the window\n", fd->file);
    rc = 1;
  }
  double area = fd->lx / fd->nx * (fd->ny > 1 ? fd->ly / fd->ny : 1);
  for (size_t j = 0; j < c && !rc; j++) {
    fd->n[j] = u.cnt[j] / used / area;
    fd->ncb[j] = 0.5 * u.ends[j] / used / area; /* half a bridge per end, as the profiles */
    fd->tg[j] = u.cnt[j] > 0 ? u.kin[j] / (u.cnt[j] * D) : NAN;
  }
  free(u.cnt), free(u.ends), free(u.kin), free(u.pm), free(u.pv), free(u.pv2);
  free(pos), free(vel), free(bc);
  return rc;
}

/* The lateral maps (wetgran-run's /observables/maps, keys map_bins, dt_map): frames of
   window averages.  Frames k0 <= k < k1 are averaged: densities plainly, T_g weighted by
   the number of particles each frame's cell held. */
#define MAPS "/observables/maps/"
static int maps_times(hid_t f, const char *file, double **t, hsize_t *n)
{
  static const char *p[] = {MAPS "number_density/value", MAPS "bridge_density/value",
                            MAPS "temperature/value", MAPS "number_density/time"};
  *t = NULL;
  *n = 0;
  for (int k = 0; k < 4; k++)
    if (need(f, file, p[k], "(a run without map_bins: use --source snapshots)")) return 1;
  int rank;
  hsize_t dims[8];
  if (wg_h5_dims(f, p[3], &rank, dims) != WG_OK || rank != 1) return 1;
  *n = dims[0];
  if (*n == 0) {
    fprintf(stderr, PROG ": %s: %s: no frames (a run shorter than one dt_map)\n", file, p[3]);
    return 1;
  }
  *t = malloc(sizeof(double) * *n);
  return !*t || wg_h5_read(f, p[3], H5T_NATIVE_DOUBLE, *t);
}

static int read_maps(hid_t f, field *fd, const options *o, long frame)
{
  double *t = NULL;
  hsize_t nt = 0;
  int rank, rc = maps_times(f, fd->file, &t, &nt);
  hsize_t dims[8];
  if (!rc && (wg_h5_dims(f, MAPS "number_density/value", &rank, dims) != WG_OK ||
              rank != (fd->dim == 3 ? 3 : 2))) {
    fprintf(stderr, PROG ": %s: " MAPS "number_density/value: not frames x [ny x] nx\n", fd->file);
    rc = 1;
  }
  if (!rc) {
    fd->nx = (int)dims[rank - 1];
    fd->ny = fd->dim == 3 ? (int)dims[1] : 1;
    if ((o->nx > 0 && o->nx != fd->nx) || (fd->dim == 3 && o->ny > 0 && o->ny != fd->ny)) {
      fprintf(stderr, PROG ": %s: the maps have %dx%d cells (map_bins of the run); --bins applies "
              "to --source snapshots\n", fd->file, fd->nx, fd->ny);
      rc = 1;
    }
  }
  if (!rc && (fd->nx < 2 || field_alloc(fd))) {
    fprintf(stderr, PROG ": %s: maps of fewer than 2 cells along x\n", fd->file);
    rc = 1;
  }
  hsize_t k0 = 0, k1 = nt;
  if (!rc && frame >= 0) {
    if ((hsize_t)frame >= nt) {
      fprintf(stderr, PROG ": %s: " MAPS "number_density: no frame %ld (%llu frames)\n",
              fd->file, frame, (unsigned long long)nt);
      rc = 1;
    }
    k0 = (hsize_t)frame;
    k1 = k0 + 1;
  } else if (!rc) {
    while (k0 < nt && t[k0] < o->t0) k0++;
    k1 = k0;
    while (k1 < nt && t[k1] <= o->t1) k1++;
    if (k1 == k0) {
      fprintf(stderr, PROG ": %s: no map frame in the window\n", fd->file);
      rc = 1;
    }
  }
  size_t c = (size_t)fd->nx * fd->ny;
  double *buf = rc ? NULL : malloc(sizeof(double) * c * 3);
  double *wt = rc ? NULL : calloc(c, sizeof(double));
  if (!rc && (!buf || !wt)) rc = 1;
  for (size_t j = 0; j < c && !rc; j++) fd->n[j] = fd->ncb[j] = fd->tg[j] = 0;
  for (hsize_t k = k0; k < k1 && !rc; k++) {
    if (wg_h5_read_rows(f, MAPS "number_density/value", H5T_NATIVE_DOUBLE, k, 1, buf) ||
        wg_h5_read_rows(f, MAPS "bridge_density/value", H5T_NATIVE_DOUBLE, k, 1, buf + c) ||
        wg_h5_read_rows(f, MAPS "temperature/value", H5T_NATIVE_DOUBLE, k, 1, buf + 2 * c)) {
      rc = 1;
      break;
    }
    for (size_t j = 0; j < c; j++) {
      fd->n[j] += buf[j];
      fd->ncb[j] += buf[c + j];
      if (buf[j] > 0 && isfinite(buf[2 * c + j])) {
        fd->tg[j] += buf[j] * buf[2 * c + j];
        wt[j] += buf[j];
      }
    }
  }
  for (size_t j = 0; j < c && !rc; j++) {
    fd->n[j] /= (double)(k1 - k0);
    fd->ncb[j] /= (double)(k1 - k0);
    fd->tg[j] = wt[j] > 0 ? fd->tg[j] / wt[j] : NAN;
  }
  if (!rc) {
    fd->t_from = t[k0]; /* the frames' times: their windows' centres */
    fd->t_to = t[k1 - 1];
  }
  free(buf), free(wt), free(t);
  return rc;
}

/* Which record of the lateral plane a field is read from. */
static enum source_kind pick_source(hid_t f, const field *fd, const options *o, long frame)
{
  if (o->source != SOURCE_AUTO) return o->source;
  if (fd->dim == 2 && frame < 0 && !(o->window > 0) && wg_h5_exists(f, "/observables/profiles/number_density"))
    return SOURCE_PROFILE;
  return wg_h5_exists(f, MAPS "number_density/value") ? SOURCE_MAPS : SOURCE_SNAPSHOTS;
}

static int run_head(hid_t f, field *fd)
{
  if (wg_run_param(f, fd->file, "e_cb", &fd->e_cb, 1)) return 1;
  wg_run_param(f, fd->file, "gamma", &fd->gamma, 0);
  wg_run_param(f, fd->file, "estar", &fd->estar, 0);
  wg_run_param(f, fd->file, "s_crit", &fd->s_crit, 0);
  wg_run_param(f, fd->file, "f_b", &fd->f_b, 0);
  wg_run_param(f, fd->file, "height", &fd->height, 0);
  if (need(f, fd->file, "/particles/all/box/edges", NULL)) return 1;
  int rank;
  hsize_t dims[8];
  double e[3] = {0, 0, 0};
  if (wg_h5_dims(f, "/particles/all/box/edges", &rank, dims) || dims[0] < 2 || dims[0] > 3 ||
      wg_h5_read(f, "/particles/all/box/edges", H5T_NATIVE_DOUBLE, e)) {
    fprintf(stderr, PROG ": %s: /particles/all/box/edges: not 2 or 3 lengths\n", fd->file);
    return 1;
  }
  fd->dim = (int)dims[0];
  fd->lx = e[0];
  fd->ly = fd->dim == 3 ? e[1] : 1;
  return 0;
}

/* One run's field.  frame >= 0: that snapshot alone (relax). */
static int load_field(const char *file, const options *o, field *fd, long frame)
{
  memset(fd, 0, sizeof *fd);
  fd->file = file;
  hid_t f = wg_run_open(file);
  if (f < 0) return 1;
  int rc = run_head(f, fd);
  enum source_kind src = rc ? SOURCE_AUTO : pick_source(f, fd, o, frame);
  if (!rc && src == SOURCE_PROFILE) {
    rc = read_profile(f, fd);
  } else if (!rc && src == SOURCE_MAPS) {
    rc = read_maps(f, fd, o, frame);
  } else if (!rc) {
    snaps s = {0};
    rc = snaps_open(f, file, &s);
    if (!rc) {
      fd->nx = o->nx > 0 ? o->nx : (int)fmax(2, round(fd->lx / 4));
      fd->ny = fd->dim == 3 ? (o->ny > 0 ? o->ny : (int)fmax(2, round(fd->ly / 4))) : 1;
      rc = field_alloc(fd);
    }
    if (!rc) {
      hsize_t k0 = 0, k1 = s.frames;
      if (frame >= 0 && (hsize_t)frame >= s.frames) {
        fprintf(stderr, PROG ": %s: /particles/all/position/value: no snapshot %ld (%llu snapshots)\n",
                file, frame, (unsigned long long)s.frames);
        rc = 1;
      } else if (frame >= 0) {
        k0 = (hsize_t)frame;
        k1 = k0 + 1;
      } else {
        while (k0 < s.frames && s.time[k0] < o->t0) k0++;
        k1 = k0;
        while (k1 < s.frames && s.time[k1] <= o->t1) k1++;
      }
      if (!rc) rc = read_snapshots(f, fd, &s, k0, k1);
      if (!rc) {
        fd->t_from = s.time[k0];
        fd->t_to = s.time[k1 - 1];
      }
    }
    free(s.time);
    free(s.mass);
  }
  wg_h5_close(f);
  return rc;
}

/* ---- the mask ---------------------------------------------------------------------------- */

/* log10 of the cell's value in the mask's field; gas-like values are large (temperature) or
   small (densities); -INFINITY / +INFINITY where the cell is empty. */
static double cell_value(const field *fd, size_t j, enum field_kind k)
{
  switch (k) {
  case FIELD_TEMPERATURE: return isfinite(fd->tg[j]) && fd->tg[j] > 0 ? log10(fd->tg[j] / fd->e_cb) : INFINITY;
  case FIELD_DENSITY: return fd->n[j] > 0 ? log10(fd->n[j]) : -INFINITY;
  case FIELD_COORDINATION: /* bridges per grain: two ends per bridge */
    return fd->n[j] > 0 && fd->ncb[j] > 0 ? log10(2 * fd->ncb[j] / fd->n[j]) : -INFINITY;
  default: return fd->ncb[j] > 0 ? log10(fd->ncb[j]) : -INFINITY;
  }
}

static int cmp_int(const void *a, const void *b)
{
  int x = *(const int *)a, y = *(const int *)b;
  return (x > y) - (x < y);
}

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* Otsu: the cut of sorted x[0..n-1] into two classes with the largest between-class
   variance (as wetgran-orderparam); the classes' means in m1, m2. */
static double otsu(const double *x, size_t n, double *m1, double *m2)
{
  double best = -1, cut = NAN, total = 0, left = 0;
  *m1 = *m2 = NAN;
  for (size_t i = 0; i < n; i++) total += x[i];
  for (size_t k = 1; k < n; k++) {
    left += x[k - 1];
    double a = left / k, b = (total - left) / (n - k);
    double between = (double)k * (n - k) * (a - b) * (a - b);
    if (between > best && x[k] > x[k - 1]) {
      best = between;
      cut = 0.5 * (x[k - 1] + x[k]);
      *m1 = a;
      *m2 = b;
    }
  }
  return cut;
}

static const char *field_name(enum field_kind k)
{
  static const char *name[] = {"T_g/E_cb", "number_density", "bridge_density", "coordination"};
  return name[k];
}

/* The cut (log10) from all fields' cells; prints the '# threshold' line.  Empty cells (infinite
   values) are left out of the classes: they are gas whatever the cut. */
static int pooled_cut(field *fds, int nf, const options *o, double *cut)
{
  const char *name = field_name(o->field);
  double sep = o->field == FIELD_COORDINATION ? MIN_SEPARATION_Z : MIN_SEPARATION;
  if (isfinite(o->t_fg)) {
    *cut = log10(o->t_fg);
    printf("# threshold %s = %.6g (given)\n", name, o->t_fg);
    return 0;
  }
  size_t tot = 0, m = 0;
  for (int r = 0; r < nf; r++) tot += (size_t)fds[r].nx * fds[r].ny;
  double *x = malloc(sizeof(double) * (tot ? tot : 1));
  if (!x) return 1;
  for (int r = 0; r < nf; r++)
    for (size_t j = 0; j < (size_t)fds[r].nx * fds[r].ny; j++) {
      double v = cell_value(&fds[r], j, o->field);
      if (isfinite(v)) x[m++] = v;
    }
  qsort(x, m, sizeof *x, cmp_double);
  double m1, m2;
  *cut = m >= 2 ? otsu(x, m, &m1, &m2) : NAN;
  free(x);
  if (!isfinite(*cut) || m2 - m1 < sep) {
    fprintf(stderr, PROG ": %s%s: the cells' %s form one class (Otsu's classes %.3g decades apart, "
            "fewer than %.2g): no two phases to cut; give --t-fg\n", fds[0].file, nf > 1 ? " ..." : "",
            name, isfinite(*cut) ? m2 - m1 : 0.0, sep);
    return 1;
  }
  printf("# threshold %s = %.6g: Otsu's cut of log10 over %zu cells of %d field(s); class means %.4g and %.4g "
         "(%.2f decades apart)\n", name, pow(10, *cut), m, nf, pow(10, m1), pow(10, m2), m2 - m1);
  return 0;
}

static void make_mask(field *fd, const options *o, double cut)
{
  for (size_t j = 0; j < (size_t)fd->nx * fd->ny; j++) {
    double v = cell_value(fd, j, o->field);
    int gas = o->field == FIELD_TEMPERATURE ? v > cut : v < cut;
    fd->phase[j] = gas ? PH_GAS : PH_FLUID;
    if (!gas && isfinite(fd->tg[j]) && fd->tg[j] / fd->e_cb < o->t_sf) fd->phase[j] = PH_SOLID;
  }
}

/* ---- components with periodic boundaries ------------------------------------------------- */

typedef struct component {
  long cells;
  int wrap_x, wrap_y; /* the component closes on itself around the box along x / y */
} component;

/* Labels the connected components (4-neighbours, periodic) of the cells where dense(phase) is
   'want' (gas: 0, dense: 1).  A breadth-first search keeps each cell's unwrapped position; a
   neighbour already reached at another unwrapped position means the component winds around
   the box in that direction (a strip or a plug spanning the box).  Returns the number of
   components; comp[] their sizes and windings (the largest first is not guaranteed). */
static int components(const field *fd, int want, component **out)
{
  int nx = fd->nx, ny = fd->ny;
  size_t c = (size_t)nx * ny;
  int *lab = malloc(sizeof(int) * c), *ux = malloc(sizeof(int) * c), *uy = malloc(sizeof(int) * c);
  size_t *queue = malloc(sizeof(size_t) * c);
  component *comp = NULL;
  int nc = 0;
  if (!lab || !ux || !uy || !queue) goto done;
  for (size_t j = 0; j < c; j++) lab[j] = -1;
  for (size_t s = 0; s < c; s++) {
    if (lab[s] >= 0 || (fd->phase[s] != PH_GAS) != want) continue;
    component *t = realloc(comp, sizeof *comp * (nc + 1));
    if (!t) break;
    comp = t;
    comp[nc] = (component){0, 0, 0};
    size_t head = 0, tail = 0;
    queue[tail++] = s;
    lab[s] = nc;
    ux[s] = (int)(s % nx);
    uy[s] = (int)(s / nx);
    while (head < tail) {
      size_t j = queue[head++];
      comp[nc].cells++;
      static const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
      for (int k = 0; k < (ny > 1 ? 4 : 2); k++) {
        int X = ux[j] + dx[k], Y = uy[j] + dy[k];
        int x = ((X % nx) + nx) % nx, y = ((Y % ny) + ny) % ny;
        size_t q = (size_t)y * nx + x;
        if ((fd->phase[q] != PH_GAS) != want) continue;
        if (lab[q] < 0) {
          lab[q] = nc;
          ux[q] = X;
          uy[q] = Y;
          queue[tail++] = q;
        } else {
          if (ux[q] != X) comp[nc].wrap_x = 1;
          if (uy[q] != Y) comp[nc].wrap_y = 1;
        }
      }
    }
    nc++;
  }
done:
  free(lab), free(ux), free(uy), free(queue);
  *out = comp;
  return nc;
}

static int largest(const component *c, int n)
{
  int b = -1;
  for (int k = 0; k < n; k++)
    if (b < 0 || c[k].cells > c[b].cells) b = k;
  return b;
}

/* ---- mode ag ----------------------------------------------------------------------------- */

typedef struct agrow {
  double a_g, err, r_eq;
  int n_gas, n_dense;
  const char *shape;
} agrow;

static agrow measure_ag(const field *fd)
{
  agrow a = {0, 0, NAN, 0, 0, "-"};
  size_t c = (size_t)fd->nx * fd->ny, gas = 0, edge = 0;
  for (size_t j = 0; j < c; j++) {
    if (fd->phase[j] != PH_GAS) continue;
    gas++;
    int x = (int)(j % fd->nx), y = (int)(j / fd->nx);
    int nb[4][2] = {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}}, touch = 0;
    for (int k = 0; k < (fd->ny > 1 ? 4 : 2); k++) {
      size_t q = (size_t)((nb[k][1] + fd->ny) % fd->ny) * fd->nx + (nb[k][0] + fd->nx) % fd->nx;
      if (fd->phase[q] != PH_GAS) touch = 1;
    }
    edge += touch;
  }
  a.a_g = (double)gas / c;
  a.err = 0.5 * edge / c; /* the cut places each interface to within half a cell */
  component *g = NULL, *d = NULL;
  a.n_gas = components(fd, 0, &g);
  a.n_dense = components(fd, 1, &d);
  if (gas == 0) a.shape = "f";
  else if (gas == c) a.shape = "g";
  else if (fd->ny == 1) a.shape = "plug";
  else {
    int bg = largest(g, a.n_gas), bd = largest(d, a.n_dense);
    if (!g[bg].wrap_x && !g[bg].wrap_y) {
      a.shape = "I";
      a.r_eq = sqrt(g[bg].cells * (fd->lx / fd->nx) * (fd->ly / fd->ny) / M_PI);
    } else if (!d[bd].wrap_x && !d[bd].wrap_y) {
      a.shape = "III";
      a.r_eq = sqrt(d[bd].cells * (fd->lx / fd->nx) * (fd->ly / fd->ny) / M_PI);
    } else
      a.shape = "II";
  }
  free(g);
  free(d);
  return a;
}

/* The frame times of a run (for --window, relax, spacetime): of its maps or snapshots,
   whichever load_field reads frame by frame. */
static int run_times(const char *file, const options *o, double **t, hsize_t *n)
{
  *t = NULL;
  *n = 0;
  hid_t f = wg_run_open(file);
  if (f < 0) return 1;
  field head = {.file = file};
  int rc = run_head(f, &head);
  if (!rc && pick_source(f, &head, o, 0) == SOURCE_MAPS /* frame 0: never the profile */) {
    rc = maps_times(f, file, t, n);
  } else if (!rc) {
    snaps s = {0};
    rc = snaps_open(f, file, &s);
    free(s.mass);
    *t = s.time;
    *n = s.frames;
  }
  wg_h5_close(f);
  if (rc) { /* nothing for the caller to free */
    free(*t);
    *t = NULL;
    *n = 0;
  }
  return rc;
}

/* The fields of every run (with --window: of every window of every run holding a snapshot),
   masked with one cut pooled over all of them. */
static int load_all(int nf, char **files, const options *o, field **out, int *nfd, double *cut)
{
  field *fds = NULL;
  int n = 0, cap = 0;
  *out = NULL;
  *nfd = 0;
  for (int r = 0; r < nf; r++) {
    double lo = o->t0, hi = o->t1, step = INFINITY;
    double *t = NULL;
    hsize_t nt = 0;
    if (o->window > 0) {
      if (run_times(files[r], o, &t, &nt)) {
        free(t);
        return 1;
      }
      lo = fmax(o->t0, t[0]);
      hi = fmin(o->t1, t[nt - 1]);
      step = o->window;
    }
    for (double w = lo; w <= hi; w += step) {
      options one = *o;
      if (o->window > 0) {
        one.t0 = w;
        one.t1 = nextafter(w + step, -INFINITY); /* windows [w, w + step) */
        int any = 0;
        for (hsize_t k = 0; k < nt; k++) any |= t[k] >= one.t0 && t[k] <= one.t1;
        if (!any) continue;
      }
      if (n == cap) {
        cap = cap ? 2 * cap : 16;
        field *g = realloc(fds, sizeof *fds * cap);
        if (!g) {
          free(t);
          return 1;
        }
        fds = g;
        *out = fds;
      }
      if (load_field(files[r], &one, &fds[n], -1)) {
        free(t);
        *nfd = n + 1;
        return 1;
      }
      *nfd = ++n;
      if (!(o->window > 0)) break;
    }
    free(t);
  }
  if (pooled_cut(fds, n, o, cut)) return 1;
  for (int r = 0; r < n; r++) make_mask(&fds[r], o, *cut);
  return 0;
}

/* The ag table as HDF5 (--h5): one dataset per column under /ag, written to FILE.tmp and
   renamed when complete. */
#define AG_COLS 10
static int write_ag_h5(const char *path, int nf, const char **files, double (*col)[AG_COLS],
                       const char *const *shapes, double cut, const options *o)
{
  static const char *name[AG_COLS] = {"gamma", "estar", "estar_tilde", "a_g", "a_g_err", "n_gas", "n_dense", "r_eq", "t_from", "t_to"};
  static const char *unit[AG_COLS] = {"1", "1", "1", "1", "1", "1", "1", "d", "tau", "tau"};
  static const char *desc[AG_COLS] = {
      "peak acceleration Gamma of the run", "driving energy E* of the run",
      "(E* - E*_f-fgc) / (E*_fgc-g - E*_f-fgc) (--ends)", "gas fraction of the lateral plane",
      "half the interface cells over all cells", "gas components (periodic boundaries)",
      "dense (fluid or solid) components", "equivalent radius sqrt(A/pi) of the drop (shapes I, III)",
      "first time averaged over (profile: its t_start)", "last time averaged over (profile: nan)"};
  char tmp[4096];
  snprintf(tmp, sizeof tmp, "%s.tmp", path);
  hid_t f = wg_h5_create(tmp);
  if (f < 0) return 1;
  double *v = malloc(sizeof(double) * nf);
  int rc = !v;
  hsize_t dims[1] = {(hsize_t)nf};
  for (int c = 0; c < AG_COLS && !rc; c++) {
    for (int r = 0; r < nf; r++) v[r] = col[r][c];
    char p[64];
    snprintf(p, sizeof p, "/ag/%s", name[c]);
    rc = wg_h5_write(f, p, H5T_NATIVE_DOUBLE, 1, dims, v, unit[c], desc[c]) != WG_OK;
  }
  free(v);
  if (!rc) rc = wg_h5_attr_strings(f, "/ag", "file", nf, files) != WG_OK;
  if (!rc) rc = wg_h5_attr_strings(f, "/ag", "shape", nf, shapes) != WG_OK;
  if (!rc) rc = wg_h5_attr_double(f, "/ag", "threshold", pow(10, cut)) != WG_OK;
  if (!rc) rc = wg_h5_attr_string(f, "/ag", "threshold_field", field_name(o->field)) != WG_OK;
  if (wg_h5_close(f) != WG_OK) rc = 1;
  if (!rc && rename(tmp, path) != 0) {
    fprintf(stderr, PROG ": %s: cannot rename from %s\n", path, tmp);
    rc = 1;
  }
  if (rc) remove(tmp);
  return rc;
}

static int mode_ag(int nf, char **files, const options *o)
{
  field *fds = NULL;
  double cut;
  int n = 0;
  int rc = load_all(nf, files, o, &fds, &n, &cut);
  double (*col)[AG_COLS] = malloc(sizeof *col * (n ? n : 1));
  const char **shapes = malloc(sizeof *shapes * (n ? n : 1)), **names = malloc(sizeof *names * (n ? n : 1));
  if (!col || !shapes || !names) rc = 1;
  agrow *rows = malloc(sizeof *rows * (n ? n : 1));
  if (!rows) rc = 1;
  for (int r = 0; !rc && r < n; r++) rows[r] = measure_ag(&fds[r]);
  double ef = o->ef, eg = o->eg;
  if (!rc && o->ends_auto) {
    /* coexisting runs span [c0, c1]; f1 the largest E* below with a_g = 0, g0 the smallest
       above with a_g = 1 */
    double c0 = INFINITY, c1 = -INFINITY, f1 = -INFINITY, g0 = INFINITY;
    for (int r = 0; r < n; r++)
      if (rows[r].a_g > 0 && rows[r].a_g < 1) {
        c0 = fmin(c0, fds[r].estar);
        c1 = fmax(c1, fds[r].estar);
      }
    for (int r = 0; r < n; r++) {
      if (rows[r].a_g == 0 && fds[r].estar < c0) f1 = fmax(f1, fds[r].estar);
      if (rows[r].a_g == 1 && fds[r].estar > c1) g0 = fmin(g0, fds[r].estar);
    }
    if (!isfinite(c0)) {
      fprintf(stderr, PROG ": --ends auto: no coexisting run (0 < a_g < 1) in the scan\n");
      rc = 1;
    } else {
      /* an end the scan does not bracket (no fluid run below, no gas run above) is nan, and
         so is E~*; said on stderr */
      ef = isfinite(f1) ? 0.5 * (f1 + c0) : NAN;
      eg = isfinite(g0) ? 0.5 * (c1 + g0) : NAN;
      if (!isfinite(f1))
        fprintf(stderr, PROG ": --ends auto: no fluid run (a_g = 0) below E* = %g: E*_f-fgc is nan\n", c0);
      if (!isfinite(g0))
        fprintf(stderr, PROG ": --ends auto: no gas run (a_g = 1) above E* = %g: E*_fgc-g is nan\n", c1);
      printf("# ends from the scan: E*_f-fgc = %.6g +- %.3g, E*_fgc-g = %.6g +- %.3g\n", ef,
             isfinite(f1) ? 0.5 * (c0 - f1) : NAN, eg, isfinite(g0) ? 0.5 * (g0 - c1) : NAN);
    }
  }
  if (!rc) {
    printf("file\tgamma\testar\testar_tilde\ta_g\ta_g_err\tn_gas\tn_dense\tshape\tr_eq\tcells\tt_from\tt_to\n");
    for (int r = 0; r < n; r++) {
      agrow a = rows[r];
      double et = isfinite(ef) ? (fds[r].estar - ef) / (eg - ef) : NAN;
      double row[AG_COLS] = {fds[r].gamma, fds[r].estar, et, a.a_g, a.err, a.n_gas, a.n_dense, a.r_eq,
                             fds[r].t_from, fds[r].t_to};
      memcpy(col[r], row, sizeof row);
      shapes[r] = a.shape;
      names[r] = fds[r].file;
      printf("%s\t%.10g\t%.10g\t%.6g\t%.6g\t%.3g\t%d\t%d\t%s\t%.6g\t%dx%d\t%.10g\t%.10g\n", fds[r].file,
             fds[r].gamma, fds[r].estar, et, a.a_g, a.err, a.n_gas, a.n_dense, a.shape, a.r_eq, fds[r].nx,
             fds[r].ny, fds[r].t_from, fds[r].t_to);
    }
    if (o->h5) rc = write_ag_h5(o->h5, n, names, col, shapes, cut, o);
  }
  for (int r = 0; r < n; r++) field_free(&fds[r]);
  free(fds);
  free(rows);
  free(col);
  free(shapes);
  free(names);
  return rc;
}

static int mode_field(int nf, char **files, const options *o)
{
  field *fds = NULL;
  double cut;
  int n = 0;
  int rc = load_all(nf, files, o, &fds, &n, &cut);
  if (!rc) {
    printf("file\tx\ty\tnumber_density\tbridge_density\ttemperature\ttemperature_ecb\tphase\tt_from\tt_to\n");
    for (int r = 0; r < n; r++) {
      field *fd = &fds[r];
      for (int y = 0; y < fd->ny; y++)
        for (int x = 0; x < fd->nx; x++) {
          size_t j = (size_t)y * fd->nx + x;
          printf("%s\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\t%c\t%.10g\t%.10g\n", fd->file, (x + 0.5) * fd->lx / fd->nx,
                 fd->ny > 1 ? (y + 0.5) * fd->ly / fd->ny : 0.0, fd->n[j], fd->ncb[j], fd->tg[j],
                 fd->tg[j] / fd->e_cb, "gfs"[fd->phase[j]], fd->t_from, fd->t_to);
        }
    }
  }
  for (int r = 0; r < n; r++) field_free(&fds[r]);
  free(fds);
  return rc;
}

/* ---- strip: interfaces and the cosine fit ------------------------------------------------ */

/* For each column x of a strip along x: the dense band's two edges along y, found as the
   cells where the column changes phase (periodic), placed at the cell boundary; the band is
   the longest dense run of the column.  edges[x][0] lower, [1] upper (unwrapped: upper may
   exceed L_y).  Returns the number of columns with a band. */
static int strip_edges(const field *fd, double *lo, double *hi)
{
  int cols = 0;
  double dy = fd->ly / fd->ny;
  for (int x = 0; x < fd->nx; x++) {
    int best = 0, start = -1;
    lo[x] = hi[x] = NAN;
    for (int s = 0; s < fd->ny; s++) {
      /* a run starts at s where s is dense and s - 1 is gas */
      int here = fd->phase[(size_t)s * fd->nx + x] != PH_GAS;
      int prev = fd->phase[(size_t)((s - 1 + fd->ny) % fd->ny) * fd->nx + x] != PH_GAS;
      if (!here || prev) continue;
      int len = 0;
      while (len < fd->ny && fd->phase[(size_t)((s + len) % fd->ny) * fd->nx + x] != PH_GAS) len++;
      if (len > best) {
        best = len;
        start = s;
      }
    }
    if (start < 0) continue;
    lo[x] = start * dy;
    hi[x] = (start + best) * dy;
    cols++;
  }
  return cols;
}

/* h(x) = c + A cos(2 pi x / L) + B sin(2 pi x / L) by linear least squares (GSL); the
   amplitude A of the cosine (the force's own shape, Eq. 5.3-5.4) and its error, scaled by
   sqrt(chi^2/dof).  Columns with NAN are skipped; the edges are unwrapped relative to the
   first column so that a band crossing y = L_y stays one curve. */
static int cosine_fit(const double *xs, const double *h, int n, double L, double *A, double *dA)
{
  int m = 0;
  for (int i = 0; i < n; i++) m += isfinite(h[i]);
  if (m < 4) return 1;
  gsl_matrix *X = gsl_matrix_alloc(m, 3), *cov = gsl_matrix_alloc(3, 3);
  gsl_vector *y = gsl_vector_alloc(m), *c = gsl_vector_alloc(3);
  gsl_multifit_linear_workspace *w = gsl_multifit_linear_alloc(m, 3);
  int k = 0;
  for (int i = 0; i < n; i++) {
    if (!isfinite(h[i])) continue;
    double ph = 2 * M_PI * xs[i] / L;
    gsl_matrix_set(X, k, 0, 1);
    gsl_matrix_set(X, k, 1, cos(ph));
    gsl_matrix_set(X, k, 2, sin(ph));
    gsl_vector_set(y, k, h[i]);
    k++;
  }
  double chi2;
  gsl_multifit_linear(X, y, c, cov, &chi2, w);
  *A = gsl_vector_get(c, 1);
  *dA = sqrt(gsl_matrix_get(cov, 1, 1) * (m > 3 ? chi2 / (m - 3) : 0));
  gsl_matrix_free(X), gsl_matrix_free(cov), gsl_vector_free(y), gsl_vector_free(c);
  gsl_multifit_linear_free(w);
  return 0;
}

/* Unwraps a periodic edge curve along x (jumps of more than L/2 are taken across y = L). */
static void unwrap(double *h, int n, double L)
{
  double prev = NAN;
  for (int i = 0; i < n; i++) {
    if (!isfinite(h[i])) continue;
    if (isfinite(prev)) {
      while (h[i] - prev > L / 2) h[i] -= L;
      while (h[i] - prev < -L / 2) h[i] += L;
    }
    prev = h[i];
  }
}

/* A~_d of one field: the mean of the two interfaces' cosine amplitudes over L_x, its error. */
static int strip_amplitude(const field *fd, double *ad, double *err)
{
  double *lo = malloc(sizeof(double) * fd->nx), *hi = malloc(sizeof(double) * fd->nx),
         *xs = malloc(sizeof(double) * fd->nx);
  int rc = !lo || !hi || !xs;
  if (!rc) {
    for (int x = 0; x < fd->nx; x++) xs[x] = (x + 0.5) * fd->lx / fd->nx;
    if (strip_edges(fd, lo, hi) < 4) rc = 1;
  }
  double a1, e1, a2, e2;
  if (!rc) {
    unwrap(lo, fd->nx, fd->ly);
    unwrap(hi, fd->nx, fd->ly);
    rc = cosine_fit(xs, lo, fd->nx, fd->lx, &a1, &e1) || cosine_fit(xs, hi, fd->nx, fd->lx, &a2, &e2);
  }
  if (!rc) {
    *ad = 0.5 * (a1 + a2) / fd->lx;
    *err = 0.5 * sqrt(e1 * e1 + e2 * e2) / fd->lx;
  }
  if (rc) fprintf(stderr, PROG ": %s: no strip along x to trace (shape must be II)\n", fd->file);
  free(lo), free(hi), free(xs);
  return rc;
}

static int mode_strip(int nf, char **files, const options *o)
{
  field *fds = NULL;
  double cut;
  int n = 0;
  int rc = load_all(nf, files, o, &fds, &n, &cut);
  for (int r = 0; !rc && r < n; r++) {
    field *fd = &fds[r];
    if (fd->ny < 2) {
      fprintf(stderr, PROG ": %s: a strip needs a 2D lateral plane (a 3D run)\n", fd->file);
      rc = 1;
      break;
    }
    agrow shape = measure_ag(fd);
    double ad = NAN, err = NAN;
    int strip = !strcmp(shape.shape, "II");
    if (strip && o->window > 0) { /* a window of a run's history: a gap, not an error */
      strip = strip_amplitude(fd, &ad, &err) == 0;
    } else if (strip && (rc = strip_amplitude(fd, &ad, &err))) break;
    if (!strip && o->window > 0) {
      printf("file\t%s\tnan\nkey\tvalue\terror\nt_from\t%.10g\tnan\nt_to\t%.10g\tnan\n"
             "ad_tilde\tnan\tnan\n# shape %s: no strip along x in this window\n",
             fd->file, fd->t_from, fd->t_to, shape.shape);
      continue;
    }
    if (!strip) {
      fprintf(stderr, PROG ": %s: no strip along x to trace (shape %s, not II)\n", fd->file, shape.shape);
      rc = 1;
      break;
    }
    /* N_p: particles in the dense cells; the fluid's n and n_cb per volume (height) */
    double cell = fd->lx / fd->nx * fd->ly / fd->ny, np = 0, ncb = 0, area = 0;
    for (size_t j = 0; j < (size_t)fd->nx * fd->ny; j++)
      if (fd->phase[j] != PH_GAS) {
        np += fd->n[j] * cell;
        ncb += fd->ncb[j] * cell;
        area += cell;
      }
    printf("file\t%s\tnan\nkey\tvalue\terror\nt_from\t%.10g\tnan\nt_to\t%.10g\tnan\n", fd->file, fd->t_from, fd->t_to);
    printf("ad_tilde\t%.6g\t%.3g\nn_p\t%.6g\tnan\n", ad, err, np);
    double h = fd->height > 0 ? fd->height : NAN;
    double nvol = np / (area * h), ncbvol = ncb / (area * h);
    double gamma_l = fd->f_b / M_PI; /* F_B = pi d gamma (Eq. 2.8), d = 1 */
    if (isfinite(o->fsmax)) {
      double sigma = np * o->fsmax / (4 * M_PI * M_PI * ad); /* Eq. 5.9 */
      printf("sigma\t%.6g\t%.3g\nsigma_over_gamma\t%.6g\t%.3g\n", sigma, sigma * err / fabs(ad),
             sigma / gamma_l, sigma / gamma_l * err / fabs(ad));
      /* Eq. 5.9 balances the work against the extra length of the interface line; spread
         over the height H of the box it is an energy per area, the quantity of Eq. 5.10 */
      printf("sigma_area_over_gamma\t%.6g\t%.3g\n", sigma / (gamma_l * h), sigma / (gamma_l * h) * err / fabs(ad));
    }
    /* Eq. 5.10 */
    printf("eq5_10_sigma_over_gamma\t%.6g\tnan\n", M_PI / 6 * ncbvol * fd->s_crit * pow(1 / nvol, 1.0 / 3));
    /* the same with the densities per lateral area (the layer seen from above, as Fig. 5.7
       draws n_cb): the quasi-2D reading */
    printf("eq5_10_lateral_sigma_over_gamma\t%.6g\tnan\n",
           M_PI / 6 * (ncb / area) * fd->s_crit * pow(area / np, 1.0 / 3));
  }
  for (int r = 0; r < n; r++) field_free(&fds[r]);
  free(fds);
  return rc;
}

/* ---- relax: A~_d(t) over seeds ----------------------------------------------------------- */

static int mode_relax(int nf, char **files, const options *o)
{
  /* the frames of the first run set the times; every run must have them */
  double *t0 = NULL;
  hsize_t nt = 0;
  if (run_times(files[0], o, &t0, &nt)) return 1;
  int rc = 0;
  double *sum = calloc(nt, sizeof(double)), *sum2 = calloc(nt, sizeof(double));
  int *cnt = calloc(nt, sizeof(int));
  if (!sum || !sum2 || !cnt) rc = 1;
  double cut = isfinite(o->t_fg) ? log10(o->t_fg) : NAN;
  for (int r = 0; !rc && r < nf; r++)
    for (hsize_t k = 0; !rc && k < nt; k++) {
      field fd;
      if ((rc = load_field(files[r], o, &fd, (long)k))) break;
      if (fd.ny < 2) {
        fprintf(stderr, PROG ": %s: relax needs a 3D run (a strip on the lateral plane)\n", files[r]);
        rc = 1;
      }
      if (!rc && !isfinite(cut)) rc = pooled_cut(&fd, 1, o, &cut);
      if (!rc) {
        make_mask(&fd, o, cut);
        double ad, err;
        if (strip_amplitude(&fd, &ad, &err) == 0) {
          sum[k] += fabs(ad);
          sum2[k] += ad * ad;
          cnt[k]++;
        }
      }
      field_free(&fd);
    }
  if (!rc) {
    printf("t\tad_tilde\tsd\tn\n");
    double *lt = malloc(sizeof(double) * nt), *ly = malloc(sizeof(double) * nt);
    size_t m = 0;
    for (hsize_t k = 0; k < nt; k++) {
      if (!cnt[k]) continue;
      double mean = sum[k] / cnt[k], var = cnt[k] > 1 ? (sum2[k] - cnt[k] * mean * mean) / (cnt[k] - 1) : NAN;
      printf("%.10g\t%.6g\t%.3g\t%d\n", t0[k], mean, var > 0 ? sqrt(var) : 0.0, cnt[k]);
      if (mean > 0 && lt && ly && t0[k] >= o->t0 && t0[k] <= o->t1) { /* --from, --to: the fit */
        lt[m] = t0[k];
        ly[m++] = log(mean);
      }
    }
    if (m >= 3) {
      double c0, c1, c00, c01, c11, ss;
      gsl_fit_linear(lt, 1, ly, 1, m, &c0, &c1, &c00, &c01, &c11, &ss);
      double tau = -1 / c1, dtau = sqrt(c11) / (c1 * c1);
      printf("# fit ad_tilde = A0 exp(-t / tau): A0 = %.6g, tau = %.6g +- %.3g\n", exp(c0), tau, dtau);
      if (isfinite(o->sigma))
        printf("# mu_f = 1 / ((2 pi)^2 sigma tau) = %.6g +- %.3g (Eq. 5.13, sigma = %g)\n",
               1 / (4 * M_PI * M_PI * o->sigma * tau), dtau / (4 * M_PI * M_PI * o->sigma * tau * tau), o->sigma);
    } else
      printf("# fewer than 3 times with a strip: no fit\n");
    free(lt), free(ly);
  }
  free(sum), free(sum2), free(cnt), free(t0);
  return rc;
}

/* ---- spacetime ---------------------------------------------------------------------------- */

static int mode_spacetime(int nf, char **files, const options *o)
{
  if (nf != 1) {
    fprintf(stderr, PROG ": spacetime takes one run\n");
    return 2;
  }
  double *tk = NULL;
  hsize_t nt = 0;
  if (run_times(files[0], o, &tk, &nt)) return 1;
  int rc = 0;
  printf("t\tx\tnumber_density\tbridge_density\n");
  for (hsize_t k = 0; !rc && k < nt; k++) {
    if (tk[k] < o->t0 || tk[k] > o->t1) continue;
    options one = *o;
    if (one.source != SOURCE_MAPS) one.ny = 1; /* snapshots: one cell across y */
    field fd;
    rc = load_field(files[0], &one, &fd, (long)k);
    if (!rc) {
      /* along x only: sum over y (3D runs) */
      for (int x = 0; x < fd.nx; x++) {
        double n = 0, b = 0;
        for (int y = 0; y < fd.ny; y++) {
          n += fd.n[(size_t)y * fd.nx + x];
          b += fd.ncb[(size_t)y * fd.nx + x];
        }
        printf("%.10g\t%.6g\t%.6g\t%.6g\n", tk[k], (x + 0.5) * fd.lx / fd.nx, n / fd.ny, b / fd.ny);
      }
      printf("\n");
    }
    field_free(&fd);
  }
  free(tk);
  return rc;
}

/* ---- powerfit ----------------------------------------------------------------------------- */

typedef struct pdata {
  size_t n;
  double *x, *y;
} pdata;

static int power_f(const gsl_vector *p, void *d_, gsl_vector *r)
{
  const pdata *d = d_;
  double a = gsl_vector_get(p, 0), b = gsl_vector_get(p, 1);
  for (size_t i = 0; i < d->n; i++) gsl_vector_set(r, i, a * pow(d->x[i], b) - d->y[i]);
  return GSL_SUCCESS;
}

static int power_df(const gsl_vector *p, void *d_, gsl_matrix *J)
{
  const pdata *d = d_;
  double a = gsl_vector_get(p, 0), b = gsl_vector_get(p, 1);
  for (size_t i = 0; i < d->n; i++) {
    double xb = pow(d->x[i], b);
    gsl_matrix_set(J, i, 0, xb);
    gsl_matrix_set(J, i, 1, a * xb * log(d->x[i]));
  }
  return GSL_SUCCESS;
}

static int mode_powerfit(const char *path, const options *o)
{
  if (!o->xcol || !o->ycol) {
    fprintf(stderr, PROG ": powerfit needs --x COL and --y COL\n");
    return 2;
  }
  wg_xy t;
  if (wg_table_read_xy(path, o->xcol, o->ycol, 0, &t)) return 1;
  pdata d = {0, t.x, t.y};
  for (size_t i = 0; i < t.n; i++)
    if (t.x[i] > o->xmin && t.x[i] <= o->xmax && isfinite(t.y[i]) && t.y[i] > 0)
      d.x[d.n] = t.x[i], d.y[d.n++] = t.y[i];
  if (d.n < 3) {
    fprintf(stderr, PROG ": %s: %zu points with %g < %s <= %g and %s > 0, fewer than 3\n", path, d.n,
            o->xmin, o->xcol, o->xmax, o->ycol);
    free(d.x), free(d.y);
    return 1;
  }
  /* start: the straight line through log y against log x */
  double *lx = malloc(sizeof(double) * d.n), *ly = malloc(sizeof(double) * d.n);
  for (size_t i = 0; i < d.n; i++) lx[i] = log(d.x[i]), ly[i] = log(d.y[i]);
  double c0, c1, c00, c01, c11, ss;
  gsl_fit_linear(lx, 1, ly, 1, d.n, &c0, &c1, &c00, &c01, &c11, &ss);
  free(lx), free(ly);
  gsl_multifit_nlinear_fdf fdf = {power_f, power_df, NULL, d.n, 2, &d, 0, 0, 0};
  gsl_multifit_nlinear_parameters par = gsl_multifit_nlinear_default_parameters();
  gsl_multifit_nlinear_workspace *w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &par, d.n, 2);
  double start[2] = {exp(c0), c1};
  gsl_vector_view sv = gsl_vector_view_array(start, 2);
  gsl_multifit_nlinear_init(&sv.vector, &fdf, w);
  int info;
  gsl_set_error_handler_off();
  int st = gsl_multifit_nlinear_driver(500, 1e-10, 1e-10, 0, NULL, NULL, &info, w);
  gsl_matrix *cov = gsl_matrix_alloc(2, 2);
  gsl_multifit_nlinear_covar(gsl_multifit_nlinear_jac(w), 0, cov);
  double chi2;
  gsl_blas_ddot(gsl_multifit_nlinear_residual(w), gsl_multifit_nlinear_residual(w), &chi2);
  double s = d.n > 2 ? sqrt(chi2 / (d.n - 2)) : NAN;
  gsl_vector *p = gsl_multifit_nlinear_position(w);
  printf("key\tvalue\terror\n");
  printf("a\t%.6g\t%.3g\nbeta\t%.6g\t%.3g\nn\t%zu\tnan\n", gsl_vector_get(p, 0),
         s * sqrt(gsl_matrix_get(cov, 0, 0)), gsl_vector_get(p, 1), s * sqrt(gsl_matrix_get(cov, 1, 1)), d.n);
  if (st != GSL_SUCCESS) fprintf(stderr, PROG ": %s: the fit did not converge (%s)\n", path, gsl_strerror(st));
  gsl_matrix_free(cov);
  gsl_multifit_nlinear_free(w);
  free(d.x), free(d.y);
  return st != GSL_SUCCESS;
}

/* ---- coarsening: frame by frame (droplets, domains, plug) -------------------------------- */

/* Every frame of one run as its own field (maps: one read of each dataset; snapshots: one
   snapshot per frame), frames with time in [--from, --to].  The cut (log10) is Otsu's over
   all of the run's frames unless given; each frame is masked with it. */
typedef struct frames {
  int n;
  field *f;
  double cut;
} frames;

static void frames_free(frames *fr)
{
  for (int k = 0; k < fr->n; k++) field_free(&fr->f[k]);
  free(fr->f);
  fr->f = NULL;
  fr->n = 0;
}

static int load_frames(const char *file, const options *o, frames *fr)
{
  double cut = NAN;
  memset(fr, 0, sizeof *fr);
  double *t = NULL;
  hsize_t nt = 0;
  if (run_times(file, o, &t, &nt)) return 1;
  int rc = 0;
  fr->f = calloc(nt ? nt : 1, sizeof *fr->f);
  if (!fr->f) rc = 1;
  hid_t f = rc ? -1 : wg_run_open(file);
  if (f < 0) rc = 1;
  field head = {.file = file};
  if (!rc) rc = run_head(f, &head);
  int maps = !rc && pick_source(f, &head, o, 0) == SOURCE_MAPS;
  if (maps) {
    /* all frames at once: frames x cells per field */
    int rank;
    hsize_t dims[8];
    rc = wg_h5_dims(f, MAPS "number_density/value", &rank, dims) != WG_OK || rank != (head.dim == 3 ? 3 : 2);
    size_t c = rc ? 0 : (size_t)dims[rank - 1] * (head.dim == 3 ? dims[1] : 1);
    double *b[3] = {NULL, NULL, NULL};
    static const char *p[3] = {MAPS "number_density/value", MAPS "bridge_density/value", MAPS "temperature/value"};
    for (int q = 0; q < 3 && !rc; q++)
      rc = !(b[q] = malloc(sizeof(double) * c * nt)) || wg_h5_read(f, p[q], H5T_NATIVE_DOUBLE, b[q]);
    for (hsize_t k = 0; k < nt && !rc; k++) {
      if (t[k] < o->t0 || t[k] > o->t1) continue;
      field *fd = &fr->f[fr->n];
      *fd = head;
      fd->nx = (int)dims[rank - 1];
      fd->ny = head.dim == 3 ? (int)dims[1] : 1;
      if ((rc = field_alloc(fd))) break;
      fr->n++;
      for (size_t j = 0; j < c; j++) {
        fd->n[j] = b[0][k * c + j];
        fd->ncb[j] = b[1][k * c + j];
        fd->tg[j] = fd->n[j] > 0 ? b[2][k * c + j] : NAN;
      }
      fd->t_from = fd->t_to = t[k];
    }
    for (int q = 0; q < 3; q++) free(b[q]);
  }
  if (f >= 0) wg_h5_close(f);
  for (hsize_t k = 0; k < nt && !rc && !maps; k++) {
    if (t[k] < o->t0 || t[k] > o->t1) continue;
    if ((rc = load_field(file, o, &fr->f[fr->n], (long)k))) break;
    fr->n++;
  }
  free(t);
  if (!rc && fr->n == 0) {
    fprintf(stderr, PROG ": %s: no frame in [--from, --to]\n", file);
    rc = 1;
  }
  if (!rc) rc = pooled_cut(fr->f, fr->n, o, &cut);
  fr->cut = cut;
  for (int k = 0; k < fr->n && !rc; k++) make_mask(&fr->f[k], o, cut);
  if (rc) frames_free(fr);
  return rc;
}

/* 0 when the run has dimension 'dim'; else 1, with 'why' on stderr (or the file's own error). */
static int need_dim(const char *file, int dim, const char *why)
{
  hid_t f = wg_run_open(file);
  if (f < 0) return 1;
  field head = {.file = file};
  int rc = run_head(f, &head);
  wg_h5_close(f);
  if (!rc && head.dim != dim) {
    fprintf(stderr, PROG ": %s: %s\n", file, why);
    rc = 1;
  }
  return rc;
}

/* The driving period T_driv = 2 pi / omega, omega = Gamma g / (A omega), A omega from E*
   (wetgran-run's shaker_driving); NAN for a run without them. */
static double t_driv(const char *file)
{
  hid_t f = wg_run_open(file);
  if (f < 0) return NAN;
  double gam, es, ecb, g;
  wg_run_param(f, file, "gamma", &gam, 0), wg_run_param(f, file, "estar", &es, 0), wg_run_param(f, file, "e_cb", &ecb, 0);
  wg_run_param(f, file, "gravity", &g, 0);
  wg_h5_close(f);
  if (!isfinite(g)) g = 1; /* wetgran-run's default */
  if (!(gam > 0) || !(es > 0) || !(ecb > 0)) return NAN;
  return 2 * M_PI * sqrt(2 * es * ecb) / (gam * g);
}

/* The dense stretches of a 2D frame's row (periodic): start cell s[k] and length len[k] in
   cells, the stretch running s, s+1, ... (mod nx).  A row all dense is one stretch of nx
   cells starting at 0.  Returns their number. */
static int stretches(const field *fd, int *s, int *len)
{
  int nx = fd->nx, m = 0, g = -1;
  for (int i = 0; i < nx && g < 0; i++)
    if (fd->phase[i] == PH_GAS) g = i;
  if (g < 0) {
    s[0] = 0, len[0] = nx;
    return 1;
  }
  for (int k = 1; k <= nx; k++) { /* from the cell after a gas cell, once round */
    int i = (g + k) % nx;
    if (fd->phase[i] == PH_GAS) continue;
    if (fd->phase[(i + nx - 1) % nx] == PH_GAS) s[m] = i, len[m++] = 0;
    len[m - 1]++;
  }
  return m;
}

/* Fills the gas stretches of a 2D frame's row narrower than minw cells that lie between dense
   cells: one noisy cell must not split a droplet in two. */
static void close_gaps(field *fd, int minw)
{
  int nx = fd->nx, d = -1;
  for (int i = 0; i < nx && d < 0; i++)
    if (fd->phase[i] != PH_GAS) d = i;
  if (d < 0) return;
  for (int k = 1; k <= nx; k++) { /* from the cell after a dense cell, once round */
    int i = (d + k) % nx, len = 0;
    if (fd->phase[i] != PH_GAS) continue;
    while (len < nx && fd->phase[(i + len) % nx] == PH_GAS) len++;
    if (len < minw)
      for (int j = 0; j < len; j++) fd->phase[(i + j) % nx] = PH_FLUID;
    k += len - 1;
  }
}

/* The position of the cut between the centres of cells a (dense) and b (gas, next to it
   along +x or -x): linear in the log field, so an interface is placed to better than a cell.
   Returns the offset from a's centre towards b, in cells, in [0, 1]. */
static double cut_offset(const field *fd, const options *o, int a, int b, double cut)
{
  double va = cell_value(fd, (size_t)a, o->field), vb = cell_value(fd, (size_t)b, o->field);
  if (!isfinite(va) || !isfinite(vb) || va == vb) return 0.5;
  double u = (cut - va) / (vb - va);
  return u < 0 ? 0 : u > 1 ? 1 : u;
}

/* A power law y = D x^alpha through the points with x, y > 0, by the log-log line (GSL);
   *err: alpha's error from the line's residuals (NULL: not wanted).  1 with fewer than 3. */
static int loglog_fit(const double *x, const double *y, size_t n, double *d, double *alpha, double *err)
{
  double *lx = malloc(sizeof(double) * (n ? n : 1)), *ly = malloc(sizeof(double) * (n ? n : 1));
  size_t m = 0;
  for (size_t i = 0; i < n && lx && ly; i++)
    if (x[i] > 0 && y[i] > 0) lx[m] = log(x[i]), ly[m++] = log(y[i]);
  int rc = m < 3;
  if (!rc) {
    double c0, c1, c00, c01, c11, ss;
    gsl_fit_linear(lx, 1, ly, 1, m, &c0, &c1, &c00, &c01, &c11, &ss);
    *d = exp(c0), *alpha = c1;
    if (err) *err = sqrt(c11);
  }
  free(lx), free(ly);
  return rc;
}

/* ---- droplets (2D): N_f(t), positions, spacing; the coalescence regime ----------------- */

/* The droplets of a 2D frame (gaps narrower than minw cells filled first): their centres,
   sorted, in pos; the dense share of the row in *dense.  Returns their number. */
static int droplet_centres(field *fd, int minw, int *s, int *len, double *pos, double *dense)
{
  close_gaps(fd, minw);
  int m = stretches(fd, s, len), nd = 0;
  double dx = fd->lx / fd->nx, cells = 0;
  for (int q = 0; q < m; q++) {
    cells += len[q];
    if (len[q] >= minw) pos[nd++] = fmod((s[q] + 0.5 * len[q]) * dx, fd->lx);
  }
  *dense = cells / fd->nx;
  qsort(pos, nd, sizeof *pos, cmp_double);
  return nd;
}

static double gap_after(const double *pos, int nd, int q, double lx)
{
  return q + 1 < nd ? pos[q + 1] - pos[q] : pos[0] + lx - pos[q];
}

static int mode_droplets(int nf, char **files, const options *o)
{
  int rc = 0;
  printf("file\tt\tperiods\tn_f\tn_f_smooth\tdense_fraction\ttg_ecb\tmean_spacing\tpositions\n");
  for (int r = 0; r < nf && !rc; r++) {
    frames fr;
    if (need_dim(files[r], 2, "droplets needs a 2D run (domains is the 3D mode)")) return 1;
    if ((rc = load_frames(files[r], o, &fr))) break;
    int nx = fr.f[0].nx, minw = (int)ceil(o->min_width / (fr.f[0].lx / nx) - 1e-9), h = o->smooth / 2;
    if (minw < 1) minw = 1;
    double td = t_driv(files[r]), lx = fr.f[0].lx;
    int *s = malloc(sizeof(int) * nx), *len = malloc(sizeof(int) * nx);
    int *cnt = malloc(sizeof(int) * fr.n), *sm = malloc(sizeof(int) * fr.n);
    /* pos + k nx: frame k's droplet centres, found once */
    double *tg = malloc(sizeof(double) * fr.n), *dense = malloc(sizeof(double) * fr.n);
    double *pos = malloc(sizeof(double) * (size_t)nx * fr.n), *gaps = malloc(sizeof(double) * (size_t)nx * fr.n);
    if (!s || !len || !cnt || !sm || !tg || !dense || !pos || !gaps) rc = 1;
    for (int k = 0; k < fr.n && !rc; k++) {
      const field *fd = &fr.f[k];
      double nsum = 0, tsum = 0;
      for (int i = 0; i < nx; i++)
        if (fd->n[i] > 0 && isfinite(fd->tg[i])) nsum += fd->n[i], tsum += fd->n[i] * fd->tg[i];
      tg[k] = nsum > 0 ? tsum / nsum / fd->e_cb : NAN;
      cnt[k] = droplet_centres(&fr.f[k], minw, s, len, pos + (size_t)k * nx, &dense[k]);
    }
    /* the count smoothed against flicker: running median of --smooth frames, the window
       shrunk symmetrically at the ends */
    for (int k = 0; k < fr.n && !rc; k++) {
      int w[64], m = 0, hk = h < k ? h : k;
      if (hk > fr.n - 1 - k) hk = fr.n - 1 - k;
      for (int j = k - hk; j <= k + hk; j++) w[m++] = cnt[j];
      qsort(w, m, sizeof *w, cmp_int);
      sm[k] = w[m / 2];
    }
    for (int k = 0; k < fr.n && !rc; k++) {
      const field *fd = &fr.f[k];
      int nd = cnt[k];
      const double *p = pos + (size_t)k * nx;
      printf("%s\t%.10g\t%.6g\t%d\t%d\t%.4g\t%.6g\t%.6g\t", files[r], fd->t_from, fd->t_from / td, nd, sm[k], dense[k],
             tg[k], nd > 1 ? lx / nd : NAN);
      for (int q = 0; q < nd; q++) printf("%s%.4g", q ? "," : "", p[q]);
      printf("%s\n", nd ? "" : "-");
    }
    if (!rc) {
      /* the regimes (Sec. 5.3.1) on the smoothed count: nucleation while N_f grows, to its
         first maximum t0; coalescence while it does not rise above its running minimum, to
         t1, the last frame before it first does (a gas bubble splits a drop: the reordering
         regime begins) */
      int k0 = 0, k1;
      for (int k = 1; k < fr.n; k++)
        if (sm[k] > sm[k0]) k0 = k;
      int low = sm[k0];
      for (k1 = k0 + 1; k1 < fr.n && sm[k1] <= low; k1++) low = sm[k1];
      k1--;
      printf("# %s: nucleation to t0 = %.6g (N_f reaches its maximum %d), coalescence to t1 = %.6g "
             "(N_f %d, rising after; counts smoothed over %d frames)\n", files[r], fr.f[k0].t_from,
             sm[k0], fr.f[k1].t_from, sm[k1], 2 * h + 1);
      /* N_f = c (T_g / E_cb)^(-1/2) over the coalescence frames (Fig. 5.19), and the free
         exponent of the log-log line as the check */
      double sxy = 0, sxx = 0, *xt = malloc(sizeof(double) * fr.n), *yn = malloc(sizeof(double) * fr.n), c, ex, dex;
      size_t m = 0;
      for (int k = k0; k <= k1 && xt && yn; k++)
        if (sm[k] > 0 && tg[k] > 0) {
          double x = 1 / sqrt(tg[k]);
          sxy += x * sm[k], sxx += x * x;
          xt[m] = tg[k], yn[m++] = sm[k];
        }
      if (xt && yn && !loglog_fit(xt, yn, m, &c, &ex, &dex))
        printf("# %s: coalescence frames %zu: N_f = %.4g (T_g/E_cb)^(-1/2); free fit N_f ~ (T_g/E_cb)^%.4g +- %.2g\n",
               files[r], m, sxy / sxx, ex, dex);
      else
        printf("# %s: coalescence frames %zu: fewer than 3, no fit\n", files[r], m);
      free(xt), free(yn);
      /* spacing of adjacent droplets (Fig. 5.16's inset): over --spacing A:B, else over the
         frames of the smoothing window at t0, the nuclei before they merge (the mean of one
         frame's gaps is L_x / N_f; their spread is the pattern's) */
      double a = fr.f[k0 - h < 0 ? 0 : k0 - h].t_from, b = fr.f[k0 + h >= fr.n ? fr.n - 1 : k0 + h].t_from;
      if (isfinite(o->sp0)) a = o->sp0, b = o->sp1;
      size_t ng = 0;
      for (int k = 0; k < fr.n; k++) {
        if (fr.f[k].t_from < a || fr.f[k].t_from > b) continue;
        for (int q = 0; q < cnt[k] && cnt[k] > 1; q++) gaps[ng++] = gap_after(pos + (size_t)k * nx, cnt[k], q, lx);
      }
      double gm = 0, g2 = 0;
      for (size_t q = 0; q < ng; q++) gm += gaps[q], g2 += gaps[q] * gaps[q];
      if (ng) gm /= ng;
      double sd = ng > 1 ? sqrt(fmax(0, (g2 - ng * gm * gm) / (ng - 1))) : NAN;
      qsort(gaps, ng, sizeof *gaps, cmp_double);
      printf("# %s: spacing of adjacent droplets over t in [%.6g, %.6g]: mean %.4g d, sd %.3g, median %.4g, "
             "%zu gaps\n", files[r], a, b, ng ? gm : NAN, sd, ng ? gaps[ng / 2] : NAN, ng);
    }
    free(s), free(len), free(cnt), free(sm), free(tg), free(dense), free(pos), free(gaps);
    frames_free(&fr);
  }
  return rc;
}

/* ---- domains (3D): crystalline domains on the lateral plane ------------------------------ */

/* A cell is crystalline where its grains hold more bridges than the fluid's: the coordination
   z = 2 n_cb / n (bridges per grain) above a cut.  Grains in hexagonal layers touch six in
   the layer and more in the layers beside it, where the fluid's keep about four (the cells of
   the Fig. 5.20 system, T_g/E_cb about 0.7 in both phases, give two classes near z = 4.1 and
   5.5); the cut is Otsu's over every cell of the run's frames in [--from, --to] (the hot gas of
   the start has z near 0: leave it out), refused when the classes are less than a factor 1.26
   apart, or --t-fg Z.  --field chooses another field (bridges, density: crystalline above;
   temperature: below) and --t-sf X is the temperature cut T_g/E_cb < X.  Domains are the
   connected components (4-neighbours, periodic) of crystalline cells, of at least
   --min-cells cells. */
static int mode_domains(int nf, char **files, const options *o)
{
  int rc = 0;
  printf("file\tt\tperiods\tn_d\tarea_fraction\tmean_area\n");
  options ot = *o;
  if (o->t_sf_given) ot.field = FIELD_TEMPERATURE, ot.t_fg = o->t_sf;
  else if (!o->field_given) ot.field = FIELD_COORDINATION;
  for (int r = 0; r < nf && !rc; r++) {
    frames fr;
    if (need_dim(files[r], 3, "domains needs a 3D run (a lateral plane); droplets is the 2D mode")) return 1;
    if ((rc = load_frames(files[r], &ot, &fr))) break;
    double td = t_driv(files[r]), cell = fr.f[0].lx / fr.f[0].nx * (fr.f[0].ly / fr.f[0].ny);
    double *xt = malloc(sizeof(double) * fr.n), *yn = malloc(sizeof(double) * fr.n);
    double a_first = NAN, a_last = NAN, a, beta, dbeta;
    size_t m = 0;
    for (int k = 0; k < fr.n && xt && yn; k++) {
      field *fd = &fr.f[k];
      size_t c = (size_t)fd->nx * fd->ny, solid = 0;
      for (size_t j = 0; j < c; j++) /* make_mask: crystalline is the side that is not gas */
        fd->phase[j] = fd->phase[j] != PH_GAS && fd->n[j] > 0 ? PH_SOLID : PH_GAS;
      component *d = NULL;
      int nc = components(fd, 1, &d), nd = 0;
      for (int q = 0; q < nc; q++)
        if (d[q].cells >= o->min_cells) nd++, solid += (size_t)d[q].cells;
      free(d);
      double per = fd->t_from / td, frac = (double)solid / c;
      printf("%s\t%.10g\t%.6g\t%d\t%.5g\t%.6g\n", files[r], fd->t_from, per, nd, frac,
             nd ? solid * cell / nd : NAN);
      if (per > o->xmin && per <= o->xmax && nd > 0) {
        if (!m) a_first = frac;
        a_last = frac;
        xt[m] = per, yn[m++] = nd;
      }
    }
    if (xt && yn && !loglog_fit(xt, yn, m, &a, &beta, &dbeta)) /* error: the residuals' scatter */
      printf("# %s: fit n_d = a (t/T_driv)^beta over %g < t/T_driv <= %g (%zu frames): a = %.4g, beta = %.4g +- %.2g; "
             "area fraction %.4g -> %.4g\n", files[r], o->xmin, o->xmax, m, a, beta, dbeta, a_first, a_last);
    else
      printf("# %s: fewer than 3 frames with domains in %g < t/T_driv <= %g: no fit\n", files[r], o->xmin, o->xmax);
    free(xt), free(yn);
    frames_free(&fr);
  }
  return rc;
}

/* ---- plug (2D): the dense plug's centre of mass and its mean square displacement --------- */

/* The plug of one frame: the longest dense stretch; its interfaces placed by cut_offset, its
   centre the mean of the two (Sec. 5.3.3), unwrapped to the image nearest 'prev' (NAN: none).
   Returns 0 and x, left, right; 1 where the frame has no plug (all gas, or all dense). */
static int plug_centre(const field *fd, const options *o, double cut, double prev, double *x,
                       double *left, double *right)
{
  int nx = fd->nx, *s = malloc(sizeof(int) * nx), *len = malloc(sizeof(int) * nx);
  if (!s || !len) {
    free(s), free(len);
    return 1;
  }
  int m = stretches(fd, s, len), b = -1;
  for (int q = 0; q < m; q++)
    if (b < 0 || len[q] > len[b]) b = q;
  int none = b < 0 || len[b] >= nx;
  if (!none) {
    double dx = fd->lx / nx;
    int a0 = s[b], a1 = s[b] + len[b] - 1; /* first and last dense cell (a1 may pass nx) */
    double l = (a0 + 0.5 - cut_offset(fd, o, a0, (a0 + nx - 1) % nx, cut)) * dx;
    double r = (a1 + 0.5 + cut_offset(fd, o, a1 % nx, (a1 + 1) % nx, cut)) * dx;
    double c = 0.5 * (l + r);
    if (isfinite(prev)) {
      double shift = fd->lx * round((prev - c) / fd->lx);
      c += shift, l += shift, r += shift;
    }
    *x = c, *left = l, *right = r;
  }
  free(s), free(len);
  return none;
}

#define PLUG_BOOT 400 /* bootstrap resamples of the runs */

static int mode_plug(int nf, char **files, const options *o)
{
  /* tracks[r][k]: run r's unwrapped centre at frame k (NAN: no plug); every run must have
     the first run's frame times */
  frames fr;
  int rc = 0, nt = 0, found = 0;
  double *tk = NULL, **tr = calloc(nf, sizeof *tr), lx = NAN, td = NAN;
  if (!tr) return 1;
  for (int r = 0; r < nf && !rc; r++) {
    if ((rc = need_dim(files[r], 2, "plug needs a 2D run")) || (rc = load_frames(files[r], o, &fr))) break;
    if (r == 0) {
      nt = fr.n, lx = fr.f[0].lx, td = t_driv(files[0]);
      tk = malloc(sizeof(double) * nt);
      for (int k = 0; tk && k < nt; k++) tk[k] = fr.f[k].t_from;
    } else if (fr.n != nt || fabs(fr.f[0].lx - lx) > 1e-9 * lx ||
               fabs(fr.f[nt - 1].t_from - tk[nt - 1]) > 1e-6 * fabs(tk[nt - 1]) + 1e-9) {
      fprintf(stderr, PROG ": %s: %d frames to t = %g in a box of %g d, where %s has %d to t = %g in %g d: "
              "the runs of one plug MSD must share box and frames\n", files[r], fr.n, fr.f[fr.n - 1].t_from,
              fr.f[0].lx, files[0], nt, tk[nt - 1], lx);
      rc = 1;
    }
    if (!rc && !(tr[r] = malloc(sizeof(double) * nt))) rc = 1;
    double prev = NAN, l, rr;
    int jumps = 0, missing = 0;
    for (int k = 0; k < nt && !rc; k++) {
      double x;
      if (plug_centre(&fr.f[k], o, fr.cut, prev, &x, &l, &rr)) {
        tr[r][k] = NAN, missing++;
        continue;
      }
      if (isfinite(prev) && fabs(x - prev) > 0.25 * lx) jumps++;
      tr[r][k] = prev = x;
      if (o->tracks)
        printf("%s%s\t%.10g\t%.6g\t%.6g\t%.6g\t%.6g\n", r + k == 0 ? "file\tt\tperiods\tx\tleft\tright\n" : "",
               files[r], tk[k], tk[k] / td, x, l, rr);
    }
    found += nt - missing;
    if (!rc && (jumps || missing))
      fprintf(stderr, PROG ": %s: %d frames without a plug, %d jumps of the centre by more than L_x/4\n",
              files[r], missing, jumps);
    frames_free(&fr);
  }
  if (rc || o->tracks) {
    for (int r = 0; r < nf; r++) free(tr[r]);
    free(tr), free(tk);
    return rc;
  }
  /* the origin: each run's centre at the first frame (the frames start at --from) */
  double *msd = calloc(nt, sizeof(double)), *err = calloc(nt, sizeof(double)), *px = malloc(sizeof(double) * nt);
  int *cnt = calloc(nt, sizeof(int)), *use = malloc(sizeof(int) * nf);
  double *bm = malloc(sizeof(double) * nt);
  int *bc = malloc(sizeof(int) * nt);
  if (!msd || !err || !px || !cnt || !use || !bm || !bc) rc = 1;
  int nuse = 0;
  for (int r = 0; r < nf && !rc; r++)
    if (isfinite(tr[r][0])) use[nuse++] = r;
    else fprintf(stderr, PROG ": %s: no plug in the first frame (t = %g): left out of the MSD\n", files[r], tk[0]);
  if (!rc && nuse < 2) {
    fprintf(stderr, PROG ": %d run(s) with a plug in the first frame: the MSD needs at least 2\n", nuse);
    rc = 1;
  }
  for (int k = 0; k < nt && !rc; k++) {
    double s = 0, s2 = 0;
    for (int q = 0; q < nuse; q++) {
      double d = tr[use[q]][k] - tr[use[q]][0];
      if (!isfinite(d)) continue;
      s += d * d, s2 += d * d * d * d, cnt[k]++;
    }
    msd[k] = cnt[k] ? s / cnt[k] : NAN;
    err[k] = cnt[k] > 1 ? sqrt(fmax(0, (s2 / cnt[k] - msd[k] * msd[k]) / (cnt[k] - 1))) : NAN;
    px[k] = (tk[k] - tk[0]) / td;
  }
  if (!rc) {
    printf("# a plug in %d of %d frames (%d runs x %d frames)\n", found, nf * nt, nf, nt);
    printf("t\tperiods\tmsd\tmsd_over_lx2\terr\tn\n");
    for (int k = 0; k < nt; k++)
      printf("%.10g\t%.6g\t%.6g\t%.6g\t%.3g\t%d\n", tk[k], px[k], msd[k], msd[k] / (lx * lx), err[k] / (lx * lx), cnt[k]);
    /* the fit sigma_rw / L_x^2 = D_x (t/T_driv)^alpha over the window; its errors from the
       runs resampled with replacement (the MSD's points share the runs: their own error bars
       are not independent) */
    size_t n = 0;
    double *x = malloc(sizeof(double) * nt), *y = malloc(sizeof(double) * nt), d, alpha;
    for (int k = 0; x && y && k < nt; k++)
      if (px[k] > o->xmin && px[k] <= o->xmax && cnt[k] > 0) x[n] = px[k], y[n++] = msd[k] / (lx * lx);
    if (!x || !y || loglog_fit(x, y, n, &d, &alpha, NULL)) {
      printf("# fewer than 3 frames with a displacement in %g < t/T_driv <= %g: no fit\n", o->xmin, o->xmax);
    } else {
      gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
      gsl_rng_set(g, 1);
      double sa = 0, sa2 = 0, sd = 0, sd2 = 0;
      int nb = 0;
      for (int b = 0; b < PLUG_BOOT && g; b++) {
        for (int k = 0; k < nt; k++) bm[k] = 0, bc[k] = 0;
        for (int q = 0; q < nuse; q++) {
          int rr = use[gsl_rng_uniform_int(g, nuse)];
          for (int k = 0; k < nt; k++) {
            double dd = tr[rr][k] - tr[rr][0];
            if (isfinite(dd)) bm[k] += dd * dd, bc[k]++;
          }
        }
        size_t m = 0;
        for (int k = 0; k < nt; k++)
          if (px[k] > o->xmin && px[k] <= o->xmax && bc[k] > 0) x[m] = px[k], y[m++] = bm[k] / bc[k] / (lx * lx);
        double bd, ba;
        if (loglog_fit(x, y, m, &bd, &ba, NULL)) continue;
        sa += ba, sa2 += ba * ba, sd += log10(bd), sd2 += log10(bd) * log10(bd), nb++;
      }
      gsl_rng_free(g);
      double ea = nb > 1 ? sqrt(fmax(0, (sa2 - sa * sa / nb) / (nb - 1))) : NAN;
      double el = nb > 1 ? sqrt(fmax(0, (sd2 - sd * sd / nb) / (nb - 1))) : NAN;
      printf("# fit msd/L_x^2 = D_x (t/T_driv)^alpha over %g < t/T_driv <= %g (%zu frames, %d runs): "
             "D_x = %.4g (log10 %.4g +- %.2g), alpha = %.4g +- %.2g (bootstrap over the runs, %d resamples)\n",
             o->xmin, o->xmax, n, nuse, d, log10(d), el, alpha, ea, nb);
    }
    free(x), free(y);
  }
  free(msd), free(err), free(px), free(cnt), free(use), free(bm), free(bc);
  for (int r = 0; r < nf; r++) free(tr[r]);
  free(tr), free(tk);
  return rc;
}

/* ---- main --------------------------------------------------------------------------------- */

static int pair(const char *opt, const char *s, double *a, double *b)
{
  char buf[256];
  snprintf(buf, sizeof buf, "%s", s);
  char *c = strchr(buf, ':');
  if (!c) {
    fprintf(stderr, PROG ": option %s: '%s' is not A:B\n", opt, s);
    return 1;
  }
  *c = 0;
  return wg_arg_double(opt, buf, a) || wg_arg_double(opt, c + 1, b);
}

int main(int argc, char **argv)
{
  if (argc < 2) return usage(stderr, 2);
  if (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) return usage(stdout, 0);
  const char *mode = argv[1];
  options o = {.field = FIELD_TEMPERATURE, .source = SOURCE_AUTO, .t0 = -INFINITY, .t1 = INFINITY,
               .window = 0, .t_fg = NAN, .t_sf = T_SF_DEFAULT, .ef = NAN, .eg = NAN, .fsmax = NAN,
               .sigma = NAN, .xmin = 0, .xmax = NAN, .min_width = 0, .min_cells = 2, .sp0 = NAN,
               .sp1 = NAN, .smooth = 5};
  char *files[argc]; /* the inputs among the arguments: at most argc - 2 */
  int nf = 0;
  for (int i = 2; i < argc; i++) {
    const char *a = argv[i];
    const char *v = i + 1 < argc ? argv[i + 1] : NULL;
    int val = a[0] == '-' && a[1] == '-' && strcmp(a, "--help") && strcmp(a, "--tracks");
    if (val && !v) {
      fprintf(stderr, PROG ": option %s needs a value\n", a);
      return 2;
    }
    if (!strcmp(a, "-h") || !strcmp(a, "--help")) return usage(stdout, 0);
    else if (!strcmp(a, "--source")) {
      if (!strcmp(v, "profile")) o.source = SOURCE_PROFILE;
      else if (!strcmp(v, "maps")) o.source = SOURCE_MAPS;
      else if (!strcmp(v, "snapshots")) o.source = SOURCE_SNAPSHOTS;
      else {
        fprintf(stderr, PROG ": option --source: '%s' is not profile, maps or snapshots\n", v);
        return 2;
      }
    } else if (!strcmp(a, "--field")) {
      if (!strcmp(v, "temperature")) o.field = FIELD_TEMPERATURE;
      else if (!strcmp(v, "density")) o.field = FIELD_DENSITY;
      else if (!strcmp(v, "bridges")) o.field = FIELD_BRIDGES;
      else if (!strcmp(v, "coordination")) o.field = FIELD_COORDINATION;
      else {
        fprintf(stderr, PROG ": option --field: '%s' is not temperature, density, bridges or coordination\n", v);
        return 2;
      }
      o.field_given = 1;
    } else if (!strcmp(a, "--bins")) {
      long nx, ny = 0;
      char buf[64];
      snprintf(buf, sizeof buf, "%s", v);
      char *xp = strchr(buf, 'x');
      if (xp) *xp = 0;
      if (wg_arg_long(a, buf, &nx) || (xp && wg_arg_long(a, xp + 1, &ny))) return 2;
      if (nx < 2 || (xp && ny < 2)) {
        fprintf(stderr, PROG ": option --bins: at least 2 cells per direction\n");
        return 2;
      }
      o.nx = (int)nx;
      o.ny = (int)ny;
    } else if (!strcmp(a, "--from")) { if (wg_arg_double(a, v, &o.t0)) return 2; }
    else if (!strcmp(a, "--to")) { if (wg_arg_double(a, v, &o.t1)) return 2; }
    else if (!strcmp(a, "--window")) {
      if (wg_arg_double(a, v, &o.window)) return 2;
      if (!(o.window > 0)) {
        fprintf(stderr, PROG ": option --window: must be positive\n");
        return 2;
      }
    }
    else if (!strcmp(a, "--t-fg")) { if (wg_arg_double(a, v, &o.t_fg)) return 2; }
    else if (!strcmp(a, "--t-sf")) {
      if (wg_arg_double(a, v, &o.t_sf)) return 2;
      o.t_sf_given = 1;
    }
    else if (!strcmp(a, "--min-width")) { if (wg_arg_double(a, v, &o.min_width)) return 2; }
    else if (!strcmp(a, "--min-cells")) { if (wg_arg_long(a, v, &o.min_cells)) return 2; }
    else if (!strcmp(a, "--spacing")) { if (pair(a, v, &o.sp0, &o.sp1)) return 2; }
    else if (!strcmp(a, "--tracks")) { o.tracks = 1; continue; }
    else if (!strcmp(a, "--smooth")) {
      long k;
      if (wg_arg_long(a, v, &k)) return 2;
      if (k < 1 || k > 63 || k % 2 == 0) {
        fprintf(stderr, PROG ": option --smooth: an odd number of frames from 1 to 63\n");
        return 2;
      }
      o.smooth = (int)k;
    }
    else if (!strcmp(a, "--fsmax")) { if (wg_arg_double(a, v, &o.fsmax)) return 2; }
    else if (!strcmp(a, "--sigma")) { if (wg_arg_double(a, v, &o.sigma)) return 2; }
    else if (!strcmp(a, "--xmin")) { if (wg_arg_double(a, v, &o.xmin)) return 2; }
    else if (!strcmp(a, "--xmax")) { if (wg_arg_double(a, v, &o.xmax)) return 2; }
    else if (!strcmp(a, "--h5")) o.h5 = v;
    else if (!strcmp(a, "--x")) o.xcol = v;
    else if (!strcmp(a, "--y")) o.ycol = v;
    else if (!strcmp(a, "--ends") && !strcmp(v, "auto"))
      o.ends_auto = 1;
    else if (!strcmp(a, "--ends")) {
      if (pair(a, v, &o.ef, &o.eg)) return 2;
      if (!(o.eg != o.ef)) {
        fprintf(stderr, PROG ": option --ends: the two E* must differ\n");
        return 2;
      }
    } else if (a[0] == '-' && a[1]) {
      fprintf(stderr, PROG ": unknown option %s\n", a);
      return 2;
    } else {
      files[nf++] = argv[i];
      continue;
    }
    i++;
  }
  if (isfinite(o.t_fg) && !(o.t_fg > 0)) {
    fprintf(stderr, PROG ": option --t-fg: must be positive\n");
    return 2;
  }
  if (o.ends_auto && o.window > 0) {
    fprintf(stderr, PROG ": option --ends auto: one row per run is needed (not with --window)\n");
    return 2;
  }
  if (nf == 0) {
    fprintf(stderr, PROG ": %s: no input file\n", mode);
    return 2;
  }
  if (!isfinite(o.xmax)) o.xmax = strcmp(mode, "powerfit") ? INFINITY : 1;
  wg_h5_quiet();
  int rc;
  if (!strcmp(mode, "ag")) rc = mode_ag(nf, files, &o);
  else if (!strcmp(mode, "field")) rc = mode_field(nf, files, &o);
  else if (!strcmp(mode, "strip")) rc = mode_strip(nf, files, &o);
  else if (!strcmp(mode, "relax")) rc = mode_relax(nf, files, &o);
  else if (!strcmp(mode, "spacetime")) rc = mode_spacetime(nf, files, &o);
  else if (!strcmp(mode, "droplets")) rc = mode_droplets(nf, files, &o);
  else if (!strcmp(mode, "domains")) rc = mode_domains(nf, files, &o);
  else if (!strcmp(mode, "plug")) rc = mode_plug(nf, files, &o);
  else if (!strcmp(mode, "powerfit")) {
    if (nf != 1) {
      fprintf(stderr, PROG ": powerfit takes one table\n");
      return 2;
    }
    rc = mode_powerfit(files[0], &o);
  } else {
    fprintf(stderr, PROG ": unknown mode '%s' (ag, field, strip, relax, spacetime, droplets, domains, plug, powerfit)\n", mode);
    rc = 2;
  }
  return rc;
}
