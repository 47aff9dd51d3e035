#include <deal.II/base/utilities.h>
#include <fourier_ssi/command_line.h>
#include <fourier_ssi/parameters.h>
#include <fstream>
#include <sstream>

namespace FourierSSI
{
  void
  DiscretizationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    prm.declare_entry("Harmonics",
                      "1",
                      Patterns::List(Patterns::Integer(0, 256)),
                      "Fourier harmonics n to solve.");
    prm.declare_entry("Family",
                      "symmetric",
                      Patterns::Selection("symmetric|antisymmetric|both"),
                      "symmetric: u, v ~ cos n t, w ~ sin n t; "
                      "antisymmetric: u, v ~ sin n t, w ~ cos n t "
                      "(thesis eq. 3.2). For n = 0 symmetric is the "
                      "axisymmetric (u, v) problem, antisymmetric is torsion.");
    prm.declare_entry("Polynomial degree",
                      "2",
                      Patterns::Selection("2|4"),
                      "FE_Q degree of the solid elements: 2 (pairs with the "
                      "6-node interface element) or 4 (equidistant nodes, "
                      "pairs with the 10-node interface element).");
    prm.declare_entry("Refinement cycles",
                      "1",
                      Patterns::Integer(1, 40),
                      "Solve, refine globally, solve again ... (convergence "
                      "studies).");
    prm.leave_subsection();
  }

  void
  DiscretizationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    const std::string family = prm.get("Family");
    harmonics.clear();
    for (const std::string &s :
         Utilities::split_string_list(prm.get("Harmonics")))
      {
        const unsigned int n = Utilities::string_to_int(s);
        if (family != "antisymmetric")
          harmonics.push_back({n, Family::symmetric});
        if (family != "symmetric")
          harmonics.push_back({n, Family::antisymmetric});
      }
    degree            = prm.get_integer("Polynomial degree");
    refinement_cycles = prm.get_integer("Refinement cycles");
    prm.leave_subsection();
  }

  void
  ExactSolutionParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact solution");
    prm.declare_entry("Enabled",
                      "false",
                      Patterns::Bool(),
                      "Compute error norms against the amplitudes below.");
    prm.declare_entry("U", "0", Patterns::Anything(), "Radial amplitude [m].");
    prm.declare_entry("V", "0", Patterns::Anything(), "Axial amplitude [m].");
    prm.declare_entry("W",
                      "0",
                      Patterns::Anything(),
                      "Circumferential amplitude [m].");
    prm.leave_subsection();
  }

  void
  ExactSolutionParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact solution");
    enabled               = prm.get_bool("Enabled");
    amplitudes.expression = {{prm.get("U"), prm.get("V"), prm.get("W")}};
    amplitudes.given      = {{true, true, true}};
    prm.leave_subsection();
    if (enabled)
      BoundaryConditions::make_function(amplitudes, 1, "Exact solution");
  }

  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "output",
                      Patterns::DirectoryName(),
                      "Where results go (created if missing).");
    prm.declare_entry("Results file",
                      "results.csv",
                      Patterns::FileName(),
                      "CSV of scalar results: one row per quantity, harmonic "
                      "and cycle, with units.");
    prm.declare_entry("Write vtu",
                      "true",
                      Patterns::Bool(),
                      "Write displacement and stress amplitudes as VTU.");
    prm.leave_subsection();
  }

  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory    = prm.get("Directory");
    results_file = prm.get("Results file");
    write_vtu    = prm.get_bool("Write vtu");
    prm.leave_subsection();
  }

  AllParameters::AllParameters() = default;

  void
  AllParameters::declare_parameters(ParameterHandler &prm)
  {
    DiscretizationParameters::declare_parameters(prm);
    MeshBuilder::declare_parameters(prm);
    MaterialLibrary::declare_parameters(prm);
    BoundaryConditions::declare_parameters(prm);
    LinearSolver::declare_parameters(prm);
    ExactSolutionParameters::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
    InterfaceParameters::declare_parameters(prm);
    RigidFoundationParameters::declare_parameters(prm);
    AdaptivityParameters::declare_parameters(prm);
  }

  void
  AllParameters::parse_parameters(ParameterHandler &prm)
  {
    discretization.parse_parameters(prm);
    mesh.parse_parameters(prm);
    materials.parse_parameters(prm);
    boundary_conditions.parse_parameters(prm);
    solver.parse_parameters(prm);
    exact_solution.parse_parameters(prm);
    output.parse_parameters(prm);
    interfaces.parse_parameters(prm);
    rigid_foundation.parse_parameters(prm);
    adaptivity.parse_parameters(prm);
  }


  void
  AllParameters::read_file(const std::string &filename)
  {
    std::ifstream in(filename);
    AssertThrow(in, ExcMessage(filename + ": cannot open parameter file"));
    ParameterHandler prm;
    declare_parameters(prm);
    try
      {
        prm.parse_input(in, filename);
        parse_parameters(prm);
      }
    catch (const std::exception &e)
      {
        AssertThrow(false, ExcMessage(filename + ": " + one_line_message(e)));
      }
  }

  void
  AllParameters::read_string(const std::string &text)
  {
    ParameterHandler prm;
    declare_parameters(prm);
    prm.parse_input_from_string(text, "input");
    parse_parameters(prm);
  }
} // namespace FourierSSI
