/**
 * Adaptive mesh refinement between cycles: Kelly indicators summed over the
 * harmonics of a run (each harmonic's indicators normalised by their own
 * l2 norm, so every harmonic steers the mesh equally whatever its load
 * magnitude) or goal-oriented indicators (goal_estimator.h), a fixed
 * fraction of the summed indicator refined, and interface pairs kept valid
 * by refining both sides of an interface alike.
 */
#ifndef fourier_ssi_adaptivity_h
#define fourier_ssi_adaptivity_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <set>
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

  /**
   * The a priori refinements of AdaptivityParameters, in this order: boxes
   * (each in turn), grading toward points (refine_toward_points()), then
   * layers. Interface twins are refined alike throughout.
   */
  void
  refine_a_priori(Triangulation<2>                   &triangulation,
                  const AdaptivityParameters         &parameters,
                  const std::set<types::boundary_id> &interface_ids);

  /**
   * Refine the cells flagged in `triangulation`, after mirroring the flags
   * across every interface (faces with an id in `interface_ids` and their
   * geometric twins) until both sides agree, so interface pairs stay valid.
   */
  void
  execute_refinement_keeping_interface_twins(
    Triangulation<2>                   &triangulation,
    const std::set<types::boundary_id> &interface_ids);

  /**
   * Geometric grading toward singular points (a rigid foundation's edges):
   * for each (point, levels), refine the cells with a vertex at the point,
   * `levels` times. Each pass halves the cells at the point, so the mesh
   * size falls like 2^-k toward it while the cell count grows only by a
   * constant per pass. A point touching no vertex is an input error.
   */
  void
  refine_toward_points(
    Triangulation<2>                                     &triangulation,
    const std::vector<std::pair<Point<2>, unsigned int>> &point_refinements,
    const std::set<types::boundary_id>                   &interface_ids);

  /** Collects the indicators of the harmonics of one cycle. */
  class RefinementIndicator
  {
  public:
    explicit RefinementIndicator(const Triangulation<2> &triangulation);

    /** Add the normalised Kelly indicators of one harmonic's solution. */
    void
    add_kelly(const DoFHandler<2> &dof_handler, const Vector<double> &solution);

    /** Add given cell indicators (goal-oriented estimator) unchanged. */
    void
    add(const Vector<float> &cell_indicators);

    /**
     * Flag the top `fraction` of cells by indicator and refine them, with
     * execute_refinement_keeping_interface_twins().
     */
    void
    refine(Triangulation<2>                   &triangulation,
           const double                        fraction,
           const std::set<types::boundary_id> &interface_ids) const;

  private:
    Vector<float> indicators;
  };
} // namespace FourierSSI

#endif
