/**
 * All run-time parameters of fourier-ssi, one struct per .prm subsection
 * (deal.II step-44 habit), combined in AllParameters.
 */
#ifndef fourier_ssi_parameters_h
#define fourier_ssi_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <fourier_ssi/input/adaptivity_parameters.h>
#include <fourier_ssi/input/boundary_conditions.h>
#include <fourier_ssi/input/harmonic.h>
#include <fourier_ssi/input/initial_stress_parameters.h>
#include <fourier_ssi/input/interface_parameters.h>
#include <fourier_ssi/input/linear_solver_parameters.h>
#include <fourier_ssi/input/load_parameters.h>
#include <fourier_ssi/input/load_path_parameters.h>
#include <fourier_ssi/input/material.h>
#include <fourier_ssi/input/mesh_parameters.h>
#include <fourier_ssi/input/rigid_foundation_parameters.h>
#include <fourier_ssi/input/soil_plasticity_parameters.h>
#include <optional>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** Which harmonics to solve and with which element. */
  /** Discretization/Volumetric strain once 'auto' is resolved. */
  enum class VolumetricStrain
  {
    standard,
    bbar
  };

  struct DiscretizationParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** Harmonics chosen from the loads (Harmonics = auto), see ScenePlan. */
    bool                  automatic = false;
    std::vector<Harmonic> harmonics;
    unsigned int          degree = 2;
    /**
     * What is solved: the standard strain or B-bar (projected dilatation,
     * p = 2). The entry's default 'auto' is resolved when the parameters
     * are read (AllParameters::parse_parameters): bbar for p = 2 when a
     * material has nu >= locking_poisson_ratio, standard otherwise.
     */
    VolumetricStrain volumetric = VolumetricStrain::standard;
    /** True if `volumetric` was chosen by 'auto' (the log says so). */
    bool         volumetric_automatic = false;
    unsigned int refinement_cycles    = 1;
    /**
     * Relative accuracy asked of the goal values (0: not set). When set,
     * the program designs an FE_Q(4) discretization and refines it until
     * the estimated error is below it (discretization_design.h).
     */
    double target_accuracy = 0.;
    /** Harmonics solved at the same time (threads); 0: one per core. */
    unsigned int concurrent_harmonics = 0;
  };

  /** Optional exact amplitudes for error norms (tests, verification). */
  struct ExactSolutionParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    bool                 enabled = false;
    ComponentExpressions amplitudes;
  };

  /** A straight line in the (r, z) plane sampled at n_points points. */
  struct OutputLine
  {
    Point<2>     start, end;
    unsigned int n_points = 2;
  };

  struct OutputParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    std::string directory    = "output";
    std::string results_file = "results.csv";
    bool        write_vtu    = true;
    /** Stress amplitudes in the per-harmonic VTU. */
    bool write_stresses = true;
    /** Relative displacement and traction per interface node pair (CSV). */
    bool write_interface_tractions = true;
    /** 3D reconstruction along lines at the angles theta_degrees. */
    std::vector<OutputLine> lines;
    /**
     * Limit of Lines 3D points per line: a typo such as 1e8 points would
     * otherwise write gigabytes of CSV (each point is a search in the mesh
     * and one row per angle).
     */
    static constexpr unsigned int max_points_per_line = 100000;
    std::vector<double>           theta_degrees;
    /** The mesh revolved about the axis with the 3D displacement. */
    bool         write_3d_vtu    = false;
    unsigned int theta_divisions = 36;
    /**
     * Soil-reaction curves (Soil reaction depths): the depths [m below
     * the pile's head], or, if soil_reaction_auto > 0, that many evenly
     * spaced; none if both are empty (doc/soil-reaction-curves.md).
     */
    std::vector<double> soil_reaction_depths;
    unsigned int        soil_reaction_auto = 0;

    bool
    soil_reaction_curves() const
    {
      return soil_reaction_auto > 0 || !soil_reaction_depths.empty();
    }

    /** Read the entry Soil reaction depths; one line if it is malformed. */
    void
    parse_soil_reaction_depths(const std::string &text);

    /**
     * Soil reaction pile: the pile's material id, or -1 (auto) for the
     * Rigid foundation's tied material (doc/soil-reaction-curves.md 8).
     */
    int soil_reaction_pile = -1;

    /** Read the entry Soil reaction pile; one line if it is malformed. */
    void
    parse_soil_reaction_pile(const std::string &text);

    /**
     * Only Output/Directory and Output/Results file of a parameter file,
     * read before (and whatever) the rest of the file is refused, by a
     * light scan of its lines that also reads files the parser refuses
     * (broken subsections, NUL bytes, UTF-16): every other entry is
     * skipped and no value is checked. Empty if the file cannot be read.
     */
    static std::optional<OutputParameters>
    read_folder_of(const std::string &prm_file);
  };

  struct AllParameters
  {
    /**
     * Plastic soil or a coulomb interface: the harmonics are coupled
     * through theta and solved together along a load path.
     */
    bool
    coupled() const
    {
      return soil_plasticity.any() || interfaces.any_nonlinear();
    }

    /**
     * The one choice of CoupledSolver's linearisation: the coupled tangent
     * of every harmonic with plastic soil, and for a swipe with nonlinear
     * interfaces on elastic soil, a scene with no soil points (the
     * interfaces' condensed iteration does not keep the swipe's w).
     * Otherwise nonlinear interfaces run condensed (InterfaceCondensation).
     */
    bool
    linearises_on_coupled_tangent() const
    {
      return soil_plasticity.any() ||
             (interfaces.any_nonlinear() && rigid_foundation.swipes());
    }

    /**
     * Newton steps the load path (Stiffness = tangent): Soil
     * plasticity/Stiffness on the coupled tangent, Load path/Stiffness where
     * the interfaces run condensed; otherwise the initial-stiffness
     * iteration.
     */
    bool
    newton_on_load_path() const
    {
      return linearises_on_coupled_tangent() ? soil_plasticity.tangent :
                                               load_path.tangent_stiffness;
    }

    AllParameters();

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** Read a .prm file; errors name the file and the entry. */
    void
    read_file(const std::string &filename);

    /** Read .prm text (tests). */
    void
    read_string(const std::string &text);

    DiscretizationParameters  discretization;
    MeshParameters            mesh;
    MaterialLibrary           materials;
    BoundaryConditions        boundary_conditions;
    LinearSolverParameters    solver;
    ExactSolutionParameters   exact_solution;
    OutputParameters          output;
    InterfaceParameters       interfaces;
    RigidFoundationParameters rigid_foundation;
    AdaptivityParameters      adaptivity;
    LoadParameters            loads;
    InitialStressParameters   initial_stress;
    LoadPathParameters        load_path;
    SoilPlasticityParameters  soil_plasticity;
  };
} // namespace FourierSSI

#endif
