/* Two-body cases of the event-driven engine against their closed forms: collision time and
   restitution, unequal masses, periodic images, capture versus rupture of a thin-thread
   bridge at exactly 1/2 mu u^2 = E_cb, and a ball bouncing on the shaken floor. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "ed.h"
#include "tharness.h"

/* A periodic 2D box of side 20 with two particles; extra overrides after the defaults. */
static int make_scene(wg_scene *sc, const char *const *extra)
{
  const char *base[] = {"dim=2", "n=2", "container=periodic", "lx=20", "height=20",
                        "sigma_p=0", "tg_init_abs=1", "seed=1", "t_end=10", NULL};
  wg_scene_init(sc);
  for (int k = 0; base[k]; k++)
    if (wg_scene_set_override(sc, base[k]) != WG_OK) return 1;
  for (int k = 0; extra && extra[k]; k++)
    if (wg_scene_set_override(sc, extra[k]) != WG_OK) return 1;
  return wg_scene_finish(sc) != WG_OK;
}

static double kinetic(const wg_ed *s)
{
  double ek, ep;
  wg_ed_energy(s, &ek, &ep);
  return ek;
}

static void head_on_elastic(void)
{
  wg_scene sc;
  TH_CHECK(make_scene(&sc, NULL) == 0, "elastic scene accepted");
  double r[4] = {5, 10, 8, 10}, v[4] = {1, 0, -1, 0}, rad[2] = {0.5, 0.5};
  wg_ed s;
  TH_CHECK(wg_ed_alloc_state(&s, &sc, 2, r, v, rad, NULL, 0) == WG_OK, "state set up");
  wg_ed_advance(&s, 0.999999);
  TH_CHECK(s.counts.collisions == 0, "no collision before t = 1 (gap 2, closing speed 2)");
  wg_ed_advance(&s, 1.000001);
  TH_CHECK(s.counts.collisions == 1, "one collision at t = 1");
  double rr[2], vv[2];
  wg_ed_position_of(&s, 0, 1.5, rr, vv);
  TH_CLOSE("velocity of 0 after: reversed", vv[0], -1.0, 1e-15, 0);
  TH_CLOSE("position of 0 at t = 1.5", rr[0], 6.0 - 0.5, 1e-14, 0);
  TH_CLOSE("kinetic energy conserved", kinetic(&s), 1.0, 1e-15, 0);
  wg_ed_free(&s);
}

static void restitution_unequal_masses(void)
{
  const char *extra[] = {"eps=0.8", "tc=0", "mass=volume", NULL};
  wg_scene sc;
  TH_CHECK(make_scene(&sc, extra) == 0, "inelastic scene with m = d^2 accepted");
  double r[4] = {5, 10, 8, 10}, v[4] = {0.7, 0, -0.4, 0}, rad[2] = {0.5, 0.7};
  double m[2] = {1.0, 1.4 * 1.4};
  wg_ed s;
  TH_CHECK(wg_ed_alloc_state(&s, &sc, 2, r, v, rad, m, 0) == WG_OK, "state set up");
  double e0 = kinetic(&s);
  wg_ed_advance(&s, 5);
  double ra[2], va[2], rb[2], vb[2];
  wg_ed_position_of(&s, 0, 5, ra, va);
  wg_ed_position_of(&s, 1, 5, rb, vb);
  double e = 0.8, m1 = m[0], m2 = m[1], u1 = v[0], u2 = v[2];
  double v1 = ((m1 - e * m2) * u1 + (1 + e) * m2 * u2) / (m1 + m2);
  double v2 = ((m2 - e * m1) * u2 + (1 + e) * m1 * u1) / (m1 + m2);
  TH_CHECK(s.counts.collisions == 1, "one collision (%llu)", s.counts.collisions);
  TH_CLOSE("v1 after, 1D restitution formula", va[0], v1, 1e-14, 1e-16);
  TH_CLOSE("v2 after, 1D restitution formula", vb[0], v2, 1e-14, 1e-16);
  TH_CLOSE("relative velocity reversed times eps", vb[0] - va[0], -e * (u2 - u1), 1e-14, 0);
  TH_CLOSE("momentum conserved", m1 * va[0] + m2 * vb[0], m1 * u1 + m2 * u2, 1e-15, 1e-16);
  double mu = m1 * m2 / (m1 + m2), un = u2 - u1;
  double lost = 0.5 * mu * (1 - e * e) * un * un; /* Eq. 2.6 */
  TH_CLOSE("ledger: dissipated = mu (1 - e^2) u^2 / 2", wg_ksum_value(&s.ledger.dissipated_coll), lost, 1e-14, 0);
  TH_CLOSE("kinetic energy drop equals the ledger", e0 - kinetic(&s), lost, 1e-13, 0);
  wg_ed_free(&s);
}

static void tc_model(void)
{
  const char *extra[] = {"eps=0.5", "tc=1", NULL};
  wg_scene sc;
  TH_CHECK(make_scene(&sc, extra) == 0, "TC scene accepted");
  /* three in a row: 1 hits 2 at t = 0.5, then 2 hits 3 within tc: elastic */
  double r[6] = {5, 10, 7, 10, 8.2, 10}, v[6] = {2, 0, 0, 0, 0, 0}, rad[3] = {0.5, 0.5, 0.5};
  sc.n = 3;
  wg_ed s;
  TH_CHECK(wg_ed_alloc_state(&s, &sc, 3, r, v, rad, NULL, 0) == WG_OK, "state set up");
  wg_ed_advance(&s, 0.8); /* collisions at t = 0.5 and 0.6333; the next is at 0.9 */
  double rr[2], v2[2], v3[2];
  wg_ed_position_of(&s, 1, 0.8, rr, v2);
  wg_ed_position_of(&s, 2, 0.8, rr, v3);
  TH_CHECK(s.counts.collisions == 2, "two collisions by t = 0.8 (%llu)", s.counts.collisions);
  /* first collision inelastic: v2 = (1+e)/2 * 2 = 1.5; second within tc: elastic swap */
  TH_CLOSE("second particle stops (elastic swap inside tc)", v2[0], 0.0, 0, 1e-15);
  TH_CLOSE("third particle takes 1.5", v3[0], 1.5, 1e-15, 0);
  wg_ed_free(&s);
}

/* Three disks touching in a row, the outer two closing in: every collision after the first
   happens at the same instant, so the TC model's elastic rule would not apply (RIGID_TIME):
   they are perfectly inelastic and the row ends at rest as one body, after finitely many
   collisions, with all its kinetic energy in the ledger. */
static void rigid_row(void)
{
  const char *extra[] = {"eps=0.5", "tc=1", NULL};
  wg_scene sc;
  TH_CHECK(make_scene(&sc, extra) == 0, "TC scene accepted");
  sc.n = 3;
  double r[6] = {5, 10, 6, 10, 7, 10}, v[6] = {1, 0, 0, 0, -1, 0}, rad[3] = {0.5, 0.5, 0.5};
  wg_ed s;
  TH_CHECK(wg_ed_alloc_state(&s, &sc, 3, r, v, rad, NULL, 0) == WG_OK, "state set up");
  double e0 = kinetic(&s);
  TH_CHECK(wg_ed_advance(&s, 1.0) == WG_OK, "the jammed row does not stall the run");
  TH_CHECK(s.counts.collisions < 200, "finitely many collisions (%llu)", s.counts.collisions);
  TH_CHECK(s.counts.rigid + 1 == s.counts.collisions, "all but the first are same-instant (%llu of %llu)",
           s.counts.rigid, s.counts.collisions);
  double rr[2], vv[2], vmax = 0;
  for (long k = 0; k < 3; k++) {
    wg_ed_position_of(&s, k, 1.0, rr, vv);
    vmax = fmax(vmax, fabs(vv[0]));
  }
  TH_CLOSE("row at rest (momentum was zero)", vmax, 0.0, 0, 1e-9);
  TH_CLOSE("kinetic energy all in the ledger", wg_ksum_value(&s.ledger.dissipated_coll), e0, 1e-12, 0);
  wg_ed_free(&s);
}

/* A bonded pair at gap s_crit spinning with a purely tangential relative velocity: the hard
   edge alone would need infinitely many reflections (Zeno).  The first reflection grazes and
   leaves at grazing_angle = 0.05 (default): u_n = 0.05 |u| inward, |u| and the momentum unchanged, the
   angular momentum mu L |u| reduced by sqrt(1 - 0.05^2); after that the relative position
   runs along chords of angle 2 * 0.05, one reflection each. */
static void grazing_bridge(const char *angle_key, double theta)
{
  const char *extra[] = {"s_crit=0.1", "e_cb=0.5", angle_key, NULL};
  wg_scene sc;
  TH_CHECK(make_scene(&sc, extra) == 0, "wet elastic scene accepted (%s)", angle_key ? angle_key : "default angle");
  const double L = 1.1, u = 0.3;
  wg_ed s;
  TH_CHECK(wg_ed_alloc_empty(&s, &sc, 2) == WG_OK, "empty state allocated");
  double r[2][2] = {{10, 10}, {10 + L, 10}}, v[2][2] = {{0, -0.5 * u}, {0, 0.5 * u}};
  for (int i = 0; i < 2; i++) {
    for (int k = 0; k < 2; k++) {
      s.p[i].r[k] = r[i][k];
      s.p[i].v[k] = v[i][k];
    }
    s.p[i].radius = 0.5;
    s.nbond[i] = 1;
    s.bond[(size_t)i * s.bond_cap] = 1 - i;
  }
  TH_CHECK(wg_ed_start(&s, 0) == WG_OK, "bonded pair at the edge set up");
  double t_end = 20;
  TH_CHECK(wg_ed_advance(&s, t_end) == WG_OK, "the spinning pair does not stall the run");
  double ra[2], va[2], rb[2], vb[2];
  wg_ed_position_of(&s, 0, t_end, ra, va);
  wg_ed_position_of(&s, 1, t_end, rb, vb);
  double du[2] = {vb[0] - va[0], vb[1] - va[1]}, dr[2] = {rb[0] - ra[0], rb[1] - ra[1]};
  TH_CHECK(s.counts.grazing == 1 && s.counts.ruptures == 0 && wg_ed_bond_total(&s) == 1,
           "one grazing reflection, bridge intact (grazing %llu, ruptures %llu)", s.counts.grazing,
           s.counts.ruptures);
  TH_CLOSE("relative speed unchanged", hypot(du[0], du[1]), u, 1e-13, 0);
  TH_CLOSE("momentum unchanged", va[1] + vb[1], 0.0, 0, 1e-15);
  TH_CLOSE("angular momentum L |u| sqrt(1 - theta^2)", dr[0] * du[1] - dr[1] * du[0],
           L * u * sqrt(1 - theta * theta), 1e-12, 0);
  /* chord length 2 L sin(theta), travelled at speed u; the first starts at t = 0 */
  double chords = t_end * u / (2 * L * sin(theta));
  TH_CHECK(fabs((double)s.counts.reflections - ceil(chords)) <= 1,
           "one reflection per chord: %llu reflections, %.2f chords", s.counts.reflections, chords);
  TH_CHECK(s.counts.collisions == 0, "the pair never comes back to contact (%llu)", s.counts.collisions);
  wg_ed_free(&s);
}

static void periodic_image(void)
{
  wg_scene sc;
  TH_CHECK(make_scene(&sc, NULL) == 0, "scene accepted");
  /* gap through the boundary: 20 - 19.5 + 0.8 - 1 = 0.3, closing speed 2 */
  double r[4] = {0.8, 10, 19.5, 10}, v[4] = {-1, 0, 1, 0}, rad[2] = {0.5, 0.5};
  wg_ed s;
  TH_CHECK(wg_ed_alloc_state(&s, &sc, 2, r, v, rad, NULL, 0) == WG_OK, "state set up");
  wg_ed_advance(&s, 0.149999);
  TH_CHECK(s.counts.collisions == 0, "no collision before t = 0.15");
  wg_ed_advance(&s, 0.150001);
  TH_CHECK(s.counts.collisions == 1, "collision through the periodic boundary at t = 0.15");
  double rr[2], vv[2];
  wg_ed_position_of(&s, 0, 1.0, rr, vv);
  TH_CLOSE("particle 0 bounced back", vv[0], 1.0, 1e-15, 0);
  wg_ed_free(&s);
}

/* Head-on wet pair of unit masses (mu = 1/2) with relative speed u: after the capture the
   pair separates elastically with speed u and reaches gap s_crit with 1/2 mu u^2 = u^2/4. */
static void bridge_case(double u, double e_cb, int *ruptures, int *reflections, double *u_after,
                        double *energy_lost, long *bonds)
{
  char ecb[64];
  snprintf(ecb, sizeof ecb, "e_cb=%.17g", e_cb);
  const char *extra[] = {"s_crit=0.1", ecb, NULL};
  wg_scene sc;
  make_scene(&sc, extra);
  double r[4] = {5, 10, 7, 10}, v[4] = {0.5 * u, 0, -0.5 * u, 0}, rad[2] = {0.5, 0.5};
  wg_ed s;
  wg_ed_alloc_state(&s, &sc, 2, r, v, rad, NULL, 0);
  double e0 = kinetic(&s);
  wg_ed_advance(&s, 3.0 / u);
  double rr[2], va[2], vb[2];
  wg_ed_position_of(&s, 0, s.now, rr, va);
  wg_ed_position_of(&s, 1, s.now, rr, vb);
  *ruptures = (int)s.counts.ruptures;
  *reflections = (int)s.counts.reflections;
  *u_after = vb[0] - va[0];
  *energy_lost = e0 - kinetic(&s);
  *bonds = wg_ed_bond_total(&s);
  wg_ed_free(&s);
}

static void capture_and_rupture(void)
{
  int nr, nf;
  double ua, lost;
  long bonds;
  /* exactly at threshold: 1/2 mu u^2 = 1/4 = E_cb -> reflected, stays bound */
  bridge_case(1.0, 0.25, &nr, &nf, &ua, &lost, &bonds);
  TH_CHECK(nr == 0 && nf >= 1 && bonds == 1,
           "at 1/2 mu u^2 = E_cb exactly: captured and reflected (ruptures %d, reflections %d, bonds %ld)",
           nr, nf, bonds);
  TH_CLOSE("bound pair keeps its energy", lost, 0.0, 0, 1e-15);
  /* just above: ruptures, losing exactly E_cb */
  bridge_case(1.0 + 1e-9, 0.25, &nr, &nf, &ua, &lost, &bonds);
  TH_CHECK(nr == 1 && nf == 0 && bonds == 0, "just above threshold: one rupture, no bond left");
  TH_CLOSE("rupture removes exactly E_cb", lost, 0.25, 1e-12, 0);
  double u = 1.3;
  bridge_case(u, 0.25, &nr, &nf, &ua, &lost, &bonds);
  TH_CLOSE("speed after rupture sqrt(u^2 - 2 E_cb / mu)", ua, sqrt(u * u - 4 * 0.25), 1e-14, 0);
  TH_CLOSE("energy taken by rupture", lost, 0.25, 1e-14, 0);
  /* just below: bound forever */
  bridge_case(1.0 - 1e-9, 0.25, &nr, &nf, &ua, &lost, &bonds);
  TH_CHECK(nr == 0 && nf >= 1 && bonds == 1, "just below threshold: bound (reflections %d)", nf);
}

/* One ball on a floor shaken at Gamma = 3: elastic, so E(t) - E(0) is exactly the walls' work. */
static void ball_on_shaken_floor(void)
{
  wg_scene sc;
  wg_scene_init(&sc);
  const char *keys[] = {"dim=2", "n=1", "lx=10", "height=50", "sigma_p=0", "gamma=3",
                        "estar_d=0.5", "tg_init_abs=0.01", "seed=3", "t_end=1000", NULL};
  for (int k = 0; keys[k]; k++) wg_scene_set_override(&sc, keys[k]);
  TH_CHECK(wg_scene_finish(&sc) == WG_OK, "single-ball shaker scene accepted");
  double r[2] = {5, 2}, v[2] = {0.1, 0}, rad[1] = {0.5};
  wg_ed s;
  TH_CHECK(wg_ed_alloc_state(&s, &sc, 1, r, v, rad, NULL, 0) == WG_OK, "state set up");
  wg_ed_advance(&s, 1000);
  double rr[2], vv[2];
  wg_ed_position_of(&s, 0, s.now, rr, vv);
  double wall = sc.amplitude * sin(sc.omega * s.now);
  TH_CHECK(s.counts.wall_hits > 100, "ball keeps bouncing (%llu wall hits)", s.counts.wall_hits);
  TH_CHECK(rr[1] - 0.5 >= wall - 1e-9 && rr[1] + 0.5 <= 50 + sc.amplitude,
           "ball stays inside the container (z = %.6f, floor at %.6f)", rr[1], wall);
  double res = wg_ed_ledger_residual(&s);
  TH_CHECK(res < 1e-12, "ledger closes: residual %.3g < 1e-12", res);
  wg_ed_free(&s);
}

int main(void)
{
  head_on_elastic();
  restitution_unequal_masses();
  tc_model();
  rigid_row();
  grazing_bridge(NULL, 0.05);
  grazing_bridge("grazing_angle=0.1", 0.1);
  periodic_image();
  capture_and_rupture();
  ball_on_shaken_floor();
  return th_summary();
}
