/**
 * Subsection "Adaptivity" of the .prm file: the refinement between cycles
 * (strategy, fraction, goal), the work bound of Discretization/Target
 * accuracy and the a priori refinements (points, boxes, layers) that
 * mesh/adaptivity.h carries out.
 */
#ifndef fourier_ssi_adaptivity_parameters_h
#define fourier_ssi_adaptivity_parameters_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <string>
#include <utility>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** Adaptivity/Strategy, parsed once. */
  enum class RefinementStrategy
  {
    global, // refine every cell once per cycle
    kelly,  // Kelly indicators summed over the harmonics
    goal    // DWR indicators of K_H, K_M, K_MH (goal_estimator.h)
  };

  /**
   * Adaptivity/Goal, parsed once: the stiffness coefficient whose estimated
   * error steers a goal-oriented refinement; `all` the largest relative
   * error of the three. The order of K_H, K_M, K_MH is that of
   * GoalEstimate::relative_error.
   */
  enum class StiffnessGoal
  {
    K_H,
    K_M,
    K_MH,
    all
  };

  /** The Adaptivity/Goal value of `goal` ("K_H", ..., "all"). */
  std::string
  name_of(const StiffnessGoal goal);

  struct AdaptivityParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Point refinement levels allowed: 25 halvings make a cell 3e-8 of its
     * coarse size; near 30 the vertices of the smallest cells are no longer
     * found within the lookup tolerance (round-off of their coordinates).
     */
    static constexpr unsigned int max_point_refinement_levels = 25;

    RefinementStrategy strategy        = RefinementStrategy::global;
    double             refine_fraction = 0.3;
    StiffnessGoal      goal            = StiffnessGoal::all;
    double             goal_tolerance  = 0.; // relative; 0: no stop
    /** Work bound of Discretization/Target accuracy (DoFs per harmonic). */
    double maximum_dofs = 5e5;
    /** Exit 0 although Target accuracy was not reached (the CSV says so). */
    bool allow_unconverged = false;
    /**
     * A priori grading: each (point, levels) pair refines the cells that
     * touch the point `levels` times before the first cycle.
     */
    std::vector<std::pair<Point<2>, unsigned int>> point_refinements;
    /** Each box refines the cells whose centre lies in it, `levels` times. */
    std::vector<std::pair<BoundingBox<2>, unsigned int>> box_refinements;
    /**
     * A layer refinement cuts the cells with a face on a straight segment
     * (r = value or z = value, from..to) across the segment only, `levels`
     * times: a boundary layer graded geometrically toward the segment.
     */
    struct LayerRefinement
    {
      unsigned int fixed_coordinate; // 0: r = value, 1: z = value
      double       value, from, to;
      unsigned int levels;
    };
    std::vector<LayerRefinement> layer_refinements;
  };
} // namespace FourierSSI

#endif
