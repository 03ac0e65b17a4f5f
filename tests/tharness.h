/* Minimal test harness: each check prints "ok" or "FAIL" with the values involved; the
   program ends with "N passed, N failed" and exits non-zero on any failure.  tests/run.sh
   adds the counts of all test programs into the final line CI reads. */
#ifndef WG_THARNESS_H
#define WG_THARNESS_H

#include <math.h>
#include <stdio.h>

static int th_passed, th_failed;

#define TH_CHECK(cond, ...)                                                  \
  do {                                                                       \
    if (cond) {                                                              \
      th_passed++;                                                           \
      printf("ok    ");                                                      \
    } else {                                                                 \
      th_failed++;                                                           \
      printf("FAIL  %s:%d: ", __FILE__, __LINE__);                           \
    }                                                                        \
    printf(__VA_ARGS__);                                                     \
    printf("\n");                                                            \
    fflush(stdout);                                                          \
  } while (0)

/* |a - b| <= rel * max(|a|, |b|) + abs_tol */
static inline int th_close(double a, double b, double rel, double abs_tol)
{
  double scale = fabs(a) > fabs(b) ? fabs(a) : fabs(b);
  return fabs(a - b) <= rel * scale + abs_tol;
}

#define TH_CLOSE(name, a, b, rel, abs_tol)                                   \
  TH_CHECK(th_close((a), (b), (rel), (abs_tol)), "%s: %.17g vs %.17g (rel %.1e, abs %.1e)", \
           (name), (double)(a), (double)(b), (double)(rel), (double)(abs_tol))

static inline int th_summary(void)
{
  printf("%d passed, %d failed\n", th_passed, th_failed);
  return th_failed ? 1 : 0;
}

#endif
