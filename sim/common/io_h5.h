/* Thin, checked wrappers over the HDF5 C API (1.10, current "2" interfaces), used by every
   tool: deterministic files (object timestamps off, fixed creation order), every dataset
   carrying "unit" and "description" attributes, and the H5MD 1.1 layout for particle data.
   Errors are reported through wg_error() naming the file and object path; the HDF5 library's
   own error stack printing is switched off by wg_h5_quiet(). */
#ifndef WG_IO_H5_H
#define WG_IO_H5_H

#include <hdf5.h>
#include "wg.h"

/* Switch off HDF5's automatic error printing (call once at program start). */
void wg_h5_quiet(void);

/* Create (truncate) a file / open one read-only / read-write.  Return a file id or a
   negative value after reporting the error. */
hid_t wg_h5_create(const char *path);
hid_t wg_h5_open_read(const char *path);
hid_t wg_h5_open_rw(const char *path);
int wg_h5_close(hid_t file);

/* Create a group, with intermediate groups, timestamps off; or open it if it exists.
   Returns the group id (caller closes with H5Gclose) or negative after reporting. */
hid_t wg_h5_group(hid_t loc, const char *path);

/* 1 if the object (group or dataset) at path exists, 0 if not. */
int wg_h5_exists(hid_t loc, const char *path);

/* Write a whole dataset in one call (contiguous layout; intermediate groups created).
   mem_type is the memory type (H5T_NATIVE_DOUBLE, H5T_NATIVE_INT, H5T_NATIVE_LLONG,
   H5T_NATIVE_UINT8 ...); the file type is the matching little-endian standard type.
   unit: in the grammar of the H5MD units module (a variable-length string): e.g. "d", "tau",
   "m d+2 tau-2", "1" for dimensionless; description: one sentence. */
int wg_h5_write(hid_t loc, const char *path, hid_t mem_type, int rank, const hsize_t *dims,
                const void *data, const char *unit, const char *description);

/* Create a dataset of known size and fill it in blocks of rows along its first dimension. */
hid_t wg_h5_dataset_create(hid_t loc, const char *path, hid_t mem_type, int rank,
                           const hsize_t *dims, const char *unit, const char *description);
int wg_h5_write_rows(hid_t dset, hid_t mem_type, hsize_t row0, hsize_t nrows, const void *data);

/* Read: dimensions, whole dataset, or a block of rows along the first dimension. */
int wg_h5_dims(hid_t loc, const char *path, int *rank, hsize_t dims[8]);
int wg_h5_read(hid_t loc, const char *path, hid_t mem_type, void *buf);
int wg_h5_read_rows(hid_t loc, const char *path, hid_t mem_type, hsize_t row0, hsize_t nrows,
                    void *buf);

/* Attributes on the object at obj_path ("." for loc itself); overwritten if present. */
int wg_h5_attr_double(hid_t loc, const char *obj_path, const char *name, double v);
int wg_h5_attr_doubles(hid_t loc, const char *obj_path, const char *name, int n, const double *v);
int wg_h5_attr_llong(hid_t loc, const char *obj_path, const char *name, long long v);
int wg_h5_attr_ints(hid_t loc, const char *obj_path, const char *name, int n, const int *v);
int wg_h5_attr_string(hid_t loc, const char *obj_path, const char *name, const char *s);
/* A scalar variable-length ASCII string (the H5MD units module's "unit" and "system"). */
int wg_h5_attr_string_vl(hid_t loc, const char *obj_path, const char *name, const char *s);
int wg_h5_attr_ullong(hid_t loc, const char *obj_path, const char *name, unsigned long long v);
/* A fixed-length string padded with NULs to len bytes, so that rewriting the value never moves
   data in the file (used for the volatile provenance). */
int wg_h5_attr_string_fixed(hid_t loc, const char *obj_path, const char *name, const char *s,
                            size_t len);
/* A 1-D array of strings (fixed length = longest + 1), e.g. H5MD box boundary. */
int wg_h5_attr_strings(hid_t loc, const char *obj_path, const char *name, int n,
                       const char *const *s);

int wg_h5_read_attr_double(hid_t loc, const char *obj_path, const char *name, double *v);
int wg_h5_read_attr_llong(hid_t loc, const char *obj_path, const char *name, long long *v);
/* Reads a string attribute (fixed or variable length) into buf of size len (NUL-terminated). */
int wg_h5_read_attr_string(hid_t loc, const char *obj_path, const char *name, char *buf,
                           size_t len);

/* A number of the run file's /parameters group: numeric attributes (layout 2) and numbers
   stored as text (layout 1) are both accepted. */
int wg_h5_read_param_double(hid_t file, const char *key, double *v);

/* ---- H5MD 1.1 ---- */

/* wetgran's own layout version, attribute "wetgran_layout" on /h5md/creator.  1 (no
   attribute): files before it, with every parameter as text and step counting each element's
   own samples.  2: typed parameters, one step clock (below), units module, walls, id/species. */
#define WG_H5_LAYOUT 2
int wg_h5_layout(hid_t file);

/* What a step is (layout 2): the description of every step dataset, and the attribute
   step_meaning on /particles/all and /observables. */
#define WG_H5_STEP_MEANING \
  "step of the run's one sampling clock: the instants at which anything is recorded (a " \
  "time-series sample or a snapshot), numbered from 0 in increasing time; equal steps are " \
  "equal times in every element of the file"

/* /h5md group: attribute version = {1, 1}; /h5md/author (name); /h5md/creator (name, version,
   wetgran_layout = WG_H5_LAYOUT). */
int wg_h5md_header(hid_t file, const char *author, const char *creator, const char *creator_version);

/* The H5MD units module: /h5md/modules/units with version {1, 0}, system, and one string
   attribute per unit symbol saying what it is. */
int wg_h5md_units(hid_t file, const char *system, int n, const char *const *symbol,
                  const char *const *meaning);

/* /particles/<group>/box: attributes dimension (int) and boundary (string array,
   "periodic" or "none" per axis), dataset edges[dim] [d]. */
int wg_h5md_box(hid_t file, const char *group, int dim, const double *edges,
                const char *const *boundary);

/* A time-dependent H5MD element at path (e.g. "/particles/all/position"): a group holding
   step[nframes] (int64), time[nframes] (double, unit "tau") and
   value[nframes][frame_dims...] (unit and description given).  Frames are then written one at
   a time, in order. */
typedef struct wg_h5md_element {
  hid_t value, step, time;     /* open datasets */
  hid_t mem_type;
  int frame_rank;               /* rank of one frame */
  hsize_t frame_dims[4];
  hsize_t nframes, written;
} wg_h5md_element;

int wg_h5md_element_create(hid_t file, const char *path, hid_t mem_type, int frame_rank,
                           const hsize_t *frame_dims, hsize_t nframes, const char *unit,
                           const char *description, wg_h5md_element *el);
int wg_h5md_element_write(wg_h5md_element *el, long long step, double time, const void *frame);
int wg_h5md_element_close(wg_h5md_element *el);

#endif
