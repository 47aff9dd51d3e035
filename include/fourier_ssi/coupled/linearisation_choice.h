/**
 * The one decision of how an interface-only load path is linearised and
 * sampled, taken on the scene's first mesh: Load path/Stiffness = auto
 * becomes Newton for a contact interface or a stiff coulomb penalty
 * (InterfaceParameters::is_stiff), and Newton assembles its coulomb springs
 * no stiffer than a cap times G / l (interface_iteration_stiffness,
 * soil_iteration_stiffness), its stiffer laws acting through the augmented
 * Lagrangian's multipliers (doc/nonlinear-interfaces.md section 5b).
 */
#ifndef fourier_ssi_linearisation_choice_h
#define fourier_ssi_linearisation_choice_h

#include <deal.II/grid/tria.h>
#include <fourier_ssi/input/parameters.h>
#include <string>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * Measures the interfaces' penalty ratio on `triangulation` (once: a
   * refined mesh of a later cycle keeps the first mesh's choice, so that
   * every cycle runs the same solver on the same samples) and sets the
   * springs' cap where Newton steps the path. Call before the harmonic set
   * is assembled.
   */
  void
  choose_interface_linearisation(AllParameters          &parameters,
                                 const Triangulation<2> &triangulation);

  /**
   * The log line of that choice, e.g. "interface linearisation: tangent
   * (Load path/Stiffness = auto: stiffest coulomb penalty max(kn, ks) l / G
   * = 2.0e+06 >= 5e3)".
   */
  std::string
  describe_interface_linearisation(const AllParameters &parameters);
} // namespace FourierSSI

#endif
