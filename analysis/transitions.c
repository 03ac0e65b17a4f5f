/* wetgran-transitions: where a one-dimensional scan changes phase (thesis Figs. 3.5, 3.16,
   3.17).  Reads a labelled table (wetgran-orderparam's), optionally splits it into groups
   by the value of one column (a scan in E* for each E_cb, or each eps), and for each phase
   pair A:B places the transition at the cut along x that leaves the fewest points on the
   wrong side (A expected below, B above).  The cut lies between two neighbouring sampled
   x; the transition is their midpoint (geometric with --logx) and the error half their
   distance, so the error is the sampling resolution of the scan. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run_open.h"

#define MAX_COLS 64
#define MAX_PAIRS 8
#define LABEL_LEN 16

typedef struct point {
  double x, group;
  char label[LABEL_LEN];
} point;

typedef struct table {
  point *p;
  size_t n, cap;
} table;

static int read_table(const char *path, const char *xname, const char *gname,
                      const char *lname, table *t)
{
  FILE *f = wg_table_open(path);
  if (!f) return 1;
  char line[16384];
  int xc = -1, gc = -1, lc = -1, lineno = 0, header = 0, bad = 0;
  while (!bad && fgets(line, sizeof line, f)) {
    lineno++;
    line[strcspn(line, "\r\n")] = 0;
    if (line[0] == '#' || line[0] == 0) continue;
    char *field[MAX_COLS];
    int nf = 0;
    for (char *tok = strtok(line, "\t"); tok && nf < MAX_COLS; tok = strtok(NULL, "\t"))
      field[nf++] = tok;
    if (!header) {
      for (int k = 0; k < nf; k++) {
        if (!strcmp(field[k], xname)) xc = k;
        if (gname && !strcmp(field[k], gname)) gc = k;
        if (!strcmp(field[k], lname)) lc = k;
      }
      const char *missing = xc < 0 ? xname : lc < 0 ? lname : (gname && gc < 0) ? gname : NULL;
      if (missing) {
        fprintf(stderr, "wetgran-transitions: %s:%d: no column '%s' in the header\n", path,
                lineno, missing);
        bad = 1;
      }
      header = 1;
      continue;
    }
    int need = xc > lc ? xc : lc;
    if (gc > need) need = gc;
    if (need >= nf) {
      fprintf(stderr, "wetgran-transitions: %s:%d: too few fields\n", path, lineno);
      bad = 1;
      break;
    }
    point q = {0, 0, ""};
    char *end;
    q.x = strtod(field[xc], &end);
    if (*end || !isfinite(q.x)) {
      fprintf(stderr, "wetgran-transitions: %s:%d: column '%s': '%s' is not a number\n", path,
              lineno, xname, field[xc]);
      bad = 1;
      break;
    }
    if (gc >= 0) {
      q.group = strtod(field[gc], &end);
      if (*end || !isfinite(q.group)) {
        fprintf(stderr, "wetgran-transitions: %s:%d: column '%s': '%s' is not a number\n",
                path, lineno, gname, field[gc]);
        bad = 1;
        break;
      }
    }
    snprintf(q.label, sizeof q.label, "%s", field[lc]);
    if (t->n == t->cap) {
      t->cap = t->cap ? 2 * t->cap : 64;
      point *np = realloc(t->p, t->cap * sizeof *np);
      if (!np) {
        bad = 1;
        break;
      }
      t->p = np;
    }
    t->p[t->n++] = q;
  }
  if (f != stdin) fclose(f);
  if (!bad && !header) {
    fprintf(stderr, "wetgran-transitions: %s: no header line\n", path);
    bad = 1;
  }
  return bad;
}

static int by_group_then_x(const void *a_, const void *b_)
{
  const point *a = a_, *b = b_;
  if (a->group != b->group) return a->group < b->group ? -1 : 1;
  return (a->x > b->x) - (a->x < b->x);
}

/* The best cut between phases A (below) and B (above) among points [lo, hi), sorted in x.
   Returns 0 and fills x, err, misplaced if both phases occur; 1 otherwise. */
static int best_cut(const point *p, size_t lo, size_t hi, const char *A, const char *B,
                    int logx, double *x, double *err, int *misplaced, int *na, int *nb)
{
  /* the points of phase A or B, in order; others are ignored */
  size_t m = 0;
  *na = *nb = 0;
  for (size_t k = lo; k < hi; k++) {
    if (!strcmp(p[k].label, A)) (*na)++;
    else if (!strcmp(p[k].label, B)) (*nb)++;
  }
  if (*na == 0 || *nb == 0) return 1;
  m = (size_t)(*na + *nb);
  /* cut after the c-th relevant point: wrong = B's at or before it + A's after it */
  int best = -1, b_before = 0, a_after = *na;
  size_t c = 0;
  double x_lo = NAN, x_hi = NAN, best_lo = NAN, best_hi = NAN;
  for (size_t k = lo; k < hi && c < m; k++) {
    int isa = !strcmp(p[k].label, A), isb = !strcmp(p[k].label, B);
    if (!isa && !isb) continue;
    if (isa) a_after--;
    else b_before++;
    c++;
    x_lo = p[k].x;
    if (c == m) break;
    /* next relevant point */
    size_t k2 = k + 1;
    while (k2 < hi && strcmp(p[k2].label, A) && strcmp(p[k2].label, B)) k2++;
    x_hi = p[k2].x;
    int wrong = b_before + a_after;
    if (x_hi > x_lo && (best < 0 || wrong < best)) {
      best = wrong;
      best_lo = x_lo;
      best_hi = x_hi;
    }
  }
  if (best < 0) return 1;
  if (logx) {
    *x = sqrt(best_lo * best_hi);
    *err = 0.5 * *x * log(best_hi / best_lo); /* half the log interval, as a relative error */
  } else {
    *x = 0.5 * (best_lo + best_hi);
    *err = 0.5 * (best_hi - best_lo);
  }
  *misplaced = best;
  return 0;
}

static void usage(FILE *out)
{
  fprintf(out,
          "Usage: wetgran-transitions --x COL --pair A:B [--pair C:D ...] [--group COL]\n"
          "                           [--label COL] [--logx] [TABLE|-]\n"
          "Phase transitions along one-dimensional scans (thesis Figs. 3.5, 3.16, 3.17).\n"
          "Input: a tab-separated table with a header line (wetgran-orderparam's); rows\n"
          "starting with '#' are skipped.  Rows are split into groups by the value of the\n"
          "--group column (e.g. e_cb or eps; without it, one group) and sorted by --x.\n"
          "For each group and each --pair A:B (phase A expected at small x, B at large x),\n"
          "the transition is the cut between two neighbouring sampled x that leaves the\n"
          "fewest A points above it and B points below it (points of other phases are\n"
          "ignored; of equal cuts the lowest); its value is the midpoint of the two\n"
          "(geometric with --logx) and its "
          "error half their distance (with --logx: x ln(x_hi/x_lo)/2).\n"
          "Output: header [GROUP] pair x err n_a n_b misplaced; one row per group and pair\n"
          "in which both phases occur (a pair missing from a group is reported on stderr).\n"
          "Errors name the file, line and column and exit with status 1; bad options 2.\n");
}

int main(int argc, char **argv)
{
  const char *xname = NULL, *gname = NULL, *lname = "label", *path = "-";
  const char *pairs[MAX_PAIRS];
  int npairs = 0, logx = 0;
  for (int k = 1; k < argc; k++) {
    if (!strcmp(argv[k], "-h") || !strcmp(argv[k], "--help")) {
      usage(stdout);
      return 0;
    } else if (!strcmp(argv[k], "--x") && k + 1 < argc) xname = argv[++k];
    else if (!strcmp(argv[k], "--group") && k + 1 < argc) gname = argv[++k];
    else if (!strcmp(argv[k], "--label") && k + 1 < argc) lname = argv[++k];
    else if (!strcmp(argv[k], "--logx")) logx = 1;
    else if (!strcmp(argv[k], "--pair") && k + 1 < argc) {
      if (npairs == MAX_PAIRS || !strchr(argv[k + 1], ':')) {
        fprintf(stderr, "wetgran-transitions: --pair wants A:B (at most %d)\n", MAX_PAIRS);
        return 2;
      }
      pairs[npairs++] = argv[++k];
    } else if (argv[k][0] == '-' && argv[k][1]) {
      fprintf(stderr, "wetgran-transitions: unknown option '%s' (see --help)\n", argv[k]);
      return 2;
    } else path = argv[k];
  }
  if (!xname || npairs == 0) {
    fprintf(stderr, "wetgran-transitions: --x and at least one --pair are needed (see --help)\n");
    return 2;
  }
  table t = {NULL, 0, 0};
  if (read_table(path, xname, gname, lname, &t)) {
    free(t.p);
    return 1;
  }
  for (size_t k = 0; k < t.n; k++)
    if (logx && !(t.p[k].x > 0)) {
      fprintf(stderr, "wetgran-transitions: %s: --logx needs %s > 0 (row %zu)\n", path, xname,
              k + 1);
      free(t.p);
      return 1;
    }
  qsort(t.p, t.n, sizeof *t.p, by_group_then_x);
  if (gname) printf("%s\t", gname);
  printf("pair\tx\terr\tn_a\tn_b\tmisplaced\n");
  for (size_t lo = 0; lo < t.n;) {
    size_t hi = lo;
    while (hi < t.n && t.p[hi].group == t.p[lo].group) hi++;
    for (int q = 0; q < npairs; q++) {
      char A[LABEL_LEN], B[LABEL_LEN];
      const char *colon = strchr(pairs[q], ':');
      snprintf(A, sizeof A, "%.*s", (int)(colon - pairs[q]), pairs[q]);
      snprintf(B, sizeof B, "%s", colon + 1);
      double x, err;
      int wrong, na, nb;
      if (best_cut(t.p, lo, hi, A, B, logx, &x, &err, &wrong, &na, &nb)) {
        fprintf(stderr, "wetgran-transitions: %s%s%.6g: no %s:%s transition (%d %s, %d %s)\n",
                gname ? gname : "", gname ? " = " : "", t.p[lo].group, A, B, na, A, nb, B);
        continue;
      }
      if (gname) printf("%.10g\t", t.p[lo].group);
      printf("%s_%s\t%.10g\t%.4g\t%d\t%d\t%d\n", A, B, x, err, na, nb, wrong);
    }
    lo = hi;
  }
  free(t.p);
  return 0;
}
