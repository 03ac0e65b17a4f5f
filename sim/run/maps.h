/* Maps: coarse-grained fields averaged over windows of time, one frame per window, a few
   kilobytes per window where the particle snapshots they replace take megabytes.
   - Lateral maps (WG_MAP_LATERAL, /observables/maps): number density, bridge density and
     granular temperature of the lateral plane; cells are nx along x by ny along y (3D;
     ny = 1 in 2D, where a map is a row along x and the frames make a space-time map).
     What Ch. 5's interfaces are measured on (a_g, the strip's edge, its relaxation).
   - Height maps (WG_MAP_HEIGHT, /observables/heights): the same fields and the packing
     fraction in nx slabs across the height, z0 <= z < z0 + span, averaged over the lateral
     plane; the frames make the height-time maps of Ch. 6's Leidenfrost plug (Fig. 6.3b).
     A grain counts, temperature and bridges in the slab of its centre, its volume in every
     slab it cuts (exact sphere or disk slices), so the packing fraction stays smooth in
     slabs thinner than a grain.
   Samples are taken `samples` times per window at equal intervals; a window's frame is
   written when its last sample is in, so an unfinished window at t_end leaves no frame. */
#ifndef WG_MAPS_H
#define WG_MAPS_H

#include <hdf5.h>

#include "cellsums.h"

typedef enum { WG_MAP_LATERAL, WG_MAP_HEIGHT } wg_map_kind;

typedef struct wg_map {
  wg_map_kind kind;
  int nx, ny, dim;
  double lx, ly;              /* lateral box lengths (ly unused in 2D) */
  double z0, span;            /* height maps: the slabs cover z0 <= z < z0 + span */
  double start, window;       /* first window begins at start; windows of this length */
  int samples;                /* samples per window */
  long long k;                /* next sample index, counted from start */
  wg_cellsums sums;           /* of the open window (volumes: height maps only) */
  /* finished frames: time (window centre) and, per cell, the fields (packing: height maps) */
  long nframes, cap;
  double *time, *density, *bridge_density, *temperature, *packing;
} wg_map;

/* nx = 0: no maps (every call below is then a no-op). */
int wg_map_init(wg_map *m, int nx, int ny, int dim, double lx, double ly, double start,
                double window, int samples);
/* Height maps: nx slabs over z0 <= z < z0 + span. */
int wg_map_init_height(wg_map *m, int nx, int dim, double lx, double ly, double z0,
                       double span, double start, double window, int samples);
void wg_map_free(wg_map *m);

/* Time of the next sample (inf when there are no maps). */
double wg_map_next_time(const wg_map *m);

/* One sample: call wg_map_add for every particle, then wg_map_end_sample. */
void wg_map_add(wg_map *m, const double r[3], const double v[3], double mass, double radius,
                int bridges);
int wg_map_end_sample(wg_map *m);

/* Run file: /observables/maps/{number_density,bridge_density,temperature}/{step,time,value}
   (value: frames x ny x nx in 3D, frames x nx in 2D); height maps /observables/heights/
   {number_density,bridge_density,temperature,packing_fraction}/... (value: frames x nx).
   step_of maps a frame time to the run's step. */
int wg_map_write(const wg_map *m, hid_t f, long long (*step_of)(const void *, double),
                 const void *clock);

/* Checkpoint: the open window's sums, the finished frames and the sample counter. */
int wg_map_checkpoint_write(const wg_map *m, hid_t f);
int wg_map_checkpoint_read(wg_map *m, hid_t f, const char *path);

#endif
