/* A particle of either engine: 64 bytes, one cache line. */
#ifndef WG_PARTICLE_H
#define WG_PARTICLE_H

typedef struct wg_particle {
  double r[3];     /* centre at local time t [d]; r[dim-1] is the height */
  double v[3];     /* velocity at local time t [sqrt(g d)] */
  double t;        /* local time [sqrt(d/g)] (the event-driven engine's lazy updates) */
  double radius;   /* [d] */
} wg_particle;

#endif
