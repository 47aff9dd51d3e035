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

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/input/adaptivity_parameters.h>
#include <set>
#include <utility>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

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
   * Refine the cells flagged in `triangulation`, after mirroring across
   * every interface (faces with an id in `interface_ids` and their
   * geometric twins) each flag whose cut splits the interface face, until
   * both sides agree, so interface pairs stay valid. A cut that leaves the
   * face whole (cut_x at a face of constant r) needs no twin.
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
     * Flag the top `fraction` of cells by indicator and refine them, each
     * by `cut` (isotropic, or cut_x: in r only), with
     * execute_refinement_keeping_interface_twins().
     */
    void
    refine(Triangulation<2>                   &triangulation,
           const double                        fraction,
           const std::set<types::boundary_id> &interface_ids,
           const RefinementCase<2>             cut =
             RefinementCase<2>::isotropic_refinement) const;

  private:
    Vector<float> indicators;
  };
} // namespace FourierSSI

#endif
