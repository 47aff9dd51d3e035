#include <fourier_ssi/coupled/linearisation_choice.h>
#include <fourier_ssi/interfaces/interface_penalty_ratio.h>
#include <iomanip>
#include <sstream>

namespace FourierSSI
{
  void
  choose_interface_linearisation(AllParameters          &parameters,
                                 const Triangulation<2> &triangulation)
  {
    InterfaceParameters &interfaces = parameters.interfaces;
    if (interfaces.penalty_ratio.has_value())
      return;
    interfaces.penalty_ratio =
      coulomb_penalty_ratio(interfaces, parameters.materials, triangulation);
    if (interfaces.any_nonlinear() && parameters.newton_on_load_path())
      interfaces.iteration_stiffness_cap =
        parameters.linearises_on_coupled_tangent() ?
          soil_iteration_stiffness :
          interface_iteration_stiffness;
  }

  std::string
  describe_interface_linearisation(const AllParameters &parameters)
  {
    const InterfaceParameters &interfaces = parameters.interfaces;
    std::ostringstream         line;
    line << "interface linearisation: "
         << (parameters.newton_on_load_path() ? "tangent (Newton)" :
                                                "initial stiffness")
         << ", theta samples "
         << (interfaces.is_stiff() ? "2 n_max + 1" : "4 (n_max + 1)")
         << " unless set (";
    if (parameters.load_path.stiffness ==
        LoadPathParameters::Stiffness::automatic)
      line << "Load path/Stiffness = auto: ";
    else
      line << "Load path/Stiffness as set; ";
    if (interfaces.any_contact())
      line << "a contact interface";
    else
      line << "stiffest coulomb penalty max(kn, ks) l / G = " << std::scientific
           << std::setprecision(1) << *interfaces.penalty_ratio
           << (interfaces.is_stiff() ? " >= " : " < ") << std::defaultfloat
           << stiff_penalty_ratio;
    line << ")";
    return line.str();
  }
} // namespace FourierSSI
