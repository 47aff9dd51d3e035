/**
 * Subsection "Discretization" of the .prm file: the harmonics, the element
 * (degree, volumetric strain), the refinement cycles or the target accuracy
 * that designs them, and how many harmonics are solved at once.
 */
#ifndef fourier_ssi_discretization_parameters_h
#define fourier_ssi_discretization_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <fourier_ssi/input/harmonic.h>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** Discretization/Volumetric strain once 'auto' is resolved. */
  enum class VolumetricStrain
  {
    standard,
    bbar
  };

  /** Which harmonics to solve and with which element. */
  struct DiscretizationParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** Harmonics chosen from the loads (Harmonics = auto), see ScenePlan. */
    bool                  automatic = false;
    std::vector<Harmonic> harmonics;
    unsigned int          degree = 2;
    /**
     * What is solved: the standard strain or B-bar (projected dilatation,
     * p = 2). The entry's default 'auto' is resolved when the parameters
     * are read (AllParameters::parse_parameters): bbar for p = 2 when a
     * material has nu >= locking_poisson_ratio, standard otherwise.
     */
    VolumetricStrain volumetric = VolumetricStrain::standard;
    /** True if `volumetric` was chosen by 'auto' (the log says so). */
    bool         volumetric_automatic = false;
    unsigned int refinement_cycles    = 1;
    /**
     * Relative accuracy asked of the goal values (0: not set). When set,
     * the program designs an FE_Q(4) discretization and refines it until
     * the estimated error is below it (discretization_design.h).
     */
    double target_accuracy = 0.;
    /** Harmonics solved at the same time (threads); 0: one per core. */
    unsigned int concurrent_harmonics = 0;
  };
} // namespace FourierSSI

#endif
