/* The advective Cahn-Hilliard equation of Mahajan & Singh (2025), Eq. 1-4, in strain units
   (time gamma_dot t, so that both the mobility M = M_o gamma_dot and the shear flow scale out):

     dc/dt + shear (z - lz/2) dc/dx = M lap( f'(c) - kappa lap c ),
     f(c) = K [c_o c^2/2 - (1 + c_o) c^3/3 + c^4/4],   f'(c) = K c (c - 1)(c - c_o)   (Eq. 3)

   on lx x lz, periodic in x (the flow direction), between walls at z = 0 and lz that move at
   -+ shear lz/2 and let nothing through (dc/dz = d(lap c)/dz = 0): a Fourier series in x times
   a cosine series in z (FFTW's R2HC x REDFT10), on nx x nz points (nx = 1: the 1D problem along
   z).  Time stepping is first-order semi-implicit with a linear stabiliser S (Eyre; Shen & Yang):

     (c' - c)/dt = M lap( f'(c) + S (c' - c) - kappa lap c' ) - u . grad c,

   whose mass is conserved to round-off and whose free energy cannot rise without shear when
   S >= max |f''| / 2 over the values c takes.  A mode k of small amplitude around c_o grows at
   sigma = M k^2 (K c_o (1 - c_o) - kappa k^2) (k_c = sqrt(K c_o (1 - c_o) / kappa); notes on
   the paper, Sec. 3.2); one step multiplies it by wg_ch_gain(). */
#ifndef WG_CH_H
#define WG_CH_H

#include <fftw3.h>

typedef struct wg_ch_params {
  int nx, nz;            /* grid points along x (1: 1D) and z */
  double lx, lz;         /* box lengths */
  double K, kappa, c_o;  /* Eq. 3's bulk energy scale, gradient energy, unstable point */
  double mobility;       /* M (in strain units M_o) */
  double shear;          /* velocity gradient du_x/dz in strain units: 1 = on, 0 = off */
  double S;              /* stabiliser */
  double dt;             /* time step (strain) */
} wg_ch_params;

typedef struct wg_ch {
  wg_ch_params p;
  double *c;             /* c[ix * nz + iz] at x = ix lx/nx, z = (iz + 1/2) lz/nz */
  double *hat, *work, *work2;
  double *fp, *adv;      /* coefficients of f'(c) and of the advection term */
  double *k2;            /* kx^2 + kz^2 per spectral index */
  double *kx;            /* kx per x index of the half-complex layout (signed: see ch.c) */
  fftw_plan fwd, bwd;    /* real <-> spectral, work -> work2 (unnormalised) */
  double norm;           /* 1 / (2 nx nz): bwd(fwd(x)) = x / norm */
  int hat_valid;          /* hat holds c's coefficients (after a step); 0 when c was set anew */
  double t;
  long steps;
} wg_ch;

/* c is set by the caller after wg_ch_init (and may be set anew between steps: then clear
   hat_valid). */
int wg_ch_init(wg_ch *s, const wg_ch_params *p);
void wg_ch_free(wg_ch *s);
void wg_ch_step(wg_ch *s);

/* Diagnostics, per unit area: mean c; the bulk energy mean f(c); <|grad c|^2> (= -<c lap c>,
   the walls' and the period's boundary terms vanish); the free energy is their sum
   bulk + kappa grad2 / 2. */
double wg_ch_mass(const wg_ch *s);
double wg_ch_bulk_energy(const wg_ch *s);
double wg_ch_grad2(wg_ch *s);
double wg_ch_free_energy(wg_ch *s);
/* Amplitude a of the mode cos(2 pi mx x / lx) cos(pi mz z / lz) in c (mx, mz >= 0). */
double wg_ch_mode(wg_ch *s, int mx, int mz);
/* One step's gain of that mode around c_o in the linearised scheme. */
double wg_ch_gain(const wg_ch_params *p, int mx, int mz);
/* The x-averaged profile c(z) (nz values), and the number of its bands above the mean c. */
void wg_ch_profile(const wg_ch *s, double *prof);
int wg_ch_layers(const double *prof, int nz);

#endif
