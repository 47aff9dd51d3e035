#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fourier_ssi/input/material.h>
#include <fourier_ssi/input/messages.h>
#include <fourier_ssi/input/parameters.h>
#include <fourier_ssi/input/problem_checks.h>
#include <fstream>
#include <iterator>
#include <sstream>

namespace FourierSSI
{
  void
  DiscretizationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    prm.declare_entry("Harmonics",
                      "auto",
                      Patterns::Anything(),
                      "Fourier harmonics n to solve: 'auto' (those the loads "
                      "contain: foundation resultants and the Loads "
                      "subsection, decomposed in theta) or a list such as "
                      "'0, 1, 3' (with Family).");
    prm.declare_entry("Family",
                      "symmetric",
                      Patterns::Selection("symmetric|antisymmetric|both"),
                      "symmetric: u, v ~ cos n t, w ~ sin n t; "
                      "antisymmetric: u, v ~ sin n t, w ~ cos n t "
                      "(thesis eq. 3.2). For n = 0 symmetric is the "
                      "axisymmetric (u, v) problem, antisymmetric is torsion. "
                      "both: every listed n in both families (symmetric "
                      "first), e.g. n = 0 for V and T together.");
    prm.declare_entry("Polynomial degree",
                      "2",
                      Patterns::Selection("2|4"),
                      "FE_Q degree of the solid elements: 2 (pairs with the "
                      "6-node interface element) or 4 (equidistant nodes, "
                      "pairs with the 10-node interface element).");
    prm.declare_entry("Volumetric strain",
                      "auto",
                      Patterns::Selection("auto|standard|bbar"),
                      "standard: full integration of the dilatation; bbar: "
                      "the dilatation projected onto linear polynomials per "
                      "cell (B-bar, the Q2-P1disc volumetric space), free "
                      "of volumetric locking as nu -> 0.5, Polynomial "
                      "degree 2 only (FE_Q(4) does not lock); auto: bbar "
                      "for Polynomial degree 2 when a material has nu >= "
                      "0.45, standard otherwise (standard with degree 2 and "
                      "nu >= 0.45 is solved as asked, with a warning: it "
                      "overestimates K_M of the embedded footing by 5.6 % "
                      "at nu = 0.499, doc/robustness.md).");
    prm.declare_entry("Concurrent harmonics",
                      "0",
                      Patterns::Integer(0, 256),
                      "Harmonics solved at the same time in threads (they "
                      "are independent systems); 0: one per core.");
    prm.declare_entry("Refinement cycles",
                      "1",
                      Patterns::Integer(1, 40),
                      "Solve, refine globally, solve again ... (convergence "
                      "studies). Replaced by Target accuracy when that is "
                      "set (the log says so).");
    prm.declare_entry(
      "Target accuracy",
      "",
      Patterns::Anything(),
      "Relative accuracy asked of the goal values: K_H, K_M, "
      "K_MH when Rigid foundation/Stiffness coefficients is "
      "set (and K_V, K_T with Stiffness matrix), else the rigid foundation's motion, else the "
      "reactions of the supports. When set (0 < target < "
      "1, e.g. 1e-4) the program designs the "
      "discretization: FE_Q(4), the scene's mesh graded "
      "toward its singular points (interface line ends, "
      "corners of material and removed regions, the edge of "
      "a surface patch), surface layers where G ~ "
      "depth^alpha, and nested global refinements until the "
      "estimated error is below the target or the next mesh "
      "would exceed Adaptivity/Maximum DoFs (then the run "
      "says so and exits non-zero, unless Adaptivity/Allow "
      "unconverged). Replaces Polynomial degree, "
      "Refinement cycles and Mesh/Global refinements; Point, "
      "Box and Layer refinement "
      "are applied in addition. With plastic soil or a "
      "coulomb interface (displacement control) the goal is "
      "the load at the end of the path (with plastic soil "
      "the capacity; with plastic soil under load control "
      "the work of the loads): the scene's own mesh and "
      "element with "
      "the cells doubled per member, until the mesh, "
      "harmonic-truncation and plateau errors together are "
      "below the target (doc/soil-plasticity.md section "
      "8c). Empty: the mesh as given "
      "(doc/accuracy-vs-time.md).");
    prm.leave_subsection();
  }

  void
  DiscretizationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    const std::string family = prm.get("Family");
    harmonics.clear();
    const std::string list = Utilities::trim(prm.get("Harmonics"));
    automatic              = list == "auto";
    for (const std::string &s : automatic ? std::vector<std::string>() :
                                            Utilities::split_string_list(list))
      {
        int n = -1;
        try
          {
            n = Utilities::string_to_int(s);
          }
        catch (...)
          {}
        AssertThrow(n >= 0 && n <= 1024,
                    ExcMessage("Discretization/Harmonics: '" + s +
                               "' is not 'auto' or a harmonic number 0..1024"));
        // A repeated n would be solved twice and give duplicate rows.
        for (const Harmonic &h : harmonics)
          AssertThrow(h.n != static_cast<unsigned int>(n),
                      ExcMessage("Discretization/Harmonics: n = " + s +
                                 " is listed twice"));
        if (family != "antisymmetric")
          harmonics.push_back(
            {static_cast<unsigned int>(n), Family::symmetric});
        if (family != "symmetric")
          harmonics.push_back(
            {static_cast<unsigned int>(n), Family::antisymmetric});
      }
    AssertThrow(automatic || !harmonics.empty(),
                ExcMessage("Discretization/Harmonics: empty; write 'auto' or "
                           "a list such as '0, 1'"));
    degree                             = prm.get_integer("Polynomial degree");
    const std::string volumetric_entry = prm.get("Volumetric strain");
    volumetric_automatic               = volumetric_entry == "auto";
    volumetric = volumetric_entry == "bbar" ? VolumetricStrain::bbar :
                                              VolumetricStrain::standard;
    AssertThrow(volumetric != VolumetricStrain::bbar || degree == 2,
                ExcMessage("Discretization/Volumetric strain = bbar needs "
                           "Polynomial degree = 2"));
    refinement_cycles        = prm.get_integer("Refinement cycles");
    concurrent_harmonics     = prm.get_integer("Concurrent harmonics");
    const std::string target = Utilities::trim(prm.get("Target accuracy"));
    target_accuracy          = 0.;
    if (!target.empty())
      {
        const std::string error =
          "Discretization/Target accuracy: '" + target +
          "' is not a relative accuracy between 0 and 1 (e.g. 1e-4)";
        try
          {
            target_accuracy = Utilities::string_to_double(target);
          }
        catch (...)
          {
            AssertThrow(false, ExcMessage(error));
          }
        AssertThrow(target_accuracy > 0. && target_accuracy < 1.,
                    ExcMessage(error));
        // The element the target designs with is chosen with the scene's
        // laws known (AllParameters::parse_parameters).
      }
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
                      "Where results go (created if missing). The value "
                      "is taken literally: not empty, no quotes; the folder "
                      "(or its nearest existing parent) must be writable, "
                      "checked before the run. A relative path is relative "
                      "to the folder the program runs in (Mesh/Mesh file, "
                      "unlike it, is relative to the .prm file's folder).");
    prm.declare_entry("Results file",
                      "results.csv",
                      Patterns::FileName(),
                      "CSV of scalar results: one row per quantity, harmonic "
                      "and cycle, with units.");
    prm.declare_entry("Write vtu",
                      "true",
                      Patterns::Bool(),
                      "Write the displacement amplitudes of each harmonic "
                      "as VTU (solution-n<n>-<family>-cycle<c>.vtu); with a "
                      "coulomb interface or plastic soil those of the last "
                      "converged step, with plastic soil without stresses "
                      "(doc/output-files.md).");
    prm.declare_entry("Write stresses",
                      "true",
                      Patterns::Bool(),
                      "Add the six stress amplitudes to the VTU (stress "
                      "recovery is skipped otherwise).");
    prm.declare_entry("Write interface tractions",
                      "true",
                      Patterns::Bool(),
                      "Write relative displacements and tractions per "
                      "interface node pair (CSV per interface and harmonic).");
    prm.declare_entry("Lines 3D",
                      "",
                      Patterns::Anything(),
                      "3D reconstruction (sum of the harmonics) along "
                      "straight lines: 'r0, z0 -> r1, z1 : points; ...'; "
                      "written to lines-3d.csv at the angles below. At most "
                      "100000 points per line, every point inside the mesh "
                      "(both checked before the solve).");
    prm.declare_entry("Theta values",
                      "0",
                      Patterns::List(Patterns::Double()),
                      "Angles [degrees] of the Lines 3D output.");
    prm.declare_entry("Write 3D vtu",
                      "false",
                      Patterns::Bool(),
                      "Write the mesh revolved about the axis with the 3D "
                      "displacement (solution-3d.vtu, for ParaView).");
    prm.declare_entry("Theta divisions",
                      "36",
                      Patterns::Integer(3, 720),
                      "Sectors of the revolved 3D VTU.");
    prm.declare_entry("Soil reaction depths",
                      "",
                      Patterns::Anything(),
                      "Soil-reaction curves of a pile in plastic soil "
                      "(PISA: p-v, m-psi, base H_B-v and M_B-psi, one point "
                      "per load step) at these depths [m below the pile's "
                      "head], or 'auto' (10 evenly spaced) or 'auto N'; "
                      "written to soil-reaction-curves.csv "
                      "(doc/soil-reaction-curves.md). Empty: none.");
    prm.declare_entry("Soil reaction pile",
                      "auto",
                      Patterns::Anything(),
                      "The material id of the pile whose soil-reaction "
                      "curves are written: a solid or hollow (tube) pile, "
                      "rigid or an elastic material region loaded through "
                      "the Rigid foundation's tied material. auto: the "
                      "Rigid foundation's Id (a rigid pile).");
    prm.leave_subsection();
  }

  void
  OutputParameters::parse_soil_reaction_depths(const std::string &text)
  {
    const auto fail = [&]() {
      AssertThrow(false,
                  ExcMessage("Output/Soil reaction depths: '" + text +
                             "' is not a list of depths >= 0 [m], 'auto' or "
                             "'auto N' (N from 1 to 1000)"));
    };
    soil_reaction_depths.clear();
    soil_reaction_auto = 0;
    const auto words   = Utilities::split_string_list(text, ' ');
    if (!words.empty() && words[0] == "auto")
      {
        if (words.size() > 2)
          fail();
        try
          {
            soil_reaction_auto =
              words.size() == 1 ? 10 : Utilities::string_to_int(words[1]);
          }
        catch (...)
          {
            fail();
          }
        if (soil_reaction_auto < 1 || soil_reaction_auto > 1000)
          fail();
        return;
      }
    try
      {
        for (const std::string &d : Utilities::split_string_list(text))
          soil_reaction_depths.push_back(Utilities::string_to_double(d));
      }
    catch (...)
      {
        fail();
      }
    for (const double d : soil_reaction_depths)
      if (!(d >= 0.) || !std::isfinite(d))
        fail();
  }

  void
  OutputParameters::parse_soil_reaction_pile(const std::string &text)
  {
    soil_reaction_pile = -1;
    if (text == "auto")
      return;
    const std::string message = "Output/Soil reaction pile: '" + text +
                                "' is not 'auto' or a material id (0 to 255)";
    try
      {
        soil_reaction_pile = Utilities::string_to_int(text);
      }
    catch (...)
      {
        AssertThrow(false, ExcMessage(message));
      }
    AssertThrow(soil_reaction_pile >= 0 && soil_reaction_pile <= 255,
                ExcMessage(message));
  }

  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory                 = prm.get("Directory");
    results_file              = prm.get("Results file");
    write_vtu                 = prm.get_bool("Write vtu");
    write_stresses            = prm.get_bool("Write stresses");
    write_interface_tractions = prm.get_bool("Write interface tractions");
    write_3d_vtu              = prm.get_bool("Write 3D vtu");
    theta_divisions           = prm.get_integer("Theta divisions");
    theta_degrees.clear();
    for (const std::string &t :
         Utilities::split_string_list(prm.get("Theta values")))
      theta_degrees.push_back(Utilities::string_to_double(t));
    parse_soil_reaction_depths(prm.get("Soil reaction depths"));
    parse_soil_reaction_pile(prm.get("Soil reaction pile"));
    lines.clear();
    for (const std::string &item : split_top_level(prm.get("Lines 3D"), ';'))
      {
        const auto fail = [&]() {
          AssertThrow(false,
                      ExcMessage("Output/Lines 3D: '" + item +
                                 "' is not 'r0, z0 -> r1, z1 : points'"));
        };
        const auto arrow = item.find("->");
        const auto colon = item.find(':');
        if (arrow == std::string::npos || colon == std::string::npos ||
            colon < arrow)
          fail();
        OutputLine line;
        try
          {
            const auto a = Utilities::split_string_list(item.substr(0, arrow));
            const auto b = Utilities::split_string_list(
              item.substr(arrow + 2, colon - arrow - 2));
            if (a.size() != 2 || b.size() != 2)
              fail();
            line.start = Point<2>(Utilities::string_to_double(a[0]),
                                  Utilities::string_to_double(a[1]));
            line.end   = Point<2>(Utilities::string_to_double(b[0]),
                                Utilities::string_to_double(b[1]));
            line.n_points =
              Utilities::string_to_int(Utilities::trim(item.substr(colon + 1)));
          }
        catch (...)
          {
            fail();
          }
        if (line.n_points < 1)
          fail();
        AssertThrow(line.n_points <= max_points_per_line,
                    ExcMessage("Output/Lines 3D: '" + item + "' asks for " +
                               std::to_string(line.n_points) +
                               " points, above the limit of " +
                               std::to_string(max_points_per_line) +
                               " points per line"));
        lines.push_back(line);
      }
    prm.leave_subsection();
  }

  AllParameters::AllParameters() = default;

  void
  AllParameters::declare_parameters(ParameterHandler &prm)
  {
    DiscretizationParameters::declare_parameters(prm);
    MeshParameters::declare_parameters(prm);
    MaterialLibrary::declare_parameters(prm);
    BoundaryConditions::declare_parameters(prm);
    LinearSolverParameters::declare_parameters(prm);
    ExactSolutionParameters::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
    InterfaceParameters::declare_parameters(prm);
    RigidFoundationParameters::declare_parameters(prm);
    AdaptivityParameters::declare_parameters(prm);
    LoadParameters::declare_parameters(prm);
    InitialStressParameters::declare_parameters(prm);
    LoadPathParameters::declare_parameters(prm);
    SoilPlasticityParameters::declare_parameters(prm);
  }

  namespace
  {
    /**
     * The target's element: the linear scenes' design is FE_Q(4) (its
     * grading pairs with the 10-node interface element; FE_Q(4) does not
     * lock); a coupled scene (plastic soil, coulomb interfaces) keeps its
     * own, on its own mesh refined (FE_Q(2) with B-bar for undrained soil,
     * section 4 of doc/soil-plasticity.md). Then the volumetric strain
     * that `auto` means for that degree.
     */
    void
    choose_element(AllParameters &parameters)
    {
      if (parameters.discretization.target_accuracy > 0. &&
          !parameters.coupled())
        {
          AssertThrow(parameters.discretization.volumetric !=
                        VolumetricStrain::bbar,
                      ExcMessage("Discretization/Target accuracy: designs "
                                 "FE_Q(4) meshes, and Volumetric strain = bbar "
                                 "needs degree 2 (write auto or standard)"));
          parameters.discretization.degree = 4;
        }
      parameters.mesh.degree = parameters.discretization.degree;
      if (parameters.discretization.volumetric_automatic)
        parameters.discretization.volumetric =
          parameters.discretization.degree == 2 &&
              largest_poisson_ratio(parameters.materials) >=
                locking_poisson_ratio ?
            VolumetricStrain::bbar :
            VolumetricStrain::standard;
    }

    /** Every soil law on a material that exists. */
    void
    check_laws(const AllParameters &parameters)
    {
      for (const auto &law : parameters.soil_plasticity.laws)
        AssertThrow(parameters.materials.has(law.first),
                    ExcMessage("Soil plasticity/Laws: material " +
                               std::to_string(law.first) +
                               " is not in Materials/Materials"));
    }

    /** What Discretization/Target accuracy needs of the scene. */
    void
    check_target_accuracy(const AllParameters &parameters)
    {
      if (parameters.discretization.target_accuracy > 0.)
        {
          AssertThrow(parameters.rigid_foundation.enabled ||
                        !parameters.boundary_conditions.dirichlet.empty(),
                      ExcMessage("Discretization/Target accuracy: the scene "
                                 "has no goal quantity (no rigid foundation, "
                                 "no supports whose reactions to measure)"));
          AssertThrow(parameters.adaptivity.strategy ==
                        RefinementStrategy::global,
                      ExcMessage("Discretization/Target accuracy: refines by "
                                 "its own design; leave Adaptivity/Strategy = "
                                 "global"));
          // Load control's goal is the work of the loads (plastic soil):
          // the condensed load vector is the work's only with homogeneous
          // constraints.
          const bool load_control =
            parameters.coupled() &&
            parameters.load_path.control == LoadPathParameters::Control::load;
          AssertThrow(!load_control || parameters.soil_plasticity.any(),
                      ExcMessage("Discretization/Target accuracy: with a "
                                 "coulomb interface on elastic soil the goal "
                                 "is the load at the end of the controlled "
                                 "path, which needs Load path/"
                                 "Control = displacement"));
          bool prescribed_motion = !parameters.loads.displacement.empty();
          for (const auto &[id, e] : parameters.boundary_conditions.dirichlet)
            prescribed_motion |= !e.is_zero();
          AssertThrow(!load_control || !prescribed_motion,
                      ExcMessage("Discretization/Target accuracy: under load "
                                 "control the goal is the work of the loads, "
                                 "which needs every prescribed displacement "
                                 "(Boundary conditions/Dirichlet, Loads/"
                                 "Prescribed displacement) to be zero"));
        }
    }

    /** A boundary is either prescribed as a load or supported, not both. */
    void
    check_prescribed_displacements(const AllParameters &parameters)
    {
      for (const auto &[id, e] : parameters.loads.displacement)
        AssertThrow(parameters.boundary_conditions.dirichlet.count(id) == 0,
                    ExcMessage("Loads/Prescribed displacement: boundary id " +
                               std::to_string(id) +
                               " is also in Boundary conditions/Dirichlet"));
    }
  } // namespace

  void
  AllParameters::parse_parameters(ParameterHandler &prm)
  {
    discretization.parse_parameters(prm);
    mesh.parse_parameters(prm);
    materials.parse_parameters(prm);
    paint_soil_layers(mesh, materials.surface_elevation);
    boundary_conditions.parse_parameters(prm);
    solver.parse_parameters(prm);
    exact_solution.parse_parameters(prm);
    output.parse_parameters(prm);
    interfaces.parse_parameters(prm);
    rigid_foundation.parse_parameters(prm);
    adaptivity.parse_parameters(prm);
    loads.parse_parameters(prm);
    soil_plasticity.parse_parameters(prm);
    AssertThrow(!output.soil_reaction_curves() || soil_plasticity.any(),
                ExcMessage("Output/Soil reaction depths: not yet without "
                           "plastic soil (Soil plasticity/Laws): the curves "
                           "are read from the soil's stress at each step"));
    choose_element(*this);
    initial_stress.parse_parameters(prm);
    load_path.parse_parameters(prm);
    // Newton (either linearisation) assembles coulomb springs no
    // stiffer than a cap times G / l; stiffer laws act through the augmented
    // Lagrangian's multipliers (interface_law.h).
    if (newton_on_load_path())
      interfaces.iteration_stiffness_cap = linearises_on_coupled_tangent() ?
                                             soil_iteration_stiffness :
                                             interface_iteration_stiffness;
    check_laws(*this);
    check_target_accuracy(*this);
    check_prescribed_displacements(*this);
    check_problem_is_meaningful(*this);
  }


  namespace
  {
    /**
     * The subsection that steers every nonlinear load path (interfaces and
     * plastic soil) was called "Nonlinear interfaces"; a file written for
     * that name gets the new one in its error line instead of the parser's
     * generic "undeclared subsection".
     */
    void
    refuse_renamed_subsection(const std::string &content,
                              const std::string &filename)
    {
      std::istringstream lines(content);
      std::string        line;
      for (unsigned int number = 1; std::getline(lines, line); ++number)
        {
          std::istringstream words(line);
          std::string        keyword, name;
          words >> keyword;
          std::getline(words, name);
          AssertThrow(keyword != "subsection" ||
                        Utilities::trim(name) != "Nonlinear interfaces",
                      ExcMessage(filename + ": line " + std::to_string(number) +
                                 ": subsection 'Nonlinear interfaces' is now "
                                 "'Load path' (it steers plastic soil as well "
                                 "as interfaces): rename it"));
        }
    }

    /**
     * The text of a parameter file, without a UTF-8 byte-order mark (editors
     * on some systems start files with one; it carries no meaning here).
     */
    std::string
    parameter_text(const std::string &filename)
    {
      // An ifstream opens a directory and reads nothing: it would run as an
      // empty .prm.
      AssertThrow(!std::filesystem::is_directory(filename),
                  ExcMessage(filename +
                             ": is a directory, not a parameter file"));
      std::ifstream in(filename);
      AssertThrow(in, ExcMessage(filename + ": cannot open parameter file"));
      std::stringstream text;
      text << in.rdbuf();
      std::string content = text.str();
      // The parser reads up to the first NUL byte and would silently run the
      // rest of the file's entries at their defaults.
      const auto nul = content.find('\0');
      AssertThrow(nul == std::string::npos,
                  ExcMessage(
                    filename + ": line " +
                    std::to_string(1 + std::count(content.begin(),
                                                  content.begin() + nul,
                                                  '\n')) +
                    " contains a NUL byte: not a text parameter "
                    "file"));
      // Editors on some systems start UTF-8 files with a byte-order mark;
      // it carries no meaning here.
      const std::string byte_order_mark = "\xEF\xBB\xBF";
      if (content.compare(0, byte_order_mark.size(), byte_order_mark) == 0)
        content.erase(0, byte_order_mark.size());
      refuse_renamed_subsection(content, filename);
      return content;
    }

    /**
     * The text of a parameter file as a light scan reads it: NUL bytes
     * dropped (a UTF-16 file is ASCII with a NUL after every character),
     * byte-order marks and carriage returns dropped, lines ending in a
     * backslash joined to the next, comments cut.
     */
    std::vector<std::string>
    scanned_lines(const std::string &prm_file)
    {
      std::ifstream in(prm_file, std::ios::binary);
      std::string   raw((std::istreambuf_iterator<char>(in)),
                      std::istreambuf_iterator<char>());
      raw.erase(std::remove_if(raw.begin(),
                               raw.end(),
                               [](const char c) {
                                 const auto b = static_cast<unsigned char>(c);
                                 return b == 0 || b == '\r' || b == 0xFE ||
                                        b == 0xFF;
                               }),
                raw.end());
      const std::string byte_order_mark = "\xEF\xBB\xBF"; // UTF-8's
      if (raw.compare(0, byte_order_mark.size(), byte_order_mark) == 0)
        raw.erase(0, byte_order_mark.size());
      std::vector<std::string> lines;
      std::istringstream       text(raw);
      std::string              line, joined;
      while (std::getline(text, line))
        {
          line = line.substr(0, line.find('#'));
          if (!line.empty() && line.back() == '\\')
            {
              joined += line.substr(0, line.size() - 1);
              continue;
            }
          lines.push_back(joined + line);
          joined.clear();
        }
      lines.push_back(joined);
      return lines;
    }
  } // namespace

  std::optional<OutputParameters>
  OutputParameters::read_folder_of(const std::string &prm_file)
  {
    std::error_code ignored;
    if (!std::filesystem::is_regular_file(prm_file, ignored))
      return std::nullopt;
    // Not ParameterHandler: the folder must be found in the very files it
    // refuses (a missing or extra end, a set without '=', a NUL byte, a
    // UTF-16 file), so that their run removes the last run's results.
    OutputParameters         output;
    std::vector<std::string> subsections;
    for (const std::string &line : scanned_lines(prm_file))
      {
        std::istringstream words(line);
        std::string        word;
        words >> word;
        const std::streamoff position = words.tellg();
        const std::size_t    after_word =
          position < 0 ? line.size() : static_cast<std::size_t>(position);
        std::transform(word.begin(), word.end(), word.begin(), [](char c) {
          return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        });
        if (word == "end" && !subsections.empty())
          subsections.pop_back();
        if (word == "subsection")
          subsections.push_back(Utilities::trim(line.substr(after_word)));
        const std::size_t equals = line.find('=');
        if (word != "set" || equals == std::string::npos ||
            subsections != std::vector<std::string>{"Output"})
          continue;
        const std::string key =
          Utilities::trim(line.substr(after_word, equals - after_word));
        const std::string value = Utilities::trim(line.substr(equals + 1));
        if (key == "Directory")
          output.directory = value;
        else if (key == "Results file")
          output.results_file = value;
      }
    return output;
  }

  void
  AllParameters::read_file(const std::string &filename)
  {
    std::istringstream input(parameter_text(filename));
    ParameterHandler   prm;
    declare_parameters(prm);
    try
      {
        prm.parse_input(input, filename);
        parse_parameters(prm);
        // A relative Mesh file is relative to the folder of the .prm, so
        // that a scene runs from any working directory.
        const std::filesystem::path mesh_file(mesh.mesh_file);
        if (mesh.type == MeshType::gmsh && !mesh.mesh_file.empty() &&
            mesh_file.is_relative())
          mesh.mesh_file =
            (std::filesystem::path(filename).parent_path() / mesh_file)
              .lexically_normal()
              .string();
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
