/* wetgran: common definitions shared by every module of the library. */
#ifndef WG_H
#define WG_H

#include <stddef.h>
#include <stdint.h>

/* Status codes: every library function returns one of these; only main() exits. */
enum {
  WG_OK = 0,
  WG_EINVAL = 1,   /* bad input (scene, option, argument) */
  WG_ENOMEM = 2,   /* allocation failed */
  WG_EIO = 3,      /* file could not be read or written */
  WG_ERANGE = 4,   /* a value left its valid range during a run */
  WG_EFAIL = 5,    /* numerical method failed to converge */
  WG_ESTOPPED = 6  /* stopped on request after a checkpoint (testing aid) */
};

/* Central error report: prints "<program>: <where>: <message>" on stderr (<program>: the
   name it was started by, e.g. wetgran-run) and returns
   the status, so one breakpoint on wg_error() catches every failure. */
int wg_error(int status, const char *where, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Version string of the toolkit ("git describe --dirty" at build time). */
const char *wg_version(void);

#endif
