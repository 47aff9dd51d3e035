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
   * How a scene is solved, decided once from the effects it calls for:
   * plastic soil couples the harmonics through its points (the coupled soil
   * load path, with any coulomb interfaces in it); coulomb interfaces alone
   * couple them through the interface points; a linear scene solves each
   * harmonic once per mesh, on the cycles of Refinement cycles or on the
   * nested meshes a Target accuracy designs.
   */
  enum class RunMode
  {
    linear_cycles,
    linear_target,
    load_path,
    plastic_soil
  };

  /** The run mode of a scene (ScenePlan::run_mode). */
  RunMode
  run_mode_of(const AllParameters &parameters);

  struct ScenePlan
  {
    /** How the scene is solved. */
    RunMode run_mode = RunMode::linear_cycles;
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
