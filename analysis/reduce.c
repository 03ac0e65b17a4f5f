/* wetgran-reduce: a run file cut down to what a figure is drawn from (a "record").
   The record has the run's layout, so every analysis tool reads it as it reads the run:
   parameters, provenance, summary, the H5MD header, the box and per-particle constants, every
   profile and the wall positions are copied whole; of the time series only the chosen columns,
   of the snapshots (and their bridge lists) only the chosen frames.  Datasets are stored
   shuffled and deflated; the numbers are copied bit for bit.  Layout-agnostic: whatever else
   the run holds at the top level is copied whole too. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io_h5.h"

#define MAX_PICK 256

typedef struct reduce_opts {
  const char *in, *out;
  int snapshots_all, snapshots_last, nframes_pick;
  long frames[MAX_PICK];           /* chosen snapshot indices (negative: from the end) */
  int series_all, nseries;
  const char *series[MAX_PICK];
  int heights_all, nheights;       /* fields of the height maps kept (default all) */
  char heights[8][64];
  int nattrs;
  const char *attrs[MAX_PICK];     /* KEY=VALUE written on /record */
} reduce_opts;

static const char *prog = "wetgran-reduce";

static void usage(FILE *o)
{
  fprintf(o,
          "Usage: wetgran-reduce RUN.h5 -o RECORD.h5 [--snapshots none|last|all|K[,K...]]\n"
          "                      [--series all|none|NAME[,NAME...]] [--attr KEY=VALUE ...]\n"
          "                      [--heights all|none|FIELD[,FIELD...]]\n"
          "Writes a record of a run: a file of the run's own layout that every wetgran tool\n"
          "reads like the run, holding the parameters, provenance, summary, box, per-particle\n"
          "constants, all profiles, lateral maps and wall positions, the chosen time series\n"
          "(default: temperature,bridges), the chosen fields of the height maps (default: all;\n"
          "of number_density, bridge_density, temperature, packing_fraction) and the chosen\n"
          "snapshots with their bridge lists (default:\n"
          "none; K counts from 0, negative from the end).  Numbers are copied bit for bit,\n"
          "stored shuffled and deflated.  --attr adds a string attribute to /record (the\n"
          "archive's provenance: key, engine version, CPU seconds ...).  The record is written\n"
          "as RECORD.h5.tmp and renamed when complete.\n");
}

static int parse_list(const char *arg, const char **out, int max, const char *opt)
{
  static char buf[4096];
  if (strlen(arg) >= sizeof buf) {
    fprintf(stderr, "%s: option %s: list too long\n", prog, opt);
    return -1;
  }
  strcpy(buf, arg);
  int n = 0;
  for (char *s = strtok(buf, ","); s; s = strtok(NULL, ",")) {
    if (n == max) {
      fprintf(stderr, "%s: option %s: more than %d items\n", prog, opt, max);
      return -1;
    }
    out[n++] = s;
  }
  return n;
}

static int parse_args(int argc, char **argv, reduce_opts *o)
{
  memset(o, 0, sizeof *o);
  o->series_all = 0;
  o->series[0] = "temperature";
  o->series[1] = "bridges";
  o->nseries = 2;
  o->heights_all = 1;
  for (int a = 1; a < argc; a++) {
    const char *s = argv[a];
    if (!strcmp(s, "-o") && a + 1 < argc) o->out = argv[++a];
    else if (!strcmp(s, "--snapshots") && a + 1 < argc) {
      const char *v = argv[++a];
      o->snapshots_all = o->snapshots_last = o->nframes_pick = 0;
      if (!strcmp(v, "all")) o->snapshots_all = 1;
      else if (!strcmp(v, "last")) o->snapshots_last = 1;
      else if (strcmp(v, "none") != 0) {
        const char *items[MAX_PICK];
        int n = parse_list(v, items, MAX_PICK, "--snapshots");
        if (n < 0) return 2;
        for (int i = 0; i < n; i++) {
          char *end;
          errno = 0;
          long k = strtol(items[i], &end, 10);
          if (errno || end == items[i] || *end) {
            fprintf(stderr, "%s: option --snapshots: '%s' is not an integer\n", prog, items[i]);
            return 2;
          }
          o->frames[o->nframes_pick++] = k;
        }
      }
    } else if (!strcmp(s, "--series") && a + 1 < argc) {
      const char *v = argv[++a];
      o->series_all = !strcmp(v, "all");
      o->nseries = 0;
      if (!o->series_all && strcmp(v, "none") != 0) {
        static char copy[4096];
        snprintf(copy, sizeof copy, "%s", v);
        if ((o->nseries = parse_list(copy, o->series, MAX_PICK, "--series")) < 0) return 2;
      }
    } else if (!strcmp(s, "--heights") && a + 1 < argc) {
      const char *v = argv[++a];
      o->heights_all = !strcmp(v, "all");
      o->nheights = 0;
      if (!o->heights_all && strcmp(v, "none") != 0) {
        static const char *known[] = {"number_density", "bridge_density", "temperature",
                                      "packing_fraction"};
        char copy[4096], *save = NULL;
        snprintf(copy, sizeof copy, "%s", v);
        for (char *f = strtok_r(copy, ",", &save); f; f = strtok_r(NULL, ",", &save)) {
          int ok = 0;
          for (int k = 0; k < 4; k++) ok |= !strcmp(f, known[k]);
          if (!ok || o->nheights == 8) {
            fprintf(stderr, "%s: option --heights: '%s' is not a field of the height maps "
                    "(number_density, bridge_density, temperature, packing_fraction)\n", prog, f);
            return 2;
          }
          snprintf(o->heights[o->nheights++], sizeof o->heights[0], "%s", f);
        }
      }
    } else if (!strcmp(s, "--attr") && a + 1 < argc) {
      if (o->nattrs == MAX_PICK || !strchr(argv[a + 1], '=')) {
        fprintf(stderr, "%s: option --attr: '%s' is not KEY=VALUE\n", prog, argv[a + 1]);
        return 2;
      }
      o->attrs[o->nattrs++] = argv[++a];
    } else if (s[0] == '-' && s[1]) {
      fprintf(stderr, "%s: unknown option or missing value: '%s' (see --help)\n", prog, s);
      return 2;
    } else if (!o->in) o->in = s;
    else {
      fprintf(stderr, "%s: unexpected argument '%s' (see --help)\n", prog, s);
      return 2;
    }
  }
  if (!o->in || !o->out) {
    fprintf(stderr, "%s: need RUN.h5 and -o RECORD.h5 (see --help)\n", prog);
    return 2;
  }
  return 0;
}

/* ---- copying ------------------------------------------------------------------------- */

static herr_t copy_attr(hid_t src, const char *name, const H5A_info_t *info, void *dst_)
{
  (void)info;
  hid_t dst = *(hid_t *)dst_;
  hid_t a = H5Aopen(src, name, H5P_DEFAULT);
  hid_t type = H5Aget_type(a), space = H5Aget_space(a);
  hssize_t n = H5Sget_simple_extent_npoints(space);
  size_t size = H5Tget_size(type);
  int vlen = H5Tis_variable_str(type) > 0 || H5Tdetect_class(type, H5T_VLEN) > 0;
  void *buf = calloc((size_t)(n > 0 ? n : 1), size > 0 ? size : 1);
  herr_t rc = -1;
  if (a >= 0 && type >= 0 && space >= 0 && buf && H5Aread(a, type, buf) >= 0) {
    hid_t b = H5Acreate2(dst, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
    if (b >= 0 && H5Awrite(b, type, buf) >= 0) rc = 0;
    if (b >= 0) H5Aclose(b);
    if (vlen) H5Dvlen_reclaim(type, space, H5P_DEFAULT, buf);
  }
  free(buf);
  if (space >= 0) H5Sclose(space);
  if (type >= 0) H5Tclose(type);
  if (a >= 0) H5Aclose(a);
  return rc;
}

static int copy_attrs(hid_t src, hid_t dst)
{
  hsize_t idx = 0;
  return H5Aiterate2(src, H5_INDEX_CRT_ORDER, H5_ITER_INC, &idx, copy_attr, &dst) < 0 &&
                 H5Aiterate2(src, H5_INDEX_NAME, H5_ITER_INC, &idx, copy_attr, &dst) < 0
             ? WG_EIO
             : WG_OK;
}

/* The name of the i-th member of group g (in name order) into buf[256]; negative on error. */
static int member_name(hid_t g, hsize_t i, char *buf)
{
  return H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, buf, 256, H5P_DEFAULT) < 0 ? -1 : 0;
}

/* Is the group at loc/name an H5MD time-dependent element (step, time, value)? */
static int is_element(hid_t loc, const char *name)
{
  char p[512];
  snprintf(p, sizeof p, "%s/value", name);
  return wg_h5_exists(loc, p) && (snprintf(p, sizeof p, "%s/time", name), wg_h5_exists(loc, p));
}

static hid_t new_group(hid_t parent, const char *name, hid_t src_group)
{
  hid_t gcpl = H5Pcreate(H5P_GROUP_CREATE);
  H5Pset_obj_track_times(gcpl, 0);
  H5Pset_link_creation_order(gcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
  hid_t g = H5Gcreate2(parent, name, H5P_DEFAULT, gcpl, H5P_DEFAULT);
  H5Pclose(gcpl);
  if (g >= 0 && src_group >= 0 && copy_attrs(src_group, g) != WG_OK) {
    H5Gclose(g);
    return H5I_INVALID_HID;
  }
  return g;
}

/* Copy the chosen rows (along the first dimension) of dataset src/name into dst/name,
   shuffled and deflated, with the dataset's attributes. */
static int copy_rows(hid_t src, hid_t dst, const char *name, const hsize_t *rows, hsize_t nrows)
{
  int rc = WG_EIO;
  hid_t d = H5Dopen2(src, name, H5P_DEFAULT);
  hid_t ftype = d >= 0 ? H5Dget_type(d) : -1, fspace = d >= 0 ? H5Dget_space(d) : -1;
  hsize_t dims[8], cdims[8];
  int rank = fspace >= 0 ? H5Sget_simple_extent_dims(fspace, dims, NULL) : -1;
  if (rank < 1) goto out0;
  size_t rowsize = H5Tget_size(ftype);
  for (int k = 1; k < rank; k++) rowsize *= dims[k];
  hsize_t ndims[8];
  memcpy(ndims, dims, sizeof ndims);
  ndims[0] = nrows;
  hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_obj_track_times(dcpl, 0);
  if (nrows > 0) {
    memcpy(cdims, ndims, sizeof cdims);
    cdims[0] = 1;
    if (rank == 1) cdims[0] = nrows;
    H5Pset_chunk(dcpl, rank, cdims);
    H5Pset_shuffle(dcpl);
    H5Pset_deflate(dcpl, 9);
  }
  hid_t nspace = H5Screate_simple(rank, ndims, NULL);
  hid_t nd = H5Dcreate2(dst, name, ftype, nspace, H5P_DEFAULT, dcpl, H5P_DEFAULT);
  unsigned char *buf = malloc(rowsize ? rowsize : 1);
  if (nd < 0 || !buf || copy_attrs(d, nd) != WG_OK) goto out1;
  rc = WG_OK;
  for (hsize_t r = 0; r < nrows && rc == WG_OK; r++) {
    hsize_t start[8] = {0}, count[8];
    memcpy(count, dims, sizeof count);
    start[0] = rows[r];
    count[0] = 1;
    hid_t ms = H5Screate_simple(rank, count, NULL);
    H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start, NULL, count, NULL);
    hid_t ns = H5Dget_space(nd);
    start[0] = r;
    H5Sselect_hyperslab(ns, H5S_SELECT_SET, start, NULL, count, NULL);
    if (H5Dread(d, ftype, ms, fspace, H5P_DEFAULT, buf) < 0 ||
        H5Dwrite(nd, ftype, ms, ns, H5P_DEFAULT, buf) < 0)
      rc = WG_EIO;
    H5Sclose(ns);
    H5Sclose(ms);
  }
out1:
  free(buf);
  if (nd >= 0) H5Dclose(nd);
  H5Sclose(nspace);
  H5Pclose(dcpl);
out0:
  if (fspace >= 0) H5Sclose(fspace);
  if (ftype >= 0) H5Tclose(ftype);
  if (d >= 0) H5Dclose(d);
  return rc;
}

/* A whole object, compressed where it is a dataset of more than a few values. */
static int copy_whole(hid_t src, hid_t dst, const char *name)
{
  H5O_info_t info;
  if (H5Oget_info_by_name(src, name, &info, H5P_DEFAULT) < 0) return WG_EIO;
  if (info.type == H5O_TYPE_DATASET) {
    hid_t d = H5Dopen2(src, name, H5P_DEFAULT), sp = H5Dget_space(d);
    hsize_t dims[8];
    int rank = H5Sget_simple_extent_dims(sp, dims, NULL);
    H5Sclose(sp);
    H5Dclose(d);
    if (rank >= 1 && dims[0] > 0) {
      hsize_t *rows = malloc(sizeof *rows * dims[0]);
      if (!rows) return WG_ENOMEM;
      for (hsize_t r = 0; r < dims[0]; r++) rows[r] = r;
      int rc = copy_rows(src, dst, name, rows, dims[0]);
      free(rows);
      return rc;
    }
  } else if (info.type == H5O_TYPE_GROUP) {
    hid_t sg = H5Gopen2(src, name, H5P_DEFAULT), dg = new_group(dst, name, sg);
    H5G_info_t gi;
    int rc = (sg >= 0 && dg >= 0 && H5Gget_info(sg, &gi) >= 0) ? WG_OK : WG_EIO;
    for (hsize_t i = 0; rc == WG_OK && i < gi.nlinks; i++) {
      char child[256];
      if (member_name(sg, i, child) < 0)
        rc = WG_EIO;
      else rc = copy_whole(sg, dg, child);
    }
    if (dg >= 0) H5Gclose(dg);
    if (sg >= 0) H5Gclose(sg);
    return rc;
  }
  hid_t ocpypl = H5Pcreate(H5P_OBJECT_COPY), lcpl = H5Pcreate(H5P_LINK_CREATE);
  herr_t e = H5Ocopy(src, name, dst, name, ocpypl, lcpl);
  H5Pclose(ocpypl);
  H5Pclose(lcpl);
  return e < 0 ? WG_EIO : WG_OK;
}

/* ---- the record ---------------------------------------------------------------------- */

/* The frames to keep out of nframes, in increasing order without repeats. */
static hsize_t pick_frames(const reduce_opts *o, hsize_t nframes, hsize_t *rows)
{
  hsize_t n = 0;
  if (o->snapshots_all)
    for (hsize_t r = 0; r < nframes; r++) rows[n++] = r;
  else if (o->snapshots_last && nframes > 0) rows[n++] = nframes - 1;
  else {
    for (hsize_t r = 0; r < nframes; r++)
      for (int k = 0; k < o->nframes_pick; k++) {
        long f = o->frames[k] < 0 ? (long)nframes + o->frames[k] : o->frames[k];
        if (f == (long)r) {
          rows[n++] = r;
          break;
        }
      }
  }
  return n;
}

static int reduce_element(hid_t src, hid_t dst, const char *name, const hsize_t *rows, hsize_t n)
{
  hid_t sg = H5Gopen2(src, name, H5P_DEFAULT), dg = new_group(dst, name, sg);
  int rc = (sg >= 0 && dg >= 0) ? WG_OK : WG_EIO;
  H5G_info_t gi;
  if (rc == WG_OK && H5Gget_info(sg, &gi) < 0) rc = WG_EIO;
  for (hsize_t i = 0; rc == WG_OK && i < gi.nlinks; i++) {
    char child[256];
    if (member_name(sg, i, child) < 0) {
      rc = WG_EIO;
      break;
    }
    /* step, time, value run along the frames; anything else (an H5MD "unit" group?) whole */
    if (!strcmp(child, "step") || !strcmp(child, "time") || !strcmp(child, "value"))
      rc = copy_rows(sg, dg, child, rows, n);
    else rc = copy_whole(sg, dg, child);
  }
  if (dg >= 0) H5Gclose(dg);
  if (sg >= 0) H5Gclose(sg);
  return rc;
}

/* /bridges: pairs of every snapshot in one list, offset[frame] .. offset[frame + 1]. */
static int reduce_bridges(hid_t src, hid_t dst, const hsize_t *rows, hsize_t n)
{
  int rank;
  hsize_t od[8], pd[8];
  if (wg_h5_dims(src, "/bridges/offset", &rank, od) != WG_OK ||
      wg_h5_dims(src, "/bridges/pairs", &rank, pd) != WG_OK)
    return WG_EIO;
  long long *off = malloc(sizeof *off * od[0]);
  if (!off) return WG_ENOMEM;
  int rc = wg_h5_read(src, "/bridges/offset", H5T_NATIVE_LLONG, off);
  hsize_t total = 0;
  for (hsize_t k = 0; k < n && rc == WG_OK; k++) total += (hsize_t)(off[rows[k] + 1] - off[rows[k]]);
  hsize_t *prow = malloc(sizeof *prow * (total ? total : 1));
  long long *noff = malloc(sizeof *noff * (n + 1));
  hid_t sg = H5Gopen2(src, "/bridges", H5P_DEFAULT), dg = new_group(dst, "bridges", sg);
  if (!prow || !noff || sg < 0 || dg < 0) rc = WG_EIO;
  if (rc == WG_OK) {
    hsize_t m = 0;
    noff[0] = 0;
    for (hsize_t k = 0; k < n; k++) {
      for (long long p = off[rows[k]]; p < off[rows[k] + 1]; p++) prow[m++] = (hsize_t)p;
      noff[k + 1] = (long long)m;
    }
    rc = copy_rows(sg, dg, "pairs", prow, total);
    if (rc == WG_OK) rc = copy_rows(sg, dg, "time", rows, n);
    if (rc == WG_OK && H5Lexists(sg, "step", H5P_DEFAULT) > 0) /* layout 2 */
      rc = copy_rows(sg, dg, "step", rows, n);
    if (rc == WG_OK) {
      /* the offsets are recomputed: written with the source's type and attributes */
      hid_t d = H5Dopen2(sg, "offset", H5P_DEFAULT), t = H5Dget_type(d);
      hsize_t dims[1] = {n + 1};
      hid_t sp = H5Screate_simple(1, dims, NULL), dcpl = H5Pcreate(H5P_DATASET_CREATE);
      H5Pset_obj_track_times(dcpl, 0);
      hid_t nd = H5Dcreate2(dg, "offset", t, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
      if (nd < 0 || copy_attrs(d, nd) != WG_OK ||
          H5Dwrite(nd, H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, noff) < 0)
        rc = WG_EIO;
      if (nd >= 0) H5Dclose(nd);
      H5Pclose(dcpl);
      H5Sclose(sp);
      H5Tclose(t);
      H5Dclose(d);
    }
  }
  if (dg >= 0) H5Gclose(dg);
  if (sg >= 0) H5Gclose(sg);
  free(noff);
  free(prow);
  free(off);
  return rc;
}

static int keep_series(const reduce_opts *o, const char *name)
{
  if (o->series_all) return 1;
  for (int i = 0; i < o->nseries; i++)
    if (!strcmp(o->series[i], name)) return 1;
  return 0;
}

/* The height maps' group with its attributes and the chosen fields only. */
static int copy_heights(hid_t obs, hid_t dobs, const reduce_opts *o)
{
  if (o->nheights == 0) return WG_OK;
  hid_t sg = H5Gopen2(obs, "heights", H5P_DEFAULT), dg = sg >= 0 ? new_group(dobs, "heights", sg) : -1;
  int rc = sg >= 0 && dg >= 0 ? WG_OK : WG_EIO;
  for (int k = 0; rc == WG_OK && k < o->nheights; k++)
    if (H5Lexists(sg, o->heights[k], H5P_DEFAULT) > 0) rc = copy_whole(sg, dg, o->heights[k]);
  if (dg >= 0) H5Gclose(dg);
  if (sg >= 0) H5Gclose(sg);
  return rc;
}

static int reduce(hid_t src, hid_t dst, const reduce_opts *o)
{
  int rc = copy_attrs(src, dst);
  H5G_info_t gi;
  if (rc == WG_OK && H5Gget_info(src, &gi) < 0) rc = WG_EIO;
  hsize_t nframes = 0, *rows = NULL, nrows = 0;
  if (rc == WG_OK && wg_h5_exists(src, "/particles/all/position/time")) {
    int rank;
    hsize_t dims[8];
    rc = wg_h5_dims(src, "/particles/all/position/time", &rank, dims);
    nframes = dims[0];
  }
  rows = malloc(sizeof *rows * (nframes ? nframes : 1));
  if (!rows) return WG_ENOMEM;
  nrows = pick_frames(o, nframes, rows);
  for (hsize_t i = 0; rc == WG_OK && i < gi.nlinks; i++) {
    char top[256];
    if (member_name(src, i, top) < 0) {
      rc = WG_EIO;
      break;
    }
    if (!strcmp(top, "bridges")) {
      if (nrows > 0) rc = reduce_bridges(src, dst, rows, nrows);
    } else if (!strcmp(top, "particles") || !strcmp(top, "observables")) {
      /* two levels: /particles/<group>/<element>, /observables/<series> */
      hid_t sg = H5Gopen2(src, top, H5P_DEFAULT), dg = new_group(dst, top, sg);
      H5G_info_t si;
      if (sg < 0 || dg < 0 || H5Gget_info(sg, &si) < 0) rc = WG_EIO;
      for (hsize_t j = 0; rc == WG_OK && j < si.nlinks; j++) {
        char name[256];
        member_name(sg, j, name);
        if (!strcmp(top, "observables")) {
          if (!strcmp(name, "heights") && !o->heights_all) rc = copy_heights(sg, dg, o);
          else if (!is_element(sg, name)) rc = copy_whole(sg, dg, name); /* profiles, maps */
          else if (!strcmp(name, "walls") || keep_series(o, name)) rc = copy_whole(sg, dg, name);
          continue;
        }
        hid_t pg = H5Gopen2(sg, name, H5P_DEFAULT), pdg = new_group(dg, name, pg);
        H5G_info_t pi;
        if (pg < 0 || pdg < 0 || H5Gget_info(pg, &pi) < 0) rc = WG_EIO;
        for (hsize_t k = 0; rc == WG_OK && k < pi.nlinks; k++) {
          char el[256];
          member_name(pg, k, el);
          if (!is_element(pg, el)) rc = copy_whole(pg, pdg, el);
          else if (nrows > 0) rc = reduce_element(pg, pdg, el, rows, nrows);
        }
        if (pdg >= 0) H5Gclose(pdg);
        if (pg >= 0) H5Gclose(pg);
      }
      if (dg >= 0) H5Gclose(dg);
      if (sg >= 0) H5Gclose(sg);
    } else rc = copy_whole(src, dst, top);
  }
  free(rows);
  for (int a = 0; rc == WG_OK && a < o->nattrs; a++) {
    char key[256];
    const char *eq = strchr(o->attrs[a], '=');
    snprintf(key, sizeof key, "%.*s", (int)(eq - o->attrs[a]), o->attrs[a]);
    rc = wg_h5_group(dst, "/record") < 0 ? WG_EIO : wg_h5_attr_string(dst, "/record", key, eq + 1);
  }
  return rc;
}

/* The newest file format: single-chunk datasets need no chunk index, which halves a small
   record (HDF5 1.10 and later read it). */
static hid_t create_record(const char *path)
{
  hid_t fcpl = H5Pcreate(H5P_FILE_CREATE), fapl = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_obj_track_times(fcpl, 0);
  H5Pset_libver_bounds(fapl, H5F_LIBVER_LATEST, H5F_LIBVER_LATEST);
  hid_t f = H5Fcreate(path, H5F_ACC_TRUNC, fcpl, fapl);
  H5Pclose(fcpl);
  H5Pclose(fapl);
  if (f < 0) fprintf(stderr, "%s: %s: cannot create the record\n", prog, path);
  return f;
}

int main(int argc, char **argv)
{
  for (int a = 1; a < argc; a++)
    if (!strcmp(argv[a], "-h") || !strcmp(argv[a], "--help")) {
      usage(stdout);
      return 0;
    }
  reduce_opts o;
  int st = parse_args(argc, argv, &o);
  if (st) return st;
  wg_h5_quiet();
  hid_t src = wg_h5_open_read(o.in);
  if (src < 0) return 1;
  if (!wg_h5_exists(src, "/h5md")) {
    fprintf(stderr, "%s: %s: not a wetgran run file (no /h5md group)\n", prog, o.in);
    wg_h5_close(src);
    return 1;
  }
  char tmp[4096];
  snprintf(tmp, sizeof tmp, "%s.tmp", o.out);
  hid_t dst = create_record(tmp);
  if (dst < 0) {
    wg_h5_close(src);
    return 1;
  }
  st = reduce(src, dst, &o);
  wg_h5_close(src);
  if (wg_h5_close(dst) != WG_OK) st = WG_EIO;
  if (st == WG_OK && rename(tmp, o.out) != 0) st = WG_EIO;
  if (st != WG_OK) {
    fprintf(stderr, "%s: %s: could not write the record of %s\n", prog, o.out, o.in);
    remove(tmp);
    return 1;
  }
  return 0;
}
