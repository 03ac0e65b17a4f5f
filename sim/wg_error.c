#include "wg.h"

#include <stdarg.h>
#include <stdio.h>

#ifndef WG_GIT_VERSION
#define WG_GIT_VERSION "unknown"
#endif

int wg_error(int status, const char *where, const char *fmt, ...)
{
  va_list ap;
  fprintf(stderr, "wetgran: %s: ", where ? where : "error");
  va_start(ap, fmt);
  vfprintf(stderr, fmt, ap);
  va_end(ap);
  fputc('\n', stderr);
  return status;
}

const char *wg_version(void) { return WG_GIT_VERSION; }
