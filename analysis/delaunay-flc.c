/* wetgran-delaunay-flc: the frequency of location changes f_lc, the dynamic order parameter
   of the solid-fluid transition (Roeller 2010, Sec. 3.A.1.1, Fig. 3.28a), and, with
   --diffusion, the lateral diffusion coefficients of layers of equal population (surface
   melting, Sec. 4.3.3, Fig. 4.3), from the particle snapshots of a run file.

   Location changes.  The thesis triangulates the particle centres; each particle owns its
   Voronoi cell, the cells move with their particles, and the triangulation stays valid until
   a centre leaves its cell; "the frequency of these site changes, or equivalently the
   frequency of violations of the Delaunay triangulation" is f_lc.  A violation is repaired by
   a flip of the triangulation, which makes two particles Delaunay neighbours that were not
   before, i.e. creates an edge.  So between two snapshots we count the edges present now and
   absent before; f_lc = (number of new edges) / (time between the snapshots).

   The triangulation is that of the whole packing: particles near a periodic face are copied
   across it, particles near a wall mirrored in it, the padded set is triangulated (qhull),
   and every edge between particles with an end in the box is kept, named by its two particles
   and the periodic image that joins them (so that an edge survives a particle crossing the
   face).  Tab-separated tables on stdout, messages on stderr. */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_fit.h>
#include <libqhull_r/qhull_ra.h>

#include "io_h5.h"
#include "run_open.h"

#define PROG "wetgran-delaunay-flc"
#define POS "/particles/all/position"
#define BOX "/particles/all/box"
#define MAXDIM 3

static void usage(FILE *out)
{
  fprintf(out,
    "Usage: " PROG " [OPTIONS] RUN.h5\n"
    "       " PROG " [OPTIONS] --tsv FILE\n"
    "\n"
    "Frequency of location changes f_lc, the dynamic order parameter between solid and fluid\n"
    "of Roeller (2010), Sec. 3.A.1.1 (\"Solid-fluid phase boundary\") and Fig. 3.28a: \"A\n"
    "Delaunay triangulation for the positions of the particle centers is performed ... the\n"
    "whole triangulation is therefore valid until one of the particles' centers moves out of\n"
    "its initially calculated Voronoi cell ... The frequency of these site changes, or\n"
    "equivalently the frequency of violations of the Delaunay triangulation is called\n"
    "frequency of location changes\".  Here, for each pair of consecutive snapshots, the\n"
    "Delaunay triangulations of the particle centres (qhull \"d Qt Qbb Qc Qz\", 2D or 3D) are\n"
    "compared.  A violation is repaired by a flip of the triangulation, which makes two\n"
    "particles neighbours that were not, i.e. creates an edge: the location changes of an\n"
    "interval are the edges (pairs of Delaunay neighbours) present at its end and absent at\n"
    "its start, and f_lc = changes / dt.  In 2D every flip creates one edge; in 3D a 2-3 flip\n"
    "creates one and a 3-2 flip none (it removes one), so there the count is that of new\n"
    "neighbour pairs, about half the flips.  Snapshots must be close enough that an edge\n"
    "rarely flips away and back between them (f_lc dt small against the number of edges):\n"
    "the count of a coarser sampling is lower.  A perfect lattice (the start of a run) is\n"
    "degenerate: its triangulation is not unique, and the first interval's count depends on\n"
    "qhull's choice (leave it out with --from).\n"
    "\n"
    "The triangulation is that of the whole packing: along periodic axes the particles\n"
    "within the margin of a face are copied across it; along walls (boundary 'none', e.g.\n"
    "the vertical axis of a shaker) they are mirrored in planes half a diameter beyond the\n"
    "lowest and the highest centre, so that the Voronoi cells of particles at a wall or at\n"
    "the free surface end there (without, rows of particles along a wall, nearly collinear,\n"
    "are joined by long flat triangles outside the packing that flip whenever one rattles).\n"
    "Edges between two particles with at least one end in the box are kept, copies mapped\n"
    "back to their particles.  An edge is named by its two particles and by the periodic\n"
    "image that joins them, followed through the snapshots by unwrapping, so a rigid motion\n"
    "across a periodic face changes nothing.  Each triangulation is checked: every triangle\n"
    "(tetrahedron) with a corner in the box must have its circumcircle (sphere) inside the\n"
    "region filled with copies; if not, the margin is doubled (until the copies hold every\n"
    "particle; then a warning) and kept for the following snapshots.\n"
    "\n"
    "Input: RUN.h5, a run file of wetgran-run (H5MD: /particles/all/position/value and time,\n"
    "/particles/all/box with its edges and boundary), or --tsv FILE, a text file holding a line\n"
    "  # box LX LY [LZ] FLAG FLAG [FLAG]        (FLAG: periodic or none, one per axis)\n"
    "followed by rows 'time id x y [z]' (blanks or tabs), one per particle and snapshot, ids\n"
    "0..N-1, the rows of a snapshot together, snapshots in increasing time.  Other '#' lines\n"
    "and a header line starting with 'time' are skipped.  Coordinates along periodic axes may\n"
    "lie outside the box: they are wrapped into it.\n"
    "\n"
    "Options:\n"
    "  --tsv FILE        read the text input FILE instead of a run file\n"
    "  --from T, --to T  use only the snapshots with T <= t and t <= T [sqrt(d/g)]\n"
    "  --margin X        width of the layer of copies at each face [d] (default 3; it\n"
    "                    grows where needed, so the result does not depend on it)\n"
    "  --summary         instead of the table, key/value/error rows (below)\n"
    "  --diffusion       instead of f_lc, lateral diffusion coefficients of layers (below)\n"
    "  --layers M        with --diffusion: number of layers (default 1)\n"
    "  --max-lag T       with --diffusion: longest lag fitted [sqrt(d/g)] (default: half the\n"
    "                    window)\n"
    "  -h, --help        this text;  --version  the toolkit's version\n"
    "\n"
    "Output (default): header t_mid, dt, changes, f_lc, f_lc_per_particle; one row per pair\n"
    "of consecutive snapshots: the middle and length of the interval [sqrt(d/g)], the number\n"
    "of location changes, f_lc = changes / dt [sqrt(g/d)] and f_lc / N.\n"
    "\n"
    "Output with --summary: header key, value, error; rows particles, snapshots, t_from,\n"
    "t_to and changes (error nan), then f_lc and f_lc_per_particle: all changes over the\n"
    "whole time, error the standard error of the intervals' f_lc (taken as independent; nan\n"
    "with one interval).\n"
    "\n"
    "Output with --diffusion (Sec. 4.3.3, Fig. 4.3: \"the diffusion constant ... was measured\n"
    "individually in each layer ... The layers are defined such that the number of particles\n"
    "is constant in each layer\"): particles are sorted by their mean height (last axis) over\n"
    "the window and split into M layers of N/M particles (the last takes the rest), layer 1 at\n"
    "the bottom.  Lateral displacements are unwrapped between consecutive snapshots by the\n"
    "minimum image.  The mean squared lateral displacement of a layer, averaged over its\n"
    "particles and all time origins, is fitted against the lag by a straight line (GSL\n"
    "gsl_fit_linear) over the lags dt, 2 dt, ... up to half the window or --max-lag (at least\n"
    "3 lags; the snapshots must be equally spaced); D = slope / (2 (dim - 1)).  Header\n"
    "layer, z_mean, particles, D, D_err: the layer's mean height [d], its particles, D\n"
    "[d^2/sqrt(d/g)] and its error.  The fit is linear in the data, so the layer's slope is\n"
    "the mean of the slopes of its particles' own MSDs: D_err is their standard error\n"
    "(particles taken as independent; nan for a layer of one particle).\n"
    "\n"
    "Errors (missing or unreadable file, no snapshots, fewer than two snapshots in the window,\n"
    "a particle moving more than a quarter of a periodic box length between two snapshots,\n"
    "which cannot be unwrapped) name the file and exit with status 1; bad options exit with\n"
    "status 2.\n");
}

/* ---- snapshots: a run file or a text file ------------------------------------------------ */

typedef struct {
  const char *file;        /* as given, for messages */
  int dim;
  long n;                  /* particles */
  long nframes;
  double box[MAXDIM];      /* edge lengths [d] */
  int periodic[MAXDIM];    /* 1: periodic axis, 0: walls */
  double *time;            /* [nframes] */
  hid_t h5;                /* run file, or negative for --tsv */
  double *text_pos;        /* --tsv: [nframes][n][dim] */
} snapshots_t;

static void snapshots_free(snapshots_t *s)
{
  if (s->h5 >= 0) wg_h5_close(s->h5);
  free(s->time);
  free(s->text_pos);
}

/* Positions of snapshot k, [n][dim]. */
static int read_frame(const snapshots_t *s, long k, double *r)
{
  size_t len = (size_t)s->n * (size_t)s->dim;
  if (s->h5 < 0) {
    memcpy(r, s->text_pos + (size_t)k * len, sizeof *r * len);
    return 0;
  }
  return wg_h5_read_rows(s->h5, POS "/value", H5T_NATIVE_DOUBLE, (hsize_t)k, 1, r) != WG_OK;
}

/* The H5MD box boundary: a fixed-length string array, "periodic" or "none" per axis. */
static int read_boundary(snapshots_t *s)
{
  int status = 1;
  hid_t a = H5I_INVALID_HID, t = H5I_INVALID_HID, sp = H5I_INVALID_HID;
  char *buf = NULL;
  size_t size = 0;
  if (!wg_h5_exists(s->h5, BOX) || H5Aexists_by_name(s->h5, BOX, "boundary", H5P_DEFAULT) <= 0) {
    fprintf(stderr, PROG ": %s: no attribute 'boundary' on %s\n", s->file, BOX);
    return 1;
  }
  if ((a = H5Aopen_by_name(s->h5, BOX, "boundary", H5P_DEFAULT, H5P_DEFAULT)) < 0 ||
      (t = H5Aget_type(a)) < 0 || (sp = H5Aget_space(a)) < 0) {
    fprintf(stderr, PROG ": %s: %s: cannot read attribute 'boundary'\n", s->file, BOX);
    goto done;
  }
  if (H5Tget_class(t) != H5T_STRING || H5Tis_variable_str(t) != 0 ||
      H5Sget_simple_extent_npoints(sp) != s->dim || (size = H5Tget_size(t)) == 0) {
    fprintf(stderr, PROG ": %s: %s: attribute 'boundary' is not an array of %d fixed-length "
            "strings\n", s->file, BOX, s->dim);
    goto done;
  }
  if (!(buf = calloc((size_t)s->dim * size + 1, 1)) || H5Aread(a, t, buf) < 0) {
    fprintf(stderr, PROG ": %s: %s: cannot read attribute 'boundary'\n", s->file, BOX);
    goto done;
  }
  for (int ax = 0; ax < s->dim; ax++) {
    char word[32] = "";
    snprintf(word, sizeof word, "%.*s", (int)(size < 31 ? size : 31), buf + (size_t)ax * size);
    for (size_t k = strlen(word); k > 0 && word[k - 1] == ' '; k--) word[k - 1] = 0;
    if (!strcmp(word, "periodic")) s->periodic[ax] = 1;
    else if (!strcmp(word, "none")) s->periodic[ax] = 0;
    else {
      fprintf(stderr, PROG ": %s: %s: boundary[%d] = '%s' is neither 'periodic' nor 'none'\n",
              s->file, BOX, ax, word);
      goto done;
    }
  }
  status = 0;
done:
  free(buf);
  if (sp >= 0) H5Sclose(sp);
  if (t >= 0) H5Tclose(t);
  if (a >= 0) H5Aclose(a);
  return status;
}

static int open_run(const char *path, snapshots_t *s)
{
  int rank;
  hsize_t dims[8];
  s->file = path;
  s->h5 = wg_run_open(path);
  if (s->h5 < 0) return 1;
  if (!wg_h5_exists(s->h5, POS "/value") || !wg_h5_exists(s->h5, POS "/time")) {
    fprintf(stderr, PROG ": %s: no particle snapshots (%s/value and /time missing); "
            "not a run file of wetgran-run?\n", path, POS);
    return 1;
  }
  if (wg_h5_dims(s->h5, POS "/value", &rank, dims) != WG_OK) return 1;
  if (rank != 3 || (dims[2] != 2 && dims[2] != 3)) {
    fprintf(stderr, PROG ": %s: %s/value is not [snapshots][particles][2 or 3]\n", path, POS);
    return 1;
  }
  s->nframes = (long)dims[0];
  s->n = (long)dims[1];
  s->dim = (int)dims[2];
  if (wg_h5_dims(s->h5, POS "/time", &rank, dims) != WG_OK) return 1;
  if (rank != 1 || (long)dims[0] != s->nframes) {
    fprintf(stderr, PROG ": %s: %s/time does not hold one time per snapshot\n", path, POS);
    return 1;
  }
  if (s->nframes == 0) {
    fprintf(stderr, PROG ": %s: no particle snapshots (%s/value is empty)\n", path, POS);
    return 1;
  }
  if (!(s->time = malloc(sizeof *s->time * (size_t)s->nframes))) {
    fprintf(stderr, PROG ": out of memory\n");
    return 1;
  }
  if (wg_h5_read(s->h5, POS "/time", H5T_NATIVE_DOUBLE, s->time) != WG_OK) return 1;
  if (!wg_h5_exists(s->h5, BOX "/edges")) {
    fprintf(stderr, PROG ": %s: no box (%s/edges missing)\n", path, BOX);
    return 1;
  }
  if (wg_h5_dims(s->h5, BOX "/edges", &rank, dims) != WG_OK) return 1;
  if (rank != 1 || (int)dims[0] != s->dim) {
    fprintf(stderr, PROG ": %s: %s/edges does not hold %d edge lengths\n", path, BOX, s->dim);
    return 1;
  }
  if (wg_h5_read(s->h5, BOX "/edges", H5T_NATIVE_DOUBLE, s->box) != WG_OK) return 1;
  return read_boundary(s);
}

/* One row of --tsv input, kept until its snapshot is complete. */
typedef struct {
  long id, line;
  double x[MAXDIM];
} text_row_t;

/* Checks the rows of one snapshot (every id 0..n-1 once; the first snapshot sets n) and
   appends their positions. */
static int text_finish_frame(snapshots_t *s, const text_row_t *rows, long nrows, double t,
                             size_t *poscap, size_t *tcap)
{
  if (s->nframes == 0) s->n = nrows;
  if (nrows != s->n) {
    fprintf(stderr, PROG ": %s:%ld: the snapshot at t = %g has %ld rows, the first had %ld\n",
            s->file, rows[0].line, t, nrows, s->n);
    return 1;
  }
  size_t len = (size_t)s->n * (size_t)s->dim;
  if ((size_t)(s->nframes + 1) * len > *poscap) {
    size_t cap = *poscap ? 2 * *poscap : 16 * len;
    double *p = realloc(s->text_pos, sizeof *p * cap);
    if (!p) goto nomem;
    s->text_pos = p;
    *poscap = cap;
  }
  if ((size_t)s->nframes + 1 > *tcap) {
    size_t cap = *tcap ? 2 * *tcap : 64;
    double *p = realloc(s->time, sizeof *p * cap);
    if (!p) goto nomem;
    s->time = p;
    *tcap = cap;
  }
  double *frame = s->text_pos + (size_t)s->nframes * len;
  char *seen = calloc((size_t)s->n, 1);
  if (!seen) goto nomem;
  for (long k = 0; k < nrows; k++) {
    long id = rows[k].id;
    if (id < 0 || id >= s->n || seen[id]) {
      fprintf(stderr, PROG ": %s:%ld: particle id %ld %s (ids run from 0 to %ld, once per "
              "snapshot)\n", s->file, rows[k].line, id,
              id < 0 || id >= s->n ? "out of range" : "repeated in its snapshot", s->n - 1);
      free(seen);
      return 1;
    }
    seen[id] = 1;
    memcpy(frame + id * s->dim, rows[k].x, sizeof(double) * (size_t)s->dim);
  }
  free(seen);
  s->time[s->nframes++] = t;
  return 0;
nomem:
  fprintf(stderr, PROG ": out of memory\n");
  return 1;
}

static int parse_double(const char *tok, double *v)
{
  char *end;
  if (!tok) return 0;
  errno = 0;
  *v = strtod(tok, &end);
  return end != tok && *end == 0 && isfinite(*v);
}

/* "# box LX LY [LZ] FLAG FLAG [FLAG]" */
static int text_box_line(snapshots_t *s, char *rest, long lineno)
{
  char *tok[2 * MAXDIM + 1], *save = NULL;
  int nt = 0;
  for (char *w = strtok_r(rest, " \t\r\n", &save); w; w = strtok_r(NULL, " \t\r\n", &save))
    if (nt < 2 * MAXDIM + 1) tok[nt++] = w;
    else nt++;
  if (nt != 4 && nt != 6) goto bad;
  s->dim = nt / 2;
  for (int ax = 0; ax < s->dim; ax++) {
    if (!parse_double(tok[ax], &s->box[ax]) || s->box[ax] <= 0) goto bad;
    const char *f = tok[s->dim + ax];
    if (!strcmp(f, "periodic")) s->periodic[ax] = 1;
    else if (!strcmp(f, "none")) s->periodic[ax] = 0;
    else goto bad;
  }
  return 0;
bad:
  fprintf(stderr, PROG ": %s:%ld: expected '# box LX LY [LZ] FLAG FLAG [FLAG]' (edge lengths > 0, "
          "FLAG periodic or none, one per axis)\n", s->file, lineno);
  return 1;
}

static int open_text(const char *path, snapshots_t *s)
{
  s->file = path;
  FILE *in = wg_table_open(path);
  if (!in) return 1;
  char *line = NULL;
  size_t linecap = 0, poscap = 0, tcap = 0;
  long lineno = 0, nrows = 0, rowcap = 0;
  text_row_t *rows = NULL;
  double tcur = NAN;
  int status = 1;
  while (getline(&line, &linecap, in) >= 0) {
    lineno++;
    char *c = line;
    while (*c == ' ' || *c == '\t') c++;
    if (*c == '#') {
      char *w = c + 1;
      while (*w == ' ' || *w == '\t') w++;
      if (!strncmp(w, "box", 3) && (w[3] == ' ' || w[3] == '\t')) {
        if (s->dim) {
          fprintf(stderr, PROG ": %s:%ld: a second '# box' line\n", path, lineno);
          goto done;
        }
        if (text_box_line(s, w + 3, lineno)) goto done;
      }
      continue;
    }
    char *tok[2 + MAXDIM + 1], *save = NULL;
    int nt = 0;
    for (char *w = strtok_r(c, " \t\r\n", &save); w; w = strtok_r(NULL, " \t\r\n", &save))
      if (nt < 2 + MAXDIM + 1) tok[nt++] = w;
      else nt++;
    if (nt == 0) continue;
    if (!strcmp(tok[0], "time") && s->nframes == 0 && nrows == 0) continue; /* header */
    if (!s->dim) {
      fprintf(stderr, PROG ": %s:%ld: data before the '# box LX LY [LZ] FLAG ...' line\n",
              path, lineno);
      goto done;
    }
    text_row_t r = {.line = lineno};
    double t, id;
    int ok = nt == 2 + s->dim && parse_double(tok[0], &t) && parse_double(tok[1], &id) &&
             id == floor(id) && fabs(id) < 1e9;
    for (int ax = 0; ok && ax < s->dim; ax++) ok = parse_double(tok[2 + ax], &r.x[ax]);
    if (!ok) {
      fprintf(stderr, PROG ": %s:%ld: expected 'time id x y%s' (numbers, id an integer)\n",
              path, lineno, s->dim == 3 ? " z" : "");
      goto done;
    }
    r.id = (long)id;
    if (nrows > 0 && t != tcur) { /* a new snapshot begins */
      if (t < tcur) {
        fprintf(stderr, PROG ": %s:%ld: time %g is before the previous snapshot's %g\n", path,
                lineno, t, tcur);
        goto done;
      }
      if (text_finish_frame(s, rows, nrows, tcur, &poscap, &tcap)) goto done;
      nrows = 0;
    }
    tcur = t;
    if (nrows == rowcap) {
      long cap = rowcap ? 2 * rowcap : 256;
      text_row_t *p = realloc(rows, sizeof *p * (size_t)cap);
      if (!p) {
        fprintf(stderr, PROG ": out of memory\n");
        goto done;
      }
      rows = p;
      rowcap = cap;
    }
    rows[nrows++] = r;
  }
  if (ferror(in)) {
    fprintf(stderr, PROG ": %s: read error: %s\n", path, strerror(errno));
    goto done;
  }
  if (nrows > 0 && text_finish_frame(s, rows, nrows, tcur, &poscap, &tcap)) goto done;
  if (!s->dim) {
    fprintf(stderr, PROG ": %s: no '# box LX LY [LZ] FLAG ...' line\n", path);
    goto done;
  }
  if (s->nframes == 0) {
    fprintf(stderr, PROG ": %s: no particle snapshots (no data rows)\n", path);
    goto done;
  }
  status = 0;
done:
  free(rows);
  free(line);
  fclose(in);
  return status;
}

/* ---- periodic bookkeeping ---------------------------------------------------------------- */

/* Coordinates along periodic axes into [0, L). */
static void wrap_into_box(const snapshots_t *s, double *r)
{
  for (long i = 0; i < s->n; i++)
    for (int ax = 0; ax < s->dim; ax++) {
      if (!s->periodic[ax]) continue;
      double L = s->box[ax], *x = &r[i * s->dim + ax];
      *x -= L * floor(*x / L);
      if (*x >= L) *x = 0; /* -1e-17 wraps to L by round-off */
    }
}

/* The displacement of every particle between two consecutive snapshots (wrapped positions
   prev, now): the minimum image along periodic axes.  wraps[i][ax] counts the box lengths by
   which particle i's unwrapped coordinate exceeds its wrapped one (unwrapped = wrapped +
   wraps L); it is updated.  A displacement of more than a quarter box cannot be told from a
   jump through the periodic face: stop with a message. */
static int unwrap_step(const snapshots_t *s, const double *prev, const double *now, double t0,
                       double t1, int32_t (*wraps)[MAXDIM], double *disp)
{
  static const char axis[] = "xyz";
  for (long i = 0; i < s->n; i++)
    for (int ax = 0; ax < s->dim; ax++) {
      double d = now[i * s->dim + ax] - prev[i * s->dim + ax];
      if (s->periodic[ax]) {
        double L = s->box[ax], jumps = nearbyint(d / L);
        d -= jumps * L;
        if (fabs(d) > 0.25 * L) {
          fprintf(stderr, PROG ": %s: particle %ld moves %.4g d along %c between t = %g and "
                  "t = %g, more than a quarter of the periodic box (%g d): the snapshots are "
                  "too far apart to unwrap\n", s->file, i, d, axis[ax], t0, t1, L);
          return 1;
        }
        wraps[i][ax] -= (int32_t)jumps;
      }
      if (disp) disp[i * s->dim + ax] = d;
    }
  return 0;
}

/* ---- the Delaunay edges of one snapshot -------------------------------------------------- */

typedef struct {
  int32_t i, j;          /* particles, i <= j */
  int32_t k[MAXDIM];     /* the edge joins unwrapped u_i and u_j + k L (periodic axes) */
} edge_t;

typedef struct {
  edge_t *e;
  size_t n, cap;
} edges_t;

static int cmp_edge(const void *pa, const void *pb)
{
  const edge_t *a = pa, *b = pb;
  if (a->i != b->i) return a->i < b->i ? -1 : 1;
  if (a->j != b->j) return a->j < b->j ? -1 : 1;
  for (int ax = 0; ax < MAXDIM; ax++)
    if (a->k[ax] != b->k[ax]) return a->k[ax] < b->k[ax] ? -1 : 1;
  return 0;
}

/* The snapshot with its copies, the points given to qhull.  Point q is particle owner[q],
   shifted by shift[q] box lengths along the periodic axes, or (mirror[q]) its mirror image
   in a wall.  The particles themselves come first (q < n). */
typedef struct {
  long np, cap;
  double *x;                     /* [np][dim] */
  long *owner;
  int32_t (*shift)[MAXDIM];
  char *mirror;
  double wall_lo[MAXDIM], wall_hi[MAXDIM]; /* wall axes: the mirror planes */
  double lo[MAXDIM], hi[MAXDIM]; /* the region inside which every point of the (infinite)
                                    periodic and mirrored packing has been placed */
} padded_t;

static void padded_free(padded_t *p)
{
  free(p->x);
  free(p->owner);
  free(p->shift);
  free(p->mirror);
}

static int padded_add(padded_t *p, int dim, const double *x, long owner, const int *sh, int mirror)
{
  if (p->np == p->cap) {
    long cap = p->cap ? 2 * p->cap : 1024;
    double *nx = realloc(p->x, sizeof *nx * (size_t)cap * (size_t)dim);
    if (nx) p->x = nx;
    long *no = realloc(p->owner, sizeof *no * (size_t)cap);
    if (no) p->owner = no;
    int32_t (*ns)[MAXDIM] = realloc(p->shift, sizeof *ns * (size_t)cap);
    if (ns) p->shift = ns;
    char *nm = realloc(p->mirror, (size_t)cap);
    if (nm) p->mirror = nm;
    if (!nx || !no || !ns || !nm) {
      fprintf(stderr, PROG ": out of memory\n");
      return 1;
    }
    p->cap = cap;
  }
  memcpy(p->x + p->np * dim, x, sizeof *x * (size_t)dim);
  for (int ax = 0; ax < MAXDIM; ax++) p->shift[p->np][ax] = ax < dim && !mirror ? sh[ax] : 0;
  p->owner[p->np] = owner;
  p->mirror[p->np++] = (char)mirror;
  return 0;
}

/* Copies of the particles within margin of a face of the box: across a periodic face, shifted
   by a box length; at a wall, mirrored.  The walls are taken as planes WALL_GAP beyond the
   lowest and the highest centre along each wall axis (a wall touching the outermost
   particle), so that the Voronoi cells of the particles at a wall or at the free surface end
   there, and rows of particles along a wall, nearly collinear, are not joined by long, flat
   triangles outside the packing that flip whenever a particle rattles. */
#define WALL_GAP 0.5
static int pad(const snapshots_t *s, const double *r, double margin, padded_t *p)
{
  int dim = s->dim, ncomb = dim == 2 ? 9 : 27;
  double reach[MAXDIM];
  p->np = 0;
  for (int ax = 0; ax < dim; ax++) {
    if (s->periodic[ax]) {
      reach[ax] = fmin(margin, s->box[ax]);
      p->lo[ax] = -reach[ax];
      p->hi[ax] = s->box[ax] + reach[ax];
      continue;
    }
    double zmin = INFINITY, zmax = -INFINITY;
    for (long i = 0; i < s->n; i++) {
      zmin = fmin(zmin, r[i * dim + ax]);
      zmax = fmax(zmax, r[i * dim + ax]);
    }
    p->wall_lo[ax] = zmin - WALL_GAP;
    p->wall_hi[ax] = zmax + WALL_GAP;
    double extent = p->wall_hi[ax] - p->wall_lo[ax];
    reach[ax] = fmin(margin, extent);
    /* all particles mirrored: no point lies beyond the copies along this axis */
    p->lo[ax] = reach[ax] < extent ? p->wall_lo[ax] - reach[ax] : -INFINITY;
    p->hi[ax] = reach[ax] < extent ? p->wall_hi[ax] + reach[ax] : INFINITY;
  }
  /* c = 0 (no copy) first: the particles themselves are points 0 .. n-1 */
  for (int c = 0; c < ncomb; c++) {
    int sh[MAXDIM] = {0};
    for (int ax = 0, cc = c; ax < dim; ax++, cc /= 3)
      sh[ax] = cc % 3 == 0 ? 0 : cc % 3 == 1 ? 1 : -1;
    for (long i = 0; i < s->n; i++) {
      double x[MAXDIM];
      int near = 1, mirror = 0;
      for (int ax = 0; ax < dim && near; ax++) {
        x[ax] = r[i * dim + ax];
        if (!sh[ax]) continue;
        if (s->periodic[ax]) { /* +1: copy to x + L, -1: to x - L */
          near = sh[ax] == 1 ? x[ax] < reach[ax] : x[ax] >= s->box[ax] - reach[ax];
          x[ax] += sh[ax] * s->box[ax];
        } else {               /* -1: mirror in the lower wall, +1: in the upper one */
          double w = sh[ax] == 1 ? p->wall_hi[ax] : p->wall_lo[ax];
          near = fabs(x[ax] - w) < reach[ax];
          x[ax] = 2 * w - x[ax];
          mirror = 1;
        }
      }
      if (near && padded_add(p, dim, x, i, sh, mirror)) return 1;
    }
  }
  return 0;
}

/* Circumcentre c and squared radius r2 of the simplex v[0..dim]; 0 if it is flat. */
static int circumsphere(int dim, const double *v[MAXDIM + 1], double *c, double *r2)
{
  double A[MAXDIM][MAXDIM], b[MAXDIM], longest = 0, det, y[MAXDIM];
  for (int i = 0; i < dim; i++) {
    b[i] = 0;
    for (int ax = 0; ax < dim; ax++) {
      A[i][ax] = v[i + 1][ax] - v[0][ax];
      b[i] += A[i][ax] * A[i][ax];
    }
    longest = fmax(longest, b[i]);
    b[i] *= 0.5; /* (v_i - v_0) . (c - v_0) = |v_i - v_0|^2 / 2 */
  }
  if (dim == 2) {
    det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
    if (!(fabs(det) > 1e-10 * longest)) return 0;
    y[0] = (b[0] * A[1][1] - A[0][1] * b[1]) / det;
    y[1] = (A[0][0] * b[1] - b[0] * A[1][0]) / det;
  } else {
    double m[3][3];
    det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
          A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
          A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
    if (!(fabs(det) > 1e-10 * longest * sqrt(longest))) return 0;
    for (int col = 0; col < 3; col++) { /* Cramer's rule */
      memcpy(m, A, sizeof m);
      for (int row = 0; row < 3; row++) m[row][col] = b[row];
      y[col] = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])) / det;
    }
  }
  *r2 = 0;
  for (int ax = 0; ax < dim; ax++) {
    c[ax] = v[0][ax] + y[ax];
    *r2 += y[ax] * y[ax];
  }
  return 1;
}

/* The empty circumsphere of a simplex with a corner in the box is an empty sphere of the whole
   periodic, mirrored packing if it lies inside the region where all its points were placed. */
static int sphere_covered(int dim, const padded_t *p, const double *c, double r2)
{
  double R = sqrt(r2);
  for (int ax = 0; ax < dim; ax++)
    if (c[ax] - R < p->lo[ax] || c[ax] + R > p->hi[ax]) return 0;
  return 1;
}

static int push_edge(edges_t *E, edge_t e)
{
  if (E->n == E->cap) {
    size_t cap = E->cap ? 2 * E->cap : 1024;
    edge_t *ne = realloc(E->e, sizeof *ne * cap);
    if (!ne) return 1;
    E->e = ne;
    E->cap = cap;
  }
  E->e[E->n++] = e;
  return 0;
}

/* The edge between points a and b (particles or their periodic copies), named by the two
   particles and the periodic image that joins them. */
static edge_t edge_of(const snapshots_t *s, const padded_t *p, long a, long b,
                      int32_t (*wraps)[MAXDIM])
{
  edge_t e = {.i = (int32_t)p->owner[a], .j = (int32_t)p->owner[b]};
  /* b is at r_j + shift_b L and a at r_i + shift_a L, with r = u - wraps L, so the edge
     joins u_i and u_j + (shift_b - shift_a - wraps_j + wraps_i) L */
  for (int ax = 0; ax < MAXDIM; ax++)
    e.k[ax] = ax < s->dim ? p->shift[b][ax] - p->shift[a][ax] - wraps[e.j][ax] + wraps[e.i][ax] : 0;
  int swap = e.i > e.j;
  for (int ax = 0; !swap && e.i == e.j && ax < MAXDIM; ax++) { /* a particle and its own copy */
    if (e.k[ax] > 0) break;
    if (e.k[ax] < 0) swap = 1;
  }
  if (swap) {
    int32_t t = e.i;
    e.i = e.j;
    e.j = t;
    for (int ax = 0; ax < MAXDIM; ax++) e.k[ax] = -e.k[ax];
  }
  return e;
}

/* Triangulates the padded snapshot with qhull and collects, sorted and without repeats, the
   edges between two particles (not mirror images) with at least one end in the box.
   *complete is cleared if a simplex with a corner in the box has a circumsphere that the
   copies do not cover, or lies on the hull of the points (its outside is not covered). */
static int qhull_edges(const snapshots_t *s, const padded_t *p, int32_t (*wraps)[MAXDIM],
                       double t, edges_t *E, int *complete)
{
  qhT qh_qh;
  qhT *qh = &qh_qh;
  char flags[] = "qhull d Qt Qbb Qc Qz";
  int dim = s->dim, status = 0;
  E->n = 0;
  *complete = 1;
  QHULL_LIB_CHECK
  qh_zero(qh, stderr);
  int exitcode = qh_new_qhull(qh, dim, (int)p->np, p->x, False, flags, NULL, stderr);
  if (exitcode) {
    fprintf(stderr, PROG ": %s: snapshot at t = %g: qhull failed (exit code %d, message above)\n",
            s->file, t, exitcode);
    status = 1;
  } else {
    facetT *facet, *neighbor, **neighborp;
    vertexT *vertex, **vertexp;
    FORALLfacets {
      if (facet->upperdelaunay) continue; /* only the lower hull projects to Delaunay simplices */
      long id[MAXDIM + 1];
      int k = 0, bad = 0, in_box = 0;
      FOREACHvertex_(facet->vertices) {
        int pid = qh_pointid(qh, vertex->point);
        if (pid < 0 || pid >= p->np) bad = 1; /* e.g. the point at infinity of Qz */
        else if (k <= dim) {
          id[k] = pid;
          in_box |= pid < s->n;
        }
        k++;
      }
      if (bad || k != dim + 1 || !in_box) continue;
      const double *v[MAXDIM + 1];
      double c[MAXDIM], r2;
      for (int m = 0; m <= dim; m++) v[m] = p->x + id[m] * dim;
      if (!circumsphere(dim, v, c, &r2)) continue; /* a flat simplex of Qt */
      if (!sphere_covered(dim, p, c, r2)) *complete = 0;
      FOREACHneighbor_(facet)
        if (neighbor->upperdelaunay) *complete = 0; /* on the hull */
      for (int m1 = 0; m1 <= dim; m1++)
        for (int m2 = m1 + 1; m2 <= dim; m2++) {
          long a = id[m1], b = id[m2];
          if ((a >= s->n && b >= s->n) || p->mirror[a] || p->mirror[b]) continue;
          if (push_edge(E, edge_of(s, p, a, b, wraps))) {
            fprintf(stderr, PROG ": out of memory\n");
            status = 1;
          }
        }
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong, totlong;
  qh_memfreeshort(qh, &curlong, &totlong);
  if (status) return status;
  if (E->n) qsort(E->e, E->n, sizeof *E->e, cmp_edge);
  size_t m = 0;
  for (size_t k = 0; k < E->n; k++)
    if (m == 0 || cmp_edge(&E->e[m - 1], &E->e[k])) E->e[m++] = E->e[k];
  E->n = m;
  return 0;
}

/* The Delaunay edges of the snapshot r (wrapped), with copies within *margin of the faces;
   the margin is doubled until the check of qhull_edges passes or the copies cover every
   particle.  *margin keeps the margin used (the next snapshot starts from it).  *incomplete
   counts the snapshots whose check still fails (a warning names the first). */
static int delaunay_edges(const snapshots_t *s, const double *r, int32_t (*wraps)[MAXDIM],
                          double *margin, double t, padded_t *p, edges_t *E, long *incomplete)
{
  for (;;) {
    int complete, all = 1;
    if (pad(s, r, *margin, p) || qhull_edges(s, p, wraps, t, E, &complete)) return 1;
    if (complete) return 0;
    for (int ax = 0; ax < s->dim; ax++)
      all &= *margin >= (s->periodic[ax] ? s->box[ax] : p->wall_hi[ax] - p->wall_lo[ax]);
    if (all) {
      if (!(*incomplete)++)
        fprintf(stderr, PROG ": warning: %s: snapshot at t = %g: even copies of the whole box "
                "do not cover every circumsphere; edges near the faces may be missing\n",
                s->file, t);
      return 0;
    }
    *margin *= 2;
  }
}

/* Edges of now that were not in before (both sorted): the location changes. */
static long new_edges(const edges_t *before, const edges_t *now)
{
  long count = 0;
  size_t a = 0;
  for (size_t b = 0; b < now->n; b++) {
    while (a < before->n && cmp_edge(&before->e[a], &now->e[b]) < 0) a++;
    if (a == before->n || cmp_edge(&before->e[a], &now->e[b])) count++;
  }
  return count;
}

/* ---- f_lc --------------------------------------------------------------------------------- */

typedef struct {
  double from, to, margin, max_lag;
  int summary, diffusion, layers;
} opts_t;

static int location_changes(const snapshots_t *s, long first, long last, const opts_t *o)
{
  int status = 1;
  size_t len = (size_t)s->n * (size_t)s->dim;
  double *prev = malloc(sizeof *prev * len), *now = malloc(sizeof *now * len);
  int32_t (*wraps)[MAXDIM] = calloc((size_t)s->n, sizeof *wraps);
  edges_t before = {0}, after = {0};
  padded_t p = {0};
  long total = 0, intervals = 0;
  double elapsed = 0, mean = 0, m2 = 0; /* Welford's running mean and variance of the rates */
  if (!prev || !now || !wraps) {
    fprintf(stderr, PROG ": out of memory\n");
    goto done;
  }
  if (read_frame(s, first, prev)) goto done;
  wrap_into_box(s, prev);
  double margin = o->margin;
  long incomplete = 0;
  if (delaunay_edges(s, prev, wraps, &margin, s->time[first], &p, &before, &incomplete))
    goto done;
  if (!o->summary) printf("t_mid\tdt\tchanges\tf_lc\tf_lc_per_particle\n");
  for (long k = first + 1; k <= last; k++) {
    double t0 = s->time[k - 1], t1 = s->time[k], dt = t1 - t0;
    if (read_frame(s, k, now)) goto done;
    wrap_into_box(s, now);
    if (unwrap_step(s, prev, now, t0, t1, wraps, NULL)) goto done;
    if (delaunay_edges(s, now, wraps, &margin, t1, &p, &after, &incomplete)) goto done;
    long changes = new_edges(&before, &after);
    double f = changes / dt;
    if (!o->summary)
      printf("%.10g\t%.10g\t%ld\t%.10g\t%.10g\n", 0.5 * (t0 + t1), dt, changes, f, f / s->n);
    total += changes;
    elapsed += dt;
    intervals++;
    double delta = f - mean;
    mean += delta / intervals;
    m2 += delta * (f - mean);
    edges_t e = before;
    before = after;
    after = e;
    double *r = prev;
    prev = now;
    now = r;
  }
  if (incomplete > 1)
    fprintf(stderr, PROG ": warning: %s: %ld snapshots had edges near the faces that may be "
            "missing\n", s->file, incomplete);
  if (o->summary) {
    double f = total / elapsed, err = intervals > 1 ? sqrt(m2 / (intervals - 1) / intervals) : NAN;
    printf("key\tvalue\terror\n");
    printf("particles\t%ld\tnan\n", s->n);
    printf("snapshots\t%ld\tnan\n", last - first + 1);
    printf("t_from\t%.10g\tnan\n", s->time[first]);
    printf("t_to\t%.10g\tnan\n", s->time[last]);
    printf("changes\t%ld\tnan\n", total);
    printf("f_lc\t%.6g\t%.3g\n", f, err);
    printf("f_lc_per_particle\t%.6g\t%.3g\n", f / s->n, err / s->n);
  }
  status = 0;
done:
  free(prev);
  free(now);
  free(wraps);
  free(before.e);
  free(after.e);
  padded_free(&p);
  return status;
}

/* ---- lateral diffusion of layers (Sec. 4.3.3, Fig. 4.3) ---------------------------------- */

typedef struct {
  double z;
  long id;
} height_t;

static int cmp_height(const void *pa, const void *pb)
{
  const height_t *a = pa, *b = pb;
  if (a->z != b->z) return a->z < b->z ? -1 : 1;
  return a->id < b->id ? -1 : a->id > b->id;
}

static int layer_diffusion(const snapshots_t *s, long first, long last, const opts_t *o)
{
  int status = 1, dim = s->dim, lat = dim - 1, vert = dim - 1;
  long nf = last - first + 1, n = s->n;
  double dt = (s->time[last] - s->time[first]) / (nf - 1);
  for (long k = first + 1; k <= last; k++)
    if (fabs(s->time[k] - s->time[k - 1] - dt) > 1e-6 * dt) {
      fprintf(stderr, PROG ": %s: --diffusion needs equally spaced snapshots, but the one at "
              "t = %g follows t = %g after %g, not %g (choose the window with --from/--to)\n",
              s->file, s->time[k], s->time[k - 1], s->time[k] - s->time[k - 1], dt);
      return 1;
    }
  long maxlag = (nf - 1) / 2;
  if (o->max_lag > 0) maxlag = (long)floor(o->max_lag / dt + 1e-9);
  if (maxlag > nf - 1) maxlag = nf - 1;
  if (maxlag < 3) {
    fprintf(stderr, PROG ": %s: %ld lag%s of %g to fit in the window (%ld snapshots); "
            "--diffusion needs at least 3\n", s->file, maxlag, maxlag == 1 ? "" : "s", dt, nf);
    return 1;
  }
  if (o->layers > n) {
    fprintf(stderr, PROG ": %s: %d layers but only %ld particles\n", s->file, o->layers, n);
    return 1;
  }
  size_t len = (size_t)n * (size_t)dim;
  double *prev = malloc(sizeof *prev * len), *now = malloc(sizeof *now * len);
  double *disp = malloc(sizeof *disp * len), *u = malloc(sizeof *u * len);
  double *lateral = malloc(sizeof *lateral * (size_t)nf * (size_t)n * (size_t)lat);
  double *lag = malloc(sizeof *lag * (size_t)maxlag), *msd = malloc(sizeof *msd * (size_t)maxlag);
  double *own = malloc(sizeof *own * (size_t)maxlag);
  int32_t (*wraps)[MAXDIM] = calloc((size_t)n, sizeof *wraps);
  height_t *h = calloc((size_t)n, sizeof *h);
  if (!prev || !now || !disp || !u || !lateral || !lag || !msd || !own || !wraps || !h) {
    fprintf(stderr, PROG ": out of memory\n");
    goto done;
  }
  /* unwrapped trajectories: lateral coordinates of every snapshot, mean heights */
  for (long k = 0; k < nf; k++) {
    if (read_frame(s, first + k, now)) goto done;
    wrap_into_box(s, now);
    if (k == 0) memcpy(u, now, sizeof *u * len);
    else {
      if (unwrap_step(s, prev, now, s->time[first + k - 1], s->time[first + k], wraps, disp))
        goto done;
      for (size_t m = 0; m < len; m++) u[m] += disp[m];
    }
    for (long i = 0; i < n; i++) {
      for (int ax = 0; ax < lat; ax++) lateral[((size_t)k * n + i) * lat + ax] = u[i * dim + ax];
      h[i].z += u[i * dim + vert] / nf;
      h[i].id = i;
    }
    double *r = prev;
    prev = now;
    now = r;
  }
  /* layers of equal population, by mean height, layer 1 at the bottom */
  qsort(h, (size_t)n, sizeof *h, cmp_height);
  long per = n / o->layers;
  printf("layer\tz_mean\tparticles\tD\tD_err\n");
  for (int l = 0; l < o->layers; l++) {
    long a = l * per, b = l == o->layers - 1 ? n : a + per;
    double zmean = 0;
    for (long q = a; q < b; q++) zmean += h[q].z / (b - a);
    /* The mean squared lateral displacement of each particle over all time origins, and
       its slope; the layer's MSD is their mean.  MSD = 2 (dim - 1) D t + const. */
    double c0, c1, cov00, cov01, cov11, sumsq, slope_sum = 0, slope_sum2 = 0;
    for (long m = 0; m < maxlag; m++) {
      lag[m] = (m + 1) * dt;
      msd[m] = 0;
    }
    for (long q = a; q < b; q++) {
      long i = h[q].id;
      for (long m = 1; m <= maxlag; m++) {
        double sum = 0;
        for (long k = 0; k + m < nf; k++)
          for (int ax = 0; ax < lat; ax++) {
            double d = lateral[((size_t)(k + m) * n + i) * lat + ax] -
                       lateral[((size_t)k * n + i) * lat + ax];
            sum += d * d;
          }
        own[m - 1] = sum / (double)(nf - m);
        msd[m - 1] += own[m - 1] / (double)(b - a);
      }
      gsl_fit_linear(lag, 1, own, 1, (size_t)maxlag, &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
      slope_sum += c1;
      slope_sum2 += c1 * c1;
    }
    gsl_fit_linear(lag, 1, msd, 1, (size_t)maxlag, &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
    /* the layer's slope is the mean of its particles' slopes (a fit is linear in the data):
       its error is their standard error */
    long np = b - a;
    double err = NAN;
    if (np > 1) {
      double var = (slope_sum2 - slope_sum * slope_sum / np) / (np - 1);
      err = sqrt(fmax(var, 0) / np) / (2 * lat);
    }
    printf("%d\t%.6g\t%ld\t%.6g\t%.3g\n", l + 1, zmean, np, c1 / (2 * lat), err);
  }
  status = 0;
done:
  free(prev);
  free(now);
  free(disp);
  free(u);
  free(lateral);
  free(lag);
  free(msd);
  free(own);
  free(wraps);
  free(h);
  return status;
}

/* ---- main --------------------------------------------------------------------------------- */

static int option_number(const char *opt, const char *arg, double *v, int positive)
{
  if (parse_double(arg, v) && (positive ? *v > 0 : 1)) return 0;
  fprintf(stderr, PROG ": option %s: '%s' is not a%s number (see --help)\n", opt,
          arg ? arg : "", positive ? " positive" : "");
  return 1;
}

int main(int argc, char **argv)
{
  opts_t o = {.from = -INFINITY, .to = INFINITY, .margin = 3, .layers = 1};
  const char *run = NULL, *text = NULL;
  int layers_given = 0, maxlag_given = 0;
  for (int a = 1; a < argc; a++) {
    const char *opt = argv[a], *arg = a + 1 < argc ? argv[a + 1] : NULL;
    if (!strcmp(opt, "-h") || !strcmp(opt, "--help")) {
      usage(stdout);
      return 0;
    } else if (!strcmp(opt, "--version")) {
      printf(PROG " %s\n", wg_version());
      return 0;
    } else if (!strcmp(opt, "--summary")) {
      o.summary = 1;
    } else if (!strcmp(opt, "--diffusion")) {
      o.diffusion = 1;
    } else if (!strcmp(opt, "--tsv")) {
      if (!arg) goto needs_arg;
      text = argv[++a];
    } else if (!strcmp(opt, "--from") || !strcmp(opt, "--to") || !strcmp(opt, "--margin") ||
               !strcmp(opt, "--max-lag")) {
      if (!arg) goto needs_arg;
      double *dst = !strcmp(opt, "--from") ? &o.from : !strcmp(opt, "--to") ? &o.to
                  : !strcmp(opt, "--margin") ? &o.margin : &o.max_lag;
      maxlag_given |= dst == &o.max_lag;
      if (option_number(opt, argv[++a], dst, dst == &o.margin || dst == &o.max_lag)) return 2;
    } else if (!strcmp(opt, "--layers")) {
      double m;
      if (!arg) goto needs_arg;
      if (option_number(opt, argv[++a], &m, 1)) return 2;
      if (m != floor(m) || m > 1e6) {
        fprintf(stderr, PROG ": option --layers: '%s' is not a whole number >= 1\n", argv[a]);
        return 2;
      }
      o.layers = (int)m;
      layers_given = 1;
    } else if (opt[0] == '-' && opt[1]) {
      fprintf(stderr, PROG ": unknown option '%s' (see --help)\n", opt);
      return 2;
    } else if (run) {
      fprintf(stderr, PROG ": more than one run file ('%s', '%s')\n", run, opt);
      return 2;
    } else {
      run = opt;
    }
    continue;
  needs_arg:
    fprintf(stderr, PROG ": option %s needs an argument (see --help)\n", opt);
    return 2;
  }
  if (!run == !text) {
    fprintf(stderr, PROG ": %s (see --help)\n",
            run ? "give either a run file or --tsv FILE, not both" : "no run file given");
    return 2;
  }
  if ((layers_given || maxlag_given) && !o.diffusion) {
    fprintf(stderr, PROG ": --layers and --max-lag go with --diffusion (see --help)\n");
    return 2;
  }
  if (o.diffusion && o.summary) {
    fprintf(stderr, PROG ": --summary goes with f_lc, not with --diffusion\n");
    return 2;
  }
  if (o.from > o.to) {
    fprintf(stderr, PROG ": --from %g is after --to %g\n", o.from, o.to);
    return 2;
  }

  wg_h5_quiet();
  snapshots_t s = {.h5 = H5I_INVALID_HID};
  int status = 1;
  if (run ? open_run(run, &s) : open_text(text, &s)) goto out;
  for (long k = 1; k < s.nframes; k++)
    if (!(s.time[k] > s.time[k - 1])) {
      fprintf(stderr, PROG ": %s: snapshot times do not increase (t = %g after %g)\n", s.file,
              s.time[k], s.time[k - 1]);
      goto out;
    }
  long first = 0, last = s.nframes - 1;
  while (first < s.nframes && s.time[first] < o.from) first++;
  while (last >= 0 && s.time[last] > o.to) last--;
  long inwin = last >= first ? last - first + 1 : 0;
  if (inwin < 2) {
    fprintf(stderr, PROG ": %s: %ld snapshot%s%s; %s needs two at least%s\n", s.file, inwin,
            inwin == 1 ? "" : "s",
            isinf(o.from) && isinf(o.to) ? "" : " in the window given by --from/--to",
            o.diffusion ? "--diffusion" : "f_lc",
            s.nframes < 2 && s.h5 >= 0 ? " (write snapshots during the run: dt_snapshot > 0)" : "");
    goto out;
  }
  if (!o.diffusion && s.n < s.dim + 2) {
    fprintf(stderr, PROG ": %s: %ld particles; a %dD triangulation needs %d at least\n", s.file,
            s.n, s.dim, s.dim + 2);
    goto out;
  }
  status = o.diffusion ? layer_diffusion(&s, first, last, &o)
                       : location_changes(&s, first, last, &o);
out:
  snapshots_free(&s);
  return status;
}
