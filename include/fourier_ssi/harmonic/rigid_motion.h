/**
 * What a rigid foundation's solve gives back: its rigid motion, and the
 * influence and stiffness coefficients under unit loads (the values that
 * RigidFoundation, rigid_foundation.h, reads from a solution).
 */
#ifndef fourier_ssi_rigid_motion_h
#define fourier_ssi_rigid_motion_h

namespace FourierSSI
{
  /**
   * Dimensionless influence and stiffness coefficients of a rigid
   * foundation under (H, M), thesis eqs 4.2-4.5 (6.1-6.3 for piles):
   *   [u_H / a, theta]^T = [[I_H, I_MH], [I_MH, I_M]] [H/(G a^2), M/(G a^3)]^T
   * and K = I^-1. I_MH is read from both load cases (the flexibility matrix
   * must be symmetric: a check of the whole system).
   */
  struct FoundationCoefficients
  {
    double I_H = 0., I_M = 0., I_MH_from_H = 0., I_MH_from_M = 0.;
    double K_H = 0., K_M = 0., K_MH = 0.;
  };

  /** The rigid motion read back from a solution. */
  struct RigidMotion
  {
    double horizontal_displacement = 0.; // U_h [m]
    double rotation                = 0.; // Theta [rad]
    double vertical_displacement   = 0.; // W_v [m]
    double twist                   = 0.; // Phi [rad]
  };
} // namespace FourierSSI

#endif
