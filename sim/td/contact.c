#include "contact.h"

#include <math.h>

double wg_contact_zeta(double e)
{
  double l = log(e);
  return -l / sqrt(M_PI * M_PI + l * l);
}

wg_contact wg_contact_linear(double e, double t_c, double m_ref)
{
  double l = log(e);
  wg_contact c = {.law = WG_CONTACT_LINEAR};
  c.k = m_ref * (M_PI * M_PI + l * l) / (t_c * t_c);
  c.zeta = wg_contact_zeta(e);
  return c;
}

wg_contact wg_contact_hertz(double kh, double ad)
{
  wg_contact c = {.law = WG_CONTACT_HERTZ, .kh = kh, .ad = ad};
  return c;
}

double wg_contact_force(const wg_contact *c, double xi, double xidot, double r_eff,
                        double m_eff, double *f_elastic, double *u_elastic)
{
  if (c->law == WG_CONTACT_LINEAR) {
    *f_elastic = c->k * xi;
    *u_elastic = 0.5 * c->k * xi * xi;
    return c->k * xi + 2 * c->zeta * sqrt(c->k * m_eff) * xidot;
  }
  double k = c->kh * sqrt(r_eff), s = sqrt(xi); /* Eq. 2.7 */
  *f_elastic = k * xi * s;
  *u_elastic = 0.4 * k * xi * xi * s;
  double f = k * (xi * s + c->ad * s * xidot);
  return f > 0 ? f : 0;
}

void wg_contact_stiffness(const wg_contact *c, double xi, double r_eff, double m_eff,
                          double *k_n, double *gamma_n)
{
  if (c->law == WG_CONTACT_LINEAR) {
    *k_n = c->k;
    *gamma_n = 2 * c->zeta * sqrt(c->k * m_eff);
    return;
  }
  double k = c->kh * sqrt(r_eff * xi); /* Eq. 2.7: F = k xi + k A_d xidot */
  *k_n = k;
  *gamma_n = k * c->ad;
}
