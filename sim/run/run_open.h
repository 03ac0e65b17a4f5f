/* Opening the inputs of the analysis tools: a run file of wetgran-run, or a text table, with
   one line on stderr (prefixed by the program's name, through wg_error) saying why a file is
   not one: missing, empty, not HDF5, truncated or damaged HDF5, HDF5 without /h5md.  So every
   tool answers a wrong input the same way, whatever it then reads from the file. */
#ifndef WG_RUN_OPEN_H
#define WG_RUN_OPEN_H

#include <stdio.h>
#include <hdf5.h>

/* Open an H5MD run file of wetgran-run read-only.  Returns the file id, or a negative value
   after one line on stderr.  Switches HDF5's own error printing off (wg_h5_quiet). */
hid_t wg_run_open(const char *path);

/* Which kind a tool's input is: 1 an HDF5 file (open it with wg_run_open), 0 anything else
   ("-" included: a table for wg_table_open), -1 after one line on stderr (missing, unreadable,
   empty, a directory). */
int wg_input_is_h5(const char *path);

/* Open a tab-separated text table for reading ("-": stdin).  Returns NULL after one line on
   stderr if the file is missing, unreadable, empty or an HDF5 file (a run given where its
   table was meant). */
FILE *wg_table_open(const char *path);

/* Two columns of a table, by the names in its header line. */
typedef struct wg_xy {
  size_t n;
  double *x, *y;
} wg_xy;

/* Reads columns xname and yname of a tab-separated table (wg_table_open: "-" is stdin; '#'
   and blank lines skipped; the first other line is the header) into t, one pair per data
   row.  strict: a row lacking a field or holding one that is no number is an error; else
   that value is NAN and the caller filters.  Returns 0, or 1 after one line on stderr naming
   file and line ("path:line: no column 'x' in the header").  Free with wg_xy_free. */
int wg_table_read_xy(const char *path, const char *xname, const char *yname, int strict,
                     wg_xy *t);
void wg_xy_free(wg_xy *t);

/* A real of a run's /parameters into *v (NAN when absent).  Returns 1 after one line on stderr
   when a required one is absent, else 0. */
int wg_run_param(hid_t f, const char *file, const char *key, double *v, int required);

#endif
