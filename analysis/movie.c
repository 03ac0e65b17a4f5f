/* wetgran-movie: a run's particle snapshots as a movie.  Each snapshot is drawn by gnuplot
   (pngcairo: the grains as circles of their diameter, side view x-z, coloured by bridge count or
   speed) into a scratch folder, and ffmpeg encodes the frames (H.264, yuv420p, so that common
   players take it).  The movie is written under a temporary name and renamed when complete;
   a progress line on a terminal, nothing in a pipe. */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "io_h5.h"
#include "run_open.h"
#include "wg_args.h"

static void usage(void)
{
  printf("Usage: wetgran-movie RUN.h5 -o MOVIE.mp4 [--fps F] [--width W] [--color bridges|speed] [-q]\n"
         "Renders every particle snapshot of RUN.h5 (side view: x across, the vertical up; a\n"
         "3D run is projected along y) with gnuplot and encodes them with ffmpeg into an\n"
         "H.264 movie, F frames per second (default 10), W pixels wide (default 960; the\n"
         "height follows the box).  Colour: bridge count (default) or speed |v| [sqrt(g d)].\n"
         "The axes span the grains' extent over the whole run.  Progress on a terminal;\n"
         "-q silences it.  Needs gnuplot and ffmpeg (scripts/install-deps.sh installs them).\n");
}

/* The run's snapshots: dims, and the extent of the grains in the side view over all frames. */
typedef struct movie_run {
  hid_t f;
  long nf, n;
  int dim;
  double *r, *v, *d;
  unsigned char *nb;
} movie_run;

static int read_frame(movie_run *m, long k, double *t)
{
  int st = wg_h5_read_rows(m->f, "/particles/all/position/value", H5T_NATIVE_DOUBLE, (hsize_t)k, 1, m->r);
  if (st == WG_OK) st = wg_h5_read_rows(m->f, "/particles/all/velocity/value", H5T_NATIVE_DOUBLE, (hsize_t)k, 1, m->v);
  if (st == WG_OK) st = wg_h5_read_rows(m->f, "/particles/all/bridge_count/value", H5T_NATIVE_UINT8, (hsize_t)k, 1, m->nb);
  if (st == WG_OK) st = wg_h5_read_rows(m->f, "/particles/all/position/time", H5T_NATIVE_DOUBLE, (hsize_t)k, 1, t);
  return st;
}

/* The colour of grain i in the frame read last: its bridge count, or its speed. */
static double colour_of(const movie_run *m, long i, int by_speed)
{
  if (!by_speed) return (double)m->nb[i];
  double s2 = 0;
  for (int a = 0; a < m->dim; a++) s2 += m->v[i * m->dim + a] * m->v[i * m->dim + a];
  return sqrt(s2);
}

int main(int argc, char **argv)
{
  const char *path = NULL, *out = NULL, *color = "bridges";
  long width = 960;
  double fps = 10;
  int quiet = 0;
  for (int a = 1; a < argc; a++) {
    const char *o = argv[a];
    if (!strcmp(o, "-h") || !strcmp(o, "--help")) { usage(); return 0; }
    if (!strcmp(o, "-q")) { quiet = 1; continue; }
    if (!strcmp(o, "-o") || !strcmp(o, "--fps") || !strcmp(o, "--width") || !strcmp(o, "--color")) {
      if (a + 1 == argc) {
        fprintf(stderr, "wetgran-movie: option %s needs a value (see --help)\n", o);
        return 2;
      }
      const char *val = argv[++a];
      if (!strcmp(o, "-o")) out = val;
      else if (!strcmp(o, "--fps")) {
        if (wg_arg_double(o, val, &fps) != WG_OK) return 2;
      } else if (!strcmp(o, "--width")) {
        if (wg_arg_long(o, val, &width) != WG_OK) return 2;
      } else color = val;
      continue;
    }
    if (o[0] == '-') {
      fprintf(stderr, "wetgran-movie: unknown option '%s' (see --help)\n", o);
      return 2;
    }
    if (path) {
      fprintf(stderr, "wetgran-movie: unexpected argument '%s' (see --help)\n", o);
      return 2;
    }
    path = o;
  }
  if (!path || !out) {
    fprintf(stderr, "wetgran-movie: %s (see --help)\n", !path ? "no run file given" : "no movie named (-o)");
    return 2;
  }
  if (!(fps > 0 && fps <= 120) || width < 64 || width > 7680 ||
      (strcmp(color, "bridges") && strcmp(color, "speed"))) {
    fprintf(stderr, "wetgran-movie: --fps in (0, 120], --width in [64, 7680], --color bridges or speed\n");
    return 2;
  }
  int by_speed = !strcmp(color, "speed");
  if (system("command -v gnuplot > /dev/null && command -v ffmpeg > /dev/null") != 0) {
    fprintf(stderr, "wetgran-movie: needs gnuplot and ffmpeg on the PATH (scripts/install-deps.sh)\n");
    return 1;
  }

  movie_run m = {0};
  m.f = wg_run_open(path);
  if (m.f < 0) return 1;
  int rank;
  hsize_t dims[8];
  if (wg_h5_dims(m.f, "/particles/all/position/value", &rank, dims) != WG_OK) {
    fprintf(stderr, "wetgran-movie: %s: no particle snapshots (run with dt_snapshot > 0)\n", path);
    wg_h5_close(m.f);
    return 1;
  }
  m.nf = (long)dims[0];
  m.n = (long)dims[1];
  m.dim = (int)dims[2];
  if (m.nf < 1) {
    fprintf(stderr, "wetgran-movie: %s: the run holds no snapshot\n", path);
    wg_h5_close(m.f);
    return 1;
  }
  m.r = malloc(sizeof(double) * (size_t)(m.n * m.dim));
  m.v = malloc(sizeof(double) * (size_t)(m.n * m.dim));
  m.d = malloc(sizeof(double) * (size_t)m.n);
  m.nb = malloc((size_t)m.n);
  char dir[PATH_MAX];
  const char *tmpdir = getenv("TMPDIR");
  snprintf(dir, sizeof dir, "%s/wetgran-movie.XXXXXX", tmpdir && *tmpdir ? tmpdir : "/tmp");
  int st = m.r && m.v && m.d && m.nb ? WG_OK : WG_ENOMEM;
  if (st == WG_OK) st = wg_h5_read(m.f, "/particles/all/diameter", H5T_NATIVE_DOUBLE, m.d);
  if (st == WG_OK && !mkdtemp(dir)) {
    fprintf(stderr, "wetgran-movie: cannot make a scratch folder: %s\n", strerror(errno));
    st = WG_EIO;
  }
  int up = m.dim - 1;
  /* first pass: the extent of the side view over the whole run */
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, t = 0, cmax = 1;
  for (long k = 0; k < m.nf && st == WG_OK; k++) {
    st = read_frame(&m, k, &t);
    for (long i = 0; st == WG_OK && i < m.n; i++) {
      double xy[2] = {m.r[i * m.dim], m.r[i * m.dim + up]}, rad = 0.5 * m.d[i];
      for (int a = 0; a < 2; a++) {
        lo[a] = fmin(lo[a], xy[a] - rad);
        hi[a] = fmax(hi[a], xy[a] + rad);
      }
      cmax = fmax(cmax, colour_of(&m, i, by_speed));
    }
  }
  FILE *gp = NULL;
  if (st == WG_OK) {
    double aspect = (hi[1] - lo[1]) / (hi[0] - lo[0]);
    long height = (long)(width * aspect) + 140; /* title, axes and their labels */
    if (height < 200) height = 200;
    if (height > 4320) height = 4320;
    height += height % 2;
    gp = popen("gnuplot", "w");
    if (!gp) {
      fprintf(stderr, "wetgran-movie: cannot start gnuplot: %s\n", strerror(errno));
      st = WG_EIO;
    } else {
      fprintf(gp, "set terminal pngcairo size %ld,%ld font ',10'\n", width + width % 2, height);
      fprintf(gp, "set size ratio -1\nset xrange [%.10g:%.10g]\nset yrange [%.10g:%.10g]\n", lo[0],
              hi[0], lo[1], hi[1]);
      fprintf(gp, "set xlabel 'x [d]'\nset ylabel 'z [d]'\nset cbrange [0:%.10g]\n", cmax);
      fprintf(gp, "set cblabel '%s'\nset palette rgb 33,13,10\nunset key\n",
              by_speed ? "speed [sqrt(g d)]" : "bridges per grain");
    }
  }
  int tty = !quiet && isatty(2);
  for (long k = 0; k < m.nf && st == WG_OK; k++) {
    st = read_frame(&m, k, &t);
    if (st != WG_OK) break;
    char dat[sizeof dir + 32];
    snprintf(dat, sizeof dat, "%s/frame%06ld.dat", dir, k);
    FILE *fd = fopen(dat, "w");
    if (!fd) {
      fprintf(stderr, "wetgran-movie: %s: %s\n", dat, strerror(errno));
      st = WG_EIO;
      break;
    }
    for (long i = 0; i < m.n; i++)
      fprintf(fd, "%.8g\t%.8g\t%.6g\t%.6g\n", m.r[i * m.dim], m.r[i * m.dim + up], 0.5 * m.d[i],
              colour_of(&m, i, by_speed));
    if (fclose(fd) != 0) {
      fprintf(stderr, "wetgran-movie: %s: %s\n", dat, strerror(errno));
      st = WG_EIO;
      break;
    }
    fprintf(gp, "set output '%s/frame%06ld.png'\nset title 't = %.4g'\n", dir, k, t);
    fprintf(gp, "plot '%s' using 1:2:3:4 with circles fill solid noborder lc palette\n", dat);
    fprintf(gp, "set output\n");
    if (tty) fprintf(stderr, "\rwetgran-movie: frame %ld / %ld", k + 1, m.nf);
  }
  wg_h5_close(m.f);
  if (gp && pclose(gp) != 0 && st == WG_OK) {
    fprintf(stderr, "wetgran-movie: gnuplot failed\n");
    st = WG_EFAIL;
  }
  if (tty) fprintf(stderr, "\n");
  /* encode into OUT.tmp.mp4, then rename */
  size_t len = strlen(out) + 16;
  char *tmp = malloc(len), *cmd = malloc(2 * len + 2 * sizeof dir + 256);
  if (st == WG_OK && tmp && cmd) {
    snprintf(tmp, len, "%s.tmp.mp4", out);
    snprintf(cmd, 2 * len + 2 * sizeof dir + 256,
             "ffmpeg -nostdin -loglevel error -y -framerate %.6g -i '%s/frame%%06d.png' "
             "-c:v libx264 -pix_fmt yuv420p -threads 1 '%s'", fps, dir, tmp);
    if (strchr(out, '\'')) {
      fprintf(stderr, "wetgran-movie: %s: a quote in the movie's name is not taken\n", out);
      st = WG_EINVAL;
    } else if (system(cmd) != 0) {
      fprintf(stderr, "wetgran-movie: %s: ffmpeg failed to encode the frames\n", out);
      remove(tmp);
      st = WG_EFAIL;
    } else if (rename(tmp, out) != 0) {
      fprintf(stderr, "wetgran-movie: %s: cannot rename from %s: %s\n", out, tmp, strerror(errno));
      remove(tmp);
      st = WG_EIO;
    }
  } else if (st == WG_OK) {
    st = WG_ENOMEM;
  }
  /* the scratch frames go */
  for (long k = 0; k < m.nf; k++) {
    char f[sizeof dir + 32];
    snprintf(f, sizeof f, "%s/frame%06ld.dat", dir, k);
    remove(f);
    snprintf(f, sizeof f, "%s/frame%06ld.png", dir, k);
    remove(f);
  }
  rmdir(dir);
  free(tmp); free(cmd);
  free(m.r); free(m.v); free(m.d); free(m.nb);
  if (st == WG_OK && !quiet) fprintf(stderr, "wetgran-movie: %s: %ld frames\n", out, m.nf);
  return st == WG_OK ? 0 : 1;
}
