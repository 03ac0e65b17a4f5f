/* One opener for every analysis tool (see run_open.h). */
#include "run_open.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "io_h5.h"
#include "wg.h"

/* HDF5's file signature; the superblock lies at byte 0, 512, 1024, 2048, ... (a user block
   before it), so a file is HDF5 if one of those offsets holds it. */
static const unsigned char h5_signature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};

static int has_h5_signature(FILE *f, long long size)
{
  for (long long off = 0; off + 8 <= size; off = off ? 2 * off : 512) {
    unsigned char buf[8];
    if (fseeko(f, (off_t)off, SEEK_SET) != 0 || fread(buf, 1, 8, f) != 8) return 0;
    if (!memcmp(buf, h5_signature, 8)) return 1;
  }
  return 0;
}

/* The checks both openers share.  Returns 1 (HDF5), 0 (not HDF5) or -1 after reporting a
   missing, unreadable or empty file. */
static int classify(const char *path, const char *what)
{
  struct stat st;
  if (stat(path, &st) != 0) {
    if (errno == ENOENT) wg_error(WG_EIO, path, "no such file");
    else wg_error(WG_EIO, path, "cannot open: %s", strerror(errno));
    return -1;
  }
  if (S_ISDIR(st.st_mode)) {
    wg_error(WG_EIO, path, "is a directory, not a file");
    return -1;
  }
  FILE *f = fopen(path, "rb");
  if (!f) {
    wg_error(WG_EIO, path, "cannot open: %s", strerror(errno));
    return -1;
  }
  if (S_ISREG(st.st_mode) && st.st_size == 0) {
    fclose(f);
    wg_error(WG_EIO, path, "empty file (0 bytes), not a %s", what);
    return -1;
  }
  int h5 = S_ISREG(st.st_mode) && has_h5_signature(f, (long long)st.st_size);
  fclose(f);
  return h5;
}

/* H5Ewalk2 callback (upward walk): keep the description of the innermost error. */
static herr_t innermost(unsigned n, const H5E_error2_t *err, void *detail)
{
  if (n == 0 && err->desc) snprintf(detail, 256, "%s", err->desc);
  return 0;
}

hid_t wg_run_open(const char *path)
{
  wg_h5_quiet();
  int h5 = classify(path, "run file");
  if (h5 < 0) return H5I_INVALID_HID;
  if (!h5) {
    wg_error(WG_EINVAL, path, "not an HDF5 file, so not a wetgran run file");
    return H5I_INVALID_HID;
  }
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    char detail[256] = "";
    (void)H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, innermost, detail);
    wg_error(WG_EIO, path, "truncated or damaged HDF5 file (%s)", detail[0] ? detail : "HDF5 cannot open it");
    return H5I_INVALID_HID;
  }
  if (!wg_h5_exists(f, "/h5md")) {
    H5Fclose(f);
    wg_error(WG_EINVAL, path, "not a wetgran run file (no /h5md group)");
    return H5I_INVALID_HID;
  }
  return f;
}

int wg_input_is_h5(const char *path)
{
  if (!strcmp(path, "-")) return 0;
  return classify(path, "input");
}

FILE *wg_table_open(const char *path)
{
  if (!strcmp(path, "-")) return stdin;
  int h5 = classify(path, "table");
  if (h5 < 0) return NULL;
  if (h5) {
    wg_error(WG_EINVAL, path, "an HDF5 file, not a tab-separated table (a run file? its tool "
             "makes the table)");
    return NULL;
  }
  FILE *f = fopen(path, "r");
  if (!f) wg_error(WG_EIO, path, "cannot open: %s", strerror(errno));
  return f;
}

int wg_run_param(hid_t f, const char *file, const char *key, double *v, int required)
{
  if (H5Aexists_by_name(f, "/parameters", key, H5P_DEFAULT) <= 0 ||
      wg_h5_read_param_double(f, key, v) != WG_OK) {
    *v = NAN;
    if (required) wg_error(WG_EINVAL, file, "no parameter %s in /parameters", key);
    return required;
  }
  return 0;
}

int wg_table_read_xy(const char *path, const char *xname, const char *yname, int strict,
                     wg_xy *t)
{
  *t = (wg_xy){0, NULL, NULL};
  FILE *f = wg_table_open(path);
  if (!f) return 1;
  char *line = NULL, where[4200];
  size_t len = 0, cap = 0;
  int xc = -1, yc = -1, header = 0, rc = 0;
  long lineno = 0;
  while (!rc && getline(&line, &len, f) >= 0) {
    lineno++;
    snprintf(where, sizeof where, "%s:%ld", path, lineno);
    line[strcspn(line, "\r\n")] = 0;
    if (line[0] == '#' || !line[0]) continue;
    char *save = NULL, *xs = NULL, *ys = NULL;
    int k = 0;
    for (char *tok = strtok_r(line, "\t", &save); tok; tok = strtok_r(NULL, "\t", &save), k++) {
      if (!header) {
        if (xc < 0 && !strcmp(tok, xname)) xc = k;
        if (yc < 0 && !strcmp(tok, yname)) yc = k;
        continue;
      }
      if (k == xc) xs = tok;
      if (k == yc) ys = tok;
    }
    if (!header) {
      if (xc < 0 || yc < 0)
        rc = wg_error(WG_EINVAL, where, "no column '%s' in the header", xc < 0 ? xname : yname) != 0;
      header = 1;
      continue;
    }
    char *ex = NULL, *ey = NULL;
    double x = xs ? strtod(xs, &ex) : NAN, y = ys ? strtod(ys, &ey) : NAN;
    if (strict && (!xs || !ys)) {
      rc = wg_error(WG_EINVAL, where, "too few fields") != 0;
      break;
    }
    if (strict && (*ex || *ey)) {
      rc = wg_error(WG_EINVAL, where, "'%s' or '%s' is not a number", xs, ys) != 0;
      break;
    }
    if (xs && *ex) x = NAN;
    if (ys && *ey) y = NAN;
    if (t->n == cap) {
      cap = cap ? 2 * cap : 256;
      double *a = realloc(t->x, sizeof(double) * cap), *b = a ? realloc(t->y, sizeof(double) * cap) : NULL;
      if (a) t->x = a;
      if (!b) {
        rc = wg_error(WG_ENOMEM, path, "no memory for %zu rows", cap) != 0;
        break;
      }
      t->y = b;
    }
    t->x[t->n] = x, t->y[t->n++] = y;
  }
  if (!rc && !header) rc = wg_error(WG_EINVAL, path, "no header line: not a table") != 0;
  free(line);
  if (f != stdin) fclose(f);
  if (rc) wg_xy_free(t);
  return rc;
}

void wg_xy_free(wg_xy *t)
{
  free(t->x), free(t->y);
  *t = (wg_xy){0, NULL, NULL};
}
