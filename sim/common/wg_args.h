/* Whole-string parsing of numeric command-line values: "2x", "abc" or "" are refused, not
   read as 2 or 0 as atoi()/atof() would.  On failure one line on stderr through wg_error:
   "<program>: option OPT: 'S' is not an integer" (or "... not a number"); the caller exits 2. */
#ifndef WG_ARGS_H
#define WG_ARGS_H

#include <stdio.h>

#include "wg.h"

int wg_arg_long(const char *opt, const char *s, long *v);
int wg_arg_double(const char *opt, const char *s, double *v);

/* Numeric key=value arguments of the small solvers (wetgran-dsmc, wetgran-cahn-hilliard): a
   table of keys with defaults (NAN: computed later, shown as "auto") and closed ranges. */
typedef struct wg_num_key {
  const char *name;
  double value, min, max;
  int whole;             /* 1: an integer */
  const char *help;
} wg_num_key;

/* Sets the key ARG names ("key=value"); on an unknown key, a non-number, a value out of range
   or a fraction for a whole key: one line on stderr naming the argument, return 2. */
int wg_num_key_set(const char *prog, wg_num_key *keys, int nkeys, const char *arg);
/* "  name  default  help" lines for --help. */
void wg_num_key_help(FILE *out, const wg_num_key *keys, int nkeys);

#endif
