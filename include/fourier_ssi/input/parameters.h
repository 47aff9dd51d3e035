/**
 * All run-time parameters of fourier-ssi, one struct per .prm subsection
 * (deal.II step-44 habit), combined in AllParameters. Each struct has its
 * own header in input/, the lowest layer, so that every layer reads the
 * parameters it needs and none of them includes a model: parsing ends in
 * plain values, and the models are built from them.
 */
#ifndef fourier_ssi_parameters_h
#define fourier_ssi_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <fourier_ssi/input/adaptivity_parameters.h>
#include <fourier_ssi/input/boundary_conditions.h>
#include <fourier_ssi/input/discretization_parameters.h>
#include <fourier_ssi/input/exact_solution_parameters.h>
#include <fourier_ssi/input/initial_stress_parameters.h>
#include <fourier_ssi/input/interface_parameters.h>
#include <fourier_ssi/input/linear_solver_parameters.h>
#include <fourier_ssi/input/load_parameters.h>
#include <fourier_ssi/input/load_path_parameters.h>
#include <fourier_ssi/input/material.h>
#include <fourier_ssi/input/mesh_parameters.h>
#include <fourier_ssi/input/output_parameters.h>
#include <fourier_ssi/input/rigid_foundation_parameters.h>
#include <fourier_ssi/input/soil_plasticity_parameters.h>
#include <string>

namespace FourierSSI
{
  using namespace dealii;

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
     * Newton steps the load path: Soil plasticity/Stiffness on the coupled
     * tangent; where the interfaces run condensed, Load path/Stiffness, and
     * for `auto` the interfaces' stiffness (InterfaceParameters::is_stiff,
     * known once the mesh is made); otherwise the initial-stiffness
     * iteration.
     */
    bool
    newton_on_load_path() const
    {
      if (linearises_on_coupled_tangent())
        return soil_plasticity.tangent;
      switch (load_path.stiffness)
        {
          case LoadPathParameters::Stiffness::tangent:
            return true;
          case LoadPathParameters::Stiffness::initial:
            return false;
          default:
            return interfaces.is_stiff();
        }
    }

    /**
     * `Linear solver/Distributed = always` on a coupled path: the coupled
     * Newton tangent is one distributed matrix factorized by MUMPS over the
     * ranks (coupled_tangent.h). The harmonics' own systems stay serial
     * there (each rank owns whole harmonics); the coupled paths without that
     * tangent refuse it (check_coupled_path_supported).
     */
    bool
    distributes_coupled_tangent() const
    {
      return solver.distributed_always && linearises_on_coupled_tangent() &&
             newton_on_load_path();
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
