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
   * Why the output paths cannot be written (Output/Directory exists and is
   * not a directory, Output/Results file is empty or names a directory), as
   * a one-line message; empty if they can. It reads the file system, so on
   * several ranks one rank must decide for all (Simulator::run).
   */
  std::string
  output_path_error(const OutputParameters &output);

} // namespace FourierSSI

#endif
