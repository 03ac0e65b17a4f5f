#include "wg.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>

#ifndef WG_GIT_VERSION
#define WG_GIT_VERSION "unknown"
#endif

int wg_error(int status, const char *where, const char *fmt, ...)
{
  va_list ap;
  /* the program's own name (GNU), so a message says which tool of a pipeline failed */
  fprintf(stderr, "%s: %s: ", program_invocation_short_name, where ? where : "error");
  va_start(ap, fmt);
  vfprintf(stderr, fmt, ap);
  va_end(ap);
  fputc('\n', stderr);
  return status;
}

const char *wg_version(void) { return WG_GIT_VERSION; }
