/* wetgran-run: simulate one scene and write its run file. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "io_h5.h"
#include "run.h"

static void usage(FILE *out)
{
  fprintf(out,
          "Usage: wetgran-run SCENE [key=value ...] -o RUN.h5 [options]\n"
          "       wetgran-run key=value ... -o RUN.h5          (no scene file)\n"
          "\n"
          "Simulates wet (or dry) granular matter in a container shaken as A sin(w t) or a\n"
          "periodic box, with one of two engines (key 'engine'): event-driven (ed: hard disks\n"
          "or spheres, thin-thread capillary bridges) or time-driven (td: soft disks or\n"
          "spheres, linear or Hertz contacts, the minimal capillary model; keys marked [td]).\n"
          "Units: d = m = g = 1.  key=value pairs override the scene file.\n"
          "Writes an H5MD run file under RUN.h5.tmp and renames it when complete; checkpoints\n"
          "go to RUN.h5.ckpt and an interrupted run resumes from there when restarted.\n"
          "\n"
          "Options:\n"
          "  -o, --output FILE  run file to write (required)\n"
          "  --fresh            ignore an existing checkpoint and start from t = 0\n"
          "  --no-volatile      leave /provenance/volatile empty (byte-comparable files)\n"
          "  -q, --quiet        no progress line even on a terminal\n"
          "  --log-every S      when stderr is not a terminal (nohup, Slurm, make -j; also with\n"
          "                     -q): a progress line every S seconds of wall time (default 60;\n"
          "                     0: none):\n"
          "                       progress: t = 19.57 / 300 (7%%), 1.03e+05 events/s, wall 21 s, ETA 296 s\n"
          "  --abort-after-checkpoint K\n"
          "                     testing aid: exit (status 3) right after the K-th checkpoint,\n"
          "                     as a crash would; rerunning the same command resumes\n"
          "  -h, --help         this text and the table of scene keys\n"
          "  -V, --version      version\n"
          "\n"
          "At the end one line on stderr:\n"
          "  summary: events=N sim_time=T wall_s=S events_per_s=R ledger_residual=X ...\n"
          "  summary: engine=td steps=N events=N sim_time=T wall_s=S particle_steps_per_s=R ...\n"
          "\n");
  wg_scene_print_keys(out);
}

static char *read_text(const char *path)
{
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  size_t cap = 4096, len = 0;
  char *s = malloc(cap);
  size_t got;
  while (s && (got = fread(s + len, 1, cap - len - 1, f)) > 0) {
    len += got;
    if (len + 1 == cap) {
      char *p = realloc(s, cap *= 2);
      if (!p) { free(s); s = NULL; }
      else s = p;
    }
  }
  fclose(f);
  if (s) s[len] = 0;
  return s;
}

int main(int argc, char **argv)
{
  const char *out = NULL, *scene_path = NULL;
  wg_run_options opt = {0};
  int tty = isatty(2), quiet = 0;
  double log_every = 60;
  wg_scene sc;
  wg_scene_init(&sc);
  wg_h5_quiet();

  /* command line recorded verbatim */
  size_t cl_len = 1;
  for (int a = 0; a < argc; a++) cl_len += strlen(argv[a]) + 1;
  char *cl = calloc(cl_len, 1);
  for (int a = 0; cl && a < argc; a++) {
    strcat(cl, argv[a]);
    if (a + 1 < argc) strcat(cl, " ");
  }
  opt.command_line = cl;

  /* first pass: options and the scene file; second pass: overrides (they win) */
  for (int a = 1; a < argc; a++) {
    const char *arg = argv[a];
    if (!strcmp(arg, "-h") || !strcmp(arg, "--help")) { usage(stdout); free(cl); return 0; }
    if (!strcmp(arg, "-V") || !strcmp(arg, "--version")) { printf("wetgran-run %s\n", wg_version()); free(cl); return 0; }
    if (!strcmp(arg, "-o") || !strcmp(arg, "--output")) {
      if (++a >= argc) { fprintf(stderr, "wetgran-run: option %s needs a file name\n", arg); free(cl); return 2; }
      out = argv[a];
    } else if (!strcmp(arg, "--fresh")) opt.fresh = 1;
    else if (!strcmp(arg, "--no-volatile")) opt.no_volatile = 1;
    else if (!strcmp(arg, "--abort-after-checkpoint")) {
      if (++a >= argc || atoi(argv[a]) < 1) { fprintf(stderr, "wetgran-run: --abort-after-checkpoint needs a count >= 1\n"); free(cl); return 2; }
      opt.abort_after_checkpoint = atoi(argv[a]);
    }
    else if (!strcmp(arg, "--log-every")) {
      char *end = NULL;
      if (++a < argc) log_every = strtod(argv[a], &end);
      if (a >= argc || end == argv[a] || *end || !isfinite(log_every) || log_every < 0) {
        fprintf(stderr, "wetgran-run: --log-every needs seconds >= 0 (0: no progress lines)\n");
        free(cl);
        return 2;
      }
    }
    else if (!strcmp(arg, "-q") || !strcmp(arg, "--quiet")) quiet = 1;
    else if (arg[0] == '-') {
      fprintf(stderr, "wetgran-run: unknown option '%s' (see --help)\n", arg);
      free(cl);
      return 2;
    } else if (!strchr(arg, '=')) {
      if (scene_path) {
        fprintf(stderr, "wetgran-run: two scene files given ('%s' and '%s')\n", scene_path, arg);
        free(cl);
        return 2;
      }
      scene_path = arg;
    }
  }
  opt.progress = tty && !quiet;      /* a terminal: the line redrawn in place */
  opt.log_every = tty ? 0 : log_every; /* a batch log: a line now and then, -q or not */
  if (!out) {
    fprintf(stderr, "wetgran-run: no output file: give -o RUN.h5 (see --help)\n");
    free(cl);
    return 2;
  }
  char *text = NULL;
  if (scene_path) {
    if (wg_scene_read_file(&sc, scene_path) != WG_OK) { free(cl); return 1; }
    text = read_text(scene_path);
    opt.scene_text = text;
  }
  for (int a = 1; a < argc; a++) {
    if (!strcmp(argv[a], "-o") || !strcmp(argv[a], "--output") ||
        !strcmp(argv[a], "--abort-after-checkpoint") || !strcmp(argv[a], "--log-every")) {
      a++;
      continue;
    }
    if (argv[a][0] != '-' && strchr(argv[a], '='))
      if (wg_scene_set_override(&sc, argv[a]) != WG_OK) { free(cl); free(text); return 1; }
  }
  if (wg_scene_finish(&sc) != WG_OK) { free(cl); free(text); return 1; }

  opt.out_path = out;
  wg_run run;
  int st = wg_run_init(&run, &sc, &opt);
  if (st == WG_OK) st = wg_run_execute(&run);
  wg_run_free(&run);
  free(cl);
  free(text);
  return st == WG_OK ? 0 : st == WG_ESTOPPED ? 3 : 1;
}
