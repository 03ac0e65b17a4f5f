/* Checked HDF5 wrappers and the H5MD 1.1 layout (see io_h5.h).

   Conventions: every HDF5 call is checked; a failure is reported once, by the function that
   saw it, through fail()/bad() as "<file>:<object>: cannot <operation> (<HDF5 message>)";
   callers of another wg_h5_* function only propagate its status.  Every id opened here is
   closed on all paths through close_id().  Groups and datasets are created with object
   timestamps off (H5Pset_obj_track_times(.., 0)) and the default, untracked attribute
   creation order, so identical write sequences give byte-identical files. */
#include "io_h5.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PATH_LEN 1024 /* longest object path handled */

/* ---- error reporting and closing ---------------------------------------------------- */

/* H5Ewalk2 callback (upward walk): keep the description of the innermost error. */
static herr_t innermost_error(unsigned n, const H5E_error2_t *err, void *detail)
{
  if (n == 0 && err->desc) snprintf(detail, 256, "%s", err->desc);
  return 0;
}

/* "<file>:<object>" for path relative to loc (path NULL or ".": loc itself); loc < 0: path. */
static void where_of(hid_t loc, const char *path, char *where, size_t n)
{
  char file[PATH_LEN] = "", obj[PATH_LEN] = "";
  if (loc < 0) {
    snprintf(where, n, "%s", path ? path : "HDF5");
    return;
  }
  if (H5Fget_name(loc, file, sizeof file) < 0) file[0] = '\0';
  if (path && path[0] == '/') {
    snprintf(where, n, "%s:%s", file, path);
    return;
  }
  if (H5Iget_name(loc, obj, sizeof obj) < 0) obj[0] = '\0';
  if (!path || strcmp(path, ".") == 0)
    snprintf(where, n, "%s:%s", file, obj);
  else
    snprintf(where, n, "%s:%s%s%s", file, obj,
             obj[0] && obj[strlen(obj) - 1] != '/' ? "/" : "", path);
}

/* Report status at (loc, path): "cannot <op>" plus, if hdf5, HDF5's innermost message.  The
   error stack is read first, before any other HDF5 call resets it. */
static int vreport(int status, int hdf5, hid_t loc, const char *path, const char *fmt,
                   va_list ap)
{
  char detail[256] = "", where[2 * PATH_LEN + 8], msg[512];
  if (hdf5) (void)H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, innermost_error, detail);
  where_of(loc, path, where, sizeof where);
  vsnprintf(msg, sizeof msg, fmt, ap);
  if (hdf5) return wg_error(status, where, "cannot %s (%s)", msg, detail[0] ? detail : "HDF5 error");
  return wg_error(status, where, "%s", msg);
}

/* An HDF5 call failed: WG_EIO naming the operation. */
__attribute__((format(printf, 3, 4)))
static int fail(hid_t loc, const char *path, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  int rc = vreport(WG_EIO, 1, loc, path, fmt, ap);
  va_end(ap);
  return rc;
}

/* Bad argument or data that does not fit: WG_EINVAL. */
__attribute__((format(printf, 3, 4)))
static int bad(hid_t loc, const char *path, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  int rc = vreport(WG_EINVAL, 0, loc, path, fmt, ap);
  va_end(ap);
  return rc;
}

/* Close any id (negative: nothing to do).  Returns rc, or the close failure if rc was OK. */
static int close_id(hid_t id, int rc)
{
  herr_t r;
  if (id < 0) return rc;
  switch (H5Iget_type(id)) {
  case H5I_FILE: r = H5Fclose(id); break;
  case H5I_GROUP: r = H5Gclose(id); break;
  case H5I_DATASET: r = H5Dclose(id); break;
  case H5I_ATTR: r = H5Aclose(id); break;
  case H5I_DATATYPE: r = H5Tclose(id); break;
  case H5I_DATASPACE: r = H5Sclose(id); break;
  case H5I_GENPROP_LST: r = H5Pclose(id); break;
  default: r = H5Idec_ref(id) < 0 ? -1 : 0; break;
  }
  if (r < 0 && rc == WG_OK) rc = fail(id, NULL, "close object");
  return rc;
}

/* ---- files and groups ---------------------------------------------------------------- */

void wg_h5_quiet(void) { (void)H5Eset_auto2(H5E_DEFAULT, NULL, NULL); }

hid_t wg_h5_create(const char *path)
{
  hid_t f = H5I_INVALID_HID, fcpl = H5Pcreate(H5P_FILE_CREATE);
  /* the file creation plist also governs the root group: no timestamps there either */
  if (fcpl < 0 || H5Pset_obj_track_times(fcpl, 0) < 0 ||
      (f = H5Fcreate(path, H5F_ACC_TRUNC, fcpl, H5P_DEFAULT)) < 0)
    fail(H5I_INVALID_HID, path, "create file");
  if (close_id(fcpl, WG_OK)) {
    close_id(f, WG_EIO);
    f = H5I_INVALID_HID;
  }
  return f;
}

static hid_t open_file(const char *path, unsigned flags)
{
  hid_t f = H5Fopen(path, flags, H5P_DEFAULT);
  if (f < 0)
    fail(H5I_INVALID_HID, path, "open file %s",
         flags == H5F_ACC_RDONLY ? "for reading" : "for reading and writing");
  return f;
}

hid_t wg_h5_open_read(const char *path) { return open_file(path, H5F_ACC_RDONLY); }
hid_t wg_h5_open_rw(const char *path) { return open_file(path, H5F_ACC_RDWR); }

/* A negative id (e.g. a failed open) is accepted and ignored, like free(NULL). */
int wg_h5_close(hid_t file)
{
  if (file >= 0 && H5Iget_type(file) != H5I_FILE) return bad(file, NULL, "not a file id");
  return close_id(file, WG_OK);
}

/* Copy path into buf[PATH_LEN], reporting paths that are too long. */
static int copy_path(hid_t loc, const char *path, char *buf)
{
  if (!path) return bad(loc, NULL, "null object path");
  if (strlen(path) >= PATH_LEN) return bad(loc, NULL, "object path longer than %d bytes", PATH_LEN - 1);
  strcpy(buf, path);
  return WG_OK;
}

hid_t wg_h5_group(hid_t loc, const char *path)
{
  char buf[PATH_LEN], *c = buf, *end;
  hid_t cur = H5I_INVALID_HID, gcpl = H5I_INVALID_HID;
  int rc = copy_path(loc, path, buf);
  if (rc) return H5I_INVALID_HID;
  if ((gcpl = H5Pcreate(H5P_GROUP_CREATE)) < 0 || H5Pset_obj_track_times(gcpl, 0) < 0) {
    rc = fail(loc, path, "set up group creation properties");
    goto done;
  }
  if ((cur = H5Gopen2(loc, path[0] == '/' ? "/" : ".", H5P_DEFAULT)) < 0) {
    rc = fail(loc, path, "open start group");
    goto done;
  }
  /* walk the components, creating each missing one with timestamps off */
  for (;;) {
    if ((end = strchr(c, '/'))) *end = '\0';
    if (*c && strcmp(c, ".") != 0) {
      htri_t e = H5Lexists(cur, c, H5P_DEFAULT);
      hid_t g = e > 0 ? H5Gopen2(cur, c, H5P_DEFAULT)
                : e == 0 ? H5Gcreate2(cur, c, H5P_DEFAULT, gcpl, H5P_DEFAULT) : H5I_INVALID_HID;
      if (g < 0) {
        rc = fail(loc, path, "%s group component '%s'",
                  e > 0 ? "open" : e == 0 ? "create" : "look up", c);
        goto done;
      }
      rc = close_id(cur, rc);
      cur = g;
      if (rc) goto done;
    }
    if (!end) break;
    c = end + 1;
  }
done:
  rc = close_id(gcpl, rc);
  if (rc) {
    close_id(cur, rc);
    return H5I_INVALID_HID;
  }
  return cur;
}

/* Create (or open) the group at path and close it again. */
static int make_group(hid_t loc, const char *path)
{
  hid_t g = wg_h5_group(loc, path);
  return g < 0 ? WG_EIO : close_id(g, WG_OK);
}

int wg_h5_exists(hid_t loc, const char *path)
{
  char buf[PATH_LEN];
  if (!path || strlen(path) >= PATH_LEN) return 0;
  strcpy(buf, path);
  /* H5Lexists needs every intermediate link to exist, so test the prefixes in order */
  for (char *s = strchr(buf[0] ? buf + 1 : buf, '/'); s; s = strchr(s + 1, '/')) {
    *s = '\0';
    if (H5Lexists(loc, buf, H5P_DEFAULT) <= 0) return 0;
    *s = '/';
  }
  return H5Oexists_by_name(loc, path, H5P_DEFAULT) > 0;
}

/* ---- types ----------------------------------------------------------------------------- */

/* The little-endian standard file type for a native memory type (a copy; caller closes),
   or a negative value for unsupported types. */
static hid_t file_type(hid_t mem)
{
  hid_t t = H5I_INVALID_HID;
  size_t size = H5Tget_size(mem);
  H5T_class_t cls = H5Tget_class(mem);
  if (cls == H5T_FLOAT && size == 4) t = H5T_IEEE_F32LE;
  else if (cls == H5T_FLOAT && size == 8) t = H5T_IEEE_F64LE;
  else if (cls == H5T_STRING) t = mem;
  else if (cls == H5T_INTEGER) {
    int u = H5Tget_sign(mem) == H5T_SGN_NONE;
    switch (size) {
    case 1: t = u ? H5T_STD_U8LE : H5T_STD_I8LE; break;
    case 2: t = u ? H5T_STD_U16LE : H5T_STD_I16LE; break;
    case 4: t = u ? H5T_STD_U32LE : H5T_STD_I32LE; break;
    case 8: t = u ? H5T_STD_U64LE : H5T_STD_I64LE; break;
    default: break;
    }
  }
  return t < 0 ? t : H5Tcopy(t);
}

/* Fixed-length (len bytes), NUL-padded ASCII string type; caller closes. */
static hid_t string_type(size_t len)
{
  hid_t t = H5Tcopy(H5T_C_S1);
  if (t >= 0 && (H5Tset_size(t, len) < 0 || H5Tset_strpad(t, H5T_STR_NULLPAD) < 0 ||
                 H5Tset_cset(t, H5T_CSET_ASCII) < 0)) {
    close_id(t, WG_EIO);
    t = H5I_INVALID_HID;
  }
  return t;
}

/* ---- attributes ------------------------------------------------------------------------ */

/* Write attribute name on obj with file type ftype and shape space; an existing attribute of
   that name is deleted first.  (Rewriting in place with H5Awrite is not used: HDF5 1.10 fails
   with "can't locate open attribute?" when the object is open through another id.)  A deleted
   attribute's header message is reused by a new one of the same size, so a fixed-size value
   keeps its place in the file. */
static int attr_put(hid_t loc, const char *obj, const char *name, hid_t ftype, hid_t mtype,
                    hid_t space, const void *data)
{
  hid_t a;
  int rc = WG_OK;
  htri_t e = H5Aexists_by_name(loc, obj, name, H5P_DEFAULT);
  if (e < 0) return fail(loc, obj, "look up attribute '%s'", name);
  if (e > 0 && H5Adelete_by_name(loc, obj, name, H5P_DEFAULT) < 0)
    return fail(loc, obj, "delete attribute '%s'", name);
  if ((a = H5Acreate_by_name(loc, obj, name, ftype, space, H5P_DEFAULT, H5P_DEFAULT,
                             H5P_DEFAULT)) < 0)
    return fail(loc, obj, "create attribute '%s'", name);
  if (H5Awrite(a, mtype, data) < 0) rc = fail(loc, obj, "write attribute '%s'", name);
  return close_id(a, rc);
}

/* n == 0: scalar attribute; n > 0: 1-D array of n elements. */
static int attr_put_n(hid_t loc, const char *obj, const char *name, hid_t ftype, hid_t mtype,
                      int n, const void *data)
{
  hsize_t dim = (hsize_t)n;
  hid_t s;
  if (!obj || !name || !data || n < 0) return bad(loc, obj, "invalid arguments for attribute");
  if ((s = n ? H5Screate_simple(1, &dim, NULL) : H5Screate(H5S_SCALAR)) < 0)
    return fail(loc, obj, "create dataspace for attribute '%s'", name);
  return close_id(s, attr_put(loc, obj, name, ftype, mtype, s, data));
}

/* A fixed-length string attribute of len bytes (s padded with NULs): n == 0 scalar, else an
   array of n strings stored contiguously in s. */
static int attr_put_str(hid_t loc, const char *obj, const char *name, int n, size_t len,
                        const char *s)
{
  hid_t t = string_type(len);
  if (t < 0) return fail(loc, obj, "create string type for attribute '%s'", name);
  return close_id(t, attr_put_n(loc, obj, name, t, t, n, s));
}

int wg_h5_attr_double(hid_t loc, const char *obj_path, const char *name, double v)
{
  return attr_put_n(loc, obj_path, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 0, &v);
}

int wg_h5_attr_doubles(hid_t loc, const char *obj_path, const char *name, int n, const double *v)
{
  if (n < 1) return bad(loc, obj_path, "attribute '%s': %d values", name ? name : "?", n);
  return attr_put_n(loc, obj_path, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, n, v);
}

int wg_h5_attr_llong(hid_t loc, const char *obj_path, const char *name, long long v)
{
  return attr_put_n(loc, obj_path, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, 0, &v);
}

int wg_h5_attr_ints(hid_t loc, const char *obj_path, const char *name, int n, const int *v)
{
  if (n < 1) return bad(loc, obj_path, "attribute '%s': %d values", name ? name : "?", n);
  return attr_put_n(loc, obj_path, name, H5T_STD_I32LE, H5T_NATIVE_INT, n, v);
}

int wg_h5_attr_string(hid_t loc, const char *obj_path, const char *name, const char *s)
{
  if (!s) return bad(loc, obj_path, "attribute '%s': null string", name ? name : "?");
  return attr_put_str(loc, obj_path, name, 0, strlen(s) + 1, s);
}

int wg_h5_attr_string_vl(hid_t loc, const char *obj_path, const char *name, const char *s)
{
  hid_t t = H5Tcopy(H5T_C_S1);
  int rc;
  if (!s) return bad(loc, obj_path, "attribute '%s': null string", name ? name : "?");
  if (t < 0 || H5Tset_size(t, H5T_VARIABLE) < 0 || H5Tset_cset(t, H5T_CSET_ASCII) < 0)
    return close_id(t, fail(loc, obj_path, "create string type for attribute '%s'", name));
  rc = attr_put_n(loc, obj_path, name, t, t, 0, &s);
  return close_id(t, rc);
}

int wg_h5_attr_ullong(hid_t loc, const char *obj_path, const char *name, unsigned long long v)
{
  return attr_put_n(loc, obj_path, name, H5T_STD_U64LE, H5T_NATIVE_ULLONG, 0, &v);
}

int wg_h5_attr_string_fixed(hid_t loc, const char *obj_path, const char *name, const char *s,
                            size_t len)
{
  char *buf;
  int rc;
  if (!s || strlen(s) >= len)
    return bad(loc, obj_path, "attribute '%s': string does not fit in %zu bytes with its NUL",
               name ? name : "?", len);
  if (!(buf = calloc(len, 1))) return wg_error(WG_ENOMEM, "wg_h5_attr_string_fixed", "out of memory");
  strcpy(buf, s);
  rc = attr_put_str(loc, obj_path, name, 0, len, buf);
  free(buf);
  return rc;
}

int wg_h5_attr_strings(hid_t loc, const char *obj_path, const char *name, int n,
                       const char *const *s)
{
  size_t len = 1;
  char *buf;
  int rc;
  if (n < 1 || !s) return bad(loc, obj_path, "attribute '%s': %d strings", name ? name : "?", n);
  for (int i = 0; i < n; i++) {
    if (!s[i]) return bad(loc, obj_path, "attribute '%s': null string", name ? name : "?");
    if (strlen(s[i]) + 1 > len) len = strlen(s[i]) + 1;
  }
  if (!(buf = calloc((size_t)n, len))) return wg_error(WG_ENOMEM, "wg_h5_attr_strings", "out of memory");
  for (int i = 0; i < n; i++) strcpy(buf + (size_t)i * len, s[i]);
  rc = attr_put_str(loc, obj_path, name, n, len, buf);
  free(buf);
  return rc;
}

/* Open attribute name on obj and check that it holds exactly one element. */
static int attr_open1(hid_t loc, const char *obj, const char *name, hid_t *a)
{
  hid_t s = H5I_INVALID_HID;
  hssize_t np;
  int rc = WG_OK;
  if (!obj || !name) return bad(loc, obj, "invalid attribute arguments");
  if ((*a = H5Aopen_by_name(loc, obj, name, H5P_DEFAULT, H5P_DEFAULT)) < 0)
    return fail(loc, obj, "open attribute '%s'", name);
  if ((s = H5Aget_space(*a)) < 0 || (np = H5Sget_simple_extent_npoints(s)) < 0)
    rc = fail(loc, obj, "get dataspace of attribute '%s'", name);
  else if (np != 1)
    rc = bad(loc, obj, "attribute '%s' has %lld elements, expected 1", name, (long long)np);
  rc = close_id(s, rc);
  if (rc) {
    close_id(*a, rc);
    *a = H5I_INVALID_HID;
  }
  return rc;
}

static int attr_get1(hid_t loc, const char *obj, const char *name, hid_t mtype, void *v)
{
  hid_t a;
  int rc = attr_open1(loc, obj, name, &a);
  if (rc) return rc;
  if (H5Aread(a, mtype, v) < 0) rc = fail(loc, obj, "read attribute '%s'", name);
  return close_id(a, rc);
}

int wg_h5_read_attr_double(hid_t loc, const char *obj_path, const char *name, double *v)
{
  return attr_get1(loc, obj_path, name, H5T_NATIVE_DOUBLE, v);
}

int wg_h5_read_attr_llong(hid_t loc, const char *obj_path, const char *name, long long *v)
{
  return attr_get1(loc, obj_path, name, H5T_NATIVE_LLONG, v);
}

int wg_h5_read_attr_string(hid_t loc, const char *obj_path, const char *name, char *buf,
                           size_t len)
{
  hid_t a, t = H5I_INVALID_HID, mt = H5I_INVALID_HID;
  char *s = NULL;
  htri_t vl = -1;
  size_t size = 0;
  int rc;
  if (!buf || len == 0) return bad(loc, obj_path, "no buffer for attribute string");
  if ((rc = attr_open1(loc, obj_path, name, &a))) return rc;
  if ((t = H5Aget_type(a)) < 0 || H5Tget_class(t) != H5T_STRING) {
    rc = t < 0 ? fail(loc, obj_path, "get type of attribute '%s'", name)
               : bad(loc, obj_path, "attribute '%s' is not a string", name);
  } else if ((vl = H5Tis_variable_str(t)) < 0) {
    rc = fail(loc, obj_path, "get type of attribute '%s'", name);
  } else if (vl) { /* variable length: HDF5 allocates the string, H5free_memory releases it */
    if ((mt = H5Tcopy(H5T_C_S1)) < 0 || H5Tset_size(mt, H5T_VARIABLE) < 0 ||
        H5Tset_cset(mt, H5Tget_cset(t)) < 0 || H5Aread(a, mt, &s) < 0)
      rc = fail(loc, obj_path, "read string attribute '%s'", name);
  } else if ((size = H5Tget_size(t)) == 0) {
    rc = fail(loc, obj_path, "get size of attribute '%s'", name);
  } else if (!(s = calloc(size + 1, 1))) {
    rc = wg_error(WG_ENOMEM, "wg_h5_read_attr_string", "out of memory");
  } else if (H5Aread(a, t, s) < 0) { /* fixed length: read the raw bytes, add the NUL */
    rc = fail(loc, obj_path, "read string attribute '%s'", name);
  } else if (H5Tget_strpad(t) == H5T_STR_SPACEPAD) {
    for (size_t k = strlen(s); k > 0 && s[k - 1] == ' '; k--) s[k - 1] = '\0';
  }
  if (!rc && strlen(s ? s : "") >= len)
    rc = bad(loc, obj_path, "attribute '%s' (%zu characters) does not fit in %zu bytes", name,
             strlen(s), len);
  if (!rc) strcpy(buf, s ? s : "");
  if (vl > 0) {
    if (s && H5free_memory(s) < 0 && !rc) rc = fail(loc, obj_path, "free attribute string");
  } else {
    free(s);
  }
  return close_id(a, close_id(t, close_id(mt, rc)));
}

int wg_h5_read_param_double(hid_t file, const char *key, double *v)
{
  hid_t a, t = H5I_INVALID_HID;
  int rc;
  H5T_class_t cls = H5T_NO_CLASS;
  char buf[128], *end;
  if ((rc = attr_open1(file, "/parameters", key, &a))) return rc;
  if ((t = H5Aget_type(a)) < 0 || (cls = H5Tget_class(t)) == H5T_NO_CLASS) {
    rc = fail(file, "/parameters", "get type of parameter '%s'", key);
  } else if (cls == H5T_INTEGER || cls == H5T_FLOAT) {
    if (H5Aread(a, H5T_NATIVE_DOUBLE, v) < 0) rc = fail(file, "/parameters", "read parameter '%s'", key);
  } else if (cls != H5T_STRING) {
    rc = bad(file, "/parameters", "parameter '%s' is neither a number nor a string", key);
  }
  rc = close_id(t, close_id(a, rc));
  if (rc || cls != H5T_STRING) return rc;
  /* layout 1: every value as text */
  if ((rc = wg_h5_read_attr_string(file, "/parameters", key, buf, sizeof buf))) return rc;
  *v = strtod(buf, &end);
  if (end == buf || *end)
    return bad(file, "/parameters", "parameter '%s' = '%s' is not a number", key, buf);
  return WG_OK;
}

int wg_h5_layout(hid_t file)
{
  long long v;
  htri_t e = H5Aexists_by_name(file, "/h5md/creator", "wetgran_layout", H5P_DEFAULT);
  if (e <= 0 || wg_h5_read_attr_llong(file, "/h5md/creator", "wetgran_layout", &v) != WG_OK) return 1;
  return (int)v;
}

/* ---- datasets -------------------------------------------------------------------------- */

/* Create a contiguous dataset (parent groups with timestamps off, dataset timestamps off) with
   its unit and description attributes.  fill: H5D_FILL_TIME_NEVER when the whole dataset is
   written at once, H5D_FILL_TIME_ALLOC (zeros) when rows are filled later. */
static int dset_create(hid_t loc, const char *path, hid_t mem_type, int rank, const hsize_t *dims,
                       const char *unit, const char *description, H5D_fill_time_t fill,
                       hid_t *dset)
{
  char parent[PATH_LEN], *slash;
  hid_t ft = H5I_INVALID_HID, space = H5I_INVALID_HID, dcpl = H5I_INVALID_HID;
  hid_t lcpl = H5I_INVALID_HID, d = H5I_INVALID_HID;
  int rc;
  *dset = H5I_INVALID_HID;
  if ((rc = copy_path(loc, path, parent))) return rc;
  if (rank < 1 || rank > 8 || !dims || !unit || !description)
    return bad(loc, path, "invalid dataset arguments (rank %d, unit/description must be given)", rank);
  if ((slash = strrchr(parent, '/')) && slash != parent) { /* make the parent groups first */
    *slash = '\0';
    if ((rc = make_group(loc, parent))) return rc;
  }
  if ((ft = file_type(mem_type)) < 0) return bad(loc, path, "unsupported memory type");
  if ((space = H5Screate_simple(rank, dims, NULL)) < 0 ||
      (dcpl = H5Pcreate(H5P_DATASET_CREATE)) < 0 || H5Pset_obj_track_times(dcpl, 0) < 0 ||
      H5Pset_layout(dcpl, H5D_CONTIGUOUS) < 0 || H5Pset_fill_time(dcpl, fill) < 0 ||
      (lcpl = H5Pcreate(H5P_LINK_CREATE)) < 0 || H5Pset_create_intermediate_group(lcpl, 1) < 0)
    rc = fail(loc, path, "set up dataset creation properties");
  else if ((d = H5Dcreate2(loc, path, ft, space, lcpl, dcpl, H5P_DEFAULT)) < 0)
    rc = fail(loc, path, "create dataset");
  else if (!(rc = wg_h5_attr_string_vl(d, ".", "unit", unit)))
    rc = wg_h5_attr_string(d, ".", "description", description);
  rc = close_id(ft, close_id(space, close_id(dcpl, close_id(lcpl, rc))));
  if (rc) return close_id(d, rc);
  *dset = d;
  return WG_OK;
}

int wg_h5_write(hid_t loc, const char *path, hid_t mem_type, int rank, const hsize_t *dims,
                const void *data, const char *unit, const char *description)
{
  hid_t d;
  hsize_t n = 1;
  int rc = dset_create(loc, path, mem_type, rank, dims, unit, description,
                       H5D_FILL_TIME_NEVER, &d);
  if (rc) return rc;
  for (int i = 0; i < rank; i++) n *= dims[i];
  if (n > 0 && !data) rc = bad(loc, path, "no data to write");
  else if (n > 0 && H5Dwrite(d, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    rc = fail(loc, path, "write dataset");
  return close_id(d, rc);
}

hid_t wg_h5_dataset_create(hid_t loc, const char *path, hid_t mem_type, int rank,
                           const hsize_t *dims, const char *unit, const char *description)
{
  hid_t d;
  dset_create(loc, path, mem_type, rank, dims, unit, description, H5D_FILL_TIME_ALLOC, &d);
  return d;
}

/* Rows [row0, row0 + nrows) of dset as one hyperslab: written from wbuf, or read into rbuf
   when wbuf is NULL (both NULL: error). */
static int row_io(hid_t dset, hid_t mem_type, hsize_t row0, hsize_t nrows, const void *wbuf,
                  void *rbuf)
{
  hsize_t dims[8], start[8] = {0}, count[8], n = 1;
  hid_t fs = H5Dget_space(dset), ms = H5I_INVALID_HID;
  int rc = WG_OK, rank;
  if (fs < 0) return fail(dset, NULL, "get dataspace");
  if ((rank = H5Sget_simple_extent_ndims(fs)) < 0)
    rc = fail(dset, NULL, "get dimensions");
  else if (rank < 1 || rank > 8)
    rc = bad(dset, NULL, "rank %d does not allow row access", rank);
  else if (H5Sget_simple_extent_dims(fs, dims, NULL) < 0)
    rc = fail(dset, NULL, "get dimensions");
  else if (row0 > dims[0] || nrows > dims[0] - row0)
    rc = bad(dset, NULL, "rows %llu..%llu outside the %llu rows", (unsigned long long)row0,
             (unsigned long long)(row0 + nrows), (unsigned long long)dims[0]);
  if (rc) return close_id(fs, rc);
  for (int i = 0; i < rank; i++) n *= count[i] = i ? dims[i] : nrows;
  start[0] = row0;
  if (n > 0) { /* nothing to transfer otherwise */
    if ((wbuf ? wbuf : rbuf) == NULL)
      rc = bad(dset, NULL, "null buffer");
    else if (H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL) < 0 ||
             (ms = H5Screate_simple(rank, count, NULL)) < 0)
      rc = fail(dset, NULL, "select rows %llu..%llu", (unsigned long long)row0,
                (unsigned long long)(row0 + nrows));
    else if ((wbuf ? H5Dwrite(dset, mem_type, ms, fs, H5P_DEFAULT, wbuf)
                   : H5Dread(dset, mem_type, ms, fs, H5P_DEFAULT, rbuf)) < 0)
      rc = fail(dset, NULL, "%s rows %llu..%llu", wbuf ? "write" : "read",
                (unsigned long long)row0, (unsigned long long)(row0 + nrows));
  }
  return close_id(ms, close_id(fs, rc));
}

int wg_h5_write_rows(hid_t dset, hid_t mem_type, hsize_t row0, hsize_t nrows, const void *data)
{
  return row_io(dset, mem_type, row0, nrows, data, NULL);
}

static int open_dset(hid_t loc, const char *path, hid_t *d)
{
  if (!path) return bad(loc, NULL, "null dataset path");
  if ((*d = H5Dopen2(loc, path, H5P_DEFAULT)) < 0) return fail(loc, path, "open dataset");
  return WG_OK;
}

int wg_h5_dims(hid_t loc, const char *path, int *rank, hsize_t dims[8])
{
  hid_t d, s = H5I_INVALID_HID;
  int rc = open_dset(loc, path, &d), r;
  if (rc) return rc;
  if ((s = H5Dget_space(d)) < 0 || (r = H5Sget_simple_extent_ndims(s)) < 0)
    rc = fail(loc, path, "get dimensions");
  else if (r > 8)
    rc = bad(loc, path, "rank %d exceeds 8", r);
  else if (H5Sget_simple_extent_dims(s, dims, NULL) < 0)
    rc = fail(loc, path, "get dimensions");
  else
    *rank = r;
  return close_id(d, close_id(s, rc));
}

int wg_h5_read(hid_t loc, const char *path, hid_t mem_type, void *buf)
{
  hid_t d, s = H5I_INVALID_HID;
  hssize_t n = 0;
  int rc = open_dset(loc, path, &d);
  if (rc) return rc;
  if ((s = H5Dget_space(d)) < 0 || (n = H5Sget_simple_extent_npoints(s)) < 0)
    rc = fail(loc, path, "get dataspace");
  else if (n > 0 && !buf)
    rc = bad(loc, path, "null buffer");
  else if (n > 0 && H5Dread(d, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) < 0)
    rc = fail(loc, path, "read dataset");
  return close_id(d, close_id(s, rc));
}

int wg_h5_read_rows(hid_t loc, const char *path, hid_t mem_type, hsize_t row0, hsize_t nrows,
                    void *buf)
{
  hid_t d;
  int rc = open_dset(loc, path, &d);
  if (rc) return rc;
  return close_id(d, row_io(d, mem_type, row0, nrows, NULL, buf));
}

/* ---- H5MD 1.1 ---------------------------------------------------------------------------- */

int wg_h5md_header(hid_t file, const char *author, const char *creator, const char *creator_version)
{
  static const int version[2] = {1, 1};
  int rc;
  if ((rc = make_group(file, "/h5md")) || (rc = wg_h5_attr_ints(file, "/h5md", "version", 2, version)) ||
      (rc = make_group(file, "/h5md/author")) ||
      (rc = wg_h5_attr_string(file, "/h5md/author", "name", author)) ||
      (rc = make_group(file, "/h5md/creator")) ||
      (rc = wg_h5_attr_string(file, "/h5md/creator", "name", creator)))
    return rc;
  if ((rc = wg_h5_attr_string(file, "/h5md/creator", "version", creator_version))) return rc;
  return attr_put_n(file, "/h5md/creator", "wetgran_layout", H5T_STD_I32LE, H5T_NATIVE_INT, 0,
                    &(int){WG_H5_LAYOUT});
}

int wg_h5md_units(hid_t file, const char *system, int n, const char *const *symbol,
                  const char *const *meaning)
{
  static const int version[2] = {1, 0};
  const char *g = "/h5md/modules/units";
  int rc;
  if ((rc = make_group(file, g)) || (rc = wg_h5_attr_ints(file, g, "version", 2, version)) ||
      (rc = wg_h5_attr_string_vl(file, g, "system", system)))
    return rc;
  for (int i = 0; i < n && !rc; i++) rc = wg_h5_attr_string(file, g, symbol[i], meaning[i]);
  return rc;
}

int wg_h5md_box(hid_t file, const char *group, int dim, const double *edges,
                const char *const *boundary)
{
  char box[PATH_LEN], path[PATH_LEN + 8];
  hsize_t n = (hsize_t)dim;
  int rc;
  if (!group || !*group || strchr(group, '/') || dim < 1 || !edges || !boundary)
    return bad(file, "/particles", "invalid H5MD box arguments (group '%s', dimension %d)",
               group ? group : "(null)", dim);
  if (snprintf(box, sizeof box, "/particles/%s/box", group) >= (int)sizeof box)
    return bad(file, "/particles", "particle group name too long");
  for (int i = 0; i < dim; i++)
    if (!boundary[i] || (strcmp(boundary[i], "periodic") && strcmp(boundary[i], "none")))
      return bad(file, box, "boundary[%d] = '%s' is neither 'periodic' nor 'none'", i,
                 boundary[i] ? boundary[i] : "(null)");
  snprintf(path, sizeof path, "%s/edges", box);
  if ((rc = make_group(file, box)) ||
      (rc = attr_put_n(file, box, "dimension", H5T_STD_I32LE, H5T_NATIVE_INT, 0, &dim)) ||
      (rc = wg_h5_attr_strings(file, box, "boundary", dim, boundary)))
    return rc;
  return wg_h5_write(file, path, H5T_NATIVE_DOUBLE, 1, &n, edges, "d",
                     "Edge lengths of the rectangular simulation box.");
}

int wg_h5md_element_create(hid_t file, const char *path, hid_t mem_type, int frame_rank,
                           const hsize_t *frame_dims, hsize_t nframes, const char *unit,
                           const char *description, wg_h5md_element *el)
{
  char p[PATH_LEN + 8];
  hsize_t dims[5] = {nframes};
  int rc;
  if (!el) return bad(file, path, "no element");
  el->value = el->step = el->time = H5I_INVALID_HID;
  if (!path || strlen(path) >= PATH_LEN || frame_rank < 0 || frame_rank > 4 ||
      (frame_rank > 0 && !frame_dims))
    return bad(file, path, "invalid H5MD element arguments (frame rank %d)", frame_rank);
  if ((rc = make_group(file, path))) return rc;
  for (int i = 0; i < 4; i++) el->frame_dims[i] = i < frame_rank ? frame_dims[i] : 0;
  for (int i = 0; i < frame_rank; i++) dims[i + 1] = frame_dims[i];
  el->mem_type = mem_type;
  el->frame_rank = frame_rank;
  el->nframes = nframes;
  el->written = 0;
  snprintf(p, sizeof p, "%s/step", path);
  rc = dset_create(file, p, H5T_NATIVE_LLONG, 1, dims, "1", WG_H5_STEP_MEANING,
                   H5D_FILL_TIME_ALLOC, &el->step);
  snprintf(p, sizeof p, "%s/time", path);
  if (!rc)
    rc = dset_create(file, p, H5T_NATIVE_DOUBLE, 1, dims, "tau",
                     "simulated time of each frame", H5D_FILL_TIME_ALLOC, &el->time);
  snprintf(p, sizeof p, "%s/value", path);
  if (!rc)
    rc = dset_create(file, p, mem_type, frame_rank + 1, dims, unit, description,
                     H5D_FILL_TIME_ALLOC, &el->value);
  if (rc) wg_h5md_element_close(el);
  return rc;
}

int wg_h5md_element_write(wg_h5md_element *el, long long step, double time, const void *frame)
{
  int rc;
  if (el->written >= el->nframes)
    return bad(el->value, NULL, "all %llu frames already written",
               (unsigned long long)el->nframes);
  if ((rc = row_io(el->step, H5T_NATIVE_LLONG, el->written, 1, &step, NULL)) ||
      (rc = row_io(el->time, H5T_NATIVE_DOUBLE, el->written, 1, &time, NULL)) ||
      (rc = row_io(el->value, el->mem_type, el->written, 1, frame, NULL)))
    return rc;
  el->written++;
  return WG_OK;
}

int wg_h5md_element_close(wg_h5md_element *el)
{
  int rc = close_id(el->value, close_id(el->time, close_id(el->step, WG_OK)));
  el->value = el->step = el->time = H5I_INVALID_HID;
  return rc;
}
