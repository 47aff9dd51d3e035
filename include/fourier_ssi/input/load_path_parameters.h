/**
 * Subsection "Load path": how the coupled iteration of
 * CoupledSolver loads the scene and when it has converged
 * (doc/nonlinear-interfaces.md, section 5).
 */
#ifndef fourier_ssi_load_path_parameters_h
#define fourier_ssi_load_path_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** Subsection "Load path" of the .prm file. */
  struct LoadPathParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    enum class Control
    {
      load,
      displacement
    };
    /** Rigid-foundation motion that displacement control prescribes. */
    enum class Motion
    {
      vertical,
      twist,
      horizontal,
      rotation
    };

    /**
     * Upper bounds of the counts of this subsection: a typo (1e9 load
     * steps, a million harmonics) is refused when the file is read instead
     * of running for hours or ending in std::bad_alloc. Each is far above
     * what a scene needs: the harmonics are those of
     * Discretization/Harmonics (n <= 1024), whose alias-free sampling needs
     * 2049 angles; a step cut 20 times is a millionth of the step.
     */
    static constexpr unsigned int largest_harmonic   = 1024;
    static constexpr unsigned int most_theta_samples = 8192;
    static constexpr unsigned int most_load_steps    = 10000;
    static constexpr unsigned int most_step_cuts     = 20;
    static constexpr unsigned int most_iterations    = 100000;

    /** 0: automatic, 4 (n_max + 1), at least 2 n_max + 1 (no aliasing). */
    unsigned int theta_samples = 0;
    unsigned int load_steps    = 10;
    /** Steps that bring Rigid foundation/Held ... loads on (plastic soil). */
    unsigned int held_load_steps = 4;
    Control      control         = Control::load;
    Motion       motion          = Motion::vertical;
    /** How the fixed point of the out-of-balance load is accelerated. */
    enum class Acceleration
    {
      none,
      aitken,
      anderson
    };

    /** Final value of the controlled motion [m or rad]. */
    double target = 0.;
    /**
     * A cyclic path (Targets, Cycles; load_path_targets.h): its turning
     * points, load factors (load control) or controlled motions
     * (displacement control); empty for a monotonic path.
     */
    std::vector<double> targets;
    /** The cycles Targets was expanded with (0: the list as given). */
    unsigned int cycles = 0;

    bool
    is_cyclic() const
    {
      return !targets.empty();
    }

    /**
     * The end of each loading segment: the targets of a cyclic path, else
     * Target (displacement control) or the full loads, 1 (load control).
     */
    std::vector<double>
    segment_targets() const
    {
      if (is_cyclic())
        return targets;
      return {control == Control::displacement ? target : 1.};
    }
    /**
     * Relative out-of-balance force at which a step has converged. Bounded
     * below `largest_tolerance`: at 1e-2 a step may stop with a percent of
     * the load unbalanced, and at Tolerance = 1 the elastic trial of every
     * step is accepted before any iteration (the elastic answer, reported
     * with slipping and open samples).
     */
    double                  tolerance          = 1e-10;
    static constexpr double largest_tolerance  = 1e-2;
    unsigned int            maximum_iterations = 2000;
    Acceleration            acceleration       = Acceleration::aitken;
    /**
     * Interface-only scenes: Newton with the consistent tangent and a line
     * search (tangent), the initial stiffness (initial), or whichever the
     * interfaces' stiffness calls for (automatic: Newton for contact and for
     * stiff penalties, InterfaceParameters::is_stiff()).
     */
    enum class Stiffness
    {
      automatic,
      initial,
      tangent
    };
    Stiffness stiffness = Stiffness::automatic;
    /** Previous residuals an Anderson update uses (m). */
    unsigned int anderson_depth    = 5;
    unsigned int maximum_step_cuts = 4;
    /**
     * Harmonics chosen by the solution: up to this n the set grows where the
     * interface-traction spectrum has not decayed (0, or not above the
     * highest listed harmonic: the listed harmonics only).
     */
    unsigned int maximum_harmonic = 0;
    /** Relative amplitude of the traction spectrum that adds a harmonic. */
    double harmonic_tolerance = 1e-3;
  };

} // namespace FourierSSI

#endif
