#include <fourier_ssi/input/load_parameters.h>

namespace FourierSSI
{
  void
  LoadParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loads");
    prm.declare_entry(
      "Traction",
      "",
      Patterns::Anything(),
      "Surface tractions [kPa] as functions of r, z and theta [rad] (the 3D "
      "load, not an amplitude): 'id: r=expr, z=expr, theta=expr; ...'. The "
      "program decomposes them into harmonics and solves only those whose "
      "amplitude exceeds the tolerance (with Discretization/Harmonics = "
      "auto). Nonlinear runs with a Rigid foundation: held in every "
      "harmonic (see Boundary conditions/Traction).");
    prm.declare_entry(
      "Prescribed displacement",
      "",
      Patterns::Anything(),
      "Prescribed 3D displacements [m] as functions of r, z, theta: "
      "'id: u=expr, v=expr, w=expr; ...' (u radial, v axial, w "
      "circumferential; an omitted component is free).");
    prm.declare_entry("Harmonic tolerance",
                      "1e-6",
                      Patterns::Double(1e-15, 1.),
                      "A harmonic is solved if the amplitude of some load "
                      "exceeds this fraction of the load's largest value.");
    prm.declare_entry("Maximum harmonic",
                      "32",
                      Patterns::Integer(0, 1024),
                      "Largest harmonic n considered by the decomposition.");
    prm.leave_subsection();
  }

  void
  LoadParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loads");
    traction = BoundaryConditions::parse_boundary_map(prm.get("Traction"),
                                                      {{"r", "z", "theta"}},
                                                      "Loads/Traction");
    displacement =
      BoundaryConditions::parse_boundary_map(prm.get("Prescribed displacement"),
                                             {{"u", "v", "w"}},
                                             "Loads/Prescribed displacement");
    tolerance    = prm.get_double("Harmonic tolerance");
    max_harmonic = prm.get_integer("Maximum harmonic");
    prm.leave_subsection();
    // Fail at parse time on an expression that does not parse.
    for (const auto &[id, e] : traction)
      make_theta_function(e, "Loads/Traction");
    for (const auto &[id, e] : displacement)
      make_theta_function(e, "Loads/Prescribed displacement");
  }
} // namespace FourierSSI
