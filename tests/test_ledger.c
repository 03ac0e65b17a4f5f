/* The energy ledger closes: kinetic + potential energy changes by exactly the walls' work
   minus what collisions, wall losses and bridge ruptures took, in shaken, inelastic, wet
   runs in 2D and 3D. */
#include <math.h>
#include <stdio.h>

#include "ed.h"
#include "tharness.h"

static void ledger_case(const char *name, const char *const *keys, double t_end)
{
  wg_scene sc;
  wg_scene_init(&sc);
  for (int k = 0; keys[k]; k++) wg_scene_set_override(&sc, keys[k]);
  TH_CHECK(wg_scene_finish(&sc) == WG_OK, "%s: scene accepted", name);
  wg_ed s;
  TH_CHECK(wg_ed_alloc(&s, &sc) == WG_OK, "%s: set up", name);
  double worst = 0;
  for (int k = 1; k <= 20; k++) {
    if (wg_ed_advance(&s, t_end * k / 20) != WG_OK) {
      TH_CHECK(0, "%s: run failed at t = %g", name, s.now);
      break;
    }
    double r = wg_ed_ledger_residual(&s);
    if (r > worst) worst = r;
  }
  TH_CHECK(s.counts.ruptures > 100 && s.counts.wall_hits > 100 && s.counts.collisions > 10000,
           "%s: all ledger terms at work (collisions %llu, ruptures %llu, wall hits %llu)", name,
           s.counts.collisions, s.counts.ruptures, s.counts.wall_hits);
  TH_CHECK(wg_ksum_value(&s.ledger.dissipated_coll) > 0 && wg_ksum_value(&s.ledger.dissipated_wall) > 0,
           "%s: inelastic losses recorded (%.4g, %.4g)", name,
           wg_ksum_value(&s.ledger.dissipated_coll), wg_ksum_value(&s.ledger.dissipated_wall));
  TH_CHECK(worst < 1e-9, "%s: largest ledger residual %.3g < 1e-9", name, worst);
  wg_ed_free(&s);
}

int main(void)
{
  const char *shake2d[] = {"dim=2", "n=600", "lx=200", "height=9", "s_crit=0.0711", "f_b=4",
                           "eps=0.9", "eps_wall=0.95", "gamma=15", "estar=1.42", "seed=5",
                           "t_end=100", NULL};
  ledger_case("2D wet inelastic shaker", shake2d, 100);
  const char *shake3d[] = {"dim=3", "n=800", "lx=14", "ly=14", "height=8", "s_crit=0.0625",
                           "e_cb_mgs=4", "eps=0.9", "eps_wall=0.95", "gamma=15", "estar=2",
                           "seed=6", "t_end=40", NULL};
  ledger_case("3D wet inelastic shaker", shake3d, 40);
  return th_summary();
}
