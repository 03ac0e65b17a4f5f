/* Turning points of a noisy series, for the analysis tools (the Leidenfrost plug's interface,
   the cycles of a limit cycle for Poincare sections). */
#ifndef WG_EXTREMA_H
#define WG_EXTREMA_H

/* Maxima and minima of x[0..n-1] with hysteresis: a maximum is taken once x has fallen `swing`
   below it, a minimum once x has risen `swing` above it, alternately (the first one by
   whichever comes first).  Non-finite values are skipped.  Indices to idx[], +1 (maximum) or
   -1 (minimum) to kind[] (both of room n); returns their number. */
long wg_turning_points(const double *x, long n, double swing, long *idx, int *kind);

/* A swing for wg_turning_points: frac of the 10-90 percentile range of x's finite values
   (at least floor; floor when fewer than 10). */
double wg_auto_swing(const double *x, long n, double frac, double floor);

#endif
