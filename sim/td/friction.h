/* Tangential contact forces of the time-driven engine: a spring with history and a dashpot
   along the contact plane, capped by Coulomb's law (Cundall and Strack), as the two papers
   in ../shared/seeds use them (notes-streams.md Sec. 1.4, notes-sheared-layering.md
   Sec. 1.8).

   The spring's extension xi lives in the tangent plane of its contact.  Each step it is
   turned into the plane of the new normal with its length kept, advanced by the tangential
   velocity of the contact point times dt, and the force is F_t = -k_t xi - gamma_t v_t.
   When |F_t| > mu F_n the contact slides: F_t is scaled down to mu F_n and xi truncated so
   that -k_t xi - gamma_t v_t = F_t.  F_n is the repulsive contact force (elastic plus
   dashpot), not the bridge's pull.

   Rolling resistance (mu_roll > 0) adds a torque against the pair's relative rolling
   (wg_rolling_resistance).

   Stiffness and damping are fractions of the normal law's at the same overlap:
   k_t = kt_ratio k_n, gamma_t = gt_ratio gamma_n, with k_n = F_elastic / xi_n (linear: k;
   Hertz: K sqrt(R_eff xi_n), the layering paper's (delta R_eff)^1/2 scaling) and gamma_n the
   normal dashpot's coefficient.

   Energy: the spring holds k_t |xi|^2 / 2.  What the tangential force does not store there
   is lost (to the dashpot, to slip, to the spring's release when the contact ends, and with
   Hertz to k_t's change under a loaded spring): the engine books the power -F_t . v_t into
   its dissipation integral and the spring energy's change, negated, as a loss at each step,
   so that dissipated = -(work of F_t) - (change of spring energy). */
#ifndef WG_FRICTION_H
#define WG_FRICTION_H

typedef struct wg_friction {
  double mu;        /* Coulomb coefficient; 0: frictionless (no rotation, no history) */
  double kt_ratio;  /* k_t / k_n */
  double gt_ratio;  /* gamma_t / gamma_n */
  double mu_roll;   /* rolling resistance: torque up to mu_roll F_n times the lever */
} wg_friction;

/* A contact's tangential spring: extension and the energy it held after the last update. */
typedef struct wg_spring {
  double xi[3];
  double u;
} wg_spring;

/* Tangential relative velocity of the contact point of j against i's: v_ji the relative
   velocity of the centres, n the unit normal from i to j, li, lj the lever arms (centre to
   contact point) and wi, wj the angular velocities. */
void wg_contact_tangential_velocity(const double v_ji[3], const double n[3], double li,
                                    double lj, const double wi[3], const double wj[3],
                                    double vt[3]);

/* Update the spring sp at a force evaluation: into the plane of the normal n, extended by
   dv_t dt (dv_t: the tangential velocity over the step just taken, i.e. the displacement of
   the contact points; NULL at an evaluation that does not follow a step), then the force on
   j (on i: minus it) ft = -k_t xi - g_t v_t with the current tangential velocity v_t,
   stiffness kt, damping gt, capped at fmax = mu F_n.  Returns the change of the spring's
   energy since its last update; *power gets the power the force takes from the pair,
   -ft . v_t.  The spring energy is in sp->u. */
double wg_spring_update(wg_spring *sp, const double n[3], const double vt[3], const double *dvt,
                        double kt, double gt, double fmax, double dt, double ft[3],
                        double *power);

/* Rolling resistance (notes-sheared-layering Eq. 18): the rolling velocity
   w = l (w_i - w_j) x n meets a force F_r = min(fmax, cap |w|) along w at lever l, i.e. the
   torque -l n x F_r on i and its opposite on j (a wall: w_j = 0, no partner).  The paper's
   levers l_i, l_j are replaced by their harmonic mean l, so that the torques cancel and
   angular momentum is kept; for equal grains this is the paper's law.  fmax = mu_roll F_n;
   cap = 1 / (2 dt l^2 (1/I_i + 1/I_j)) keeps one step's kick from reversing w (a sticking
   roll instead of a torque flipping sign at every step).  Adds the torque on i to tq_i and
   returns the power it dissipates, F_r . w >= 0. */
double wg_rolling_resistance(const double n[3], double l, const double wi[3], const double wj[3],
                             double fmax, double cap, double tq_i[3]);

/* A contact has ended: the spring is reset; returns the energy it held. */
double wg_spring_release(wg_spring *sp);

/* Moment of inertia of a uniform disk (dim 2) or sphere (dim 3) of mass m and radius R. */
static inline double wg_inertia(int dim, double m, double radius)
{
  return (dim == 2 ? 0.5 : 0.4) * m * radius * radius;
}

#endif
