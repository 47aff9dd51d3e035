#include <fourier_ssi/nonlinear_interface_parameters.h>

namespace FourierSSI
{
  void
  NonlinearInterfaceParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Nonlinear interfaces");
    prm.declare_entry("Theta samples",
                      "0",
                      Patterns::Integer(0),
                      "Angles N at which the interface law is evaluated. 0: "
                      "4 (n_max + 1). Must exceed 2 n_max (n_max the highest "
                      "harmonic), else a band-limited field aliases.");
    prm.declare_entry("Load steps",
                      "10",
                      Patterns::Integer(1),
                      "Equal steps from 0 to the full loads (load control) "
                      "or to the target motion (displacement control).");
    prm.declare_entry("Control",
                      "load",
                      Patterns::Selection("load|displacement"),
                      "load: the Rigid foundation loads (H, M, V, T) times "
                      "step/steps. displacement: those loads give the "
                      "direction, their factor is found so that the "
                      "controlled motion reaches Target (past a peak too).");
    prm.declare_entry("Controlled motion",
                      "vertical",
                      Patterns::Selection("vertical|twist|horizontal|rotation"),
                      "Displacement control: the rigid-foundation motion "
                      "prescribed (vertical [m], twist about z [rad], "
                      "horizontal along x [m], rotation about y [rad]).");
    prm.declare_entry("Target",
                      "0",
                      Patterns::Double(),
                      "Displacement control: final value of the controlled "
                      "motion [m or rad].");
    prm.declare_entry("Tolerance",
                      "1e-10",
                      Patterns::Double(0.),
                      "Converged when |out-of-balance force| <= Tolerance "
                      "|applied load| (2-norms over all harmonics; the "
                      "interface tractions then balance the load to it).");
    prm.declare_entry("Maximum iterations",
                      "2000",
                      Patterns::Integer(1),
                      "Out-of-balance solves per step before it is cut.");
    prm.declare_entry("Acceleration",
                      "aitken",
                      Patterns::Selection("aitken|none"),
                      "aitken: Aitken's Delta^2 relaxation of the "
                      "out-of-balance load; none: plain initial stiffness.");
    prm.declare_entry("Maximum step cuts",
                      "4",
                      Patterns::Integer(0),
                      "Halvings of a step that does not converge before "
                      "the run stops with an error.");
    prm.leave_subsection();
  }

  void
  NonlinearInterfaceParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Nonlinear interfaces");
    theta_samples = prm.get_integer("Theta samples");
    load_steps    = prm.get_integer("Load steps");
    control =
      prm.get("Control") == "load" ? Control::load : Control::displacement;
    const std::string m = prm.get("Controlled motion");
    motion              = m == "vertical"   ? Motion::vertical :
                          m == "twist"      ? Motion::twist :
                          m == "horizontal" ? Motion::horizontal :
                                              Motion::rotation;
    target              = prm.get_double("Target");
    tolerance           = prm.get_double("Tolerance");
    maximum_iterations  = prm.get_integer("Maximum iterations");
    aitken              = prm.get("Acceleration") == "aitken";
    maximum_step_cuts   = prm.get_integer("Maximum step cuts");
    prm.leave_subsection();
  }
} // namespace FourierSSI
