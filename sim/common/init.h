/* Initial state (thesis Sec. 3.1.1): particles on a regular lattice filling the container,
   diameters uniform in [1 - sqrt(3) sigma_p, 1 + sqrt(3) sigma_p] (Eq. 2.21-2.22), Gaussian
   velocities at the scene's temperature, no bridges.  Random numbers: GSL's MT19937 seeded
   with the scene's seed; diameters first (particle order), then velocities (particle order,
   axis order).  The centre-of-mass velocity is removed and the velocities rescaled so that
   T_g (Eq. 3.2) equals the requested value exactly.
   With init_from, the last snapshot of that run file instead: positions (moved vertically so
   that the floor's position at that instant becomes 0, the new floor's position at t = 0),
   velocities, diameters and masses; then no random numbers are drawn. */
#ifndef WG_INIT_H
#define WG_INIT_H

#include "particle.h"
#include "scene.h"

/* Fill p[0..n-1] (positions, velocities, radii; local times 0) and, if mass is non-NULL,
   the masses (m = d^dim). */
int wg_init_state(const wg_scene *sc, wg_particle *p, double *mass);

/* With init_from: the bridges of the run file's last snapshot, as n_pairs pairs of particle
   ids (*pairs, 2 per pair, malloc'ed; NULL when there are none). */
int wg_init_bonds(const wg_scene *sc, int32_t **pairs, long *n_pairs);

/* Temperature T_g (Eq. 3.2) the scene asks for at t = 0 [m g d]. */
double wg_init_temperature(const wg_scene *sc);

#endif
