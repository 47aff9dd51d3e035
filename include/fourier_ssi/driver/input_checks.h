/**
 * Checks of a scene made once its coarse mesh and plan exist and before
 * anything is assembled or solved: input that would solve the wrong problem
 * (a load on a harmonic that is not solved, a traction on fixed DoFs, a
 * rigid foundation tied to the supports), or fail only after the solve
 * (output paths, Lines 3D points off the mesh), or put NaN into the system.
 * Each error is one line naming the .prm entry; legal but suspicious input
 * gets a note saying what will be solved.
 */
#ifndef fourier_ssi_input_checks_h
#define fourier_ssi_input_checks_h

#include <deal.II/grid/tria.h>
#include <fourier_ssi/driver/scene_plan.h>
#include <fourier_ssi/input/parameters.h>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * Throw a one-line error for input that cannot be solved as meant; return
   * the notes for the log ("warning: ..." lines and the choice made by
   * Discretization/Volumetric strain = auto). Call right after plan_scene().
   */
  std::vector<std::string>
  check_scene_before_solve(const AllParameters    &parameters,
                           const Triangulation<2> &triangulation,
                           const ScenePlan        &plan);

  /**
   * Throw a one-line error, naming the entry, for parameters that are legal
   * one by one but together describe no problem to solve (a displacement-
   * controlled path to a target of 0, a load-controlled path with every load
   * zero, error norms a coupled run never computes). Called by
   * AllParameters::parse_parameters once every subsection is read, so that
   * the refusal comes before any output is touched.
   */
  void
  check_problem_is_meaningful(const AllParameters &parameters);

  /**
   * Why the output paths cannot be written (Output/Directory exists and is
   * not a directory, Output/Results file is empty or names a directory), as
   * a one-line message; empty if they can. It reads the file system, so on
   * several ranks one rank must decide for all (Simulator::run).
   */
  std::string
  output_path_error(const OutputParameters &output);

  /**
   * Poisson's ratio from which FE_Q(2) with the standard (fully integrated)
   * dilatation locks noticeably. On the bundled embedded footing (finer
   * cycle) locking adds 0.2 % to K_M at nu = 0.3, 0.9 % at 0.45 (more than
   * the discretization error, 0.7 %), 2.6 % at 0.49 and 5.0 % at 0.499
   * (doc/robustness.md).
   */
  constexpr double locking_poisson_ratio = 0.45;

  /** The largest Poisson's ratio defined in Materials/Materials. */
  double
  largest_poisson_ratio(const MaterialLibrary &materials);
} // namespace FourierSSI

#endif
