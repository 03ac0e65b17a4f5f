#include "wg_args.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>

#include "wg.h"

int wg_arg_long(const char *opt, const char *s, long *v)
{
  char *end;
  errno = 0;
  long x = s ? strtol(s, &end, 10) : 0;
  if (!s || end == s || *end || errno == ERANGE) {
    char where[128];
    snprintf(where, sizeof where, "option %s", opt);
    return wg_error(WG_EINVAL, where, "'%s' is not an integer", s ? s : "");
  }
  *v = x;
  return WG_OK;
}

int wg_arg_double(const char *opt, const char *s, double *v)
{
  char *end;
  errno = 0;
  double x = s ? strtod(s, &end) : 0;
  if (!s || end == s || *end || errno == ERANGE) {
    char where[128];
    snprintf(where, sizeof where, "option %s", opt);
    return wg_error(WG_EINVAL, where, "'%s' is not a number", s ? s : "");
  }
  *v = x;
  return WG_OK;
}
