/**
 * What a scene calls for, decided before anything is assembled: the
 * harmonics its loads contain (exactly for foundation resultants, by Fourier
 * decomposition for loads given as functions of theta) and the effects to
 * simulate (interfaces, non-homogeneity, stiffness extraction, output). The
 * plan's log lines say, one each, what is simulated and what is skipped and
 * why.
 */
#ifndef fourier_ssi_scene_plan_h
#define fourier_ssi_scene_plan_h

#include <deal.II/grid/tria.h>
#include <fourier_ssi/fourier/load_decomposition.h>
#include <fourier_ssi/input/harmonic.h>
#include <fourier_ssi/input/parameters.h>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * What runs for a scene, decided once from the effects it calls for:
   * plastic soil couples the harmonics through its points (the load path on
   * the coupled tangent, with any coulomb interfaces in it); coulomb
   * interfaces on elastic soil couple them through the interface points (the
   * load path condensed onto the interfaces), except a swipe, whose second
   * load multiplier keeps the vertical motion on the coupled tangent; a
   * linear scene solves each harmonic once per mesh, on the cycles of
   * Refinement cycles or on the nested meshes a Target accuracy designs.
   */
  enum class RunMode
  {
    linear_cycles,
    linear_target,
    interface_load_path,
    interface_swipe,
    plastic_soil
  };

  /** The run mode of a scene (ScenePlan::run_mode). */
  RunMode
  run_mode_of(const AllParameters &parameters);

  /** True for the run modes that step a coupled load path. */
  bool
  is_coupled(const RunMode mode);

  /**
   * The meshes a scene is solved on: its own mesh once, Discretization/
   * Refinement cycles > 1 (a convergence study of the mesh), or the nested
   * meshes of Discretization/Target accuracy, which replaces the cycles.
   */
  enum class MeshSequence
  {
    one_mesh,
    refinement_cycles,
    target_accuracy
  };

  /**
   * The one place that reads Discretization/Target accuracy and Refinement
   * cycles to choose the meshes (ScenePlan::meshes).
   */
  MeshSequence
  mesh_sequence_of(const AllParameters &parameters);

  struct ScenePlan
  {
    /** How the scene is solved. */
    RunMode run_mode = RunMode::linear_cycles;
    /** The meshes it is solved on. */
    MeshSequence meshes = MeshSequence::one_mesh;
    /** Harmonics to solve, n ascending, symmetric before antisymmetric. */
    std::vector<Harmonic> harmonics;
    /** The theta-dependent loads with their sampling chosen. */
    LoadDecomposition loads;
    /** Relative amplitude of each (n, family) in the theta-dependent loads. */
    std::map<std::pair<unsigned int, Family>, double> load_amplitudes;
    std::vector<std::string>                          log_lines;
  };

  /**
   * Plan a scene on its (coarse) mesh. Resultants on a rigid foundation map
   * exactly: V -> n = 0 symmetric, T -> n = 0 antisymmetric, H_x and M_y ->
   * n = 1 symmetric, H_y and M_x -> n = 1 antisymmetric; the stiffness
   * coefficients need n = 1 symmetric. Throws a one-line error for a scene
   * without load in automatic mode or with harmonic-dependent amplitude
   * expressions that cannot be attributed to harmonics.
   */
  ScenePlan
  plan_scene(const AllParameters    &parameters,
             const Triangulation<2> &triangulation);

  /** "n = 0, 2..6, 8" style list of harmonic numbers. */
  std::string
  compact_list(const std::vector<unsigned int> &numbers);
} // namespace FourierSSI

#endif
