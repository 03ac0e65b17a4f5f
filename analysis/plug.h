/* The Leidenfrost plug's frequency, thesis Eq. 6.5, shared by wetgran-theory (plug) and
   wetgran-leidenfrost (oscillation): a plug on a gas cushion of height h0 and base area A_g,
   the cushion's N grains excluding V_ex = 4 N V_bead, adiabatic index kappa:
     omega_p^2 = kappa g / h0 (1 + V_ex / (A_g h0)). */
#ifndef WG_PLUG_H
#define WG_PLUG_H

/* omega_p^2 */
static inline double wg_plug_omega2(double kappa, double g, double h0, double v_ex, double area)
{
  return kappa * g / h0 * (1 + v_ex / (area * h0)); /* Eq. 6.5 */
}

#endif
