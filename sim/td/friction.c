#include "friction.h"

#include <math.h>

static void cross(const double a[3], const double b[3], double c[3])
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void wg_contact_tangential_velocity(const double v_ji[3], const double n[3], double li,
                                    double lj, const double wi[3], const double wj[3],
                                    double vt[3])
{
  double w[3], wxn[3];
  for (int a = 0; a < 3; a++) w[a] = li * wi[a] + lj * wj[a];
  cross(w, n, wxn);
  double vc[3];
  for (int a = 0; a < 3; a++) vc[a] = v_ji[a] - wxn[a]; /* notes-sheared-layering Eq. 16 */
  double vn = dot(vc, n);
  for (int a = 0; a < 3; a++) vt[a] = vc[a] - vn * n[a];
}

double wg_spring_update(wg_spring *sp, const double n[3], const double vt[3], const double *dvt,
                        double kt, double gt, double fmax, double dt, double ft[3],
                        double *power)
{
  double *xi = sp->xi;
  double len2 = dot(xi, xi);
  if (len2 > 0) { /* into the new tangent plane, length kept */
    double xn = dot(xi, n);
    for (int a = 0; a < 3; a++) xi[a] -= xn * n[a];
    double now2 = dot(xi, xi);
    if (now2 > 0) {
      double s = sqrt(len2 / now2);
      for (int a = 0; a < 3; a++) xi[a] *= s;
    }
  }
  if (dvt)
    for (int a = 0; a < 3; a++) xi[a] += dvt[a] * dt;
  for (int a = 0; a < 3; a++) ft[a] = -kt * xi[a] - gt * vt[a];
  double f2 = dot(ft, ft);
  if (f2 > fmax * fmax) { /* sliding: Coulomb's bound, the spring holds all of it */
    double s = fmax / sqrt(f2);
    for (int a = 0; a < 3; a++) {
      ft[a] *= s;
      xi[a] = kt > 0 ? -ft[a] / kt : 0;
    }
  }
  *power = -dot(ft, vt);
  double u_old = sp->u;
  sp->u = 0.5 * kt * dot(xi, xi);
  return sp->u - u_old;
}

double wg_spring_release(wg_spring *sp)
{
  double u = sp->u;
  sp->xi[0] = sp->xi[1] = sp->xi[2] = 0;
  sp->u = 0;
  return u;
}

double wg_rolling_resistance(const double n[3], double l, const double wi[3], const double wj[3],
                             double fmax, double cap, double tq_i[3])
{
  double dw[3], w[3], fr[3], t[3];
  for (int a = 0; a < 3; a++) dw[a] = l * (wi[a] - wj[a]);
  cross(dw, n, w);
  double wl = sqrt(dot(w, w));
  if (wl == 0 || fmax <= 0) return 0;
  double f = fmin(fmax, cap * wl);
  for (int a = 0; a < 3; a++) fr[a] = f * w[a] / wl;
  cross(n, fr, t);
  for (int a = 0; a < 3; a++) tq_i[a] -= l * t[a];
  return f * wl;
}
