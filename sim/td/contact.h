/* Normal contact laws of the time-driven engine (thesis Sec. 2.2): the overlap xi > 0 of two
   soft spheres (or a sphere and a wall) and its rate xidot give a repulsive force along the
   line of centres.  Two laws:
     linear spring-dashpot  F = k xi + gamma xidot,  gamma = 2 zeta sqrt(k m_eff),
                            zeta = -ln e / sqrt(pi^2 + ln^2 e): restitution e for any m_eff,
                            contact time pi / sqrt(k / m_eff - (gamma / 2 m_eff)^2);
     Hertz (Eq. 2.7)        F = K sqrt(R_eff) (xi^(3/2) + A_d sqrt(xi) xidot), R_eff the
                            effective radius R_i R_j / (R_i + R_j) (the thesis prints its
                            inverse: a typo), kept >= 0 (no pull at the end of a contact).
   Each returns the force and the elastic energy stored, so the engine's energy ledger can
   book the rest of the work as dissipation.  Tangential forces (friction.h) take their
   stiffness and damping from the normal law's at the same overlap (wg_contact_stiffness). */
#ifndef WG_CONTACT_H
#define WG_CONTACT_H

typedef enum { WG_CONTACT_LINEAR = 0, WG_CONTACT_HERTZ = 1 } wg_contact_law;

typedef struct wg_contact {
  wg_contact_law law;
  double k;      /* linear: spring constant [m g / d] */
  double zeta;   /* linear: damping ratio from the restitution */
  double kh;     /* Hertz: K = 2 Y / (3 (1 - nu^2)) [m g / d^2] */
  double ad;     /* Hertz: dissipative constant A_d [sqrt(d/g)] */
} wg_contact;

/* Linear law with restitution e (0 < e <= 1) and contact time t_c for a pair of reduced mass
   m_ref: k = m_ref (pi^2 + ln^2 e) / t_c^2. */
wg_contact wg_contact_linear(double e, double t_c, double m_ref);
/* Hertz law with stiffness K and dissipative constant A_d. */
wg_contact wg_contact_hertz(double kh, double ad);

/* Normal force (> 0 repulsive) for overlap xi > 0 and overlap rate xidot (> 0 closing);
   *f_elastic is its elastic part and *u_elastic the elastic energy stored at this overlap
   (the rest of the force, times xidot, is the power dissipated). */
double wg_contact_force(const wg_contact *c, double xi, double xidot, double r_eff,
                        double m_eff, double *f_elastic, double *u_elastic);

/* The normal law's secant stiffness F_elastic / xi (*k_n) and dashpot coefficient (*gamma_n:
   the force per unit xidot) at overlap xi > 0. */
void wg_contact_stiffness(const wg_contact *c, double xi, double r_eff, double m_eff,
                          double *k_n, double *gamma_n);

/* Restitution damping ratio of the linear law: zeta(e). */
double wg_contact_zeta(double e);

#endif
