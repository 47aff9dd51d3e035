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

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <set>
#include <string>

namespace FourierSSI
{
  using namespace dealii;

  struct AdaptivityParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    std::string strategy        = "global"; // global | kelly | goal
    double      refine_fraction = 0.3;
    std::string goal            = "all"; // K_H | K_M | K_MH | all
    double      goal_tolerance  = 0.;    // relative; 0: no stop
  };

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
     * Flag the top `fraction` of cells by indicator, mirror the flags across
     * every interface (faces with an id in `interface_ids` and their
     * geometric twins) until both sides agree, and refine.
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
