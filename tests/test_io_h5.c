/* Tests of sim/common/io_h5.c: round trips of every writer/reader, row blocks, attribute overwrite,
   the H5MD layout, empty datasets, byte-identical files, timestamps off, and error reports. */
#define _POSIX_C_SOURCE 200809L

#include "io_h5.h"
#include "tharness.h"

#include <float.h>
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static char dir[64]; /* mkdtemp directory holding every file of this test */

static const char *tmp(const char *name)
{
  static char buf[8][256]; /* a few paths alive at once */
  static int k;
  k = (k + 1) % 8;
  snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
  return buf[k];
}

/* ---- stderr capture --------------------------------------------------------------------- */

typedef struct {
  int saved, fd;
  char path[256];
} capture;

static void capture_begin(capture *c)
{
  snprintf(c->path, sizeof c->path, "%s/stderr_XXXXXX", dir);
  fflush(stderr);
  c->fd = mkstemp(c->path);
  c->saved = dup(STDERR_FILENO);
  dup2(c->fd, STDERR_FILENO);
}

static void capture_end(capture *c, char *out, size_t n)
{
  ssize_t k;
  fflush(stderr);
  dup2(c->saved, STDERR_FILENO);
  close(c->saved);
  lseek(c->fd, 0, SEEK_SET);
  k = read(c->fd, out, n - 1);
  out[k > 0 ? k : 0] = '\0';
  if (k > 0 && out[k - 1] == '\n') out[k - 1] = '\0'; /* the last newline, for one-line output */
  close(c->fd);
  unlink(c->path);
}

/* ---- helpers ------------------------------------------------------------------------------ */

static long file_size(const char *path)
{
  struct stat st;
  return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

/* Whole file in a malloc'ed buffer (NULL on failure). */
static unsigned char *slurp(const char *path, long *n)
{
  FILE *f = fopen(path, "rb");
  unsigned char *buf = NULL;
  *n = file_size(path);
  if (f && *n >= 0 && (buf = malloc((size_t)*n + 1)) && fread(buf, 1, (size_t)*n, f) != (size_t)*n) {
    free(buf);
    buf = NULL;
  }
  if (f) fclose(f);
  return buf;
}

/* 1 if the dataset's file type equals `type` and its layout is contiguous. */
static int dset_is(hid_t loc, const char *path, hid_t type)
{
  hid_t d = H5Dopen2(loc, path, H5P_DEFAULT), t = H5Dget_type(d), p = H5Dget_create_plist(d);
  int ok = H5Tequal(t, type) > 0 && H5Pget_layout(p) == H5D_CONTIGUOUS;
  H5Pclose(p);
  H5Tclose(t);
  H5Dclose(d);
  return ok;
}

static int str_attr_is(hid_t loc, const char *obj, const char *name, const char *want)
{
  char buf[256] = "";
  return wg_h5_read_attr_string(loc, obj, name, buf, sizeof buf) == WG_OK && strcmp(buf, want) == 0;
}

typedef struct {
  int objects, stamped;
} stamps;

static herr_t count_stamps(hid_t o, const char *name, const H5O_info_t *info, void *data)
{
  stamps *s = data;
  (void)o;
  s->objects++;
  if (info->atime || info->mtime || info->ctime || info->btime) {
    s->stamped++;
    printf("      timestamped object: %s\n", name);
  }
  return 0;
}

static stamps count_file_stamps(const char *path)
{
  stamps s = {0, 0};
  hid_t f = wg_h5_open_read(path);
  H5Ovisit2(f, H5_INDEX_NAME, H5_ITER_INC, count_stamps, &s, H5O_INFO_TIME);
  wg_h5_close(f);
  return s;
}

/* ---- round trips ---------------------------------------------------------------------------- */

static void test_roundtrip(void)
{
  const char *path = tmp("roundtrip.h5");
  uint64_t nan_bits = 0x7ff8000000000123ull;
  double d[3][4] = {{-0.0, 1.0 / 3.0, DBL_MAX, 4.9e-324},
                    {-1e-300, INFINITY, -INFINITY, 0},
                    {DBL_MIN, -DBL_EPSILON, 6.02214076e23, 0}},
         d2[3][4];
  int iv[5] = {INT_MIN, -1, 0, 1, INT_MAX}, iv2[5];
  long long lv[3] = {LLONG_MIN, 0, LLONG_MAX}, lv2[3];
  uint8_t uv[4] = {0, 1, 128, 255}, uv2[4];
  unsigned long long qv[2] = {0, ULLONG_MAX}, qv2[2];
  float fv[2] = {1.5f, -FLT_MAX}, fv2[2];
  hsize_t d_dims[2] = {3, 4}, n5 = 5, n3 = 3, n4 = 4, n2 = 2, dims[8];
  int rank = -1;
  hid_t f;

  memcpy(&d[2][3], &nan_bits, sizeof nan_bits);
  f = wg_h5_create(path);
  TH_CHECK(f >= 0, "create %s", path);
  TH_CHECK(wg_h5_write(f, "/data/doubles", H5T_NATIVE_DOUBLE, 2, d_dims, d, "d", "Doubles.") == WG_OK,
           "write doubles");
  TH_CHECK(wg_h5_write(f, "data/ints", H5T_NATIVE_INT, 1, &n5, iv, "1", "Ints.") == WG_OK,
           "write ints (relative path)");
  TH_CHECK(wg_h5_write(f, "/a/b/c/llongs", H5T_NATIVE_LLONG, 1, &n3, lv, "1", "Long longs.") == WG_OK,
           "write long longs, 3 new groups");
  TH_CHECK(wg_h5_write(f, "/data/u8", H5T_NATIVE_UINT8, 1, &n4, uv, "1", "Bytes.") == WG_OK, "write uint8");
  TH_CHECK(wg_h5_write(f, "/data/u64", H5T_NATIVE_ULLONG, 1, &n2, qv, "1", "Unsigned.") == WG_OK,
           "write unsigned long long");
  TH_CHECK(wg_h5_write(f, "/data/floats", H5T_NATIVE_FLOAT, 1, &n2, fv, "1", "Floats.") == WG_OK,
           "write floats");
  TH_CHECK(wg_h5_exists(f, "/a/b/c/llongs") == 1 && wg_h5_exists(f, "a/b") == 1 && wg_h5_exists(f, "/") == 1,
           "exists: dataset, group, root");
  TH_CHECK(wg_h5_exists(f, "/a/x/y") == 0 && wg_h5_exists(f, "/data/ints/x") == 0 && wg_h5_exists(f, "") == 0,
           "exists: missing intermediate, below a dataset, empty path");
  TH_CHECK(wg_h5_close(f) == WG_OK, "close");

  f = wg_h5_open_read(path);
  TH_CHECK(f >= 0, "open read-only");
  memset(d2, 0xAB, sizeof d2);
  TH_CHECK(wg_h5_read(f, "/data/doubles", H5T_NATIVE_DOUBLE, d2) == WG_OK && memcmp(d, d2, sizeof d) == 0,
           "doubles bit-exact (-0, NaN payload, denormal, inf, DBL_MAX)");
  TH_CHECK(wg_h5_read(f, "/data/ints", H5T_NATIVE_INT, iv2) == WG_OK && memcmp(iv, iv2, sizeof iv) == 0,
           "ints");
  TH_CHECK(wg_h5_read(f, "/a/b/c/llongs", H5T_NATIVE_LLONG, lv2) == WG_OK && memcmp(lv, lv2, sizeof lv) == 0,
           "long longs");
  TH_CHECK(wg_h5_read(f, "/data/u8", H5T_NATIVE_UINT8, uv2) == WG_OK && memcmp(uv, uv2, sizeof uv) == 0,
           "uint8");
  TH_CHECK(wg_h5_read(f, "/data/u64", H5T_NATIVE_ULLONG, qv2) == WG_OK && memcmp(qv, qv2, sizeof qv) == 0,
           "unsigned long long");
  TH_CHECK(wg_h5_read(f, "/data/floats", H5T_NATIVE_FLOAT, fv2) == WG_OK && memcmp(fv, fv2, sizeof fv) == 0,
           "floats");
  TH_CHECK(wg_h5_dims(f, "/data/doubles", &rank, dims) == WG_OK && rank == 2 && dims[0] == 3 && dims[1] == 4,
           "dims: rank %d, %llu x %llu", rank, (unsigned long long)dims[0], (unsigned long long)dims[1]);
  TH_CHECK(dset_is(f, "/data/doubles", H5T_IEEE_F64LE) && dset_is(f, "/data/ints", H5T_STD_I32LE) &&
               dset_is(f, "/a/b/c/llongs", H5T_STD_I64LE) && dset_is(f, "/data/u8", H5T_STD_U8LE) &&
               dset_is(f, "/data/u64", H5T_STD_U64LE) && dset_is(f, "/data/floats", H5T_IEEE_F32LE),
           "file types are little-endian standard types, layout contiguous");
  TH_CHECK(str_attr_is(f, "/data/doubles", "unit", "d") &&
               str_attr_is(f, "/data/doubles", "description", "Doubles.") &&
               str_attr_is(f, "/a/b/c/llongs", "unit", "1"),
           "unit and description attributes");
  TH_CHECK(H5Fget_obj_count(f, H5F_OBJ_ALL) == 1, "no object left open (%ld)",
           (long)H5Fget_obj_count(f, H5F_OBJ_ALL));
  wg_h5_close(f);
  remove(path);
}

static void test_strings(void)
{
  const char *path = tmp("strings.h5");
  const char *vl = "variable-length value";
  char buf[64], small[4];
  hid_t f = wg_h5_create(path), t, s, a, at;

  TH_CHECK(wg_h5_attr_string(f, ".", "fixed", "hello world") == WG_OK, "fixed string attribute");
  /* a variable-length string attribute, as other tools (h5py) write them */
  t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, H5T_VARIABLE);
  s = H5Screate(H5S_SCALAR);
  a = H5Acreate2(f, "vlen", t, s, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, t, &vl);
  H5Aclose(a);
  H5Sclose(s);
  H5Tclose(t);
  wg_h5_close(f);

  f = wg_h5_open_read(path);
  TH_CHECK(str_attr_is(f, ".", "fixed", "hello world"), "fixed string read back");
  TH_CHECK(str_attr_is(f, "/", "vlen", vl), "variable-length string read back");
  a = H5Aopen_by_name(f, ".", "fixed", H5P_DEFAULT, H5P_DEFAULT);
  at = H5Aget_type(a);
  TH_CHECK(H5Tget_class(at) == H5T_STRING && H5Tis_variable_str(at) == 0 && H5Tget_size(at) == 12 &&
               H5Tget_strpad(at) == H5T_STR_NULLPAD && H5Tget_cset(at) == H5T_CSET_ASCII,
           "stored as fixed-length (12), NUL-padded, ASCII");
  H5Tclose(at);
  H5Aclose(a);
  {
    capture c;
    capture_begin(&c);
    int rc1 = wg_h5_read_attr_string(f, ".", "fixed", small, sizeof small);
    int rc2 = wg_h5_read_attr_string(f, ".", "vlen", small, sizeof small);
    capture_end(&c, buf, sizeof buf);
    TH_CHECK(rc1 == WG_EINVAL && rc2 == WG_EINVAL, "too small buffer refused (fixed %d, vlen %d)", rc1, rc2);
  }
  TH_CHECK(H5Fget_obj_count(f, H5F_OBJ_ALL) == 1, "no object left open");
  wg_h5_close(f);
  remove(path);
}

/* ---- row blocks ---------------------------------------------------------------------------- */

static void test_rows(void)
{
  const char *path = tmp("rows.h5");
  double all[10][3], back[10][3], part[4][3], zero[3] = {0, 0, 0};
  long long ll[6] = {10, 11, 12, 13, 14, 15}, ll2[2];
  hsize_t dims[2] = {10, 3}, dims2[2] = {4, 3}, n6 = 6;
  hid_t f = wg_h5_create(path), d, d2;
  char err[512];
  capture c;

  for (int i = 0; i < 10; i++)
    for (int j = 0; j < 3; j++)
      all[i][j] = i + 0.1 * j + 1e-17 * i * j;
  d = wg_h5_dataset_create(f, "/series/x", H5T_NATIVE_DOUBLE, 2, dims, "d", "Row test.");
  TH_CHECK(d >= 0, "dataset_create");
  TH_CHECK(wg_h5_write_rows(d, H5T_NATIVE_DOUBLE, 0, 4, all[0]) == WG_OK &&
               wg_h5_write_rows(d, H5T_NATIVE_DOUBLE, 4, 5, all[4]) == WG_OK &&
               wg_h5_write_rows(d, H5T_NATIVE_DOUBLE, 9, 1, all[9]) == WG_OK &&
               wg_h5_write_rows(d, H5T_NATIVE_DOUBLE, 10, 0, NULL) == WG_OK,
           "write rows in blocks 4+5+1 (+0)");
  capture_begin(&c);
  int rc = wg_h5_write_rows(d, H5T_NATIVE_DOUBLE, 8, 3, all[0]);
  capture_end(&c, err, sizeof err);
  TH_CHECK(rc == WG_EINVAL && strstr(err, "/series/x") && strstr(err, "outside"),
           "rows 8..11 of 10 refused: %s", err);
  TH_CHECK(H5Dclose(d) >= 0, "close dataset");
  d2 = wg_h5_dataset_create(f, "/series/partial", H5T_NATIVE_DOUBLE, 2, dims2, "d", "Partly written.");
  TH_CHECK(d2 >= 0 && wg_h5_write_rows(d2, H5T_NATIVE_DOUBLE, 1, 1, all[1]) == WG_OK,
           "write one row of four");
  H5Dclose(d2);
  d2 = wg_h5_dataset_create(f, "/series/ll", H5T_NATIVE_LLONG, 1, &n6, "1", "Rank-1 rows.");
  TH_CHECK(d2 >= 0 && wg_h5_write_rows(d2, H5T_NATIVE_LLONG, 0, 6, ll) == WG_OK, "rank-1 row write");
  H5Dclose(d2);
  wg_h5_close(f);

  f = wg_h5_open_read(path);
  TH_CHECK(wg_h5_read(f, "/series/x", H5T_NATIVE_DOUBLE, back) == WG_OK && memcmp(all, back, sizeof all) == 0,
           "whole dataset equals the blocks written");
  TH_CHECK(wg_h5_read_rows(f, "/series/x", H5T_NATIVE_DOUBLE, 3, 4, part) == WG_OK &&
               memcmp(part, all[3], sizeof part) == 0,
           "read rows 3..7");
  TH_CHECK(wg_h5_read_rows(f, "/series/partial", H5T_NATIVE_DOUBLE, 3, 1, part) == WG_OK &&
               memcmp(part[0], zero, sizeof zero) == 0,
           "unwritten rows read as zeros");
  TH_CHECK(wg_h5_read_rows(f, "/series/partial", H5T_NATIVE_DOUBLE, 1, 1, part) == WG_OK &&
               memcmp(part[0], all[1], sizeof zero) == 0,
           "written row of a partial dataset");
  TH_CHECK(wg_h5_read_rows(f, "series/ll", H5T_NATIVE_LLONG, 4, 2, ll2) == WG_OK && ll2[0] == 14 &&
               ll2[1] == 15,
           "rank-1 read rows 4..6: %lld %lld", ll2[0], ll2[1]);
  capture_begin(&c);
  rc = wg_h5_read_rows(f, "/series/x", H5T_NATIVE_DOUBLE, 11, 0, part);
  capture_end(&c, err, sizeof err);
  TH_CHECK(rc == WG_EINVAL && strstr(err, path) && strstr(err, "/series/x"), "read past the end refused: %s",
           err);
  TH_CHECK(H5Fget_obj_count(f, H5F_OBJ_ALL) == 1, "no object left open");
  wg_h5_close(f);
  remove(path);
}

/* ---- attributes ----------------------------------------------------------------------------- */

static int num_attrs(hid_t loc, const char *obj)
{
  H5O_info_t info;
  return H5Oget_info_by_name2(loc, obj, &info, H5O_INFO_NUM_ATTRS, H5P_DEFAULT) < 0 ? -1
                                                                                    : (int)info.num_attrs;
}

static void test_attributes(void)
{
  const char *path = tmp("attrs.h5"), *path2 = tmp("attrs_before.h5");
  const double three[3] = {1.0 / 3.0, -0.0, 1e300}, two[2] = {5, 6};
  const int ints[4] = {INT_MIN, 0, 7, INT_MAX};
  double v = 0, dv[3];
  long long ll = 0;
  int iv[4];
  hsize_t n1 = 1;
  hid_t f = wg_h5_create(path), g, a, s;
  char err[512];
  capture c;

  g = wg_h5_group(f, "/grp/sub");
  TH_CHECK(g >= 0, "group with intermediate group");
  TH_CHECK(wg_h5_attr_double(g, ".", "dot", 1.25) == WG_OK, "attribute on '.' (the group itself)");
  TH_CHECK(wg_h5_attr_double(f, "/grp/sub", "x", 1.5) == WG_OK &&
               wg_h5_attr_double(f, "grp/sub", "x", 2.5) == WG_OK,
           "double attribute written twice");
  TH_CHECK(wg_h5_attr_double(f, "/grp", "kind", 1.0) == WG_OK &&
               wg_h5_attr_string(f, "/grp", "kind", "now a string") == WG_OK,
           "same name, new type (double -> string)");
  TH_CHECK(wg_h5_attr_doubles(f, "/grp", "arr", 3, three) == WG_OK &&
               wg_h5_attr_doubles(f, "/grp", "arr", 2, two) == WG_OK,
           "double array rewritten with another length");
  TH_CHECK(wg_h5_attr_llong(f, "/", "seed", LLONG_MIN) == WG_OK &&
               wg_h5_attr_llong(f, "/", "seed", 0x123456789abcdefLL) == WG_OK,
           "long long attribute written twice");
  TH_CHECK(wg_h5_attr_ints(f, "/grp", "ints", 4, ints) == WG_OK, "int array attribute");
  TH_CHECK(wg_h5_write(f, "/grp/ds", H5T_NATIVE_DOUBLE, 1, &n1, two, "d", "One value.") == WG_OK &&
               wg_h5_attr_string(f, "/grp/ds", "unit", "m g d") == WG_OK,
           "dataset unit overwritten");
  H5Gclose(g);
  wg_h5_close(f);

  f = wg_h5_open_read(path);
  TH_CHECK(wg_h5_read_attr_double(f, "/grp/sub", "dot", &v) == WG_OK && v == 1.25,
           "'.' attribute read back: %g", v);
  TH_CHECK(wg_h5_read_attr_double(f, "/grp/sub", "x", &v) == WG_OK && v == 2.5, "overwritten double: %g", v);
  TH_CHECK(num_attrs(f, "/grp/sub") == 2 && num_attrs(f, "/grp") == 3 && num_attrs(f, "/grp/ds") == 2,
           "no duplicate attributes (%d, %d, %d)", num_attrs(f, "/grp/sub"), num_attrs(f, "/grp"),
           num_attrs(f, "/grp/ds"));
  TH_CHECK(str_attr_is(f, "/grp", "kind", "now a string"), "type-changed attribute read back as string");
  capture_begin(&c);
  int rc = wg_h5_read_attr_double(f, "/grp", "arr", &v);
  capture_end(&c, err, sizeof err);
  TH_CHECK(rc == WG_EINVAL && strstr(err, "'arr'") && strstr(err, "2 elements"),
           "array read as scalar refused: %s", err);
  a = H5Aopen_by_name(f, "/grp", "arr", H5P_DEFAULT, H5P_DEFAULT);
  s = H5Aget_space(a);
  TH_CHECK(H5Sget_simple_extent_npoints(s) == 2 && H5Aread(a, H5T_NATIVE_DOUBLE, dv) >= 0 && dv[0] == 5 &&
               dv[1] == 6,
           "rewritten array has 2 elements: %g %g", dv[0], dv[1]);
  H5Sclose(s);
  H5Aclose(a);
  a = H5Aopen_by_name(f, "/grp", "ints", H5P_DEFAULT, H5P_DEFAULT);
  TH_CHECK(H5Aread(a, H5T_NATIVE_INT, iv) >= 0 && memcmp(iv, ints, sizeof ints) == 0, "int array read back");
  H5Aclose(a);
  TH_CHECK(wg_h5_read_attr_llong(f, ".", "seed", &ll) == WG_OK && ll == 0x123456789abcdefLL,
           "long long: %llx", (unsigned long long)ll);
  TH_CHECK(str_attr_is(f, "/grp/ds", "unit", "m g d"), "dataset unit rewritten");
  TH_CHECK(H5Fget_obj_count(f, H5F_OBJ_ALL) == 1, "no object left open");
  wg_h5_close(f);

  /* fixed-length provenance: rewriting it changes only bytes inside its 64-byte value */
  f = wg_h5_open_rw(path);
  TH_CHECK(wg_h5_attr_string_fixed(f, ".", "provenance", "started", 64) == WG_OK, "fixed provenance written");
  wg_h5_close(f);
  {
    long n1b = 0, n2b = 0, first = -1, last = -1;
    unsigned char *before, *after;
    rename(path, path2);
    before = slurp(path2, &n1b);
    FILE *out = fopen(path, "wb");
    fwrite(before, 1, (size_t)n1b, out);
    fclose(out);
    f = wg_h5_open_rw(path);
    TH_CHECK(wg_h5_attr_string_fixed(f, ".", "provenance", "finished: 1000 steps, exit 0", 64) == WG_OK,
             "fixed provenance rewritten");
    TH_CHECK(str_attr_is(f, ".", "provenance", "finished: 1000 steps, exit 0"), "new provenance read back");
    wg_h5_close(f);
    after = slurp(path, &n2b);
    for (long i = 0; before && after && i < n1b && i < n2b; i++)
      if (before[i] != after[i]) last = i, first = first < 0 ? i : first;
    TH_CHECK(n1b == n2b && first >= 0 && last - first < 64,
             "rewrite in place: size %ld -> %ld, changed bytes %ld..%ld", n1b, n2b, first, last);
    free(before);
    free(after);
    remove(path2);
  }
  f = wg_h5_open_rw(path);
  capture_begin(&c);
  rc = wg_h5_attr_string_fixed(f, ".", "provenance", "0123456789", 10);
  capture_end(&c, err, sizeof err);
  TH_CHECK(rc == WG_EINVAL && strstr(err, "provenance"), "string without room for its NUL refused: %s", err);
  wg_h5_close(f);
  remove(path);
}

/* ---- H5MD ------------------------------------------------------------------------------------ */

static void test_h5md(void)
{
  const char *path = tmp("h5md.h5");
  const char *const bnd[3] = {"periodic", "periodic", "none"}, *const bad_bnd[2] = {"periodic", "open"};
  const double edges[3] = {20, 10, 1e9};
  double pos[3][4][3], pos2[3][4][3], e2[3], t2[3], en[2] = {-1.5, -2.5}, en2[2];
  long long st2[3];
  int version[2] = {0, 0}, rank;
  char b[3][9];
  hsize_t fd[2] = {4, 3}, dims[8];
  long long dimension = 0;
  wg_h5md_element el, en_el;
  hid_t f = wg_h5_create(path), a, s, t;
  char err[512];
  capture c;

  for (int k = 0; k < 3; k++)
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 3; j++)
        pos[k][i][j] = 100 * k + 10 * i + j + 0.5;
  TH_CHECK(wg_h5md_header(f, "A. Author", "wetgran", "v1.2-3-gabc") == WG_OK, "h5md header");
  TH_CHECK(wg_h5md_box(f, "all", 3, edges, bnd) == WG_OK, "h5md box");
  capture_begin(&c);
  int rc = wg_h5md_box(f, "bad", 2, edges, bad_bnd);
  capture_end(&c, err, sizeof err);
  TH_CHECK(rc == WG_EINVAL && strstr(err, "open"), "boundary 'open' refused: %s", err);
  TH_CHECK(wg_h5md_element_create(f, "/particles/all/position", H5T_NATIVE_DOUBLE, 2, fd, 3, "d",
                                  "Particle centres.", &el) == WG_OK,
           "element create");
  for (int k = 0; k < 3; k++)
    TH_CHECK(wg_h5md_element_write(&el, 1000 * k, 0.25 * k, pos[k]) == WG_OK, "frame %d", k);
  capture_begin(&c);
  rc = wg_h5md_element_write(&el, 3000, 0.75, pos[0]);
  capture_end(&c, err, sizeof err);
  TH_CHECK(rc == WG_EINVAL && strstr(err, "/particles/all/position/value"), "fourth frame refused: %s", err);
  TH_CHECK(wg_h5md_element_close(&el) == WG_OK && el.value < 0, "element close");
  TH_CHECK(wg_h5md_element_create(f, "/observables/energy", H5T_NATIVE_DOUBLE, 0, NULL, 2, "m g d",
                                  "Total energy.", &en_el) == WG_OK &&
               wg_h5md_element_write(&en_el, 0, 0.0, &en[0]) == WG_OK &&
               wg_h5md_element_write(&en_el, 5, 0.5, &en[1]) == WG_OK &&
               wg_h5md_element_close(&en_el) == WG_OK,
           "scalar-per-frame element");
  wg_h5_close(f);

  f = wg_h5_open_read(path);
  a = H5Aopen_by_name(f, "/h5md", "version", H5P_DEFAULT, H5P_DEFAULT);
  s = H5Aget_space(a);
  t = H5Aget_type(a);
  TH_CHECK(H5Sget_simple_extent_npoints(s) == 2 && H5Tequal(t, H5T_STD_I32LE) > 0 &&
               H5Aread(a, H5T_NATIVE_INT, version) >= 0 && version[0] == 1 && version[1] == 1,
           "/h5md version = {%d, %d}", version[0], version[1]);
  H5Tclose(t);
  H5Sclose(s);
  H5Aclose(a);
  TH_CHECK(str_attr_is(f, "/h5md/author", "name", "A. Author") &&
               str_attr_is(f, "/h5md/creator", "name", "wetgran") &&
               str_attr_is(f, "/h5md/creator", "version", "v1.2-3-gabc"),
           "author and creator");
  a = H5Aopen_by_name(f, "/particles/all/box", "dimension", H5P_DEFAULT, H5P_DEFAULT);
  s = H5Aget_space(a);
  TH_CHECK(H5Sget_simple_extent_type(s) == H5S_SCALAR &&
               wg_h5_read_attr_llong(f, "/particles/all/box", "dimension", &dimension) == WG_OK &&
               dimension == 3,
           "box dimension = %lld (scalar)", dimension);
  H5Sclose(s);
  H5Aclose(a);
  a = H5Aopen_by_name(f, "/particles/all/box", "boundary", H5P_DEFAULT, H5P_DEFAULT);
  s = H5Aget_space(a);
  t = H5Aget_type(a);
  TH_CHECK(H5Sget_simple_extent_npoints(s) == 3 && H5Tget_size(t) == 9 && H5Aread(a, t, b) >= 0 &&
               strcmp(b[0], "periodic") == 0 && strcmp(b[1], "periodic") == 0 && strcmp(b[2], "none") == 0,
           "boundary = {%.9s, %.9s, %.9s}", b[0], b[1], b[2]);
  H5Tclose(t);
  H5Sclose(s);
  H5Aclose(a);
  TH_CHECK(wg_h5_read(f, "/particles/all/box/edges", H5T_NATIVE_DOUBLE, e2) == WG_OK &&
               memcmp(e2, edges, sizeof e2) == 0 && str_attr_is(f, "/particles/all/box/edges", "unit", "d"),
           "box edges");
  TH_CHECK(wg_h5_dims(f, "/particles/all/position/value", &rank, dims) == WG_OK && rank == 3 &&
               dims[0] == 3 && dims[1] == 4 && dims[2] == 3,
           "value shape {3, 4, 3}");
  TH_CHECK(wg_h5_dims(f, "/particles/all/position/step", &rank, dims) == WG_OK && rank == 1 && dims[0] == 3 &&
               dset_is(f, "/particles/all/position/step", H5T_STD_I64LE),
           "step: int64 {3}");
  TH_CHECK(wg_h5_dims(f, "/particles/all/position/time", &rank, dims) == WG_OK && rank == 1 && dims[0] == 3 &&
               dset_is(f, "/particles/all/position/time", H5T_IEEE_F64LE),
           "time: double {3}");
  TH_CHECK(wg_h5_read(f, "/particles/all/position/value", H5T_NATIVE_DOUBLE, pos2) == WG_OK &&
               memcmp(pos, pos2, sizeof pos) == 0,
           "frames read back");
  TH_CHECK(wg_h5_read(f, "/particles/all/position/step", H5T_NATIVE_LLONG, st2) == WG_OK && st2[0] == 0 &&
               st2[1] == 1000 && st2[2] == 2000,
           "steps %lld %lld %lld", st2[0], st2[1], st2[2]);
  TH_CHECK(wg_h5_read(f, "/particles/all/position/time", H5T_NATIVE_DOUBLE, t2) == WG_OK && t2[0] == 0 &&
               t2[1] == 0.25 && t2[2] == 0.5,
           "times");
  TH_CHECK(str_attr_is(f, "/particles/all/position/time", "unit", "tau") &&
               str_attr_is(f, "/particles/all/position/value", "unit", "d") &&
               str_attr_is(f, "/particles/all/position/value", "description", "Particle centres.") &&
               str_attr_is(f, "/particles/all/position/step", "unit", "1"),
           "element units and descriptions");
  TH_CHECK(wg_h5_dims(f, "/observables/energy/value", &rank, dims) == WG_OK && rank == 1 && dims[0] == 2 &&
               wg_h5_read(f, "/observables/energy/value", H5T_NATIVE_DOUBLE, en2) == WG_OK && en2[1] == -2.5,
           "scalar element value {2}");
  TH_CHECK(H5Fget_obj_count(f, H5F_OBJ_ALL) == 1, "no object left open");
  wg_h5_close(f);
  remove(path);
}

/* ---- layout 2: typed parameters read like text ones, units module, layout version --------------- */

static void test_layout2(void)
{
  const char *path = tmp("layout2.h5");
  const char *sym[2] = {"d", "tau"}, *meaning[2] = {"length", "time"};
  hid_t f = wg_h5_create(path), g, a, t;
  double v = 0, one = 1;
  long long layout = 0;
  char err[512], buf[64];
  capture c;
  hsize_t n1 = 1;

  TH_CHECK(wg_h5_layout(f) == 1, "a file without /h5md is layout 1");
  TH_CHECK(wg_h5md_header(f, "A", "wetgran", "v") == WG_OK &&
               wg_h5md_units(f, "wetgran", 2, sym, meaning) == WG_OK &&
               wg_h5_write(f, "/x", H5T_NATIVE_DOUBLE, 1, &n1, &one, "m d+2 tau-2", "One.") == WG_OK,
           "header, units module, a dataset");
  g = wg_h5_group(f, "/parameters");
  TH_CHECK(g >= 0 && wg_h5_attr_double(g, ".", "gamma", 20) == WG_OK &&
               wg_h5_attr_llong(g, ".", "n", 1200) == WG_OK &&
               wg_h5_attr_ullong(g, ".", "seed", 18446744073709551615ULL) == WG_OK &&
               wg_h5_attr_string(g, ".", "old_gamma", "20") == WG_OK &&
               wg_h5_attr_string(g, ".", "old_eps", "0.96") == WG_OK &&
               wg_h5_attr_string(g, ".", "container", "shaker") == WG_OK &&
               wg_h5_attr_string(g, ".", "trailing", "1.5x") == WG_OK,
           "typed and text parameters written");
  if (g >= 0) H5Gclose(g);
  wg_h5_close(f);

  f = wg_h5_open_read(path);
  TH_CHECK(wg_h5_layout(f) == WG_H5_LAYOUT && WG_H5_LAYOUT == 2 &&
               wg_h5_read_attr_llong(f, "/h5md/creator", "wetgran_layout", &layout) == WG_OK && layout == 2,
           "layout %lld on /h5md/creator", layout);
  TH_CHECK(wg_h5_read_param_double(f, "gamma", &v) == WG_OK && v == 20, "float64 parameter: %g", v);
  TH_CHECK(wg_h5_read_param_double(f, "n", &v) == WG_OK && v == 1200, "int64 parameter: %g", v);
  TH_CHECK(wg_h5_read_param_double(f, "seed", &v) == WG_OK && v == 18446744073709551615.0, "uint64 parameter: %g", v);
  TH_CHECK(wg_h5_read_param_double(f, "old_gamma", &v) == WG_OK && v == 20 &&
               wg_h5_read_param_double(f, "old_eps", &v) == WG_OK && v == 0.96,
           "text parameters (layout 1) read as numbers");
  capture_begin(&c);
  int rc = wg_h5_read_param_double(f, "container", &v);
  capture_end(&c, err, sizeof err);
  TH_CHECK(rc == WG_EINVAL && strstr(err, "'container'") && strstr(err, "not a number"), "a word refused: %s", err);
  capture_begin(&c);
  rc = wg_h5_read_param_double(f, "trailing", &v);
  capture_end(&c, err, sizeof err);
  TH_CHECK(rc == WG_EINVAL && strstr(err, "'1.5x'"), "trailing text refused: %s", err);
  capture_begin(&c);
  rc = wg_h5_read_param_double(f, "nothing", &v);
  capture_end(&c, err, sizeof err);
  TH_CHECK(rc != WG_OK && strstr(err, "'nothing'"), "missing parameter named: %s", err);
  a = H5Aopen_by_name(f, "/x", "unit", H5P_DEFAULT, H5P_DEFAULT);
  t = H5Aget_type(a);
  TH_CHECK(H5Tis_variable_str(t) > 0 && H5Tget_cset(t) == H5T_CSET_ASCII && str_attr_is(f, "/x", "unit", "m d+2 tau-2"),
           "unit: variable-length ASCII string (units module)");
  H5Tclose(t);
  H5Aclose(a);
  int version[2] = {0, 0};
  a = H5Aopen_by_name(f, "/h5md/modules/units", "version", H5P_DEFAULT, H5P_DEFAULT);
  TH_CHECK(H5Aread(a, H5T_NATIVE_INT, version) >= 0 && version[0] == 1 && version[1] == 0 &&
               wg_h5_read_attr_string(f, "/h5md/modules/units", "system", buf, sizeof buf) == WG_OK &&
               strcmp(buf, "wetgran") == 0 && str_attr_is(f, "/h5md/modules/units", "tau", "time"),
           "units module: version {%d, %d}, system, symbols", version[0], version[1]);
  H5Aclose(a);
  TH_CHECK(H5Fget_obj_count(f, H5F_OBJ_ALL) == 1, "no object left open");
  wg_h5_close(f);
  remove(path);
}

/* ---- empty datasets ---------------------------------------------------------------------------- */

static void test_empty(void)
{
  const char *path = tmp("empty.h5");
  hsize_t dims0[2] = {0, 2}, dims[8], fd = 3;
  int rank = -1, dummy[2];
  wg_h5md_element el;
  hid_t f = wg_h5_create(path), d;

  TH_CHECK(wg_h5_write(f, "/bridges/pairs", H5T_NATIVE_INT, 2, dims0, NULL, "1", "No bridges.") == WG_OK,
           "write {0, 2} with no data");
  d = wg_h5_dataset_create(f, "/bridges/rows", H5T_NATIVE_DOUBLE, 2, dims0, "d", "Empty rows.");
  TH_CHECK(d >= 0 && wg_h5_write_rows(d, H5T_NATIVE_DOUBLE, 0, 0, NULL) == WG_OK,
           "empty dataset_create, write 0 rows");
  H5Dclose(d);
  TH_CHECK(wg_h5md_element_create(f, "/particles/all/force", H5T_NATIVE_DOUBLE, 1, &fd, 0, "m g", "None.",
                                  &el) == WG_OK &&
               wg_h5md_element_close(&el) == WG_OK,
           "element with zero frames");
  wg_h5_close(f);

  f = wg_h5_open_read(path);
  TH_CHECK(wg_h5_dims(f, "/bridges/pairs", &rank, dims) == WG_OK && rank == 2 && dims[0] == 0 && dims[1] == 2,
           "dims {0, 2} read back");
  TH_CHECK(dset_is(f, "/bridges/pairs", H5T_STD_I32LE), "empty dataset is contiguous int32");
  TH_CHECK(wg_h5_read(f, "/bridges/pairs", H5T_NATIVE_INT, NULL) == WG_OK &&
               wg_h5_read_rows(f, "/bridges/rows", H5T_NATIVE_DOUBLE, 0, 0, dummy) == WG_OK,
           "read empty datasets");
  TH_CHECK(wg_h5_dims(f, "/particles/all/force/value", &rank, dims) == WG_OK && rank == 2 && dims[0] == 0 &&
               dims[1] == 3,
           "empty element value {0, 3}");
  wg_h5_close(f);
  remove(path);
}

/* ---- determinism and timestamps ------------------------------------------------------------------ */

/* A representative write sequence: everything the module can write. */
static int write_sequence(const char *path)
{
  const char *const bnd[2] = {"periodic", "none"};
  const double edges[2] = {32, 16}, series[4][2] = {{1, 2}, {3, 4}, {5, 6}, {7, 8}};
  double frame[5][2];
  const int pairs[3][2] = {{0, 1}, {1, 2}, {3, 4}};
  hsize_t pd[2] = {3, 2}, sd[2] = {4, 2}, fd[2] = {5, 2}, e0[2] = {0, 2};
  wg_h5md_element el;
  hid_t f = wg_h5_create(path), d;
  int rc = f < 0;

  rc |= wg_h5md_header(f, "Author", "wetgran", "test");
  rc |= wg_h5md_box(f, "all", 2, edges, bnd);
  rc |=
      wg_h5md_element_create(f, "/particles/all/position", H5T_NATIVE_DOUBLE, 2, fd, 2, "d", "Centres.", &el);
  for (int k = 0; k < 2; k++) {
    for (int i = 0; i < 5; i++)
      frame[i][0] = frame[i][1] = k + i / 7.0;
    rc |= wg_h5md_element_write(&el, k, 0.5 * k, frame);
  }
  rc |= wg_h5md_element_close(&el);
  rc |= wg_h5_write(f, "/bridges/pairs", H5T_NATIVE_INT, 2, pd, pairs, "1", "Bridged pairs.");
  rc |= wg_h5_write(f, "/bridges/none", H5T_NATIVE_INT, 2, e0, NULL, "1", "Empty.");
  d = wg_h5_dataset_create(f, "/observables/series", H5T_NATIVE_DOUBLE, 2, sd, "m g d", "Series.");
  rc |= d < 0 || wg_h5_write_rows(d, H5T_NATIVE_DOUBLE, 0, 2, series[0]) ||
        wg_h5_write_rows(d, H5T_NATIVE_DOUBLE, 2, 2, series[2]) || H5Dclose(d) < 0;
  rc |= (d = wg_h5_group(f, "/parameters")) < 0 || wg_h5_attr_double(d, ".", "x", 1.0) || H5Gclose(d) < 0;
  rc |= wg_h5_attr_string(f, "/", "note", "first") | wg_h5_attr_double(f, "/", "note", 2.0);
  rc |= wg_h5_attr_string_fixed(f, "/", "provenance", "volatile", 32);
  rc |= wg_h5_attr_string_fixed(f, "/", "provenance", "volatile, rewritten", 32);
  rc |= wg_h5_close(f);
  return rc;
}

static void test_determinism(void)
{
  const char *a = tmp("same_a.h5"), *b = tmp("same_b.h5");
  struct timespec pause = {1, 100000000}; /* > 1 s, so that timestamps, if any, would differ */
  long na = -1, nb = -1;
  unsigned char *ba, *bb;

  TH_CHECK(write_sequence(a) == 0, "write sequence to %s", a);
  nanosleep(&pause, NULL);
  TH_CHECK(write_sequence(b) == 0, "same sequence to %s, 1.1 s later", b);
  ba = slurp(a, &na);
  bb = slurp(b, &nb);
  TH_CHECK(ba && bb && na == nb && na > 0 && memcmp(ba, bb, (size_t)na) == 0,
           "byte-identical files (%ld and %ld bytes)", na, nb);
  free(ba);
  free(bb);
  stamps st = count_file_stamps(a);
  TH_CHECK(st.objects >= 15 && st.stamped == 0,
           "%d objects visited (root, groups, datasets), %d with timestamps", st.objects, st.stamped);
  remove(a);
  remove(b);
}

/* The timestamp check itself can see timestamps: a dataset made with the default creation
   plist has them (in this file format groups never store any). */
static void test_stamps_detectable(void)
{
  const char *path = tmp("stamped.h5");
  hsize_t n1 = 1;
  hid_t f = wg_h5_create(path), s = H5Screate_simple(1, &n1, NULL);
  H5Dclose(H5Dcreate2(f, "plain", H5T_IEEE_F64LE, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  H5Sclose(s);
  wg_h5_close(f);
  stamps st = count_file_stamps(path);
  TH_CHECK(st.stamped == 1, "control: a default-plist dataset is timestamped (%d of %d objects)", st.stamped,
           st.objects);
  remove(path);
}

/* ---- error paths --------------------------------------------------------------------------------- */

static void test_errors(void)
{
  const char *path = tmp("errors.h5"), *missing = tmp("no_such_file.h5");
  const char *nodir = "/tmp/wg_no_such_dir_for_io_h5_test/x.h5";
  char err[2048];
  double x = 1, buf[4];
  hsize_t n1 = 1, dims[8];
  int rank, rc;
  capture c;
  hid_t f, g, ro;

  capture_begin(&c);
  hid_t m = wg_h5_open_read(missing);
  capture_end(&c, err, sizeof err);
  TH_CHECK(m < 0 && strstr(err, missing) && strstr(err, "cannot open file"), "open missing file: %s", err);
  TH_CHECK(!strstr(err, "HDF5-DIAG"), "HDF5's own error stack is not printed");
  capture_begin(&c);
  m = wg_h5_open_rw(missing);
  hid_t cr = wg_h5_create(nodir);
  capture_end(&c, err, sizeof err);
  TH_CHECK(m < 0 && cr < 0 && strstr(err, missing) && strstr(err, nodir),
           "open rw / create in missing dir: %s", err);

  f = wg_h5_create(path);
  TH_CHECK(wg_h5_write(f, "/grp/x", H5T_NATIVE_DOUBLE, 1, &n1, &x, "d", "X.") == WG_OK, "setup");
  g = wg_h5_group(f, "grp");
  capture_begin(&c);
  rc = wg_h5_read(f, "/missing/x", H5T_NATIVE_DOUBLE, buf);
  capture_end(&c, err, sizeof err);
  TH_CHECK(rc == WG_EIO && strstr(err, path) && strstr(err, "/missing/x") && strstr(err, "open dataset"),
           "read missing dataset: %s", err);
  capture_begin(&c);
  rc = wg_h5_read(g, "nope", H5T_NATIVE_DOUBLE, buf);
  capture_end(&c, err, sizeof err);
  TH_CHECK(rc == WG_EIO && strstr(err, "/grp/nope"), "relative path named in full: %s", err);
  capture_begin(&c);
  int r1 = wg_h5_dims(f, "/missing", &rank, dims);
  int r2 = wg_h5_read_rows(f, "/missing", H5T_NATIVE_DOUBLE, 0, 1, buf);
  int r3 = wg_h5_read_attr_double(f, "/grp/x", "nothing", &x);
  int r4 = wg_h5_attr_double(f, "/missing/obj", "a", 1.0);
  int r5 = wg_h5_write(f, "/grp/x", H5T_NATIVE_DOUBLE, 1, &n1, &x, "d", "Again.");
  int r6 = wg_h5_write(f, "/grp/ld", H5T_NATIVE_LDOUBLE, 1, &n1, &x, "d", "Long double.");
  int r7 = wg_h5_write(f, "/grp/nounit", H5T_NATIVE_DOUBLE, 1, &n1, &x, NULL, "No unit.");
  hid_t g2 = wg_h5_group(f, "/grp/x/sub");
  hid_t d2 = wg_h5_dataset_create(f, "/grp/x/y", H5T_NATIVE_DOUBLE, 1, &n1, "d", "Below a dataset.");
  capture_end(&c, err, sizeof err);
  printf("      captured:\n%s\n", err);
  TH_CHECK(r1 == WG_EIO && r2 == WG_EIO && r3 == WG_EIO && r4 == WG_EIO && r5 == WG_EIO,
           "dims/read_rows/attr read/attr on missing object/duplicate dataset fail with WG_EIO");
  TH_CHECK(r6 == WG_EINVAL && r7 == WG_EINVAL && g2 < 0 && d2 < 0,
           "unsupported type, missing unit, group below a dataset");
  TH_CHECK(strstr(err, "'nothing'") && strstr(err, "/missing/obj") && strstr(err, "create dataset") &&
               strstr(err, "/grp/x/sub: cannot open group component 'x' (not a group)") &&
               strstr(err, "/grp/x: cannot open group component 'x'"),
           "messages name the objects and operations");
  TH_CHECK(H5Fget_obj_count(f, H5F_OBJ_ALL) == 2,
           "after the errors only the file and one group are open (%ld)",
           (long)H5Fget_obj_count(f, H5F_OBJ_ALL));
  capture_begin(&c);
  rc = wg_h5_close(g);
  capture_end(&c, err, sizeof err);
  TH_CHECK(rc == WG_EINVAL && wg_h5_close(H5I_INVALID_HID) == WG_OK,
           "wg_h5_close refuses a group, ignores -1: %s", err);
  H5Gclose(g);
  wg_h5_close(f);

  ro = wg_h5_open_read(path);
  capture_begin(&c);
  rc = wg_h5_write(ro, "/new", H5T_NATIVE_DOUBLE, 1, &n1, &x, "d", "Read-only.");
  int ra = wg_h5_attr_double(ro, ".", "a", 1.0);
  capture_end(&c, err, sizeof err);
  TH_CHECK(rc == WG_EIO && ra == WG_EIO && strstr(err, path) && strstr(err, "/new"),
           "writes to a read-only file fail: %s", err);
  TH_CHECK(H5Fget_obj_count(ro, H5F_OBJ_ALL) == 1, "nothing left open");
  wg_h5_close(ro);
  remove(path);
}

int main(void)
{
  wg_h5_quiet();
  snprintf(dir, sizeof dir, "/tmp/wg_test_io_h5_XXXXXX");
  if (!mkdtemp(dir)) {
    perror("mkdtemp");
    return 1;
  }
  test_roundtrip();
  test_strings();
  test_rows();
  test_attributes();
  test_h5md();
  test_layout2();
  test_empty();
  test_determinism();
  test_stamps_detectable();
  test_errors();
  TH_CHECK(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL) == 0, "no HDF5 file or object open at the end");
  TH_CHECK(rmdir(dir) == 0, "temporary directory %s empty and removed", dir);
  return th_summary();
}
