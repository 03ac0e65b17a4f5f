/* A run: an engine (event-driven or time-driven, chosen by the scene) plus what a run file records — time series of observables and of the
   energy ledger, time-averaged lateral profiles, particle snapshots — with checkpoints from
   which an interrupted run resumes bit-identically, and the final H5MD file, written under a
   temporary name and renamed when complete. */
#ifndef WG_RUN_H
#define WG_RUN_H

#include <stdio.h>
#include "ed.h"
#include "td.h"
#include "maps.h"
#include "cellsums.h"

typedef struct wg_run_options {
  const char *out_path;      /* RUN.h5 */
  const char *command_line;  /* recorded in /provenance */
  const char *scene_text;    /* contents of the scene file, recorded in /provenance */
  int fresh;                 /* ignore an existing checkpoint */
  int no_volatile;           /* write zeros / empty strings in /provenance/volatile */
  int progress;              /* progress line on stderr (a terminal), redrawn once a second */
  double log_every;          /* > 0: a progress line every log_every s of wall time (a batch log) */
  int abort_after_checkpoint;/* testing aid: exit right after writing this many checkpoints */
} wg_run_options;

/* Profile accumulators per lateral bin along x. */
typedef struct wg_profile {
  int bins;
  long samples;
  wg_cellsums sums; /* with particle volumes (the packing fraction) */
} wg_profile;

/* What the user sees while a run goes on: the progress line, the batch log, the stall watch.
   Wall-clock bookkeeping only: nothing here touches the engines' state. */
typedef struct wg_run_watch {
  double wall0, t0;          /* wall clock and simulated time when this process started */
  double line_wall;          /* last terminal progress line */
  int line_shown;            /* a terminal line is on screen without its newline */
  double log_wall, log_t, log_work; /* last batch-log line: when, at what time, work done */
  double stall_wall, stall_t;       /* the stall watch's window: start ... */
  unsigned long long stall_events;  /* ... and physical events then */
  int stall_warned;
} wg_run_watch;

typedef struct wg_run {
  wg_scene *sc;
  wg_run_options opt;
  wg_ed ed;                  /* engine = ed */
  wg_td td;                  /* engine = td */
  uint8_t *nbond;            /* td: bridges per particle, counted from the pairs when needed */
  /* time series: one row per sample, columns as in the table in run.c */
  size_t rows, cap;
  double *series;
  /* snapshots: frames go to a scratch file beside the output until the end */
  FILE *frames;
  long nframes;
  double *frame_time;
  long long *frame_bonds;
  long long frames_bytes;
  wg_profile prof;
  wg_map map;                /* lateral maps over windows of time (maps.h) */
  wg_map heights;            /* height maps over windows of time (maps.h) */
  /* next sampling times, as multiples of their intervals (exact, no accumulation) */
  long long k_series, k_snapshot, k_profile, k_checkpoint;
  double wall_start, wall_resumed; /* wall-clock bookkeeping (volatile) */
  int resumed;
  wg_run_watch watch;
  char tmp_path[4096], ckpt_path[4096], frames_path[4096];
} wg_run;

int wg_run_init(wg_run *run, wg_scene *sc, const wg_run_options *opt);
int wg_run_execute(wg_run *run);
void wg_run_free(wg_run *run);

/* Physical events so far: collisions (td: contacts begun), bridge ruptures and reflections,
   wall hits (td: wall contacts begun). */
unsigned long long wg_run_events(const wg_run *run);

#endif
