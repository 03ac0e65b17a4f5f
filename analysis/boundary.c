/* wetgran-boundary: phase boundaries of a sampled 2-D phase diagram, as in the thesis
   (Roeller 2010, Fig. 3.3): Delaunay-triangulate the sampled points and take the midpoint of
   every edge that joins two points of different phase.  Reads a tab-separated table, writes
   a tab-separated table on stdout; messages go to stderr. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <libqhull_r/qhull_ra.h>

#include "run_open.h"
#include "wg.h"

#define PROG "wetgran-boundary"

static void usage(FILE *out)
{
  fprintf(out,
    "Usage: " PROG " [OPTIONS] [TABLE.tsv]    (no file or '-': read stdin)\n"
    "\n"
    "Phase boundaries of a sampled 2-D phase diagram, as in Roeller (2010), Fig. 3.3:\n"
    "\"a Delaunay triangulation of the simulated data points is performed and the\n"
    "mid-points between two points, which belong to different phases, is drawn as ...\n"
    "the phase boundary\".\n"
    "\n"
    "Input: a tab-separated table; the first line that is neither empty nor starts with\n"
    "'#' is the header naming the columns; later lines starting with '#' are skipped.\n"
    "Each row is one sampled point: two coordinates and a phase label (a word such as\n"
    "s, f, g, sfc, sgc, fgc).\n"
    "\n"
    "Options:\n"
    "  --x NAME, --y NAME     header columns of the coordinates (default: x, y)\n"
    "  --label NAME           header column of the phase label (default: label)\n"
    "  --logx, --logy         triangulate in log10 of that coordinate (values must be > 0;\n"
    "                         the thesis plots E* on a log axis)\n"
    "  --fit-vertical A:B     (repeatable) instead of the midpoints, print the mean x of the\n"
    "                         midpoints between phases A and B (a vertical boundary);\n"
    "                         A<B: only edges with A at the smaller x (the f-fgc line is\n"
    "                         where the fluid turns coexisting as E* rises, not where a\n"
    "                         coexistence gives way to a fluid again at larger E*)\n"
    "  --fit-horizontal A:B   (repeatable) the same for the mean y (a horizontal boundary;\n"
    "                         A<B: A at the smaller y)\n"
    "  -h, --help             this text;  --version  the toolkit's version\n"
    "\n"
    "The triangulation is done in coordinates scaled to the unit square: after the\n"
    "optional log10, each axis is divided by its range (max - min), so that an axis with\n"
    "large numbers does not dominate the triangulation.  qhull computes the Delaunay\n"
    "triangulation (\"qhull d Qt Qbb Qc Qz\"); triangles of zero area are discarded.\n"
    "A grid of samples is not in general position (the four corners of each rectangle\n"
    "lie on a circle), so its Delaunay triangulation is not unique; a fixed shear of\n"
    "1e-6 (x += 1e-6 y in the unit square) makes it so, splitting every rectangle along\n"
    "its lower-right to upper-left diagonal, and the boundary then does not depend on\n"
    "qhull's order of insertion (on points added far away).\n"
    "\n"
    "Output (default): header x, y, phase_a, phase_b; one row per Delaunay edge joining\n"
    "two points of different phase (each edge once, phase_a < phase_b in byte order):\n"
    "the edge's midpoint, taken in the triangulation coordinates and mapped back to the\n"
    "input's units (so with --logx its x is the geometric mean of the two x values).\n"
    "Rows are sorted by phase pair, then x, then y.\n"
    "\n"
    "Output with --fit-*: header key, value, error; for each fit (in the order given)\n"
    "a row <dir>_<A>_<B> (e.g. vertical_f_fgc) whose value is the mean coordinate of\n"
    "the midpoints between A and B (either order of the pair), averaged in the\n"
    "triangulation coordinate and mapped back (geometric mean on a log axis), error the\n"
    "standard error of that mean combined with the grid's resolution (the mean half-extent\n"
    "of the edges along that axis over sqrt 3; on a log axis all in log10, times value *\n"
    "ln(10)), and a row <dir>_<A>_<B>_n with the number of midpoints.  With fewer\n"
    "than 2 midpoints the error is nan (with none, the value too) and a warning is\n"
    "printed on stderr.\n"
    "\n"
    "Points with identical coordinates: the first is kept, later ones dropped with a\n"
    "warning naming their lines.  Errors (missing column, a value that is not a number,\n"
    "fewer than 3 distinct points, all points on one line) name file and line and exit\n"
    "with status 1; bad options exit with status 2.\n");
}

/* ---- input table ---------------------------------------------------------------------- */

typedef struct {
  double x, y;      /* as read */
  double tx, ty;    /* triangulation coordinates before scaling: value or log10(value) */
  char *label;
  long line;
  int dropped;      /* duplicate of an earlier point */
} point_t;

typedef struct {
  point_t *p;
  size_t n, cap;
} points_t;

static char *trim(char *s)
{
  while (*s == ' ' || *s == '\r' || *s == '\n') s++;
  size_t len = strlen(s);
  while (len > 0 && (s[len - 1] == ' ' || s[len - 1] == '\r' || s[len - 1] == '\n')) s[--len] = 0;
  return s;
}

/* splits line at tabs in place; returns the number of fields (fields[] holds at most max) */
static int split_tabs(char *line, char **fields, int max)
{
  int n = 0;
  char *s = line;
  for (;;) {
    char *tab = strchr(s, '\t');
    if (tab) *tab = 0;
    if (n < max) fields[n] = trim(s);
    n++;
    if (!tab) break;
    s = tab + 1;
  }
  return n;
}

static int is_blank(const char *s)
{
  for (; *s; s++)
    if (*s != ' ' && *s != '\t' && *s != '\r' && *s != '\n') return 0;
  return 1;
}

static int parse_number(const char *s, double *v)
{
  if (!*s) return 0;
  char *end;
  errno = 0;
  *v = strtod(s, &end);
  return *end == 0 && isfinite(*v);
}

typedef struct {
  const char *xname, *yname, *lname;
  int logx, logy;
} opts_t;

/* reads the table; returns 0 or prints an error and returns 1 */
static int read_table(FILE *in, const char *fname, const opts_t *o, points_t *pts)
{
  char *line = NULL, **fields = NULL;
  size_t linecap = 0;
  long lineno = 0;
  int ncol = 0, ix = -1, iy = -1, il = -1, status = 1;
  ssize_t len;
  while ((len = getline(&line, &linecap, in)) >= 0) {
    lineno++;
    if (line[0] == '#' || is_blank(line)) continue;
    if (!fields) { /* header */
      int nf = 1;
      for (const char *c = line; *c; c++) nf += *c == '\t';
      fields = malloc(sizeof *fields * (size_t)nf);
      if (!fields) goto nomem;
      ncol = split_tabs(line, fields, nf);
      for (int k = ncol - 1; k >= 0; k--) { /* first occurrence wins */
        if (!strcmp(fields[k], o->xname)) ix = k;
        if (!strcmp(fields[k], o->yname)) iy = k;
        if (!strcmp(fields[k], o->lname)) il = k;
      }
      const char *missing[3] = {ix < 0 ? o->xname : NULL, iy < 0 ? o->yname : NULL,
                                il < 0 ? o->lname : NULL};
      int bad = 0;
      for (int m = 0; m < 3; m++) {
        if (!missing[m]) continue;
        if (!bad) fprintf(stderr, PROG ": %s:%ld: ", fname, lineno);
        fprintf(stderr, "%sno column '%s'", bad ? ", " : "", missing[m]);
        bad = 1;
      }
      if (bad) {
        fprintf(stderr, " in the header (columns:");
        for (int k = 0; k < ncol; k++) fprintf(stderr, " '%s'", fields[k]);
        fprintf(stderr, "); choose columns with --x, --y, --label\n");
        goto done;
      }
      continue;
    }
    char *f[3] = {NULL, NULL, NULL};
    {
      int need = ix > iy ? ix : iy;
      need = (il > need ? il : need) + 1;
      /* fields[] has room for ncol entries; split with that bound */
      int nf = split_tabs(line, fields, ncol);
      if (nf < need) {
        const char *which = nf <= ix ? o->xname : nf <= iy ? o->yname : o->lname;
        fprintf(stderr, PROG ": %s:%ld: %d field%s, but column '%s' is field %d\n", fname,
                lineno, nf, nf == 1 ? "" : "s", which,
                (which == o->xname ? ix : which == o->yname ? iy : il) + 1);
        goto done;
      }
      f[0] = fields[ix];
      f[1] = fields[iy];
      f[2] = fields[il];
    }
    point_t p = {.line = lineno};
    if (!parse_number(f[0], &p.x)) {
      fprintf(stderr, PROG ": %s:%ld: column '%s': '%s' is not a finite number\n", fname,
              lineno, o->xname, f[0]);
      goto done;
    }
    if (!parse_number(f[1], &p.y)) {
      fprintf(stderr, PROG ": %s:%ld: column '%s': '%s' is not a finite number\n", fname,
              lineno, o->yname, f[1]);
      goto done;
    }
    if (!*f[2]) {
      fprintf(stderr, PROG ": %s:%ld: column '%s': empty phase label\n", fname, lineno, o->lname);
      goto done;
    }
    if ((o->logx && p.x <= 0) || (o->logy && p.y <= 0)) {
      int bx = o->logx && p.x <= 0;
      fprintf(stderr, PROG ": %s:%ld: column '%s': %s is not > 0, but --log%c was asked for\n",
              fname, lineno, bx ? o->xname : o->yname, bx ? f[0] : f[1], bx ? 'x' : 'y');
      goto done;
    }
    p.tx = o->logx ? log10(p.x) : p.x;
    p.ty = o->logy ? log10(p.y) : p.y;
    p.label = strdup(f[2]);
    if (!p.label) goto nomem;
    if (pts->n == pts->cap) {
      size_t cap = pts->cap ? 2 * pts->cap : 256;
      point_t *np = realloc(pts->p, sizeof *np * cap);
      if (!np) {
        free(p.label);
        goto nomem;
      }
      pts->p = np;
      pts->cap = cap;
    }
    pts->p[pts->n++] = p;
  }
  if (ferror(in)) {
    fprintf(stderr, PROG ": %s: read error: %s\n", fname, strerror(errno));
    goto done;
  }
  if (!fields) {
    fprintf(stderr, PROG ": %s: no header line (the input is empty)\n", fname);
    goto done;
  }
  status = 0;
  goto done;
nomem:
  fprintf(stderr, PROG ": %s:%ld: out of memory\n", fname, lineno);
done:
  free(fields);
  free(line);
  return status;
}

/* ---- duplicates ----------------------------------------------------------------------- */

static const point_t *g_sort_pts; /* qsort has no context argument in C11 */

static int cmp_xy(const void *a, const void *b)
{
  const point_t *p = &g_sort_pts[*(const size_t *)a], *q = &g_sort_pts[*(const size_t *)b];
  if (p->x != q->x) return p->x < q->x ? -1 : 1;
  if (p->y != q->y) return p->y < q->y ? -1 : 1;
  return p->line < q->line ? -1 : p->line > q->line;
}

/* marks later points with the coordinates of an earlier one as dropped; returns the number
   kept, or (size_t)-1 when out of memory */
static size_t drop_duplicates(points_t *pts, const char *fname)
{
  size_t n = pts->n, kept = n;
  if (n == 0) return 0;
  size_t *idx = malloc(sizeof *idx * n), *first = malloc(sizeof *first * n);
  if (!idx || !first) {
    free(idx);
    free(first);
    return (size_t)-1;
  }
  for (size_t i = 0; i < n; i++) idx[i] = i;
  g_sort_pts = pts->p;
  qsort(idx, n, sizeof *idx, cmp_xy);
  for (size_t k = 0; k < n; k++) {
    size_t i = idx[k];
    first[i] = i;
    if (k > 0) {
      size_t j = idx[k - 1];
      if (pts->p[j].x == pts->p[i].x && pts->p[j].y == pts->p[i].y) {
        first[i] = first[j];
        pts->p[i].dropped = 1;
        kept--;
      }
    }
  }
  for (size_t i = 0; i < n; i++) { /* warnings in input order */
    if (!pts->p[i].dropped) continue;
    const point_t *p = &pts->p[i], *q = &pts->p[first[i]];
    fprintf(stderr, PROG ": warning: %s:%ld: point (%.10g, %.10g) repeats line %ld; dropped%s%s%s%s%s\n",
            fname, p->line, p->x, p->y, q->line,
            strcmp(p->label, q->label) ? " (its phase '" : "",
            strcmp(p->label, q->label) ? p->label : "",
            strcmp(p->label, q->label) ? "' differs from '" : "",
            strcmp(p->label, q->label) ? q->label : "",
            strcmp(p->label, q->label) ? "', which is kept)" : "");
  }
  free(idx);
  free(first);
  return kept;
}

/* ---- triangulation -------------------------------------------------------------------- */

/* x += TIE_SHEAR y in the unit square before triangulating (see main) */
#define TIE_SHEAR 1e-6

typedef struct {
  size_t i, j; /* i < j, indices into the kept points */
} edge_t;

static int cmp_edge(const void *a, const void *b)
{
  const edge_t *e = a, *f = b;
  if (e->i != f->i) return e->i < f->i ? -1 : 1;
  return e->j < f->j ? -1 : e->j > f->j;
}

/* Delaunay triangulation of the n points u[2n] (unit square) with qhull; appends the edges
   of every non-degenerate lower-Delaunay triangle to *edges (deduplicated) and flags in
   used[] the points that are vertices.  Returns 0, or 1 after an error message. */
static int triangulate(double *u, size_t n, edge_t **edges, size_t *nedges, char *used,
                       const char *fname)
{
  qhT qh_qh;
  qhT *qh = &qh_qh;
  char flags[] = "qhull d Qt Qbb Qc Qz";
  edge_t *e = NULL;
  size_t ne = 0, cap = 0;
  int status = 0;

  QHULL_LIB_CHECK
  qh_zero(qh, stderr);
  int exitcode = qh_new_qhull(qh, 2, (int)n, u, False, flags, NULL, stderr);
  if (exitcode) {
    fprintf(stderr, PROG ": %s: qhull failed (exit code %d, message above)\n", fname, exitcode);
    status = 1;
  } else {
    facetT *facet;
    vertexT *vertex, **vertexp;
    FORALLfacets {
      if (facet->upperdelaunay) continue;
      size_t id[3];
      int k = 0, bad = 0;
      FOREACHvertex_(facet->vertices) {
        int pid = qh_pointid(qh, vertex->point);
        if (k < 3) id[k] = (size_t)pid;
        if (pid < 0 || (size_t)pid >= n) bad = 1; /* e.g. the point at infinity of Qz */
        k++;
      }
      if (bad || k != 3) continue;
      const double *a = u + 2 * id[0], *b = u + 2 * id[1], *c = u + 2 * id[2];
      double area2 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      if (fabs(area2) < 1e-13) continue; /* degenerate triangle of Qt: not a Delaunay face */
      if (ne + 3 > cap) {
        cap = cap ? 2 * cap : 3 * n + 16;
        edge_t *ne_ = realloc(e, sizeof *e * cap);
        if (!ne_) {
          fprintf(stderr, PROG ": out of memory\n");
          status = 1;
          break;
        }
        e = ne_;
      }
      for (int m = 0; m < 3; m++) {
        size_t p = id[m], q = id[(m + 1) % 3];
        e[ne++] = (edge_t){p < q ? p : q, p < q ? q : p};
        used[p] = 1;
      }
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong, totlong;
  qh_memfreeshort(qh, &curlong, &totlong);
  if (curlong || totlong)
    fprintf(stderr, PROG ": warning: qhull did not free all memory (%d bytes in %d blocks)\n",
            totlong, curlong);
  if (status) {
    free(e);
    return status;
  }
  if (ne) qsort(e, ne, sizeof *e, cmp_edge);
  size_t m = 0;
  for (size_t k = 0; k < ne; k++)
    if (m == 0 || cmp_edge(&e[m - 1], &e[k])) e[m++] = e[k];
  *edges = e;
  *nedges = m;
  return 0;
}

/* ---- midpoints and fits --------------------------------------------------------------- */

typedef struct {
  const char *a, *b; /* a < b */
  double tx, ty;     /* midpoint in triangulation coordinates (log10 on log axes) */
  double hx, hy;     /* half the edge's extent along each axis, same coordinates */
  double x, y;       /* mapped back */
  int a_left, a_below; /* a's point has the smaller x, the smaller y */
} mid_t;

static int cmp_mid(const void *pa, const void *pb)
{
  const mid_t *m = pa, *n = pb;
  int c = strcmp(m->a, n->a);
  if (!c) c = strcmp(m->b, n->b);
  if (c) return c;
  if (m->x != n->x) return m->x < n->x ? -1 : 1;
  if (m->y != n->y) return m->y < n->y ? -1 : 1;
  return 0;
}

typedef struct {
  int vertical; /* 1: mean x; 0: mean y */
  char *a, *b;  /* as given */
  int ordered;  /* A<B: only edges with A at the smaller coordinate */
} fit_t;

static int parse_fit(const char *arg, int vertical, fit_t *f)
{
  const char *colon = strpbrk(arg, ":<");
  if (!colon || colon == arg || !colon[1] || strpbrk(colon + 1, ":<")) return 0;
  f->vertical = vertical;
  f->ordered = *colon == '<';
  f->a = strndup(arg, (size_t)(colon - arg));
  f->b = strdup(colon + 1);
  return f->a && f->b && strcmp(f->a, f->b);
}

static int phase_occurs(const points_t *pts, const char *label)
{
  for (size_t i = 0; i < pts->n; i++)
    if (!pts->p[i].dropped && !strcmp(pts->p[i].label, label)) return 1;
  return 0;
}

/* midpoint k is one of fit f's: between its two phases, and with A<B, A on the lower side */
static int in_fit(const fit_t *f, const mid_t *m)
{
  int given_first = strcmp(f->a, f->b) < 0;
  const char *a = given_first ? f->a : f->b, *b = given_first ? f->b : f->a;
  if (strcmp(m->a, a) || strcmp(m->b, b)) return 0;
  if (!f->ordered) return 1;
  int a_lower = f->vertical ? m->a_left : m->a_below; /* the byte-order first phase lower */
  return given_first ? a_lower : !a_lower;
}

static void print_fit(const fit_t *f, const mid_t *mids, size_t nm, const points_t *pts,
                      const opts_t *o)
{
  int logaxis = f->vertical ? o->logx : o->logy;
  /* two passes: mean, then the sum of squared deviations */
  size_t n = 0;
  double sum = 0;
  for (size_t k = 0; k < nm; k++)
    if (in_fit(f, &mids[k])) {
      sum += f->vertical ? mids[k].tx : mids[k].ty;
      n++;
    }
  double mean = n ? sum / (double)n : NAN, ss = 0, half = 0;
  for (size_t k = 0; k < nm; k++)
    if (in_fit(f, &mids[k])) {
      double d = (f->vertical ? mids[k].tx : mids[k].ty) - mean;
      ss += d * d;
      half += f->vertical ? mids[k].hx : mids[k].hy;
    }
  /* the scatter of the midpoints, and the grid's resolution: each crossing lies anywhere on
     its edge (uniform: half-extent / sqrt 3), the same grid for all, so not reduced by n */
  double resolution = n ? half / (double)n / sqrt(3.0) : NAN;
  double se = n >= 2 ? sqrt(ss / (double)(n - 1) / (double)n + resolution * resolution) : NAN;
  double value = logaxis ? pow(10, mean) : mean;
  double err = logaxis ? value * log(10.0) * se : se;
  const char *dir = f->vertical ? "vertical" : "horizontal";
  if (n < 2) {
    for (int m = 0; m < 2; m++) {
      const char *ph = m ? f->b : f->a;
      if (!phase_occurs(pts, ph))
        fprintf(stderr, PROG ": warning: --fit-%s %s%s%s: phase '%s' does not occur in the input\n",
                dir, f->a, f->ordered ? "<" : ":", f->b, ph);
    }
    fprintf(stderr, PROG ": warning: --fit-%s %s%s%s: %zu midpoint%s between '%s' and '%s'; "
            "error is nan%s\n", dir, f->a, f->ordered ? "<" : ":", f->b, n, n == 1 ? "" : "s", f->a, f->b,
            n ? "" : ", value too");
  }
  printf("%s_%s_%s\t%.10g\t%.10g\n", dir, f->a, f->b, value, err);
  printf("%s_%s_%s_n\t%zu\tnan\n", dir, f->a, f->b, n);
}

/* ---- main ----------------------------------------------------------------------------- */

int main(int argc, char **argv)
{
  opts_t o = {.xname = "x", .yname = "y", .lname = "label"};
  fit_t *fits = NULL;
  int nfit = 0, status = 1;
  const char *fname = NULL;
  points_t pts = {0};
  double *u = NULL;
  size_t *keep = NULL;
  char *used = NULL;
  edge_t *edges = NULL;
  mid_t *mids = NULL;
  FILE *in = NULL;

  if (argc > 1) {
    fits = calloc((size_t)argc, sizeof *fits);
    if (!fits) {
      fprintf(stderr, PROG ": out of memory\n");
      return 1;
    }
  }
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i];
    const char **target = !strcmp(a, "--x") ? &o.xname : !strcmp(a, "--y") ? &o.yname
                          : !strcmp(a, "--label") ? &o.lname : NULL;
    int fitdir = !strcmp(a, "--fit-vertical") ? 1 : !strcmp(a, "--fit-horizontal") ? 0 : -1;
    if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
      usage(stdout);
      status = 0;
      goto out;
    } else if (!strcmp(a, "--version")) {
      printf(PROG " %s\n", wg_version());
      status = 0;
      goto out;
    } else if (!strcmp(a, "--logx")) {
      o.logx = 1;
    } else if (!strcmp(a, "--logy")) {
      o.logy = 1;
    } else if (target || fitdir >= 0) {
      if (i + 1 >= argc || !*argv[i + 1]) {
        fprintf(stderr, PROG ": option %s needs an argument (see --help)\n", a);
        status = 2;
        goto out;
      }
      const char *v = argv[++i];
      if (target) {
        *target = v;
      } else if (!parse_fit(v, fitdir, &fits[nfit++])) {
        fprintf(stderr, PROG ": %s %s: expected two different phases as A:B or A<B\n", a, v);
        status = 2;
        goto out;
      }
    } else if (a[0] == '-' && a[1]) {
      fprintf(stderr, PROG ": unknown option '%s' (see --help)\n", a);
      status = 2;
      goto out;
    } else if (fname) {
      fprintf(stderr, PROG ": more than one input file ('%s', '%s')\n", fname, a);
      status = 2;
      goto out;
    } else {
      fname = a;
    }
  }

  if (!fname || !strcmp(fname, "-")) {
    in = stdin;
    fname = "stdin";
  } else if (!(in = wg_table_open(fname))) {
    goto out;
  }
  int rd = read_table(in, fname, &o, &pts);
  if (in != stdin) fclose(in);
  if (rd) goto out;

  size_t n = drop_duplicates(&pts, fname);
  if (n == (size_t)-1) {
    fprintf(stderr, PROG ": out of memory\n");
    goto out;
  }
  if (n < 3) {
    fprintf(stderr, PROG ": %s: %zu distinct point%s; a triangulation needs at least 3\n",
            fname, n, n == 1 ? "" : "s");
    goto out;
  }

  /* unit-square coordinates of the kept points */
  keep = malloc(sizeof *keep * n);
  u = malloc(sizeof *u * 2 * n);
  used = calloc(n, 1);
  if (!keep || !u || !used) {
    fprintf(stderr, PROG ": out of memory\n");
    goto out;
  }
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (size_t i = 0, k = 0; i < pts.n; i++) {
    if (pts.p[i].dropped) continue;
    keep[k++] = i;
    double t[2] = {pts.p[i].tx, pts.p[i].ty};
    for (int d = 0; d < 2; d++) {
      if (t[d] < lo[d]) lo[d] = t[d];
      if (t[d] > hi[d]) hi[d] = t[d];
    }
  }
  for (int d = 0; d < 2; d++)
    if (!(hi[d] > lo[d])) {
      fprintf(stderr, PROG ": %s: all %zu points lie on one line (every %s is %.10g); "
              "no triangulation\n", fname, n, d ? o.yname : o.xname,
              d ? pts.p[keep[0]].y : pts.p[keep[0]].x);
      goto out;
    }
  for (size_t k = 0; k < n; k++) {
    const point_t *p = &pts.p[keep[k]];
    u[2 * k] = (p->tx - lo[0]) / (hi[0] - lo[0]);
    u[2 * k + 1] = (p->ty - lo[1]) / (hi[1] - lo[1]);
  }
  { /* collinear (e.g. on a diagonal)?  distance from the line through the first point and
       the point farthest from it, in unit-square coordinates */
    size_t far = 0;
    double dmax = 0;
    for (size_t k = 1; k < n; k++) {
      double d = hypot(u[2 * k] - u[0], u[2 * k + 1] - u[1]);
      if (d > dmax) {
        dmax = d;
        far = k;
      }
    }
    double ex = (u[2 * far] - u[0]) / dmax, ey = (u[2 * far + 1] - u[1]) / dmax, off = 0;
    for (size_t k = 1; k < n; k++) {
      double d = fabs(ex * (u[2 * k + 1] - u[1]) - ey * (u[2 * k] - u[0]));
      if (d > off) off = d;
    }
    if (off < 1e-9) {
      fprintf(stderr, PROG ": %s: all %zu points lie on one line (lines %ld and %ld span it); "
              "no triangulation\n", fname, n, pts.p[keep[0]].line, pts.p[keep[far]].line);
      goto out;
    }
  }

  /* Sampled grids are full of cocircular points (every rectangle of four), whose Delaunay
     triangulation is not unique: qhull would pick each cell's diagonal by its order of
     insertion, so a point added far away could flip diagonals, and the boundary, elsewhere.
     A fixed shear far below any grid step puts the points in general position: every
     rectangle is then split along the diagonal from its lower right to its upper left. */
  for (size_t k = 0; k < n; k++) u[2 * k] += TIE_SHEAR * u[2 * k + 1];

  size_t ne = 0;
  if (triangulate(u, n, &edges, &ne, used, fname)) goto out;
  for (size_t k = 0; k < n; k++)
    if (!used[k])
      fprintf(stderr, PROG ": warning: %s:%ld: point (%.10g, %.10g) is not a vertex of the "
              "triangulation (it nearly coincides with another point)\n", fname,
              pts.p[keep[k]].line, pts.p[keep[k]].x, pts.p[keep[k]].y);

  size_t nm = 0;
  mids = malloc(sizeof *mids * (ne ? ne : 1));
  if (!mids) {
    fprintf(stderr, PROG ": out of memory\n");
    goto out;
  }
  for (size_t k = 0; k < ne; k++) {
    const point_t *p = &pts.p[keep[edges[k].i]], *q = &pts.p[keep[edges[k].j]];
    int c = strcmp(p->label, q->label);
    if (!c) continue;
    mid_t m = {.a = c < 0 ? p->label : q->label, .b = c < 0 ? q->label : p->label,
               .tx = 0.5 * (p->tx + q->tx), .ty = 0.5 * (p->ty + q->ty),
               .hx = 0.5 * fabs(p->tx - q->tx), .hy = 0.5 * fabs(p->ty - q->ty)};
    const point_t *pa = c < 0 ? p : q, *pb = c < 0 ? q : p;
    m.a_left = pa->tx < pb->tx;
    m.a_below = pa->ty < pb->ty;
    m.x = o.logx ? pow(10, m.tx) : m.tx;
    m.y = o.logy ? pow(10, m.ty) : m.ty;
    mids[nm++] = m;
  }
  if (nm) qsort(mids, nm, sizeof *mids, cmp_mid);

  if (nfit) {
    printf("key\tvalue\terror\n");
    for (int f = 0; f < nfit; f++) print_fit(&fits[f], mids, nm, &pts, &o);
  } else {
    printf("x\ty\tphase_a\tphase_b\n");
    for (size_t k = 0; k < nm; k++)
      printf("%.10g\t%.10g\t%s\t%s\n", mids[k].x, mids[k].y, mids[k].a, mids[k].b);
  }
  if (fflush(stdout) || ferror(stdout)) {
    fprintf(stderr, PROG ": error writing stdout\n");
    goto out;
  }
  status = 0;

out:
  for (size_t i = 0; i < pts.n; i++) free(pts.p[i].label);
  free(pts.p);
  for (int f = 0; f < nfit; f++) {
    free(fits[f].a);
    free(fits[f].b);
  }
  free(fits);
  free(u);
  free(keep);
  free(used);
  free(edges);
  free(mids);
  return status;
}
