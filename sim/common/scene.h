/* Scene files: plain "key = value" text, '#' starts a comment, one key per line.
   Command-line "key=value" pairs override the file.  Every key is declared once in a
   table (scene.c) with its type, range, default, unit and description; the same table
   drives parsing, range checks, --help output and the /parameters group of a run file. */
#ifndef WG_SCENE_H
#define WG_SCENE_H

#include <stdio.h>
#include "wg.h"

typedef enum { WG_ENGINE_ED = 0, WG_ENGINE_TD = 1 } wg_engine_kind;
/* shaker: floor and lid moving as A sin(w t); periodic: every axis periodic; box: floor and lid
   at rest (the sheared systems of Ch. 7-8) */
typedef enum { WG_CONTAINER_SHAKER = 0, WG_CONTAINER_PERIODIC = 1, WG_CONTAINER_BOX = 2 } wg_container_kind;
typedef enum { WG_STALL_WARN = 0, WG_STALL_STOP = 1 } wg_stall_action;

/* All lengths in mean diameters d, masses in m, times in sqrt(d/g), energies in m g d. */
typedef struct wg_scene {
  /* --- given keys (see the table in scene.c for defaults) --- */
  int engine;          /* engine = ed | td */
  int dim;             /* dim = 2 | 3 */
  long n;              /* n: number of particles, >= 1 */
  double lx;           /* lx: lateral box length along x [d] */
  double ly;           /* ly: lateral box length along y [d] (3D only) */
  double height;       /* height: bottom-to-lid distance H (shaker) or box length along z (periodic) [d] */
  double phi;          /* phi: packing fraction; periodic container only, alternative to lx/ly/height (0 = not given) */
  int container;       /* container = shaker | periodic */
  double gravity;      /* gravity: g in units of g, 0 or 1 (default 1 for shaker, 0 for periodic) */
  double sigma_p;      /* sigma_p: polydispersity, Eq. 2.22, 0 <= sigma_p < 1/sqrt(3) (default 0.06) */
  int mass_scaling;    /* mass = unit | volume: m = 1 for all, or m = d^dim (default unit) */
  double s_crit;       /* s_crit: rupture gap [d]; 0 = dry (default 0) */
  double e_cb;         /* capillary bridge energy [m g d]; from exactly one of e_cb, e_cb_mgs, f_b */
  double eps;          /* eps: particle restitution, 0 < eps <= 1 (default 1) */
  double eps_wall;     /* eps_wall: wall restitution, 0 < eps_wall <= 1 (default 1) */
  double tc;           /* tc: TC-model time [sqrt(d/g)] (default 1e-5) */
  double grazing_angle; /* grazing_angle: least angle of a bridge reflection [rad] (0.05) */
  double rest_speed;   /* rest_speed: floor contacts slower than this come to rest [sqrt(g d)]; 0 = off */
  double shell;        /* shell: neighbour-list shell [d]; 0 = cells only */
  double noise;        /* noise: random-force strength gamma_s, Eq. 2.12 [d^2 tau^-3]; 0 = none */
  double noise_dt;     /* noise_dt: interval between its kicks [sqrt(d/g)] (0.01) */
  double gamma;        /* gamma: Gamma = A w^2 / g, Eq. 2.19 (shaker only) */
  double estar;        /* estar: E* = m (A w)^2 / (2 E_cb), Eq. 2.18 (wet shaker) */
  double estar_d;      /* estar_d: E*_d = (A w)^2 / (2 g d) (dry shaker) */
  double tg_init;      /* tg_init: initial T_g / E_cb (wet runs; default 20) */
  double tg_init_abs;  /* tg_init_abs: initial T_g [m g d] (dry runs, or instead of tg_init) */
  int init_packing;    /* init = lattice | packed: sites fill the container, or a packed bed */
  char init_from[1024];/* init_from: run file whose last snapshot (and its bridges) starts this run */
  double init_jitter;  /* init_jitter: relative Gaussian noise on init_from's velocities (0: none) */
  unsigned long long seed; /* seed: RNG seed, required */
  double t_end;        /* t_end: simulated time [sqrt(d/g)], required */
  double dt_series;    /* dt_series: sampling interval of time series (default t_end/1000) */
  double dt_snapshot;  /* dt_snapshot: interval of particle snapshots, 0 = final only (default 0) */
  int profile_bins;    /* profile_bins: lateral bins along x for profiles, 0 = none (default 0) */
  double profile_start;/* profile_start: time from which profiles are averaged (default t_end/2) */
  double dt_profile;   /* dt_profile: sampling interval of profiles (default dt_series) */
  int map_bins;        /* map_bins: cells of the lateral maps along x, 0 = no maps (default 0) */
  int map_bins_y;      /* map_bins_y: cells along y (3D; default: square cells) */
  double map_start;    /* map_start: time the first map window begins (default 0) */
  double dt_map;       /* dt_map: length of a map window (default t_end/100) */
  int map_samples;     /* map_samples: samples per map window (default 10) */
  int height_bins;     /* height_bins: slabs of the height maps across -A ... height + A, 0 = none */
  double height_start; /* height_start: time the first height-map window begins (default 0) */
  double dt_height;    /* dt_height: length of a height-map window (default dt_series) */
  int height_samples;  /* height_samples: samples per height-map window (default 1) */
  double dt_checkpoint;/* dt_checkpoint: checkpoint interval, 0 = none (default t_end/10) */
  double stall_rate;   /* stall_rate: physical events per particle and unit time above which an
                          event-driven run warns that it crawls; 0 = never (default 1000) */
  int stall_action;    /* stall_action = warn | stop (WG_STALL_WARN / WG_STALL_STOP) */
  double shear_force;  /* shear_force: F_smax of the cosine shear field, Eq. 2.20 [m g]; 0 = none */
  int shear_bins;      /* shear_bins: bins of the field across lx (default round(lx / d)) */
  double shear_on;     /* shear_on: time the field is switched on (0) */
  double shear_off;    /* shear_off: time it is switched off (inf) */

  /* time-driven engine (engine = td) */
  int contact_law;     /* contact = linear | hertz (WG_CONTACT_LINEAR / _HERTZ, contact.h) */
  double t_contact;    /* t_contact: contact time of two unit masses (0.005) */
  double steps_per_contact; /* steps_per_contact: dt = t_contact / steps_per_contact (50) */
  double hertz_ad;     /* hertz_ad: Hertz dissipative constant A_d (0) */
  double skin;         /* skin: neighbour-list skin (0.1) */
  int bridge_law;      /* bridge_law = constant | willett */
  int wall_bridges;    /* wall_bridges: 1 = particles bond to floor and lid as to each other */
  int integrator;      /* integrator = verlet | gear (WG_TD_VERLET / WG_TD_GEAR, td.h) */
  double bridge_volume;/* bridge_volume: V for the Willett law [d^3] */
  double contact_angle;/* contact_angle: theta_c in Eq. 2.10 [rad] (0) */
  double mu;           /* mu: Coulomb friction between particles, 0 = frictionless (0) */
  double mu_wall;      /* mu_wall: Coulomb friction at the walls (mu) */
  double kt_ratio;     /* kt_ratio: k_t / k_n (2/7) */
  double gt_ratio;     /* gt_ratio: gamma_t / gamma_n (0) */
  double mu_roll;      /* mu_roll: rolling resistance (0) */

  /* --- derived by wg_scene_finish() --- */
  double amplitude;    /* A [d]: from gamma and estar (or estar_d); 0 when not a shaker */
  double omega;        /* w [sqrt(g/d)]; 0 when not a shaker */
  double t_driv;       /* 2 pi / w; 0 when not a shaker */
  double f_b;          /* F_B [m g]: E_cb / s_crit (constant law), E_cb / (s_crit w) (Willett,
                          w: mean of Eq. 2.9 over 0..s_crit); 0 when dry */
  double dt;           /* td: time step t_contact / steps_per_contact */
  double hertz_k;      /* td, Hertz: K of Eq. 2.7 giving contact time t_contact at speed 1 */

  /* bookkeeping of where each key came from, for error messages and provenance */
  char source[256];    /* scene file path ("<none>" if only command-line pairs) */
  int key_line[96];    /* per table entry: line in the file that set it, 0 = default, -1 = command line */
} wg_scene;

/* Defaults for every key; "unset" for required ones. */
void wg_scene_init(wg_scene *sc);

/* Read a scene file. Errors name the file, the line and the key:
   "shake2d.ini:12: key 'gamma': value 'abc' is not a number". Returns WG_OK or WG_EINVAL/WG_EIO. */
int wg_scene_read_file(wg_scene *sc, const char *path);

/* Apply one command-line override "key=value"; errors name "command line" and the key. */
int wg_scene_set_override(wg_scene *sc, const char *pair);

/* Check required keys, ranges and consistency, and derive A, w, t_driv, f_b, e_cb.
   Errors name the file (and line, where the key was set) and the key. */
int wg_scene_finish(wg_scene *sc);

/* Mean of Willett's force profile 1 / (1 + 1.05 x + 2.5 x^2) (Eq. 2.9) over 0 <= x <= x_c. */
double wg_willett_mean(double x_c);

/* 1 if the key only changes what a run reports (stall_rate, stall_action), never a number it
   computes: a checkpoint made with another value still resumes. */
int wg_scene_key_is_advisory(const char *name);

/* Print the table of keys (name, unit, default, description) for --help. */
void wg_scene_print_keys(FILE *out);

/* Visit every key with its final value as text, in table order (for the /parameters
   group of a run file and for provenance). */
typedef int (*wg_scene_visit_fn)(void *user, const char *key, const char *value,
                                 const char *unit, const char *description);
int wg_scene_visit(const wg_scene *sc, wg_scene_visit_fn fn, void *user);

/* How a visited key's value is stored in a run file's /parameters: a real (float64), an
   integer (int64), the seed (uint64) or a word (string). */
typedef enum { WG_KEY_REAL, WG_KEY_INT, WG_KEY_UINT, WG_KEY_WORD } wg_key_kind;
wg_key_kind wg_scene_key_kind(const char *key);

/* Two texts of wg_scene_visit ("key = value" lines) name one configuration when they differ
   only by lines of keys at their fixed defaults: a key added to wetgran after one was written,
   or left out while off (shell, noise, the shear field's), means the same listed or not.
   Checkpoints are matched so. */
int wg_scene_same_configuration(const char *a, const char *b);

/* A floor and a lid bound the container (shaker or box). */
static inline int wg_scene_walled(const wg_scene *sc) { return sc->container != WG_CONTAINER_PERIODIC; }

#endif
