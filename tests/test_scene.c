/* Tests of sim/common/scene.c: a good scene and its derived driving, the three bridge-energy
   forms, overrides, a periodic scene given by phi, and every class of bad input (the error
   message, captured from stderr, must name the file, the line and the key). */
#define _POSIX_C_SOURCE 200809L
#include "scene.h"
#include "tharness.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The system of Fig. 3.2 of the thesis; line numbers below refer to this list. */
static const char *const base[] = {
  "# Fig. 3.2 of the thesis: wet 2D shaker", /* 1 */
  "dim = 2",                                 /* 2 */
  "n = 1200",                                /* 3 */
  "lx = 400",                                /* 4 */
  "height = 9",                              /* 5 */
  "sigma_p = 0.06",                          /* 6 */
  "s_crit = 0.0711   # rupture distance",    /* 7 */
  "f_b = 4",                                 /* 8 */
  "eps = 1",                                 /* 9 */
  "  eps_wall=1",                            /* 10 */
  "gamma = 15",                              /* 11 */
  "estar = 1.42",                            /* 12 */
  "seed = 1",                                /* 13 */
  "",                                        /* 14 */
  "t_end = 100",                             /* 15 */
  NULL,
};
#define APPEND (-1)

/* Replace line `line` of the base scene by `text`, or append it (line = APPEND). */
typedef struct { int line; const char *text; } edit;

static void write_file(char path[32], const char *text)
{
  int fd;
  strcpy(path, "/tmp/wg_scene_XXXXXX");
  fd = mkstemp(path);
  if (fd < 0 || write(fd, text, strlen(text)) != (ssize_t)strlen(text)) {
    perror("test_scene: temp file");
    exit(2);
  }
  close(fd);
}

static void write_variant(char path[32], const edit *edits, int nedits)
{
  char text[4096] = "";
  for (int i = 0; base[i]; i++) {
    const char *line = base[i];
    for (int e = 0; e < nedits; e++)
      if (edits[e].line == i + 1) line = edits[e].text;
    strcat(strcat(text, line), "\n");
  }
  for (int e = 0; e < nedits; e++)
    if (edits[e].line == APPEND) strcat(strcat(text, edits[e].text), "\n");
  write_file(path, text);
}

static int load(wg_scene *sc, const char *path)
{
  int rc;
  wg_scene_init(sc);
  rc = wg_scene_read_file(sc, path);
  return rc ? rc : wg_scene_finish(sc);
}

static int load_variant(wg_scene *sc, const edit *edits, int nedits)
{
  char path[32];
  int rc;
  write_variant(path, edits, nedits);
  rc = load(sc, path);
  unlink(path);
  return rc;
}

/* ---- stderr capture */

typedef struct { int saved, fd; char path[32]; } capture;

static void capture_begin(capture *c)
{
  fflush(stderr);
  strcpy(c->path, "/tmp/wg_stderr_XXXXXX");
  c->fd = mkstemp(c->path);
  c->saved = dup(2);
  if (c->fd < 0 || c->saved < 0 || dup2(c->fd, 2) < 0) {
    perror("test_scene: capture");
    exit(2);
  }
}

static void capture_end(capture *c, char *out, size_t size)
{
  ssize_t got;
  fflush(stderr);
  dup2(c->saved, 2);
  close(c->saved);
  lseek(c->fd, 0, SEEK_SET);
  got = read(c->fd, out, size - 1);
  out[got > 0 ? got : 0] = '\0';
  out[strcspn(out, "\n")] = '\0';
  close(c->fd);
  unlink(c->path);
}

/* ---- the good scene */

static void test_good_scene(void)
{
  wg_scene sc;
  double ecb = 4 * 0.0711, v;
  int rc = load_variant(&sc, NULL, 0);
  TH_CHECK(rc == WG_OK, "Fig. 3.2 scene parses and finishes (rc %d)", rc);
  v = sc.amplitude * sc.omega;
  TH_CLOSE("Gamma = A w^2", sc.amplitude * sc.omega * sc.omega, 15.0, 1e-12, 0);
  TH_CLOSE("E* = (A w)^2 / (2 E_cb)", v * v / (2 * ecb), 1.42, 1e-12, 0);
  TH_CLOSE("e_cb = f_b s_crit", sc.e_cb, ecb, 1e-12, 0);
  TH_CLOSE("f_b", sc.f_b, 4.0, 1e-15, 0);
  TH_CLOSE("t_driv = 2 pi / w", sc.t_driv * sc.omega, 2 * 3.14159265358979323846, 1e-14, 0);
  TH_CLOSE("estar_d filled in = (A w)^2 / 2", sc.estar_d, v * v / 2, 1e-14, 0);
  TH_CHECK(sc.dim == 2 && sc.n == 1200 && sc.seed == 1 && sc.container == WG_CONTAINER_SHAKER &&
               sc.engine == WG_ENGINE_ED && sc.mass_scaling == 0,
           "given integers and enum defaults");
  TH_CHECK(sc.gravity == 1 && sc.tc == 1e-5 && sc.tg_init == 20 && sc.dt_snapshot == 0 &&
               sc.profile_bins == 0,
           "fixed and conditional defaults (gravity 1, tc 1e-5, tg_init 20)");
  TH_CHECK(sc.stall_rate == 1000 && sc.stall_action == WG_STALL_WARN,
           "stall watch defaults: stall_rate 1000, stall_action warn");
  TH_CHECK(wg_scene_key_is_advisory("stall_rate") && wg_scene_key_is_advisory("stall_action") &&
               !wg_scene_key_is_advisory("gamma") && !wg_scene_key_is_advisory("tc") &&
               !wg_scene_key_is_advisory("no_such_key"),
           "advisory keys (not in a checkpoint's fingerprint): stall_rate, stall_action only");
  TH_CLOSE("tg_init_abs = 20 E_cb", sc.tg_init_abs, 20 * ecb, 1e-14, 0);
  TH_CHECK(sc.dt_series == 0.1 && sc.profile_start == 50 && sc.dt_profile == 0.1 &&
               sc.dt_checkpoint == 10,
           "defaults from t_end: dt_series %g, profile_start %g, dt_profile %g, "
           "dt_checkpoint %g", sc.dt_series, sc.profile_start, sc.dt_profile,
           sc.dt_checkpoint);
  TH_CHECK(sc.key_line[1] == 2 && sc.key_line[0] == 0, "key_line: dim from line 2, engine default");

  double a = sc.amplitude;
  rc = wg_scene_finish(&sc);
  TH_CHECK(rc == WG_OK && sc.amplitude == a, "finish() again gives the same result");
}

static void test_bridge_forms(void)
{
  static const char *const forms[] = {"f_b = 4", "e_cb = 0.2844", "e_cb_mgs = 4"};
  double ecb[3], amp[3];
  for (int i = 0; i < 3; i++) {
    wg_scene sc;
    edit e = {8, forms[i]};
    int rc = load_variant(&sc, &e, 1);
    TH_CHECK(rc == WG_OK, "bridge given as '%s' (rc %d)", forms[i], rc);
    ecb[i] = sc.e_cb;
    amp[i] = sc.amplitude;
    TH_CLOSE("f_b = e_cb / s_crit", sc.f_b * 0.0711, sc.e_cb, 1e-12, 0);
  }
  TH_CLOSE("e_cb from f_b vs e_cb", ecb[0], ecb[1], 1e-12, 0);
  TH_CLOSE("e_cb from f_b vs e_cb_mgs", ecb[0], ecb[2], 1e-12, 0);
  TH_CLOSE("amplitude from e_cb vs e_cb_mgs", amp[1], amp[2], 1e-12, 0);
}

static void test_overrides(void)
{
  wg_scene sc;
  char path[32], msg[1024];
  edit e = {8, "e_cb_mgs = 4"};
  capture cap;
  int rc;

  write_variant(path, &e, 1);
  wg_scene_init(&sc);
  rc = wg_scene_read_file(&sc, path);
  if (!rc) rc = wg_scene_set_override(&sc, "eps=0.9");
  if (!rc) rc = wg_scene_set_override(&sc, " f_b = 5 ");
  if (!rc) rc = wg_scene_finish(&sc);
  TH_CHECK(rc == WG_OK && sc.eps == 0.9, "override eps=0.9 wins over the file (eps %g)", sc.eps);
  TH_CLOSE("override f_b replaces the file's e_cb_mgs", sc.e_cb, 5 * 0.0711, 1e-12, 0);

  /* overrides given before the file is read still win */
  wg_scene_init(&sc);
  rc = wg_scene_set_override(&sc, "gamma=10");
  if (!rc) rc = wg_scene_set_override(&sc, "e_cb=0.3");
  if (!rc) rc = wg_scene_read_file(&sc, path);
  if (!rc) rc = wg_scene_finish(&sc);
  TH_CHECK(rc == WG_OK && sc.gamma == 10 && sc.e_cb == 0.3,
           "command line wins over a file read later (gamma %g, e_cb %g)", sc.gamma, sc.e_cb);

  /* an empty override removes a key: the shaker scene becomes a periodic box */
  wg_scene_init(&sc);
  rc = wg_scene_read_file(&sc, path);
  if (!rc) rc = wg_scene_set_override(&sc, "container=periodic");
  if (!rc) rc = wg_scene_set_override(&sc, "gamma=");
  if (!rc) rc = wg_scene_set_override(&sc, "estar = ");
  if (!rc) rc = wg_scene_finish(&sc);
  TH_CHECK(rc == WG_OK && sc.gamma == 0 && sc.amplitude == 0 && sc.gravity == 0,
           "empty overrides 'gamma=' and 'estar=' remove the keys (rc %d)", rc);
  unlink(path);

  wg_scene_init(&sc);
  capture_begin(&cap);
  rc = wg_scene_set_override(&sc, "eps=2");
  capture_end(&cap, msg, sizeof msg);
  TH_CHECK(rc == WG_EINVAL && strstr(msg, "command line: key 'eps'") && strstr(msg, "(0, 1]"),
           "bad override: %s", msg);
  capture_begin(&cap);
  rc = wg_scene_set_override(&sc, "gama=2");
  capture_end(&cap, msg, sizeof msg);
  TH_CHECK(rc == WG_EINVAL && strstr(msg, "command line: key 'gama'") &&
               strstr(msg, "did you mean 'gamma'"),
           "unknown override: %s", msg);
}

static void test_dry_scene(void)
{
  wg_scene sc;
  edit e[] = {{7, "s_crit = 0"}, {8, "tg_init_abs = 2"}, {12, "estar_d = 3"}};
  int rc = load_variant(&sc, e, 3);
  double v = sc.amplitude * sc.omega;
  TH_CHECK(rc == WG_OK && sc.e_cb == 0 && sc.f_b == 0 && sc.tg_init == 0,
           "dry shaker with estar_d and tg_init_abs (rc %d)", rc);
  TH_CLOSE("E*_d = (A w)^2 / (2 g d)", v * v / 2, 3.0, 1e-12, 0);
}

static void test_periodic_phi(void)
{
  wg_scene sc;
  char path[32];
  double L = cbrt(1000 * 3.14159265358979323846 / 6 / 0.3);
  int rc;
  write_file(path, "dim = 3\nn = 1000\ncontainer = periodic\nphi = 0.3\nsigma_p = 0\n"
                   "seed = 18446744073709551615\nt_end = 10\ntg_init_abs = 1\n");
  rc = load(&sc, path);
  unlink(path);
  TH_CHECK(rc == WG_OK, "periodic 3D scene from phi (rc %d)", rc);
  TH_CLOSE("lx from phi", sc.lx, L, 1e-12, 0);
  TH_CLOSE("ly from phi", sc.ly, L, 1e-12, 0);
  TH_CLOSE("height from phi", sc.height, L, 1e-12, 0);
  TH_CHECK(sc.gravity == 0 && sc.amplitude == 0 && sc.omega == 0 && sc.t_driv == 0,
           "periodic: gravity 0, no driving");
  TH_CHECK(sc.seed == 18446744073709551615ULL, "seed takes the full 64 bits");
}

/* ---- visit and --help */

typedef struct { int count; char last[32]; char gamma[64]; char container[32]; } visit_log;

static int record(void *user, const char *key, const char *value, const char *unit,
                  const char *description)
{
  visit_log *log = user;
  log->count++;
  snprintf(log->last, sizeof log->last, "%s", key);
  if (strcmp(key, "gamma") == 0) snprintf(log->gamma, sizeof log->gamma, "%s", value);
  if (strcmp(key, "container") == 0) snprintf(log->container, sizeof log->container, "%s", value);
  return unit && description ? 0 : 1;
}

static int find_amplitude(void *user, const char *key, const char *value, const char *unit,
                          const char *description)
{
  (void)unit;
  if (strcmp(key, "amplitude") == 0) {
    *(double *)user = strtod(value, NULL);
    return strncmp(description, "derived", 7) == 0 ? 0 : 1;
  }
  return 0;
}

static void test_visit_and_help(void)
{
  wg_scene sc;
  visit_log log = {0};
  double amp = 0;
  char text[8192];
  size_t got;
  FILE *f = tmpfile();
  int rc = load_variant(&sc, NULL, 0);

  rc = rc ? rc : wg_scene_visit(&sc, record, &log);
  TH_CHECK(rc == WG_OK && log.count == 43 + 3 && strcmp(log.last, "t_driv") == 0,
           "visit: 43 keys (the event-driven engine's; shell, noise and noise_dt left out while "
           "off) then 3 derived entries (count %d, last %s)", log.count, log.last);
  {
    wg_scene on = sc;
    visit_log lo = {0};
    int r1 = wg_scene_set_override(&on, "shell=0.3");
    r1 = r1 ? r1 : wg_scene_set_override(&on, "noise=0.1");
    r1 = r1 ? r1 : wg_scene_finish(&on);
    r1 = r1 ? r1 : wg_scene_visit(&on, record, &lo);
    TH_CHECK(r1 == WG_OK && lo.count == 46 + 3, "visit with shell and noise on: 46 keys then 3 derived "
             "entries (count %d)", lo.count);
  }
  {
    /* the time-driven engine: its 15 keys instead of the 6 event-driven ones, and dt;
       with contact = hertz also Hertz's K */
    wg_scene td = sc;
    visit_log lt = {0};
    int r2 = wg_scene_set_override(&td, "engine=td");
    r2 = r2 ? r2 : wg_scene_set_override(&td, "tc=");
    r2 = r2 ? r2 : wg_scene_set_override(&td, "grazing_angle=");
    r2 = r2 ? r2 : wg_scene_finish(&td);
    r2 = r2 ? r2 : wg_scene_visit(&td, record, &lt);
    TH_CHECK(r2 == WG_OK && lt.count == 43 - 5 + 15 + 3 + 1 && strcmp(lt.last, "dt") == 0,
             "visit, engine = td: 53 keys then 4 derived entries (count %d, last %s)", lt.count, lt.last);
    TH_CLOSE("engine = td: dt = t_contact / steps_per_contact", td.dt, 0.005 / 50, 1e-12, 0);
  }
  TH_CHECK(strcmp(log.gamma, "15") == 0 && strcmp(log.container, "shaker") == 0,
           "visit values: gamma '%s', container '%s'", log.gamma, log.container);
  rc = wg_scene_visit(&sc, find_amplitude, &amp);
  TH_CHECK(rc == WG_OK && amp == sc.amplitude, "visit: amplitude round-trips through text");

  wg_scene_print_keys(f);
  rewind(f);
  got = fread(text, 1, sizeof text - 1, f);
  text[got] = '\0';
  fclose(f);
  TH_CHECK(strstr(text, "gamma") && strstr(text, "required") && strstr(text, "(0, 1]") &&
               strstr(text, "sqrt(d/g)") && strstr(text, "dt_checkpoint"),
           "--help table lists keys, defaults, units and ranges (%zu bytes)", got);
}

/* ---- bad inputs */

typedef struct {
  const char *name;
  edit edits[3];
  int nedits;
  const char *where;          /* appended to the file name, NULL: file name only */
  const char *key, *key2;     /* quoted in the message */
  const char *phrase;
} bad_case;

static const bad_case bad_cases[] = {
  {"unknown key", {{APPEND, "gama = 3"}}, 1, ":16", "gama", NULL, "did you mean 'gamma'?"},
  {"non-number", {{9, "eps = abc"}}, 1, ":9", "eps", NULL, "is not a number"},
  {"not an integer", {{2, "dim = two"}}, 1, ":2", "dim", NULL, "is not an integer"},
  {"out of range", {{9, "eps = 1.5"}}, 1, ":9", "eps", NULL, "out of range (0, 1]"},
  {"bad enum", {{APPEND, "container = crate"}}, 1, ":16", "container", NULL, "shaker, periodic, box"},
  {"bad stall_action", {{APPEND, "stall_action = halt"}}, 1, ":16", "stall_action", NULL,
   "warn, stop"},
  {"negative stall_rate", {{APPEND, "stall_rate = -1"}}, 1, ":16", "stall_rate", NULL,
   "out of range [0, inf)"},
  {"duplicate key", {{APPEND, "eps = 0.9"}}, 1, ":9 and :16", "eps", NULL, "twice"},
  {"missing '='", {{11, "gamma 15"}}, 1, ":11", "gamma", NULL, "missing '='"},
  {"missing required key", {{13, "# no seed"}}, 1, NULL, "seed", NULL, "required key missing"},
  {"two bridge energies", {{APPEND, "e_cb = 0.2844"}}, 1, ":8 and :16", "f_b", "e_cb",
   "give only one of e_cb, e_cb_mgs, f_b"},
  {"bridge energy but dry", {{7, "s_crit = 0"}}, 1, ":7 and :8", "f_b", "s_crit", "s_crit > 0"},
  {"wet without bridge energy", {{8, "#"}}, 1, ":7", "s_crit", NULL, "needs one of"},
  {"ly in 2D", {{APPEND, "ly = 10"}}, 1, ":2 and :16", "ly", "dim", "only for dim = 3"},
  {"phi with a shaker", {{APPEND, "phi = 0.3"}}, 1, ":16", "phi", "container", "periodic"},
  {"tg_init in a dry run", {{7, "s_crit = 0"}, {8, "tg_init = 5"}, {12, "estar_d = 2"}}, 3,
   ":7 and :8", "tg_init", NULL, "use tg_init_abs"},
  {"dry without temperature", {{7, "s_crit = 0"}, {8, "#"}, {12, "estar_d = 2"}}, 3, NULL,
   "tg_init_abs", NULL, "required"},
  {"estar in a dry run", {{7, "s_crit = 0"}, {8, "tg_init_abs = 5"}}, 2, ":7 and :12", "estar",
   NULL, "use estar_d"},
  {"too many particles", {{3, "n = 5000"}}, 1, ":3, :4 and :5", "n", "height", "fill"},
  {"amplitude >= height/2", {{11, "gamma = 1"}, {12, "estar = 10"}}, 2, ":5, :11 and :12",
   "gamma", "height", "amplitude"},
  {"height below a diameter", {{5, "height = 1.1"}, {3, "n = 100"}}, 2, ":5 and :6", "height",
   "sigma_p", "largest diameter"},
  {"gamma missing", {{11, ""}}, 1, NULL, "gamma", NULL, "required"},
  {"gamma in a periodic box", {{APPEND, "container = periodic"}}, 1, ":11 and :16", "gamma",
   "container", "only for container = shaker"},
  {"phi with lx", {{APPEND, "container = periodic"}, {APPEND, "phi = 0.3"}}, 2, ":4 and :17",
   "phi", "lx", "either phi"},
  {"profile_start > t_end", {{APPEND, "profile_start = 200"}}, 1, ":15 and :16",
   "profile_start", "t_end", "out of range"},
};

static void test_bad_case(const bad_case *b)
{
  wg_scene sc;
  capture cap;
  char path[32], msg[1024], loc[64], quoted[2][40];
  int rc, ok;

  write_variant(path, b->edits, b->nedits);
  snprintf(loc, sizeof loc, "%s%s", path, b->where ? b->where : "");
  snprintf(quoted[0], sizeof quoted[0], "'%s'", b->key);
  snprintf(quoted[1], sizeof quoted[1], "'%s'", b->key2 ? b->key2 : b->key);
  capture_begin(&cap);
  rc = load(&sc, path);
  capture_end(&cap, msg, sizeof msg);
  unlink(path);
  ok = rc == WG_EINVAL && strstr(msg, loc) && strstr(msg, quoted[0]) && strstr(msg, quoted[1]) &&
       strstr(msg, b->phrase);
  TH_CHECK(ok, "%s: %s", b->name, msg);
}

static void test_missing_file(void)
{
  wg_scene sc;
  capture cap;
  char msg[1024];
  int rc;
  wg_scene_init(&sc);
  capture_begin(&cap);
  rc = wg_scene_read_file(&sc, "/nonexistent/dir/scene.ini");
  capture_end(&cap, msg, sizeof msg);
  TH_CHECK(rc == WG_EIO && strstr(msg, "/nonexistent/dir/scene.ini"), "missing file: %s", msg);
}

/* Checkpoint fingerprints: equal but for keys at their fixed defaults */
static void test_same_configuration(void)
{
  const char *a = "dim = 2\nn = 10\neps = 1\n";
  TH_CHECK(wg_scene_same_configuration(a, a), "same configuration: identical texts");
  TH_CHECK(wg_scene_same_configuration(a, "dim = 2\nn = 10\nshell = 0\neps = 1\n"),
           "same configuration: an extra 'shell = 0' (its default) is the same");
  TH_CHECK(wg_scene_same_configuration("dim = 2\nn = 10\nnoise = 0\neps = 1\n", a),
           "same configuration: a missing 'noise = 0' is the same");
  TH_CHECK(!wg_scene_same_configuration(a, "dim = 2\nn = 10\nshell = 0.3\neps = 1\n"),
           "other configuration: 'shell = 0.3' is not the default");
  TH_CHECK(!wg_scene_same_configuration(a, "dim = 2\nn = 10\neps = 0.9\n"),
           "other configuration: eps 0.9 against 1 (1 is eps's default, 0.9 is not)");
  TH_CHECK(!wg_scene_same_configuration(a, "dim = 2\nn = 10\neps = 1\ngamma = 15\n"),
           "other configuration: an extra key without a fixed default (gamma)");
  TH_CHECK(!wg_scene_same_configuration(a, "dim = 2\nn = 11\neps = 1\n"), "other configuration: n 11 against 10");
}

int main(void)
{
  test_same_configuration();
  test_good_scene();
  test_bridge_forms();
  test_overrides();
  test_dry_scene();
  test_periodic_phi();
  test_visit_and_help();
  for (size_t i = 0; i < sizeof bad_cases / sizeof bad_cases[0]; i++)
    test_bad_case(&bad_cases[i]);
  test_missing_file();
  return th_summary();
}
