/* Whole-string parsing of numeric command-line values: "2x", "abc" or "" are refused, not
   read as 2 or 0 as atoi()/atof() would.  On failure one line on stderr through wg_error:
   "<program>: option OPT: 'S' is not an integer" (or "... not a number"); the caller exits 2. */
#ifndef WG_ARGS_H
#define WG_ARGS_H

#include "wg.h"

int wg_arg_long(const char *opt, const char *s, long *v);
int wg_arg_double(const char *opt, const char *s, double *v);

#endif
