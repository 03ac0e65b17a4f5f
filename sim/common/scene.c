/* Scene files: parsing, range checks, derived quantities, --help and provenance, all driven
   by one static table of key descriptors.

   Self-written parser rather than libinih: Debian's libinih is built without
   INI_HANDLER_LINENO, so it cannot report line numbers.

   Rules beyond those stated in scene.h:
   - Mutually exclusive alternatives: {e_cb, e_cb_mgs, f_b}, {estar, estar_d},
     {tg_init, tg_init_abs}, {phi vs. lx/ly/height}.  A command-line override of one of them
     removes the alternatives that came from the file (they fall back to "not given"), and a
     file read after an override never replaces a value set on the command line: the command
     line always wins.  Two alternatives given in the same place are an error in finish().
   - An override with an empty value ("gamma=") removes the key read so far, as if it had
     not been given (e.g. to turn a shaker scene into a periodic one).
   - e_cb_mgs = E_cb/(m g s_crit) and f_b = F_B/(m g) are the same number (F_B = E_cb/s_crit,
     m = g = 1), so both keys share the field f_b; key_line[] tells which one was given.
   - wg_scene_finish() fills in every value that is implied by the given ones, so that a
     finished scene is self-consistent: lx/ly/height from phi; e_cb and f_b; estar_d (and
     estar when wet) from A w; tg_init_abs = tg_init * E_cb (tg_init = 0 when dry); the
     defaults that depend on other keys (gravity, dt_series, ...).  It can be called again
     after further overrides. */
#include "scene.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#define WHERE "scene"
#define LINE_MAX_LEN 1024
#define LOC_LEN 384
#define MSG_LEN 512
#define LINE_CMD (-1)

static const double pi = 3.14159265358979323846;

typedef enum { T_DOUBLE, T_LONG, T_INT, T_ENUM, T_SEED, T_PATH } key_type;
/* DEF_VALUE: fixed default; DEF_REQUIRED: must be given; DEF_COND: required or computed
   depending on other keys (finish() decides; dflt_text says how). */
typedef enum { DEF_VALUE, DEF_REQUIRED, DEF_COND } def_kind;
enum { MIN_EXCL = 1, MAX_EXCL = 2 };
/* Groups of mutually exclusive alternatives: keys of one group with different alt conflict. */
enum { G_NONE, G_BRIDGE, G_ESTAR, G_TG, G_BOX, G_INIT };
enum { ONLY_ED = 1, ONLY_TD = 2 };

typedef struct {
  const char *name;
  key_type type;
  size_t offset;
  double min, max;
  int excl;                  /* MIN_EXCL | MAX_EXCL */
  def_kind def;
  double dflt;               /* DEF_VALUE: the default (T_ENUM: index into words) */
  const char *dflt_text;     /* DEF_COND: how the value is found when not given */
  const char *unit;
  const char *desc;
  const char *const *words;  /* T_ENUM: NULL-terminated */
  int group, alt;
  int only;                  /* ONLY_ED / ONLY_TD: a key of one engine (0: both) */
  int advisory;              /* 1: changes what a run reports, never its numbers */
} key_desc;

enum {
  K_ENGINE, K_DIM, K_N, K_LX, K_LY, K_HEIGHT, K_PHI, K_CONTAINER, K_GRAVITY, K_SIGMA_P,
  K_MASS, K_S_CRIT, K_E_CB, K_E_CB_MGS, K_F_B, K_EPS, K_EPS_WALL, K_TC, K_GRAZING, K_REST_SPEED, K_SHELL, K_NOISE, K_NOISE_DT, K_GAMMA, K_ESTAR,
  K_ESTAR_D, K_TG_INIT, K_TG_INIT_ABS, K_INIT, K_INIT_FROM, K_INIT_JITTER, K_SEED, K_T_END, K_DT_SERIES, K_DT_SNAPSHOT,
  K_PROFILE_BINS, K_PROFILE_START, K_DT_PROFILE, K_MAP_BINS, K_MAP_BINS_Y, K_MAP_START,
  K_DT_MAP, K_MAP_SAMPLES, K_HEIGHT_BINS, K_HEIGHT_START, K_DT_HEIGHT, K_HEIGHT_SAMPLES,
  K_DT_CHECKPOINT, K_STALL_RATE, K_STALL_ACTION,
  K_SHEAR_FORCE, K_SHEAR_BINS, K_SHEAR_ON, K_SHEAR_OFF,
  K_CONTACT, K_T_CONTACT, K_STEPS_PER_CONTACT, K_HERTZ_AD, K_SKIN, K_BRIDGE_LAW,
  K_BRIDGE_VOLUME, K_CONTACT_ANGLE, K_WALL_BRIDGES, K_INTEGRATOR, K_MU, K_MU_WALL, K_KT_RATIO,
  K_GT_RATIO, K_MU_ROLL, NKEYS
};

static const char *const engine_words[] = {"ed", "td", NULL};
static const char *const container_words[] = {"shaker", "periodic", "box", NULL};
static const char *const mass_words[] = {"unit", "volume", NULL};
static const char *const init_words[] = {"lattice", "packed", NULL};
static const char *const contact_words[] = {"linear", "hertz", NULL};
static const char *const bridge_law_words[] = {"constant", "willett", NULL};
static const char *const integrator_words[] = {"verlet", "gear", NULL};
static const char *const stall_words[] = {"warn", "stop", NULL};

#define OFF(field) offsetof(wg_scene, field)
#define INF INFINITY

static const key_desc keys[NKEYS] = {
  [K_ENGINE] = {"engine", T_ENUM, OFF(engine), 0, 1, 0, DEF_VALUE, WG_ENGINE_ED, NULL, "",
                "simulation engine: ed = event-driven, td = time-driven", engine_words, 0, 0},
  [K_DIM] = {"dim", T_INT, OFF(dim), 2, 3, 0, DEF_REQUIRED, 0, NULL, "",
             "dimension: 2 (disks) or 3 (spheres)", NULL, 0, 0},
  [K_N] = {"n", T_LONG, OFF(n), 1, INF, MAX_EXCL, DEF_REQUIRED, 0, NULL, "",
           "number of particles", NULL, 0, 0},
  [K_LX] = {"lx", T_DOUBLE, OFF(lx), 0, INF, MIN_EXCL | MAX_EXCL, DEF_COND, 0,
            "required (or phi)", "d", "lateral box length along x", NULL, G_BOX, 0},
  [K_LY] = {"ly", T_DOUBLE, OFF(ly), 0, INF, MIN_EXCL | MAX_EXCL, DEF_COND, 0,
            "required in 3D (or phi)", "d", "lateral box length along y (3D only)", NULL,
            G_BOX, 0},
  [K_HEIGHT] = {"height", T_DOUBLE, OFF(height), 0, INF, MIN_EXCL | MAX_EXCL, DEF_COND, 0,
                "required (or phi)", "d",
                "bottom-to-lid distance H (shaker) or box length along z (periodic)", NULL,
                G_BOX, 0},
  [K_PHI] = {"phi", T_DOUBLE, OFF(phi), 0, 0.9069, MIN_EXCL | MAX_EXCL, DEF_COND, 0,
             "none", "1",
             "packing fraction, periodic only, sets lx = ly = height (< 0.74 in 3D)", NULL,
             G_BOX, 1},
  [K_CONTAINER] = {"container", T_ENUM, OFF(container), 0, 2, 0, DEF_VALUE,
                   WG_CONTAINER_SHAKER, NULL, "",
                   "shaker (vibrated bottom and lid), periodic box, or box (bottom and lid at "
                   "rest; event-driven)", container_words, 0, 0},
  [K_GRAVITY] = {"gravity", T_DOUBLE, OFF(gravity), 0, 1e3, 0, DEF_COND, 0,
                 "1 shaker or box, 0 periodic", "g", "gravitational acceleration", NULL, 0, 0},
  [K_SIGMA_P] = {"sigma_p", T_DOUBLE, OFF(sigma_p), 0, 0.57735026918962576, MAX_EXCL,
                 DEF_VALUE, 0.06, NULL, "d",
                 "polydispersity: std. dev. of the uniform diameter distribution (Eq. 2.22)",
                 NULL, 0, 0},
  [K_MASS] = {"mass", T_ENUM, OFF(mass_scaling), 0, 1, 0, DEF_VALUE, 0, NULL, "",
              "particle mass: unit (m = 1) or volume (m = d^dim)", mass_words, 0, 0},
  [K_S_CRIT] = {"s_crit", T_DOUBLE, OFF(s_crit), 0, 1, MAX_EXCL, DEF_VALUE, 0, NULL, "d",
                "rupture distance of a capillary bridge; 0 = dry", NULL, 0, 0},
  [K_E_CB] = {"e_cb", T_DOUBLE, OFF(e_cb), 0, INF, MIN_EXCL | MAX_EXCL, DEF_COND, 0,
              "wet: one of 3", "m g d",
              "capillary bridge energy E_cb (wet: give one of e_cb, e_cb_mgs, f_b)", NULL,
              G_BRIDGE, 0},
  [K_E_CB_MGS] = {"e_cb_mgs", T_DOUBLE, OFF(f_b), 0, INF, MIN_EXCL | MAX_EXCL, DEF_COND, 0,
                  "wet: one of 3", "1",
                  "bridge energy as E_cb / (m g s_crit): the same number as f_b", NULL,
                  G_BRIDGE, 1},
  [K_F_B] = {"f_b", T_DOUBLE, OFF(f_b), 0, INF, MIN_EXCL | MAX_EXCL, DEF_COND, 0,
             "wet: one of 3", "m g",
             "bridge force F_B = E_cb / s_crit", NULL,
             G_BRIDGE, 2},
  [K_EPS] = {"eps", T_DOUBLE, OFF(eps), 0, 1, MIN_EXCL, DEF_VALUE, 1, NULL, "1",
             "coefficient of normal restitution between particles", NULL, 0, 0},
  [K_EPS_WALL] = {"eps_wall", T_DOUBLE, OFF(eps_wall), 0, 1, MIN_EXCL, DEF_VALUE, 1, NULL,
                  "1", "coefficient of restitution at the walls", NULL, 0, 0},
  [K_TC] = {"tc", T_DOUBLE, OFF(tc), 0, INF, MAX_EXCL, DEF_VALUE, 1e-5, NULL, "sqrt(d/g)",
            "TC model: a collision within tc of the previous one is elastic", NULL, 0, 0,
            ONLY_ED},
  [K_GRAZING] = {"grazing_angle", T_DOUBLE, OFF(grazing_angle), 0, 1, MAX_EXCL, DEF_VALUE, 0.05,
                 NULL, "rad", "a bonded pair reaching gap s_crit at a smaller angle leaves at "
                 "this one (a spinning taut bridge would bounce endlessly)", NULL, 0, 0,
                 ONLY_ED},
  [K_REST_SPEED] = {"rest_speed", T_DOUBLE, OFF(rest_speed), 0, INF, MAX_EXCL, DEF_VALUE, 0,
                    NULL, "sqrt(g d)", "a floor contact slower than this, while the floor's "
                    "acceleration exceeds -g, comes to rest: the particle rides the floor until "
                    "its acceleration falls to -g (docs/engines.md); 0 = off", NULL, 0, 0,
                    ONLY_ED},
  [K_SHELL] = {"shell", T_DOUBLE, OFF(shell), 0, 10, MAX_EXCL, DEF_VALUE, 0, NULL, "d",
               "neighbour lists: each particle lists the others within sigma_ij + s_crit + "
               "shell of it and is listed anew when it has moved shell/2 (docs/engines.md, "
               "\"Neighbour lists\"); 0 = the cells' stencils and cell crossings", NULL, 0, 0,
               ONLY_ED},
  [K_NOISE] = {"noise", T_DOUBLE, OFF(noise), 0, INF, MAX_EXCL, DEF_VALUE, 0, NULL,
               "d2 tau-3", "strength gamma_s of the random force (Eq. 2.12): every noise_dt each "
               "particle's velocity is kicked by a Gaussian of variance 2 noise noise_dt per axis, "
               "less the mean kick (docs/engines.md, \"Random force\"); 0 = none", NULL, 0, 0,
               ONLY_ED},
  [K_NOISE_DT] = {"noise_dt", T_DOUBLE, OFF(noise_dt), 0, INF, MIN_EXCL | MAX_EXCL, DEF_VALUE,
                  0.01, NULL, "sqrt(d/g)", "interval between the random force's kicks; keep it "
                  "well below the mean free time (white noise is its limit)", NULL, 0, 0,
                  ONLY_ED},
  [K_GAMMA] = {"gamma", T_DOUBLE, OFF(gamma), 0, INF, MIN_EXCL | MAX_EXCL, DEF_COND, 0,
               "required (shaker)", "1", "reduced acceleration Gamma = A w^2 / g (Eq. 2.19)",
               NULL, 0, 0},
  [K_ESTAR] = {"estar", T_DOUBLE, OFF(estar), 0, INF, MIN_EXCL | MAX_EXCL, DEF_COND, 0,
               "wet shaker: one of 2", "1",
               "shaking energy E* = m (A w)^2 / (2 E_cb) (Eq. 2.18)", NULL, G_ESTAR, 0},
  [K_ESTAR_D] = {"estar_d", T_DOUBLE, OFF(estar_d), 0, INF, MIN_EXCL | MAX_EXCL, DEF_COND,
                 0, "dry shaker: required", "1",
                 "shaking energy E*_d = (A w)^2 / (2 g d), for dry runs", NULL, G_ESTAR, 1},
  [K_TG_INIT] = {"tg_init", T_DOUBLE, OFF(tg_init), 0, INF, MAX_EXCL, DEF_COND, 0,
                 "20 (wet runs)", "E_cb", "initial granular temperature / E_cb", NULL, G_TG,
                 0},
  [K_TG_INIT_ABS] = {"tg_init_abs", T_DOUBLE, OFF(tg_init_abs), 0, INF, MAX_EXCL, DEF_COND,
                     0, "dry: required", "m g d",
                     "initial granular temperature (dry runs, or instead of tg_init)", NULL,
                     G_TG, 1},
  [K_INIT] = {"init", T_ENUM, OFF(init_packing), 0, 1, 0, DEF_VALUE, 0, NULL, "",
              "initial positions: a lattice filling the container, or a packed bed on the "
              "floor (hexagonal rows / stacked square layers)", init_words, G_INIT, 0},
  [K_INIT_FROM] = {"init_from", T_PATH, OFF(init_from), 0, 0, 0, DEF_VALUE, 0, NULL, "",
                   "run file whose last snapshot, with its bridges, starts this run (a scan "
                   "continued from the previous point; the scene file's init, tg_init and "
                   "tg_init_abs are then not used); empty = none", NULL, G_INIT, 1},
  [K_INIT_JITTER] = {"init_jitter", T_DOUBLE, OFF(init_jitter), 0, 1, 0, DEF_VALUE, 0, NULL, "1",
                     "with init_from: each velocity component times (1 + init_jitter x), x "
                     "Gaussian from the seed: seeds of one state that part after a few "
                     "collisions (Fig. 5.14's 20 relaxations); 0 = the state as recorded",
                     NULL, 0, 0},
  [K_SEED] = {"seed", T_SEED, OFF(seed), 0, 0, 0, DEF_REQUIRED, 0, NULL, "",
              "seed of the random number generator (unsigned 64-bit)", NULL, 0, 0},
  [K_T_END] = {"t_end", T_DOUBLE, OFF(t_end), 0, INF, MIN_EXCL | MAX_EXCL, DEF_REQUIRED, 0,
               NULL, "sqrt(d/g)", "simulated time", NULL, 0, 0},
  [K_DT_SERIES] = {"dt_series", T_DOUBLE, OFF(dt_series), 0, INF, MIN_EXCL | MAX_EXCL,
                   DEF_COND, 0, "t_end/1000", "sqrt(d/g)",
                   "sampling interval of the time series", NULL, 0, 0},
  [K_DT_SNAPSHOT] = {"dt_snapshot", T_DOUBLE, OFF(dt_snapshot), 0, INF, MAX_EXCL, DEF_VALUE,
                     0, NULL, "sqrt(d/g)", "interval of particle snapshots; 0 = final only",
                     NULL, 0, 0},
  [K_PROFILE_BINS] = {"profile_bins", T_INT, OFF(profile_bins), 0, 100000, 0, DEF_VALUE, 0,
                      NULL, "", "lateral bins along x for profiles; 0 = no profiles", NULL,
                      0, 0},
  [K_PROFILE_START] = {"profile_start", T_DOUBLE, OFF(profile_start), 0, INF, MAX_EXCL,
                       DEF_COND, 0, "t_end/2", "sqrt(d/g)",
                       "time from which profiles are averaged (<= t_end)", NULL, 0, 0},
  [K_DT_PROFILE] = {"dt_profile", T_DOUBLE, OFF(dt_profile), 0, INF, MIN_EXCL | MAX_EXCL,
                    DEF_COND, 0, "dt_series", "sqrt(d/g)", "sampling interval of profiles",
                    NULL, 0, 0},
  [K_MAP_BINS] = {"map_bins", T_INT, OFF(map_bins), 0, 100000, 0, DEF_VALUE, 0, NULL, "",
                  "cells along x of the lateral maps (number density, bridge density, T_g "
                  "averaged over windows of time, /observables/maps); 0 = no maps", NULL, 0, 0},
  [K_MAP_BINS_Y] = {"map_bins_y", T_INT, OFF(map_bins_y), 1, 100000, 0, DEF_COND, 0,
                    "round(map_bins ly / lx)", "", "cells along y of the lateral maps (3D)",
                    NULL, 0, 0},
  [K_MAP_START] = {"map_start", T_DOUBLE, OFF(map_start), 0, INF, MAX_EXCL, DEF_VALUE, 0, NULL,
                   "sqrt(d/g)", "time the first map window begins", NULL, 0, 0},
  [K_DT_MAP] = {"dt_map", T_DOUBLE, OFF(dt_map), 0, INF, MIN_EXCL | MAX_EXCL, DEF_COND, 0,
                "t_end/100", "sqrt(d/g)", "length of a map window (one frame per window; a "
                "window unfinished at t_end gives none)", NULL, 0, 0},
  [K_MAP_SAMPLES] = {"map_samples", T_INT, OFF(map_samples), 1, 1000000, 0, DEF_VALUE, 10,
                     NULL, "", "samples per map window, at equal intervals", NULL, 0, 0},
  [K_HEIGHT_BINS] = {"height_bins", T_INT, OFF(height_bins), 0, 1000000, 0, DEF_VALUE, 0, NULL,
                     "", "slabs across the container's reach, -A <= z < height + A, of the "
                     "height maps (packing fraction, number and bridge density, T_g averaged "
                     "over the lateral plane and windows of time, /observables/heights); 0 = none",
                     NULL, 0, 0},
  [K_HEIGHT_START] = {"height_start", T_DOUBLE, OFF(height_start), 0, INF, MAX_EXCL, DEF_VALUE, 0,
                      NULL, "sqrt(d/g)", "time the first height-map window begins", NULL, 0, 0},
  [K_DT_HEIGHT] = {"dt_height", T_DOUBLE, OFF(dt_height), 0, INF, MIN_EXCL | MAX_EXCL, DEF_COND,
                   0, "dt_series", "sqrt(d/g)", "length of a height-map window (one frame per "
                   "window)", NULL, 0, 0},
  [K_HEIGHT_SAMPLES] = {"height_samples", T_INT, OFF(height_samples), 1, 1000000, 0, DEF_VALUE, 1,
                        NULL, "", "samples per height-map window, at equal intervals", NULL, 0, 0},
  [K_DT_CHECKPOINT] = {"dt_checkpoint", T_DOUBLE, OFF(dt_checkpoint), 0, INF, MAX_EXCL,
                       DEF_COND, 0, "t_end/10", "sqrt(d/g)",
                       "checkpoint interval; 0 = no checkpoints", NULL, 0, 0},
  [K_STALL_RATE] = {"stall_rate", T_DOUBLE, OFF(stall_rate), 0, INF, MAX_EXCL, DEF_VALUE, 1000,
                    NULL, "sqrt(g/d)",
                    "stall watch: physical events per particle and unit time above which the "
                    "run warns (once) that it crawls (the thesis's systems: 1.4 to 150); 0 = "
                    "never", NULL, 0, 0, ONLY_ED, 1},
  [K_STALL_ACTION] = {"stall_action", T_ENUM, OFF(stall_action), 0, 1, 0, DEF_VALUE,
                      WG_STALL_WARN, NULL, "", "what the stall watch does: warn and go on, or stop the run "
                      "(error, no run file)", stall_words, 0, 0, ONLY_ED, 1},
  [K_SHEAR_FORCE] = {"shear_force", T_DOUBLE, OFF(shear_force), 0, INF, MAX_EXCL, DEF_VALUE, 0,
                     NULL, "m g", "F_smax of the cosine shear field F(x) = F_smax cos(2 pi x / "
                     "lx) (Eq. 2.20), along y (3D) or z (2D, periodic container only); 0 = "
                     "no field", NULL, 0, 0, ONLY_ED},
  [K_SHEAR_BINS] = {"shear_bins", T_INT, OFF(shear_bins), 3, 1000000, 0, DEF_COND, 0,
                    "round(lx/d)", "", "bins of the field across lx (each acts with the "
                    "value at its centre)", NULL, 0, 0, ONLY_ED},
  [K_SHEAR_ON] = {"shear_on", T_DOUBLE, OFF(shear_on), 0, INF, MAX_EXCL, DEF_VALUE, 0, NULL,
                  "sqrt(d/g)", "time the shear field is switched on", NULL, 0, 0, ONLY_ED},
  [K_SHEAR_OFF] = {"shear_off", T_DOUBLE, OFF(shear_off), 0, INF, MIN_EXCL, DEF_VALUE, INF,
                   NULL, "sqrt(d/g)", "time it is switched off (relaxation, Fig. 5.13); inf "
                   "= never", NULL, 0, 0, ONLY_ED},
  /* time-driven engine (engine = td) */
  [K_CONTACT] = {"contact", T_ENUM, OFF(contact_law), 0, 1, 0, DEF_VALUE, 0, NULL, "",
                 "normal contact law: linear spring-dashpot (restitution eps) or Hertz "
                 "(Eq. 2.7)", contact_words, 0, 0, ONLY_TD},
  [K_T_CONTACT] = {"t_contact", T_DOUBLE, OFF(t_contact), 0, INF, MIN_EXCL | MAX_EXCL,
                   DEF_VALUE, 0.005, NULL, "sqrt(d/g)",
                   "contact time of two unit masses: sets the stiffness (Hertz: at impact "
                   "speed 1 sqrt(g d))", NULL, 0, 0, ONLY_TD},
  [K_STEPS_PER_CONTACT] = {"steps_per_contact", T_DOUBLE, OFF(steps_per_contact), 4, INF,
                           MAX_EXCL, DEF_VALUE, 50, NULL, "1",
                           "time step dt = t_contact / steps_per_contact (bench_td)", NULL, 0,
                           0, ONLY_TD},
  [K_HERTZ_AD] = {"hertz_ad", T_DOUBLE, OFF(hertz_ad), 0, INF, MAX_EXCL, DEF_COND, 0,
                  "0 if eps = 1", "sqrt(d/g)",
                  "dissipative constant A_d of the Hertz law (Eq. 2.7)", NULL, 0, 0, ONLY_TD},
  [K_SKIN] = {"skin", T_DOUBLE, OFF(skin), 0, 10, MIN_EXCL, DEF_VALUE, 0.1, NULL, "d",
              "neighbour-list skin", NULL, 0, 0, ONLY_TD},
  [K_BRIDGE_LAW] = {"bridge_law", T_ENUM, OFF(bridge_law), 0, 1, 0, DEF_VALUE, 0, NULL, "",
                    "bridge force of the minimal capillary model: constant F_B, or Willett's "
                    "F_B / (1 + 1.05 s^ + 2.5 s^2) (Eq. 2.9)", bridge_law_words, 0, 0,
                    ONLY_TD},
  [K_BRIDGE_VOLUME] = {"bridge_volume", T_DOUBLE, OFF(bridge_volume), 0, 1, MIN_EXCL | MAX_EXCL,
                       DEF_COND, 0, "willett: required", "d^3",
                       "liquid volume V of a bridge: s^ = s sqrt(R/V), s_crit from Eq. 2.10 "
                       "(R = d/2)", NULL, 0, 0, ONLY_TD},
  [K_CONTACT_ANGLE] = {"contact_angle", T_DOUBLE, OFF(contact_angle), 0, 1.5707963267948966,
                       MAX_EXCL, DEF_VALUE, 0, NULL, "rad",
                       "contact angle theta_c of the liquid in Eq. 2.10", NULL, 0, 0, ONLY_TD},
  [K_WALL_BRIDGES] = {"wall_bridges", T_INT, OFF(wall_bridges), 0, 1, 0, DEF_VALUE, 0, NULL, "",
                      "1: particles form bridges with floor and lid too (wet walls; the force "
                      "balance of Eq. 4.15 holds the bed to the floor)", NULL, 0, 0, ONLY_TD},
  [K_INTEGRATOR] = {"integrator", T_ENUM, OFF(integrator), 0, 1, 0, DEF_VALUE, 0, NULL, "",
                    "velocity Verlet, or the thesis's fifth-order Gear predictor-corrector "
                    "(bench_td compares them)", integrator_words, 0, 0, ONLY_TD},
  [K_MU] = {"mu", T_DOUBLE, OFF(mu), 0, INF, MAX_EXCL, DEF_VALUE, 0, NULL, "1",
            "Coulomb friction coefficient between particles (tangential springs, rotation); "
            "0 = frictionless", NULL, 0, 0, ONLY_TD},
  [K_MU_WALL] = {"mu_wall", T_DOUBLE, OFF(mu_wall), 0, INF, MAX_EXCL, DEF_COND, 0, "mu", "1",
                 "Coulomb friction coefficient at floor and lid", NULL, 0, 0, ONLY_TD},
  [K_KT_RATIO] = {"kt_ratio", T_DOUBLE, OFF(kt_ratio), 0, INF, MIN_EXCL | MAX_EXCL, DEF_VALUE,
                  2.0 / 7.0, NULL, "1",
                  "tangential over normal stiffness at the same overlap, k_t / k_n", NULL, 0,
                  0, ONLY_TD},
  [K_GT_RATIO] = {"gt_ratio", T_DOUBLE, OFF(gt_ratio), 0, INF, MAX_EXCL, DEF_VALUE, 0, NULL, "1",
                  "tangential over normal dashpot coefficient, gamma_t / gamma_n", NULL, 0, 0,
                  ONLY_TD},
  [K_MU_ROLL] = {"mu_roll", T_DOUBLE, OFF(mu_roll), 0, INF, MAX_EXCL, DEF_VALUE, 0, NULL, "1",
                 "rolling resistance: a torque up to mu_roll F_n times the lever against "
                 "relative rolling (particles and walls); 0 = none", NULL, 0, 0, ONLY_TD},
};

_Static_assert(NKEYS <= sizeof(((wg_scene *)0)->key_line) / sizeof(int),
               "key_line[] too short for the key table");

typedef union {
  double d;
  long l;
  int i;
  unsigned long long u;
  const char *s; /* T_PATH: the text, copied by store() */
} key_value;

/* ------------------------------------------------------------------ field access */

static void *field(wg_scene *sc, int k) { return (char *)sc + keys[k].offset; }
static const void *cfield(const wg_scene *sc, int k) { return (const char *)sc + keys[k].offset; }

static void store(wg_scene *sc, int k, key_value v)
{
  switch (keys[k].type) {
  case T_DOUBLE: *(double *)field(sc, k) = v.d; break;
  case T_LONG: *(long *)field(sc, k) = v.l; break;
  case T_INT:
  case T_ENUM: *(int *)field(sc, k) = v.i; break;
  case T_SEED: *(unsigned long long *)field(sc, k) = v.u; break;
  case T_PATH: snprintf((char *)field(sc, k), sizeof sc->init_from, "%s", v.s ? v.s : ""); break;
  }
}

/* Back to the state of wg_scene_init(): fixed default, or 0 when the default is not fixed. */
static void reset_key(wg_scene *sc, int k)
{
  key_value v = {0};
  double d = keys[k].def == DEF_VALUE ? keys[k].dflt : 0.0;
  switch (keys[k].type) {
  case T_DOUBLE: v.d = d; break;
  case T_LONG: v.l = (long)d; break;
  case T_INT:
  case T_ENUM: v.i = (int)d; break;
  case T_SEED: v.u = 0; break;
  case T_PATH: v.s = ""; break;
  }
  store(sc, k, v);
  sc->key_line[k] = 0;
}

static int given(const wg_scene *sc, int k) { return sc->key_line[k] != 0; }

static int conflicts(int a, int b)
{
  return a != b && keys[a].group != G_NONE && keys[a].group == keys[b].group &&
         keys[a].alt != keys[b].alt;
}

static int find_key(const char *name)
{
  for (int k = 0; k < NKEYS; k++)
    if (strcmp(keys[k].name, name) == 0) return k;
  return -1;
}

/* ------------------------------------------------------------------ error messages */

static void append(char *buf, size_t size, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static void append(char *buf, size_t size, const char *fmt, ...)
{
  size_t len = strlen(buf);
  va_list ap;
  if (len + 1 >= size) return;
  va_start(ap, fmt);
  vsnprintf(buf + len, size - len, fmt, ap);
  va_end(ap);
}

static int has_file(const wg_scene *sc) { return strcmp(sc->source, "<none>") != 0; }

static int vreport(const char *loc, const char *what, const char *fmt, va_list ap)
{
  char msg[MSG_LEN];
  vsnprintf(msg, sizeof msg, fmt, ap);
  return wg_error(WG_EINVAL, WHERE, "%s: %s: %s", loc, what, msg);
}

/* Parse-time error: "loc: key 'name': message". */
static int parse_error(const char *loc, const char *key, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static int parse_error(const char *loc, const char *key, const char *fmt, ...)
{
  char what[LINE_MAX_LEN + 16];
  va_list ap;
  int rc;
  snprintf(what, sizeof what, "key '%.*s'", LINE_MAX_LEN, key);
  va_start(ap, fmt);
  rc = vreport(loc, what, fmt, ap);
  va_end(ap);
  return rc;
}

/* Order in which keys are named: by line in the file, then command line, then defaults. */
static int rank(const wg_scene *sc, int k)
{
  int line = sc->key_line[k];
  return line > 0 ? line : line == LINE_CMD ? INT_MAX - 1 : INT_MAX;
}

static void sort_by_line(const wg_scene *sc, int *idx, int n)
{
  for (int i = 1; i < n; i++)
    for (int j = i; j > 0 && rank(sc, idx[j - 1]) > rank(sc, idx[j]); j--) {
      int t = idx[j];
      idx[j] = idx[j - 1];
      idx[j - 1] = t;
    }
}

/* "f.ini:5", "f.ini:5 and :9", "f.ini:5, :9 and :12", "f.ini:5 and command line", "f.ini". */
static void locate(const wg_scene *sc, const int *idx, int n, char *loc, size_t size)
{
  int nfile = 0, cmd = 0, done = 0;
  for (int i = 0; i < n; i++) {
    nfile += sc->key_line[idx[i]] > 0;
    cmd |= sc->key_line[idx[i]] == LINE_CMD;
  }
  loc[0] = '\0';
  if (nfile == 0) {
    append(loc, size, "%s", cmd || !has_file(sc) ? "command line" : sc->source);
    return;
  }
  for (int i = 0; i < n; i++) {
    int line = sc->key_line[idx[i]];
    if (line <= 0) continue;
    done++;
    if (done == 1) append(loc, size, "%s:%d", sc->source, line);
    else append(loc, size, "%s:%d", done == nfile && !cmd ? " and " : ", ", line);
  }
  if (cmd) append(loc, size, " and command line");
}

/* Consistency error naming n keys (sorted by where they were set) and their lines. */
static int vkeys_error(const wg_scene *sc, const int *keys_in, int n, const char *fmt,
                       va_list ap)
{
  int idx[4];
  char loc[LOC_LEN], what[128] = "";
  n = n > 4 ? 4 : n;
  memcpy(idx, keys_in, (size_t)n * sizeof idx[0]);
  sort_by_line(sc, idx, n);
  locate(sc, idx, n, loc, sizeof loc);
  append(what, sizeof what, "key%s", n > 1 ? "s" : "");
  for (int i = 0; i < n; i++)
    append(what, sizeof what, "%s'%s'", i == 0 ? " " : i == n - 1 ? " and " : ", ",
           keys[idx[i]].name);
  return vreport(loc, what, fmt, ap);
}

static int key_error(const wg_scene *sc, int a, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static int key_error(const wg_scene *sc, int a, const char *fmt, ...)
{
  va_list ap;
  int rc;
  va_start(ap, fmt);
  rc = vkeys_error(sc, &a, 1, fmt, ap);
  va_end(ap);
  return rc;
}

static int pair_error(const wg_scene *sc, int a, int b, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static int pair_error(const wg_scene *sc, int a, int b, const char *fmt, ...)
{
  int idx[2] = {a, b};
  va_list ap;
  int rc;
  va_start(ap, fmt);
  rc = vkeys_error(sc, idx, 2, fmt, ap);
  va_end(ap);
  return rc;
}

static int list_error(const wg_scene *sc, const int *idx, int n, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static int list_error(const wg_scene *sc, const int *idx, int n, const char *fmt, ...)
{
  va_list ap;
  int rc;
  va_start(ap, fmt);
  rc = vkeys_error(sc, idx, n, fmt, ap);
  va_end(ap);
  return rc;
}

/* ------------------------------------------------------------------ value parsing */

static char *trim(char *s)
{
  char *end;
  while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n' || *s == '\v' || *s == '\f') s++;
  end = s + strlen(s);
  while (end > s && strchr(" \t\r\n\v\f", end[-1])) end--;
  *end = '\0';
  return s;
}

static void format_range(const key_desc *k, char *buf, size_t size)
{
  snprintf(buf, size, "%c%g, %g%c", k->excl & MIN_EXCL ? '(' : '[', k->min, k->max,
           k->excl & MAX_EXCL ? ')' : ']');
}

static void format_words(const char *const *words, char *buf, size_t size)
{
  buf[0] = '\0';
  for (int i = 0; words[i]; i++) append(buf, size, "%s%s", i ? ", " : "", words[i]);
}

static int check_range(const key_desc *k, double x, const char *text, const char *loc)
{
  int below = k->excl & MIN_EXCL ? x <= k->min : x < k->min;
  int above = k->excl & MAX_EXCL ? x >= k->max : x > k->max;
  char range[64];
  if (!below && !above) return WG_OK;
  format_range(k, range, sizeof range);
  return parse_error(loc, k->name, "value %s out of range %s", text, range);
}

static int parse_double(const key_desc *k, const char *text, const char *loc, key_value *v)
{
  char *end;
  errno = 0;
  v->d = strtod(text, &end);
  if (end == text || *end != '\0')
    return parse_error(loc, k->name, "value '%s' is not a number", text);
  if (!isfinite(v->d))
    return parse_error(loc, k->name, "value '%s' is not a finite number", text);
  return check_range(k, v->d, text, loc);
}

static int parse_integer(const key_desc *k, const char *text, const char *loc, key_value *v)
{
  char *end;
  long x;
  int rc;
  errno = 0;
  x = strtol(text, &end, 10);
  if (end == text || *end != '\0')
    return parse_error(loc, k->name, "value '%s' is not an integer", text);
  if (errno == ERANGE)
    return parse_error(loc, k->name, "value '%s' is too large for an integer", text);
  rc = check_range(k, (double)x, text, loc);
  if (k->type == T_INT) v->i = (int)x; /* the table's ranges lie within int */
  else v->l = x;
  return rc;
}

static int parse_seed(const key_desc *k, const char *text, const char *loc, key_value *v)
{
  char *end;
  errno = 0;
  v->u = strtoull(text, &end, 10);
  if (text[0] < '0' || text[0] > '9' || *end != '\0' || errno == ERANGE)
    return parse_error(loc, k->name, "value '%s' is not an unsigned 64-bit integer", text);
  return WG_OK;
}

static int parse_enum(const key_desc *k, const char *text, const char *loc, key_value *v)
{
  char words[128];
  for (int i = 0; k->words[i]; i++)
    if (strcmp(text, k->words[i]) == 0) {
      v->i = i;
      return WG_OK;
    }
  format_words(k->words, words, sizeof words);
  return parse_error(loc, k->name, "value '%s' is not one of: %s", text, words);
}

static int parse_value(int k, const char *text, const char *loc, key_value *v)
{
  if (text[0] == '\0') return parse_error(loc, keys[k].name, "missing value");
  switch (keys[k].type) {
  case T_DOUBLE: return parse_double(&keys[k], text, loc, v);
  case T_LONG:
  case T_INT: return parse_integer(&keys[k], text, loc, v);
  case T_ENUM: return parse_enum(&keys[k], text, loc, v);
  case T_SEED: return parse_seed(&keys[k], text, loc, v);
  case T_PATH:
    if (strlen(text) >= sizeof(((wg_scene *)0)->init_from))
      return parse_error(loc, keys[k].name, "path longer than %zu characters",
                         sizeof(((wg_scene *)0)->init_from) - 1);
    v->s = text;
    return WG_OK;
  }
  return WG_EINVAL;
}

/* The command line always wins: a file does not replace a key, or an alternative of it,
   that was set on the command line. */
static int owned_by_command_line(const wg_scene *sc, int k)
{
  for (int j = 0; j < NKEYS; j++)
    if (sc->key_line[j] == LINE_CMD && (j == k || conflicts(j, k))) return 1;
  return 0;
}

static void clear_file_alternatives(wg_scene *sc, int k)
{
  for (int j = 0; j < NKEYS; j++)
    if (sc->key_line[j] > 0 && conflicts(j, k)) reset_key(sc, j);
}

/* Parse and, where the precedence rules allow, store one value; line > 0 or LINE_CMD. */
static int assign(wg_scene *sc, int k, const char *text, int line, const char *loc)
{
  key_value v;
  int rc = parse_value(k, text, loc, &v);
  if (rc) return rc;
  if (line > 0 && owned_by_command_line(sc, k)) return WG_OK;
  if (line == LINE_CMD) clear_file_alternatives(sc, k);
  store(sc, k, v);
  sc->key_line[k] = line;
  return WG_OK;
}

static int edit_distance(const char *a, const char *b)
{
  enum { MAXLEN = 32 };
  int prev[MAXLEN + 1], cur[MAXLEN + 1];
  size_t la = strlen(a), lb = strlen(b);
  if (la > MAXLEN || lb > MAXLEN) return INT_MAX;
  for (size_t j = 0; j <= lb; j++) prev[j] = (int)j;
  for (size_t i = 1; i <= la; i++) {
    cur[0] = (int)i;
    for (size_t j = 1; j <= lb; j++) {
      int sub = prev[j - 1] + (a[i - 1] != b[j - 1]);
      int del = prev[j] + 1, ins = cur[j - 1] + 1;
      cur[j] = sub < del ? (sub < ins ? sub : ins) : (del < ins ? del : ins);
    }
    memcpy(prev, cur, sizeof prev);
  }
  return prev[lb];
}

static int unknown_key(const char *loc, const char *name)
{
  int best = -1, best_d = 3;
  for (int k = 0; k < NKEYS; k++) {
    int d = edit_distance(name, keys[k].name);
    if (d < best_d) best = k, best_d = d;
  }
  if (best >= 0)
    return parse_error(loc, name, "unknown key (did you mean '%s'?)", keys[best].name);
  return parse_error(loc, name, "unknown key (see --help for the list)");
}

/* ------------------------------------------------------------------ public: reading */

static void set_source(wg_scene *sc, const char *path)
{
  size_t len = strlen(path);
  if (len >= sizeof sc->source) len = sizeof sc->source - 1;
  memcpy(sc->source, path, len);
  sc->source[len] = '\0';
}

void wg_scene_init(wg_scene *sc)
{
  memset(sc, 0, sizeof *sc);
  for (int k = 0; k < NKEYS; k++) reset_key(sc, k);
  set_source(sc, "<none>");
}

/* One line of a file; seen[k] is the line where this file already set key k. */
static int parse_line(wg_scene *sc, char *text, int line, int *seen)
{
  char loc[LOC_LEN], *hash = strchr(text, '#'), *eq, *key;
  int k;
  if (hash) *hash = '\0';
  text = trim(text);
  if (text[0] == '\0') return WG_OK;
  snprintf(loc, sizeof loc, "%s:%d", sc->source, line);
  eq = strchr(text, '=');
  if (!eq) {
    text[strcspn(text, " \t")] = '\0';
    return parse_error(loc, text, "missing '=' (expected 'key = value')");
  }
  *eq = '\0';
  key = trim(text);
  if (key[0] == '\0') return parse_error(loc, "", "missing key before '='");
  k = find_key(key);
  if (k < 0) return unknown_key(loc, key);
  if (seen[k]) {
    snprintf(loc, sizeof loc, "%s:%d and :%d", sc->source, seen[k], line);
    return parse_error(loc, key, "given twice in one file");
  }
  seen[k] = line;
  return assign(sc, k, trim(eq + 1), line, loc);
}

static int read_lines(wg_scene *sc, FILE *f)
{
  char buf[LINE_MAX_LEN];
  int seen[NKEYS] = {0}, line = 0, rc = WG_OK;
  while (rc == WG_OK && fgets(buf, sizeof buf, f)) {
    line++;
    if (!strchr(buf, '\n') && !feof(f))
      return wg_error(WG_EINVAL, WHERE, "%s:%d: line longer than %d characters", sc->source,
                      line, LINE_MAX_LEN - 2);
    rc = parse_line(sc, buf, line, seen);
  }
  if (rc == WG_OK && ferror(f))
    return wg_error(WG_EIO, WHERE, "%s:%d: read error: %s", sc->source, line, strerror(errno));
  return rc;
}

int wg_scene_read_file(wg_scene *sc, const char *path)
{
  FILE *f = fopen(path, "r");
  int rc;
  if (!f) return wg_error(WG_EIO, WHERE, "%s: cannot open scene file: %s", path, strerror(errno));
  set_source(sc, path);
  rc = read_lines(sc, f);
  fclose(f);
  return rc;
}

int wg_scene_set_override(wg_scene *sc, const char *pair)
{
  char buf[LINE_MAX_LEN], *eq, *key;
  const char *loc = "command line";
  int k;
  if (!pair || strlen(pair) >= sizeof buf)
    return wg_error(WG_EINVAL, WHERE, "command line: override missing or too long");
  memcpy(buf, pair, strlen(pair) + 1);
  eq = strchr(buf, '=');
  if (!eq) return parse_error(loc, trim(buf), "missing '=' (expected key=value)");
  *eq = '\0';
  key = trim(buf);
  k = find_key(key);
  if (k < 0) return unknown_key(loc, key);
  if (*trim(eq + 1) == '\0') {
    reset_key(sc, k);
    return WG_OK;
  }
  return assign(sc, k, trim(eq + 1), LINE_CMD, loc);
}

/* ------------------------------------------------------------------ finish: derivations */

/* Mean of d^dim for diameters uniform in [1 - sqrt(3) sigma_p, 1 + sqrt(3) sigma_p]
   (Eq. 2.21): 1 + sigma_p^2 in 2D, 1 + 3 sigma_p^2 in 3D. */
static double mean_particle_volume(const wg_scene *sc)
{
  double s2 = sc->sigma_p * sc->sigma_p;
  return sc->dim == 2 ? pi / 4 * (1 + s2) : pi / 6 * (1 + 3 * s2);
}

static double largest_diameter(const wg_scene *sc) { return 1 + sqrt(3.0) * sc->sigma_p; }

static double box_volume(const wg_scene *sc)
{
  return sc->dim == 2 ? sc->lx * sc->height : sc->lx * sc->ly * sc->height;
}

/* Densest packing: hexagonal disks / fcc spheres, the exclusive upper bound of phi. */
static double phi_max(int dim) { return dim == 2 ? 0.9069 : 0.74; }

static int check_required(const wg_scene *sc)
{
  for (int k = 0; k < NKEYS; k++)
    if (keys[k].def == DEF_REQUIRED && !given(sc, k))
      return key_error(sc, k, "required key missing");
  return WG_OK;
}

static int box_from_phi(wg_scene *sc)
{
  static const int lengths[] = {K_LX, K_LY, K_HEIGHT};
  double len;
  if (sc->container != WG_CONTAINER_PERIODIC)
    return pair_error(sc, K_PHI, K_CONTAINER, "phi is only for container = periodic");
  for (int i = 0; i < 3; i++)
    if (given(sc, lengths[i]))
      return pair_error(sc, K_PHI, lengths[i], "give either phi or the box lengths");
  if (sc->phi >= phi_max(sc->dim))
    return pair_error(sc, K_PHI, K_DIM, "value %g out of range (0, %g) for dim = %d",
                      sc->phi, phi_max(sc->dim), sc->dim);
  len = (double)sc->n * mean_particle_volume(sc) / sc->phi;
  len = sc->dim == 2 ? sqrt(len) : cbrt(len);
  sc->lx = sc->height = len;
  sc->ly = sc->dim == 3 ? len : 0;
  return WG_OK;
}

static int box_from_lengths(const wg_scene *sc)
{
  const char *hint = sc->container == WG_CONTAINER_PERIODIC ? " (or give phi)" : "";
  if (!given(sc, K_LX)) return key_error(sc, K_LX, "required key missing%s", hint);
  if (sc->dim == 3 && !given(sc, K_LY))
    return pair_error(sc, K_LY, K_DIM, "required key missing in 3D%s", hint);
  if (!given(sc, K_HEIGHT)) return key_error(sc, K_HEIGHT, "required key missing%s", hint);
  return WG_OK;
}

static int check_box_lengths(const wg_scene *sc)
{
  static const int lengths[] = {K_LX, K_LY, K_HEIGHT};
  double dmax = largest_diameter(sc);
  for (int i = 0; i < 3; i++) {
    int k = given(sc, K_PHI) ? K_PHI : lengths[i];
    double len = *(const double *)cfield(sc, lengths[i]);
    if ((lengths[i] != K_LY || sc->dim == 3) && len <= dmax)
      return pair_error(sc, k, K_SIGMA_P,
                        "%s = %g must exceed the largest diameter 1 + sqrt(3) sigma_p = %g",
                        keys[lengths[i]].name, len, dmax);
  }
  return WG_OK;
}

static int resolve_box(wg_scene *sc)
{
  int rc;
  if (sc->dim == 2 && given(sc, K_LY))
    return pair_error(sc, K_LY, K_DIM, "ly is only for dim = 3");
  rc = given(sc, K_PHI) ? box_from_phi(sc) : box_from_lengths(sc);
  return rc ? rc : check_box_lengths(sc);
}

static int resolve_gravity(wg_scene *sc)
{
  if (!given(sc, K_GRAVITY)) sc->gravity = wg_scene_walled(sc) ? 1 : 0;
  if (sc->container == WG_CONTAINER_SHAKER && sc->gravity == 0)
    return pair_error(sc, K_GRAVITY, K_CONTAINER,
                      "a shaker needs gravity > 0 (Gamma = A w^2/g is undefined for g = 0)");
  return WG_OK;
}

/* Resting contacts need a floor to rest on, and are not combined with the shear field. */
static int check_rest(const wg_scene *sc)
{
  if (sc->rest_speed == 0) return WG_OK;
  if (sc->container != WG_CONTAINER_SHAKER)
    return pair_error(sc, K_REST_SPEED, K_CONTAINER, "resting on the floor needs container = shaker");
  if (sc->shear_force != 0)
    return pair_error(sc, K_REST_SPEED, K_SHEAR_FORCE, "resting on the floor is not combined with the shear field");
  return WG_OK;
}

/* Neighbour lists follow free flights under gravity; the shear field's and the resting
   grains' paths keep the cells. */
static int check_shell(const wg_scene *sc)
{
  if (sc->shell == 0) return WG_OK;
  if (sc->shear_force != 0)
    return pair_error(sc, K_SHELL, K_SHEAR_FORCE, "neighbour lists are not combined with the shear field");
  if (sc->rest_speed != 0)
    return pair_error(sc, K_SHELL, K_REST_SPEED, "neighbour lists are not combined with resting on the floor");
  return WG_OK;
}

/* The random force kicks free particles: not the shear field's or the floor's riders. */
static int check_noise(const wg_scene *sc)
{
  if (sc->noise == 0) return WG_OK;
  if (sc->shear_force != 0)
    return pair_error(sc, K_NOISE, K_SHEAR_FORCE, "the random force is not combined with the shear field");
  if (sc->rest_speed != 0)
    return pair_error(sc, K_NOISE, K_REST_SPEED, "the random force is not combined with resting on the floor");
  return WG_OK;
}

/* The shear field: its bins (default one per diameter) and its times; in 2D it acts along
   the second axis, which must then be periodic (no walls to meet a force along them). */
static int resolve_shear(wg_scene *sc)
{
  if (sc->shear_force == 0) return WG_OK;
  if (sc->dim == 2 && sc->container != WG_CONTAINER_PERIODIC)
    return pair_error(sc, K_SHEAR_FORCE, K_CONTAINER, "in 2D the field acts along z, between "
                      "the walls of a shaker: use container = periodic (or dim = 3, where it "
                      "acts along y)");
  if (!given(sc, K_SHEAR_BINS)) {
    double b = round(sc->lx);
    sc->shear_bins = b < 3 ? 3 : b > 1000000 ? 1000000 : (int)b;
  }
  if (!(sc->shear_off > sc->shear_on))
    return pair_error(sc, K_SHEAR_OFF, K_SHEAR_ON, "the field must be switched off after it "
                      "is switched on (%g <= %g)", sc->shear_off, sc->shear_on);
  return WG_OK;
}

/* Keys of the other engine are refused; the time-driven engine's derived values:
   the Willett rupture distance (Eq. 2.10, before resolve_bridge), the time step and Hertz's K. */
static int resolve_engine(wg_scene *sc)
{
  int td = sc->engine == WG_ENGINE_TD;
  for (int k = 0; k < NKEYS; k++)
    if (keys[k].only && given(sc, k) && keys[k].only != (td ? ONLY_TD : ONLY_ED))
      return pair_error(sc, k, K_ENGINE, "applies only to engine = %s", td ? "ed" : "td");
  if (!td) return WG_OK;
  sc->dt = sc->t_contact / sc->steps_per_contact;
  sc->hertz_k = 0;
  if (sc->contact_law == 1) { /* Hertz */
    if (given(sc, K_EPS) || given(sc, K_EPS_WALL))
      return pair_error(sc, given(sc, K_EPS) ? K_EPS : K_EPS_WALL, K_CONTACT,
                        "the Hertz law dissipates through hertz_ad (Eq. 2.7), not a fixed "
                        "restitution");
    /* elastic Hertz collision F = k xi^3/2 of two unit masses (m_eff = 1/2) at speed v = 1:
       xi_max = (5 m_eff v^2 / 4k)^2/5 and t_c = c xi_max / v, c = 2 int_0^1 du/sqrt(1-u^5/2)
       = (4/5) B(2/5, 1/2) */
    double c = 0.8 * tgamma(0.4) * tgamma(0.5) / tgamma(0.9), m_eff = 0.5, r_eff = 0.25;
    double xi_max = sc->t_contact / c;
    sc->hertz_k = 5 * m_eff / (4 * pow(xi_max, 2.5)) / sqrt(r_eff);
  } else if (given(sc, K_HERTZ_AD)) {
    return pair_error(sc, K_HERTZ_AD, K_CONTACT, "only for contact = hertz");
  }
  if (sc->bridge_law == 1) { /* Willett */
    if (given(sc, K_S_CRIT))
      return pair_error(sc, K_S_CRIT, K_BRIDGE_LAW,
                        "with the Willett law s_crit follows from bridge_volume (Eq. 2.10)");
    if (given(sc, K_E_CB_MGS))
      return pair_error(sc, K_E_CB_MGS, K_BRIDGE_LAW,
                        "with the Willett law give f_b (force at contact) or e_cb");
    if (!given(sc, K_BRIDGE_VOLUME))
      return pair_error(sc, K_BRIDGE_VOLUME, K_BRIDGE_LAW, "required key missing");
    double r = 0.5, v = sc->bridge_volume / (r * r * r);
    sc->s_crit = r * (1 + sc->contact_angle / 2) * (cbrt(v) + 0.1 * cbrt(v * v)); /* Eq. 2.10 */
  } else if (given(sc, K_BRIDGE_VOLUME) || given(sc, K_CONTACT_ANGLE)) {
    return pair_error(sc, given(sc, K_BRIDGE_VOLUME) ? K_BRIDGE_VOLUME : K_CONTACT_ANGLE,
                      K_BRIDGE_LAW, "only for bridge_law = willett");
  }
  if (sc->wall_bridges && sc->s_crit == 0)
    return pair_error(sc, K_WALL_BRIDGES, K_S_CRIT, "wall bridges need a wet scene (s_crit > 0)");
  if (!given(sc, K_MU_WALL)) sc->mu_wall = sc->mu;
  if (sc->mu_roll > 0 && sc->mu == 0 && sc->mu_wall == 0)
    return pair_error(sc, K_MU_ROLL, K_MU, "rolling resistance needs friction (mu or mu_wall > 0)");
  if (sc->integrator == 1 && sc->mu_roll > 0) /* the capped torque chatters under the corrector */
    return pair_error(sc, K_MU_ROLL, K_INTEGRATOR, "rolling resistance needs integrator = verlet");
  return WG_OK;
}

/* Mean of the Willett profile 1 / (1 + 1.05 x + 2.5 x^2) (Eq. 2.9) over 0 <= x <= x_c:
   the rupture energy is F_B s_crit times this. */
double wg_willett_mean(double x_c)
{
  const double q = sqrt(4 * 2.5 - 1.05 * 1.05);
  if (x_c <= 0) return 1;
  return 2 / q * (atan((5 * x_c + 1.05) / q) - atan(1.05 / q)) / x_c;
}

static int resolve_bridge(wg_scene *sc)
{
  static const int forms[] = {K_E_CB, K_E_CB_MGS, K_F_B};
  int set[3] = {0}, n = 0;
  for (int i = 0; i < 3; i++)
    if (given(sc, forms[i])) set[n++] = forms[i];
  if (n >= 2) return pair_error(sc, set[0], set[1], "give only one of e_cb, e_cb_mgs, f_b");
  if (n == 1 && sc->s_crit == 0)
    return pair_error(sc, set[0], K_S_CRIT,
                      "a bridge energy needs s_crit > 0 (s_crit = 0 is a dry run)");
  if (n == 0 && sc->s_crit > 0)
    return key_error(sc, K_S_CRIT, "a wet run (s_crit > 0) needs one of e_cb, e_cb_mgs, f_b");
  double w = 1; /* E_cb = F_B s_crit w */
  if (sc->engine == WG_ENGINE_TD && sc->bridge_law == 1)
    w = wg_willett_mean(sc->s_crit * sqrt(0.5 / sc->bridge_volume));
  if (n == 0) sc->e_cb = sc->f_b = 0;
  else if (set[0] == K_E_CB) sc->f_b = sc->e_cb / (sc->s_crit * w);
  else sc->e_cb = sc->f_b * sc->s_crit * w;
  return WG_OK;
}

/* A box's walls are at rest: the time-driven engine has only the shaker's. */
static int check_box(const wg_scene *sc)
{
  if (sc->container == WG_CONTAINER_BOX && sc->engine == WG_ENGINE_TD)
    return pair_error(sc, K_CONTAINER, K_ENGINE, "container = box is event-driven only");
  return WG_OK;
}

static int periodic_driving(wg_scene *sc)
{
  static const int shaker_only[] = {K_GAMMA, K_ESTAR, K_ESTAR_D};
  for (int i = 0; i < 3; i++)
    if (given(sc, shaker_only[i]))
      return pair_error(sc, shaker_only[i], K_CONTAINER, "only for container = shaker");
  sc->amplitude = sc->omega = sc->t_driv = 0;
  return WG_OK;
}

/* Which of estar / estar_d sets the driving velocity A w; -1 after reporting an error. */
static int choose_estar(const wg_scene *sc, int *which)
{
  int wet = sc->e_cb > 0;
  *which = given(sc, K_ESTAR) ? K_ESTAR : K_ESTAR_D;
  if (given(sc, K_ESTAR) && given(sc, K_ESTAR_D))
    return pair_error(sc, K_ESTAR, K_ESTAR_D, "give only one of estar, estar_d");
  if (!wet && given(sc, K_ESTAR))
    return pair_error(sc, K_ESTAR, K_S_CRIT,
                      "estar is in units of E_cb, which is 0 in a dry run; use estar_d");
  if (!given(sc, *which))
    return key_error(sc, *which, wet ? "a wet shaker needs one of estar, estar_d"
                                     : "required key missing for a dry shaker");
  return WG_OK;
}

static int shaker_driving(wg_scene *sc)
{
  double g = sc->gravity, v;
  int which, rc;
  if (!given(sc, K_GAMMA)) return key_error(sc, K_GAMMA, "required key missing for a shaker");
  if ((rc = choose_estar(sc, &which))) return rc;
  v = which == K_ESTAR ? sqrt(2 * sc->estar * sc->e_cb) : sqrt(2 * g * sc->estar_d);
  sc->omega = sc->gamma * g / v;
  sc->amplitude = v / sc->omega;
  sc->t_driv = 2 * pi / sc->omega;
  if (which == K_ESTAR) sc->estar_d = v * v / (2 * g);
  else sc->estar = sc->e_cb > 0 ? v * v / (2 * sc->e_cb) : 0;
  if (sc->amplitude >= sc->height / 2) {
    int idx[3] = {K_GAMMA, which, K_HEIGHT};
    return list_error(sc, idx, 3, "amplitude A = %g must be < height/2 = %g", sc->amplitude,
                      sc->height / 2);
  }
  return WG_OK;
}

static int resolve_driving(wg_scene *sc)
{
  return sc->container == WG_CONTAINER_SHAKER ? shaker_driving(sc) : periodic_driving(sc);
}

static int resolve_temperature(wg_scene *sc)
{
  if (sc->init_from[0]) { /* an initial temperature in the scene file is not used */
    int k = sc->key_line[K_TG_INIT] == LINE_CMD       ? K_TG_INIT
            : sc->key_line[K_TG_INIT_ABS] == LINE_CMD ? K_TG_INIT_ABS : -1;
    if (k >= 0)
      return pair_error(sc, k, K_INIT_FROM, "the velocities come from the run file");
    sc->tg_init = sc->tg_init_abs = 0;
    return WG_OK;
  }
  if (given(sc, K_TG_INIT) && given(sc, K_TG_INIT_ABS))
    return pair_error(sc, K_TG_INIT, K_TG_INIT_ABS, "give only one of tg_init, tg_init_abs");
  if (sc->e_cb == 0) {
    if (given(sc, K_TG_INIT))
      return pair_error(sc, K_TG_INIT, K_S_CRIT, "tg_init is in units of E_cb, which is 0 "
                                                 "in a dry run; use tg_init_abs");
    if (!given(sc, K_TG_INIT_ABS))
      return key_error(sc, K_TG_INIT_ABS, "required key missing for a dry run (s_crit = 0)");
    sc->tg_init = 0;
    return WG_OK;
  }
  if (given(sc, K_TG_INIT_ABS)) {
    sc->tg_init = sc->tg_init_abs / sc->e_cb;
    return WG_OK;
  }
  if (!given(sc, K_TG_INIT)) sc->tg_init = 20;
  sc->tg_init_abs = sc->tg_init * sc->e_cb;
  return WG_OK;
}

static int check_fill(const wg_scene *sc)
{
  if (sc->init_packing && !wg_scene_walled(sc))
    return pair_error(sc, K_INIT, K_CONTAINER, "a packed bed needs a floor: container = shaker or box");
  if (sc->init_from[0] && given(sc, K_INIT))
    return pair_error(sc, K_INIT, K_INIT_FROM, "give either init or init_from");
  if (!sc->init_from[0] && sc->init_jitter > 0)
    return pair_error(sc, K_INIT_JITTER, K_INIT_FROM, "a jitter of the velocities needs init_from");
  return WG_OK;
}

static int resolve_output_times(wg_scene *sc)
{
  if (!given(sc, K_DT_SERIES)) sc->dt_series = sc->t_end / 1000;
  if (!given(sc, K_PROFILE_START)) sc->profile_start = sc->t_end / 2;
  if (!given(sc, K_DT_PROFILE)) sc->dt_profile = sc->dt_series;
  if (!given(sc, K_DT_CHECKPOINT)) sc->dt_checkpoint = sc->t_end / 10;
  if (!given(sc, K_DT_MAP)) sc->dt_map = sc->t_end / 100;
  if (!given(sc, K_DT_HEIGHT)) sc->dt_height = sc->dt_series;
  if (sc->height_start > sc->t_end)
    return pair_error(sc, K_HEIGHT_START, K_T_END, "value %g out of range [0, t_end = %g]",
                      sc->height_start, sc->t_end);
  if (sc->dim != 3) {
    if (given(sc, K_MAP_BINS_Y) && sc->map_bins_y != 1)
      return pair_error(sc, K_MAP_BINS_Y, K_DIM, "a 2D map is one row of cells along x: "
                        "map_bins_y must be 1 (or not given)");
    sc->map_bins_y = 1;
  } else if (!given(sc, K_MAP_BINS_Y)) {
    sc->map_bins_y = (int)lround(sc->map_bins * sc->ly / sc->lx);
    if (sc->map_bins_y < 1) sc->map_bins_y = 1;
  }
  if (sc->map_start > sc->t_end)
    return pair_error(sc, K_MAP_START, K_T_END, "value %g out of range [0, t_end = %g]",
                      sc->map_start, sc->t_end);
  if (sc->profile_start > sc->t_end)
    return pair_error(sc, K_PROFILE_START, K_T_END, "value %g out of range [0, t_end = %g]",
                      sc->profile_start, sc->t_end);
  return WG_OK;
}

/* A shaker is filled to at most 90 % (2D) or the fcc density 74 % (3D); a periodic box
   given by its lengths to below the densest packing, as for phi. */
static int check_packing(const wg_scene *sc)
{
  double fill, limit;
  int idx[4] = {K_N, K_LX, K_HEIGHT, K_LY};
  if (given(sc, K_PHI)) return WG_OK;
  fill = (double)sc->n * mean_particle_volume(sc) / box_volume(sc);
  limit = wg_scene_walled(sc) && sc->dim == 2 ? 0.9 : phi_max(sc->dim);
  if (fill < limit) return WG_OK;
  return list_error(sc, idx, sc->dim == 3 ? 4 : 3,
                    "%ld particles fill %.1f %% of the box; the limit is %g %%",
                    sc->n, 100 * fill, 100 * limit);
}

int wg_scene_finish(wg_scene *sc)
{
  int rc;
  if ((rc = check_required(sc)) || (rc = resolve_box(sc)) || (rc = resolve_gravity(sc)) ||
      (rc = resolve_engine(sc)) || (rc = resolve_bridge(sc)) || (rc = resolve_driving(sc)) ||
      (rc = resolve_temperature(sc)) || (rc = check_fill(sc)) || (rc = resolve_output_times(sc)) ||
      (rc = check_packing(sc)) || (rc = resolve_shear(sc)) || (rc = check_rest(sc)) || (rc = check_shell(sc)) || (rc = check_noise(sc)) ||
      (rc = check_box(sc)))
    return rc;
  return WG_OK;
}

/* ------------------------------------------------------------------ help and visit */

static void format_value(const wg_scene *sc, int k, char *buf, size_t size)
{
  const void *p = cfield(sc, k);
  switch (keys[k].type) {
  case T_DOUBLE: snprintf(buf, size, "%.17g", *(const double *)p); break;
  case T_LONG: snprintf(buf, size, "%ld", *(const long *)p); break;
  case T_INT: snprintf(buf, size, "%d", *(const int *)p); break;
  case T_ENUM: snprintf(buf, size, "%s", keys[k].words[*(const int *)p]); break;
  case T_SEED: snprintf(buf, size, "%llu", *(const unsigned long long *)p); break;
  case T_PATH: snprintf(buf, size, "%s", (const char *)p); break;
  }
}

static void format_default(int k, char *buf, size_t size)
{
  const key_desc *d = &keys[k];
  if (d->def == DEF_REQUIRED) snprintf(buf, size, "required");
  else if (d->def == DEF_COND) snprintf(buf, size, "%s", d->dflt_text);
  else if (d->type == T_ENUM) snprintf(buf, size, "%s", d->words[(int)d->dflt]);
  else snprintf(buf, size, "%g", d->dflt);
}

static void format_allowed(int k, char *buf, size_t size)
{
  if (keys[k].type == T_ENUM) format_words(keys[k].words, buf, size);
  else if (keys[k].type == T_SEED) snprintf(buf, size, "[0, 2^64)");
  else if (keys[k].type == T_PATH) snprintf(buf, size, "a file");
  else format_range(&keys[k], buf, size);
}

int wg_scene_key_is_advisory(const char *name)
{
  int k = find_key(name);
  return k >= 0 && keys[k].advisory;
}

void wg_scene_print_keys(FILE *out)
{
  char dflt[64], allowed[64];
  fprintf(out, "Scene keys (file: 'key = value' per line, '#' comments; command line: "
               "key=value overrides the file):\n");
  fprintf(out, "  %-14s %-24s %-10s %-18s %s\n", "key", "default", "unit", "allowed",
          "description");
  for (int k = 0; k < NKEYS; k++) {
    format_default(k, dflt, sizeof dflt);
    format_allowed(k, allowed, sizeof allowed);
    fprintf(out, "  %-14s %-24s %-10s %-18s %s%s\n", keys[k].name, dflt,
            keys[k].unit[0] ? keys[k].unit : "1", allowed,
            keys[k].only == ONLY_ED ? "[ed] " : keys[k].only == ONLY_TD ? "[td] " : "",
            keys[k].desc);
  }
}

/* 1 if the line "key = value" (len characters) names a key with a fixed default at it */
static int line_at_default(const char *line, size_t len)
{
  const char *eq = memchr(line, '=', len);
  if (!eq || eq - line < 2 || eq[-1] != ' ' || (size_t)(eq - line) + 2 > len) return 0;
  size_t klen = (size_t)(eq - line) - 1;
  for (int k = 0; k < NKEYS; k++) {
    if (strlen(keys[k].name) != klen || strncmp(keys[k].name, line, klen)) continue;
    if (keys[k].def != DEF_VALUE) return 0;
    wg_scene dflt;
    memset(&dflt, 0, sizeof dflt);
    void *p = (char *)&dflt + keys[k].offset;
    switch (keys[k].type) {
    case T_DOUBLE: *(double *)p = keys[k].dflt; break;
    case T_LONG: *(long *)p = (long)keys[k].dflt; break;
    case T_INT: case T_ENUM: *(int *)p = (int)keys[k].dflt; break;
    case T_SEED: *(unsigned long long *)p = (unsigned long long)keys[k].dflt; break;
    case T_PATH: break;
    }
    char buf[1100];
    format_value(&dflt, k, buf, sizeof buf);
    const char *value = eq + 2;
    return strlen(buf) == len - (size_t)(value - line) && !strncmp(buf, value, strlen(buf));
  }
  return 0;
}

/* 1 if every line of a is in b or at its default */
static int lines_covered(const char *a, const char *b)
{
  for (const char *l = a; *l;) {
    const char *e = strchr(l, '\n');
    size_t len = e ? (size_t)(e - l) : strlen(l);
    int found = 0;
    for (const char *m = b; *m && !found;) {
      const char *f = strchr(m, '\n');
      size_t mlen = f ? (size_t)(f - m) : strlen(m);
      found = mlen == len && !strncmp(l, m, len);
      m = f ? f + 1 : m + mlen;
    }
    if (len && !found && !line_at_default(l, len)) return 0;
    l = e ? e + 1 : l + len;
  }
  return 1;
}

int wg_scene_same_configuration(const char *a, const char *b)
{
  return lines_covered(a, b) && lines_covered(b, a);
}

wg_key_kind wg_scene_key_kind(const char *key)
{
  for (int k = 0; k < NKEYS; k++) {
    if (strcmp(keys[k].name, key) != 0) continue;
    switch (keys[k].type) {
    case T_DOUBLE: return WG_KEY_REAL;
    case T_LONG:
    case T_INT: return WG_KEY_INT;
    case T_SEED: return WG_KEY_UINT;
    case T_ENUM:
    case T_PATH: return WG_KEY_WORD;
    }
  }
  return WG_KEY_REAL; /* the derived values (amplitude, omega, ...) */
}

int wg_scene_visit(const wg_scene *sc, wg_scene_visit_fn fn, void *user)
{
  const struct { const char *name; double value; const char *unit, *desc; } derived[] = {
    {"amplitude", sc->amplitude, "d", "derived: shaking amplitude A (0 if not a shaker)"},
    {"omega", sc->omega, "sqrt(g/d)", "derived: angular frequency w of the shaker"},
    {"t_driv", sc->t_driv, "sqrt(d/g)", "derived: driving period 2 pi / w"},
    /* time-driven only */
    {"dt", sc->dt, "sqrt(d/g)", "derived: time step t_contact / steps_per_contact"},
    {"hertz_k", sc->hertz_k, "m g / d^2", "derived: Hertz K of Eq. 2.7 for contact time t_contact at speed 1"},
  };
  char buf[1100];
  int rc, only = sc->engine == WG_ENGINE_TD ? ONLY_TD : ONLY_ED;
  for (int k = 0; k < NKEYS; k++) {
    if (keys[k].only && keys[k].only != only) continue; /* the other engine's keys */
    /* the shear field's keys only with a field: a scene without one gives the parameters
       (and checkpoint fingerprint) it gave before the field existed */
    if (k >= K_SHEAR_FORCE && k <= K_SHEAR_OFF && sc->shear_force == 0) continue;
    /* and for the neighbour lists and the random force */
    if (k == K_SHELL && sc->shell == 0) continue;
    if ((k == K_NOISE || k == K_NOISE_DT) && sc->noise == 0) continue;
    /* the same for the height maps */
    if (k >= K_HEIGHT_BINS && k <= K_HEIGHT_SAMPLES && sc->height_bins == 0) continue;
    format_value(sc, k, buf, sizeof buf);
    if ((rc = fn(user, keys[k].name, buf, keys[k].unit[0] ? keys[k].unit : "1",
                 keys[k].desc)))
      return rc;
  }
  size_t nd = sizeof derived / sizeof derived[0];
  for (size_t i = 0; i < nd; i++) {
    if (i >= 3 && only != ONLY_TD) break;
    if (i == 4 && sc->contact_law != 1) continue;
    snprintf(buf, sizeof buf, "%.17g", derived[i].value);
    if ((rc = fn(user, derived[i].name, buf, derived[i].unit, derived[i].desc))) return rc;
  }
  return WG_OK;
}
