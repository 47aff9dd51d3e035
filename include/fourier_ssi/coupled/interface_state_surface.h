/**
 * The state of the nonlinear interfaces at one converged load step as a
 * surface revolved about the axis, for ParaView (Output/Interface state
 * 3D; doc/output-files.md, "The interface state in 3D"): which part of a
 * pile shaft slips, where the gap opens behind a laterally loaded pile.
 *
 * One quadrilateral per interface point i and theta sample j, the sample
 * itself and nothing interpolated: along the meridian the part of the face
 * the point's weight stands for (InterfacePoint::share, so the quads of a
 * face tile it), around the axis the sector centred on theta_j = 2 pi j / N
 * of width 2 pi / N (the trapezoidal weight of the sample). A quad's area
 * is then the point's area_per_radian times 2 pi / N: the surface is the
 * integration the iteration does, drawn. Its values are those of
 * interface-state.csv at (point i, theta_j) of that step, as cell data in
 * Float64 (write_quad_surface_vtu): state (0 stick, 1 slip, 2 open),
 * the tractions t_n, t_s, t_theta and tau = |(t_s, t_theta)| [kPa], the
 * relative displacements d_n, d_s, d_theta [m], the interface (boundary)
 * id, the point (the CSV's column point) and theta_j [degrees].
 */
#ifndef fourier_ssi_interface_state_surface_h
#define fourier_ssi_interface_state_surface_h

#include <fourier_ssi/coupled/nonlinear_interface_points.h>
#include <fourier_ssi/fourier/theta_sampling.h>
#include <string>

namespace FourierSSI
{
  /** interface-state-3d-step<s>.vtu. */
  std::string
  interface_state_3d_name(const unsigned int step);

  /** interface-state-3d.pvd. */
  std::string
  interface_state_3d_series();

  /**
   * Write the surface of `state` (a step's snapshot, index i * N + j) to
   * filename; returns its stick / slip / open counts (the quads of each).
   */
  ContactCounts
  write_interface_state_surface(const NonlinearInterfacePoints &interface,
                                const InterfaceSnapshot        &state,
                                const ThetaSampling            &sampling,
                                const std::string              &filename);
} // namespace FourierSSI

#endif
