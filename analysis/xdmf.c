/* wetgran-xdmf: an XDMF description of a run's particle snapshots, so that ParaView (and VisIt)
   open the H5MD file as it is: one grid of points per snapshot at its time, positions, velocities,
   diameters and bridge counts read straight from the run file by hyperslabs.  No data is
   copied; the .xdmf is a small XML file beside the run, written under a temporary name and
   renamed when complete. */
#include <errno.h>
#include <libgen.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io_h5.h"
#include "run_open.h"

static void usage(void)
{
  printf("Usage: wetgran-xdmf RUN.h5 [-o VIEW.xdmf]\n"
         "Writes an XDMF file (default: RUN.xdmf beside the run) that describes every particle\n"
         "snapshot of RUN.h5 as a grid of points at its time, with the attributes velocity\n"
         "(vector), diameter and bridges, all read from RUN.h5 itself (hyperslabs of the H5MD\n"
         "datasets): open it in ParaView with the XDMF reader.  2D runs have XY geometry.\n"
         "The run file is referred to by its name when the .xdmf sits beside it, else by its\n"
         "absolute path.\n");
}

/* A hyperslab of row k of an [nf x n (x dim)] dataset as an XDMF data item. */
static void slab(FILE *o, const char *h5, const char *path, long k, long nf, long n, int cols,
                 const char *type, int precision)
{
  if (cols > 1)
    fprintf(o, "        <DataItem ItemType=\"HyperSlab\" Dimensions=\"%ld %d\" Type=\"HyperSlab\">\n"
               "          <DataItem Dimensions=\"3 3\" Format=\"XML\">%ld 0 0 1 1 1 1 %ld %d</DataItem>\n"
               "          <DataItem Dimensions=\"%ld %ld %d\" NumberType=\"%s\" Precision=\"%d\" "
               "Format=\"HDF\">%s:%s</DataItem>\n        </DataItem>\n",
            n, cols, k, n, cols, nf, n, cols, type, precision, h5, path);
  else
    fprintf(o, "        <DataItem ItemType=\"HyperSlab\" Dimensions=\"%ld\" Type=\"HyperSlab\">\n"
               "          <DataItem Dimensions=\"3 2\" Format=\"XML\">%ld 0 1 1 1 %ld</DataItem>\n"
               "          <DataItem Dimensions=\"%ld %ld\" NumberType=\"%s\" Precision=\"%d\" "
               "Format=\"HDF\">%s:%s</DataItem>\n        </DataItem>\n",
            n, k, n, nf, n, type, precision, h5, path);
}

int main(int argc, char **argv)
{
  const char *path = NULL, *out = NULL;
  for (int a = 1; a < argc; a++) {
    if (!strcmp(argv[a], "-h") || !strcmp(argv[a], "--help")) { usage(); return 0; }
    if (!strcmp(argv[a], "-o")) {
      if (a + 1 == argc) {
        fprintf(stderr, "wetgran-xdmf: option -o needs a file name (see --help)\n");
        return 2;
      }
      out = argv[++a];
    } else if (argv[a][0] == '-') {
      fprintf(stderr, "wetgran-xdmf: unknown option '%s' (see --help)\n", argv[a]);
      return 2;
    } else if (!path) path = argv[a];
    else {
      fprintf(stderr, "wetgran-xdmf: unexpected argument '%s' (see --help)\n", argv[a]);
      return 2;
    }
  }
  if (!path) {
    fprintf(stderr, "wetgran-xdmf: no run file given (see --help)\n");
    return 2;
  }
  hid_t f = wg_run_open(path);
  if (f < 0) return 1;
  int rank;
  hsize_t dims[8];
  if (wg_h5_dims(f, "/particles/all/position/value", &rank, dims) != WG_OK || rank != 3 || dims[0] < 1) {
    fprintf(stderr, "wetgran-xdmf: %s: no particle snapshots\n", path);
    wg_h5_close(f);
    return 1;
  }
  long nf = (long)dims[0], n = (long)dims[1];
  int dim = (int)dims[2];
  double *t = malloc(sizeof *t * (size_t)nf);
  int st = t ? wg_h5_read(f, "/particles/all/position/time", H5T_NATIVE_DOUBLE, t) : WG_ENOMEM;
  wg_h5_close(f);
  if (st != WG_OK) {
    free(t);
    return 1;
  }

  /* where the .xdmf goes, and how it names the run file */
  char *dflt = NULL, h5[PATH_MAX];
  if (!out) {
    size_t len = strlen(path);
    dflt = malloc(len + 8);
    if (!dflt) return 1;
    strcpy(dflt, path);
    if (len > 3 && !strcmp(dflt + len - 3, ".h5")) dflt[len - 3] = 0;
    strcat(dflt, ".xdmf");
    out = dflt;
    char *copy = strdup(path);
    snprintf(h5, sizeof h5, "%s", basename(copy));
    free(copy);
  } else if (!realpath(path, h5)) {
    fprintf(stderr, "wetgran-xdmf: %s: %s\n", path, strerror(errno));
    free(t);
    return 1;
  }
  size_t olen = strlen(out) + 8;
  char *tmp = malloc(olen);
  if (!tmp) return 1;
  snprintf(tmp, olen, "%s.tmp", out);
  FILE *o = fopen(tmp, "w");
  if (!o) {
    fprintf(stderr, "wetgran-xdmf: %s: %s\n", tmp, strerror(errno));
    free(t); free(tmp); free(dflt);
    return 1;
  }
  fprintf(o, "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"2.0\">\n  <Domain>\n"
             "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n");
  for (long k = 0; k < nf; k++) {
    fprintf(o, "    <Grid Name=\"snapshot %ld\" GridType=\"Uniform\">\n      <Time Value=\"%.17g\"/>\n"
               "      <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%ld\"/>\n"
               "      <Geometry GeometryType=\"%s\">\n",
            k, t[k], n, dim == 3 ? "XYZ" : "XY");
    slab(o, h5, "/particles/all/position/value", k, nf, n, dim, "Float", 8);
    fprintf(o, "      </Geometry>\n      <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n");
    if (dim == 3) {
      slab(o, h5, "/particles/all/velocity/value", k, nf, n, dim, "Float", 8);
    } else { /* ParaView's vectors have three components: (vx, vz, 0) */
      fprintf(o, "        <DataItem ItemType=\"Function\" Function=\"JOIN($0, $1, 0 * $0)\" Dimensions=\"%ld 3\">\n", n);
      for (int c = 0; c < 2; c++)
        fprintf(o, "          <DataItem ItemType=\"HyperSlab\" Dimensions=\"%ld\" Type=\"HyperSlab\">\n"
                   "            <DataItem Dimensions=\"3 3\" Format=\"XML\">%ld 0 %d 1 1 1 1 %ld 1</DataItem>\n"
                   "            <DataItem Dimensions=\"%ld %ld 2\" NumberType=\"Float\" Precision=\"8\" "
                   "Format=\"HDF\">%s:/particles/all/velocity/value</DataItem>\n          </DataItem>\n",
                n, k, c, n, nf, n, h5);
      fprintf(o, "        </DataItem>\n");
    }
    fprintf(o, "      </Attribute>\n      <Attribute Name=\"diameter\" AttributeType=\"Scalar\" Center=\"Node\">\n"
               "        <DataItem Dimensions=\"%ld\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
               "%s:/particles/all/diameter</DataItem>\n      </Attribute>\n"
               "      <Attribute Name=\"bridges\" AttributeType=\"Scalar\" Center=\"Node\">\n",
            n, h5);
    slab(o, h5, "/particles/all/bridge_count/value", k, nf, n, 1, "UChar", 1);
    fprintf(o, "      </Attribute>\n    </Grid>\n");
  }
  fprintf(o, "    </Grid>\n  </Domain>\n</Xdmf>\n");
  st = ferror(o) ? WG_EIO : WG_OK;
  if (fclose(o) != 0) st = WG_EIO;
  if (st == WG_OK && rename(tmp, out) != 0) st = WG_EIO;
  if (st != WG_OK) {
    fprintf(stderr, "wetgran-xdmf: %s: cannot write: %s\n", out, strerror(errno));
    remove(tmp);
  }
  free(t); free(tmp); free(dflt);
  return st == WG_OK ? 0 : 1;
}
