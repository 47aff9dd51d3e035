/**
 * The values one coupled load step works on (doc/driver.md, "one load
 * step"): the state of an iterate, what evaluating it gives (the residual
 * and the nonlinear sources' state there) and a change of its correction
 * load. Value types only: the objects that read and write them are the
 * nonlinear sources (nonlinear_sources.h), the linearisations
 * (linearisation.h), the load control (load_control.h) and the step
 * iteration (step_iteration.h).
 */
#ifndef fourier_ssi_coupled_step_state_h
#define fourier_ssi_coupled_step_state_h

#include <deal.II/lac/vector.h>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/nonlinear_interface_points.h>
#include <fourier_ssi/fourier/harmonic_operator.h>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * The state of a coupled load step: lambda, rho, mu, c and K^-1 c, and
   * what the nonlinear sources keep. Condensed (interfaces only,
   * InterfaceCondensation), K^-1 c in correction_solution is exact at the
   * interface DoFs only while a step iterates, and whole once it converged.
   */
  struct CoupledStepState
  {
    double load_factor = 0.;
    /** rho: the held loads' part rho F_held of the load. */
    double held_fraction = 0.;
    /** mu: a swipe's change of the vertical load (LoadStep::swipe_force). */
    double swipe_force = 0.;
    /** K^-1 c per harmonic, and c (condensed). */
    std::vector<Vector<double>> correction_solution, correction_load;
    /** Plastic soil: s_p = D eps_p per (point, theta); empty without. */
    std::vector<StrainVector> plastic;
    /**
     * Multi-surface (iwan) soil: the plastic strains of every sample's
     * elements (NonlinearSoilPoints::history_size); empty without.
     */
    std::vector<StrainVector> soil_history;
    /**
     * Nonlinear interfaces: d_p, the return's origin and p_c per
     * (interface point, theta); empty without.
     */
    InterfaceState interfaces;
    /** Condensed: the controlled motion of K^-1 c [m or rad]. */
    double controlled_motion = 0.;
  };

  /** The residual and the state of the soil and interfaces at an iterate. */
  struct CoupledEvaluation
  {
    /**
     * Total strain and s_p per (point, theta); the iwan elements' plastic
     * strains.
     */
    std::vector<StrainVector> strain, plastic, soil_history;
    /**
     * Nonlinear interfaces (empty without): relative displacement, d_p,
     * traction, stick/slip/open per (point, theta), and the counts.
     */
    std::vector<LocalVector>  relative, interface_plastic, traction;
    std::vector<ContactState> contact;
    ContactCounts             counts = {{0, 0, 0}};
    /** R = G - c per harmonic (condensed), and |R|. */
    std::vector<Vector<double>> residual;
    double                      residual_norm = 0.;
    /** |lambda F| and the interfaces' |G|: what |R| is measured against. */
    ForceScale scale;
  };

  /**
   * A change of c and the displacement K^-1 dc it makes (per harmonic);
   * condensed, dc at the write DoFs only and no displacement (the
   * condensation gives it where it is read).
   */
  struct CoupledCorrection
  {
    std::vector<Vector<double>> load, solution;
  };
} // namespace FourierSSI

#endif
