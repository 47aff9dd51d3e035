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
          // A linear scene's members follow their own design; a coupled
          // scene's may follow its mechanism (kelly).
          AssertThrow(
            parameters.adaptivity.strategy == RefinementStrategy::global ||
              (parameters.coupled() &&
               parameters.adaptivity.strategy == RefinementStrategy::kelly),
            ExcMessage("Discretization/Target accuracy: refines by "
                       "its own design; leave Adaptivity/Strategy = "
                       "global (kelly only with plastic soil or a "
                       "coulomb interface)"));
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
    materials.use_geostatic_stress(initial_stress);
    load_path.parse_parameters(prm);
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

  } // namespace

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
