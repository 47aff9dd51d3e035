#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/input/boundary_conditions.h>
#include <fourier_ssi/input/prm_values.h>
#include <iostream>
#include <mutex>
#include <set>
#include <sstream>

namespace FourierSSI
{
  bool
  is_literal_zero(const std::string &expression)
  {
    const std::string e = Utilities::trim(expression);
    if (e.empty())
      return true;
    try
      {
        std::size_t used = 0;
        return std::stod(e, &used) == 0. && used == e.size();
      }
    catch (...)
      {
        return false;
      }
  }

  std::vector<std::string>
  split_top_level(const std::string &text, const char separator)
  {
    std::vector<std::string> pieces;
    std::string              current;
    int                      depth = 0;
    for (const char c : text)
      {
        if (c == '(')
          ++depth;
        else if (c == ')')
          --depth;
        if (c == separator && depth == 0)
          {
            pieces.push_back(Utilities::trim(current));
            current.clear();
          }
        else
          current += c;
      }
    if (!Utilities::trim(current).empty())
      pieces.push_back(Utilities::trim(current));
    return pieces;
  }

  void
  BoundaryConditions::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    prm.declare_entry(
      "Dirichlet",
      "",
      Patterns::Anything(),
      "Prescribed displacement amplitudes [m] per boundary id: "
      "'id: u=expr, v=expr, w=expr; id: ...' (u radial, v axial, w "
      "circumferential; omit a component to leave it free). Expressions in "
      "r, z and the constants pi, n.");
    prm.declare_entry(
      "Traction",
      "",
      Patterns::Anything(),
      "Surface traction amplitudes [kPa] per boundary id: "
      "'id: r=expr, z=expr, theta=expr; ...'. Unlisted boundaries are "
      "traction free. Nonlinear runs with a Rigid foundation: held, like "
      "the Body force (applied in full in the held stage, Nonlinear "
      "interfaces/Held load steps, then constant while the load factor "
      "scales only the foundation's loads or motion); without one, scaled "
      "by the load factor.");
    prm.leave_subsection();

    prm.enter_subsection("Body force");
    prm.declare_entry("Radial",
                      "0",
                      Patterns::Anything(),
                      "Amplitude [kN/m^3]. Nonlinear runs with a Rigid "
                      "foundation: held (see Boundary conditions/Traction).");
    prm.declare_entry("Axial",
                      "0",
                      Patterns::Anything(),
                      "Amplitude [kN/m^3]. Nonlinear runs with a Rigid "
                      "foundation: held (see Boundary conditions/Traction).");
    prm.declare_entry("Circumferential",
                      "0",
                      Patterns::Anything(),
                      "Amplitude [kN/m^3]. Nonlinear runs with a Rigid "
                      "foundation: held (see Boundary conditions/Traction).");
    prm.leave_subsection();
  }

  void
  BoundaryConditions::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    dirichlet = parse_boundary_map(prm.get("Dirichlet"),
                                   {{"u", "v", "w"}},
                                   "Boundary conditions/Dirichlet");
    traction  = parse_boundary_map(prm.get("Traction"),
                                  {{"r", "z", "theta"}},
                                  "Boundary conditions/Traction");
    prm.leave_subsection();

    prm.enter_subsection("Body force");
    body_force.expression = {
      {prm.get("Radial"), prm.get("Axial"), prm.get("Circumferential")}};
    body_force.given = {{true, true, true}};
    prm.leave_subsection();
    // Fail now, not in the middle of a run, on an expression that does not
    // parse.
    make_function(body_force, 1, "Body force");
    for (const auto &[id, e] : dirichlet)
      make_function(e, 1, "Boundary conditions/Dirichlet");
    for (const auto &[id, e] : traction)
      make_function(e, 1, "Boundary conditions/Traction");
  }

  std::map<types::boundary_id, ComponentExpressions>
  BoundaryConditions::parse_boundary_map(const std::string                &text,
                                         const std::array<std::string, 3> &keys,
                                         const std::string &entry)
  {
    std::map<types::boundary_id, ComponentExpressions> result;
    const auto fail = [&](const std::string &what) {
      AssertThrow(false, ExcMessage(entry + ": " + what));
    };
    for (const std::string &item : split_top_level(text, ';'))
      {
        const auto colon = item.find(':');
        if (colon == std::string::npos)
          fail("'" + item + "' lacks 'boundary_id:'");
        int id = -1;
        try
          {
            id =
              Utilities::string_to_int(Utilities::trim(item.substr(0, colon)));
          }
        catch (...)
          {
            fail("boundary id '" + item.substr(0, colon) +
                 "' is not an integer");
          }
        if (id < 0)
          fail("negative boundary id in '" + item + "'");
        if (result.count(id))
          fail("boundary id " + std::to_string(id) + " given twice");
        ComponentExpressions  e;
        std::set<std::string> keys_given;
        for (const std::string &pair :
             split_top_level(item.substr(colon + 1), ','))
          {
            const auto eq = pair.find('=');
            if (eq == std::string::npos)
              fail("'" + pair + "' is not key=expression");
            const std::string key = Utilities::trim(pair.substr(0, eq));
            record_key_once(keys_given, key, entry, item);
            unsigned int c = 0;
            while (c < 3 && keys[c] != key)
              ++c;
            if (c == 3)
              fail("unknown key '" + key + "' (expected " + keys[0] + ", " +
                   keys[1] + " or " + keys[2] + ")");
            e.expression[c] = Utilities::trim(pair.substr(eq + 1));
            e.given[c]      = true;
          }
        result[id] = e;
      }
    return result;
  }

  template <int dim>
  void
  initialize_parser(FunctionParser<dim>                 &function,
                    const ComponentExpressions          &expressions,
                    const std::string                   &variables,
                    const std::map<std::string, double> &constants,
                    const std::string                   &entry)
  {
    std::vector<std::string> formulas(3, "0");
    for (unsigned int c = 0; c < 3; ++c)
      if (expressions.given[c] && !expressions.expression[c].empty())
        formulas[c] = expressions.expression[c];
    static std::mutex           cerr_mutex;
    std::lock_guard<std::mutex> lock(cerr_mutex);
    std::ostringstream          swallowed;
    std::streambuf *const cerr_buffer = std::cerr.rdbuf(swallowed.rdbuf());
    try
      {
        function.initialize(variables, formulas, constants);
        // muparser compiles each component lazily, on first evaluation.
        Vector<double> values(3);
        Point<dim>     probe;
        for (unsigned int d = 0; d < dim; ++d)
          probe[d] = 0.5;
        function.vector_value(probe, values);
        std::cerr.rdbuf(cerr_buffer);
      }
    catch (const std::exception &)
      {
        std::cerr.rdbuf(cerr_buffer);
        AssertThrow(false,
                    ExcMessage(entry + ": cannot parse '" + formulas[0] +
                               "', '" + formulas[1] + "', '" + formulas[2] +
                               "'"));
      }
  }

  template void
  initialize_parser<2>(FunctionParser<2> &,
                       const ComponentExpressions &,
                       const std::string &,
                       const std::map<std::string, double> &,
                       const std::string &);
  template void
  initialize_parser<3>(FunctionParser<3> &,
                       const ComponentExpressions &,
                       const std::string &,
                       const std::map<std::string, double> &,
                       const std::string &);

  std::shared_ptr<FunctionParser<3>>
  make_theta_function(const ComponentExpressions &expressions,
                      const std::string          &entry)
  {
    auto function = std::make_shared<FunctionParser<3>>(3);
    initialize_parser(
      *function, expressions, "r,z,theta", {{"pi", numbers::PI}}, entry);
    return function;
  }

  std::unique_ptr<FunctionParser<2>>
  BoundaryConditions::make_function(const ComponentExpressions &expressions,
                                    const unsigned int          harmonic_n,
                                    const std::string          &entry)
  {
    auto function = std::make_unique<FunctionParser<2>>(3);
    initialize_parser(*function,
                      expressions,
                      "r,z",
                      {{"pi", numbers::PI},
                       {"n", static_cast<double>(harmonic_n)}},
                      entry);
    return function;
  }
} // namespace FourierSSI
