/**
 * The error of a capacity read as the load at the end of a displacement-
 * controlled path (doc/soil-plasticity.md section 8b): the rise still to
 * come, to the asymptote 1/b of the hyperbola |u| / |P| = a + b |u| fitted
 * through the last three steps by least squares. The same rule as
 * tools/capacity.py's plateau(), which bounded the remaining rise of every
 * shipped curve; the mesh and harmonic errors need other runs (that tool).
 */
#ifndef fourier_ssi_capacity_plateau_h
#define fourier_ssi_capacity_plateau_h

#include <vector>

namespace FourierSSI
{
  /**
   * |1/b - |P_last|| for the curve (motion[i], load[i]) (any signs, in the
   * units of the load); infinity with fewer than three steps or when the
   * last three do not bend over (b <= 0).
   */
  double
  plateau_error(const std::vector<double> &motion,
                const std::vector<double> &load);
} // namespace FourierSSI

#endif
