#include "wg_args.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

int wg_num_key_set(const char *prog, wg_num_key *keys, int nkeys, const char *arg)
{
  const char *eq = strchr(arg, '=');
  int k = 0;
  if (eq)
    for (; k < nkeys; k++)
      if (strlen(keys[k].name) == (size_t)(eq - arg) && !strncmp(arg, keys[k].name, (size_t)(eq - arg))) break;
  if (!eq || k == nkeys) {
    fprintf(stderr, "%s: argument '%s': not key=value with a known key (--help)\n", prog, arg);
    return 2;
  }
  double v;
  if (wg_arg_double(keys[k].name, eq + 1, &v) != WG_OK) return 2;
  if (!(v >= keys[k].min && v <= keys[k].max)) {
    fprintf(stderr, "%s: argument '%s': %s must lie in [%g, %g]\n", prog, arg, keys[k].name, keys[k].min, keys[k].max);
    return 2;
  }
  if (keys[k].whole && v != floor(v)) {
    fprintf(stderr, "%s: argument '%s': %s must be a whole number\n", prog, arg, keys[k].name);
    return 2;
  }
  keys[k].value = v;
  return 0;
}

void wg_num_key_help(FILE *out, const wg_num_key *keys, int nkeys)
{
  for (int k = 0; k < nkeys; k++) {
    if (isnan(keys[k].value)) fprintf(out, "  %-12s %-8s %s\n", keys[k].name, "auto", keys[k].help);
    else fprintf(out, "  %-12s %-8g %s\n", keys[k].name, keys[k].value, keys[k].help);
  }
}
