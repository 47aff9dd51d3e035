/**
 * What the coupled iterations (nonlinear interfaces, plastic soil) share:
 * sums over the harmonics of a correction, the acceleration of the fixed
 * point c = G(c), and the harmonic and component that carry a controlled
 * rigid-foundation motion (doc/nonlinear-interfaces.md section 5,
 * doc/soil-plasticity.md).
 */
#ifndef fourier_ssi_coupled_iteration_h
#define fourier_ssi_coupled_iteration_h

#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/coupled/anderson_acceleration.h>
#include <fourier_ssi/harmonic/rigid_motion.h>
#include <fourier_ssi/input/atomic_file.h>
#include <fourier_ssi/input/harmonic.h>
#include <fourier_ssi/input/load_path_parameters.h>
#include <fourier_ssi/input/rigid_foundation_parameters.h>
#include <fourier_ssi/postprocess/results_table.h>
#include <fstream>
#include <iomanip>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  class HarmonicProblem;

  /**
   * The loads the load factor lambda scales in a nonlinear run (condensed):
   * with a Rigid foundation its loads H, M, V, T alone; without one, every
   * load of the scene (the body force and tractions are then the loading).
   */
  Vector<double>
  load_factor_pattern(const HarmonicProblem &problem);

  /**
   * The held loads F_held of a nonlinear run (condensed): brought on in full
   * by the held stage (Load path/Held load steps), then constant
   * while lambda scales load_factor_pattern(). With a Rigid foundation they
   * are its Held ... loads, the Body force and the tractions (Boundary
   * conditions/Traction, Loads/Traction): self-weight and surcharges are in
   * place before the foundation is loaded, as in a staged geotechnical
   * analysis. Without a Rigid foundation there are none.
   */
  Vector<double>
  held_stage_load(const HarmonicProblem &problem);

  /**
   * |lambda F + rho F_held| from |F|, F . F_held and |F_held| (2-norms over
   * the harmonics): the applied load scale of a step of either stage.
   */
  double
  combined_load_norm(const double load_factor,
                     const double held_fraction,
                     const double pattern_norm,
                     const double pattern_held_dot,
                     const double held_norm);

  /**
   * One harmonic's total displacement in the coupled load path:
   * u = lambda u_F + v + rho u_held (the pattern solution scaled by the load
   * factor, the correction solution, the held-stage solution scaled by the
   * held fraction; `held` null without a held stage).
   */
  Vector<double>
  total_displacement(const Vector<double> &pattern,
                     const double          load_factor,
                     const Vector<double> &correction,
                     const Vector<double> *held,
                     const double          held_fraction);

  /** sqrt(sum_h |v_h|^2): the norm of a field given per harmonic. */
  double
  norm_over_harmonics(const std::vector<Vector<double>> &vectors);

  /**
   * The convergence test of the coupled load path: the out-of-balance force
   * R = G - c is measured against the internal force scale, the largest of
   * |lambda F| (the applied loads, held ones included) and |G| (the load of
   * the plastic part that the nonlinear sources return: slip and gaps of
   * the interfaces, plastic strain of the soil). |G| is the force the
   * interfaces and the soil carry beyond the elastic solution; with a stiff
   * interface G ~ kn gap is many times |lambda F| (5e4 at kappa = 1e5 for
   * the disc in a ring) and a test against |lambda F| alone asks for R
   * below the round-off of G. The support reactions balance lambda F
   * (plus the self-equilibrated part inside |G|), so they set no larger
   * scale and are not assembled per iteration.
   */
  struct ForceScale
  {
    /** |lambda F| [kN]. */
    double applied = 0.;
    /** |G| [kN]. */
    double out_of_balance = 0.;

    double
    largest() const
    {
      return std::max(applied, out_of_balance);
    }

    /** |R| <= tolerance largest(); never with a non-finite |R|. */
    bool
    converged(const double residual_norm, const double tolerance) const
    {
      return std::isfinite(residual_norm) &&
             residual_norm <= tolerance * largest();
    }

    /** |R| / largest() (0 if the scale is 0), as the step records print. */
    double
    relative(const double residual_norm) const
    {
      return largest() > 0. ? residual_norm / largest() : 0.;
    }
  };

  /** sum_h a_h . b_h. */
  double
  dot_over_harmonics(const std::vector<Vector<double>> &a,
                     const std::vector<Vector<double>> &b);

  /**
   * The harmonic that carries a controlled foundation motion: n = 0
   * symmetric (vertical), n = 0 antisymmetric (twist), n = 1 symmetric
   * (horizontal, rotation).
   */
  Harmonic
  controlled_harmonic(const LoadPathParameters::Motion motion);

  /** The component of a rigid motion that a load step controls. */
  double
  controlled_component(const RigidMotion               &motion,
                       const LoadPathParameters::Motion controlled);

  /**
   * The foundation loads of a load step, load_factor times the given ones,
   * as the resultant (F_x, F_y, F_z, M_x, M_y, M_z) about the origin [kN,
   * kN.m]: (H, M) act at (0, 0, z_ref), so moved to the origin M_y gains
   * z_ref H_x and M_x loses z_ref H_y. held_fraction times the held loads
   * (Rigid foundation/Held ...) is added.
   */
  std::array<double, 6>
  applied_foundation_loads(const RigidFoundationParameters &foundation,
                           const double                     load_factor,
                           const double                     held_fraction = 0.);

  /**
   * M_y about the reference point (as the prm gives it) out of the
   * resultant about the origin: M_y - z_ref H_x [kN.m].
   */
  double
  moment_about_reference(const std::array<double, 6>     &loads,
                         const RigidFoundationParameters &foundation);

  /** A foundation load by name, with its unit. */
  struct NamedLoad
  {
    std::string name, unit;
    double      value = 0.;
  };

  /**
   * The load that works on a controlled motion (vertical: V [kN],
   * horizontal: H [kN], rotation: M about the reference point [kN.m],
   * twist: T [kN.m]) out of the resultant about the origin
   * (applied_foundation_loads).
   */
  NamedLoad
  conjugate_load(const std::array<double, 6>     &loads,
                 const RigidFoundationParameters &foundation,
                 const LoadPathParameters::Motion controlled);

  /** The leading columns of every load-displacement.csv. */
  constexpr const char *load_step_csv_header =
    "step,load_factor,V_kN,H_kN,M_kNm,T_kNm,vertical_m,horizontal_m,"
    "rotation_rad,twist_rad,iterations,residual";

  /**
   * The V on the foundation at a step: loads[2] of applied_foundation_loads
   * plus a swipe's change swipe_force (LoadStep::swipe_force; the load
   * itself without a swipe).
   */
  inline double
  vertical_force_of(const std::array<double, 6> &loads,
                    const double                 swipe_force)
  {
    return swipe_force == 0. ? loads[2] : loads[2] + swipe_force;
  }

  /**
   * The columns of the held reactions (LoadStep::held_reactions) in
   * load-displacement.csv: ",<results row>_<unit>" each, units as in the
   * leading columns (kN, kNm); empty without.
   */
  std::string
  held_reaction_columns(
    const RigidFoundationParameters                        &foundation,
    const std::vector<std::pair<FoundationMotion, double>> &reactions);

  /** One row's leading columns, in the order of load_step_csv_header. */
  void
  write_load_step_columns(std::ostream                    &out,
                          const unsigned int               step,
                          const double                     load_factor,
                          const double                     held_fraction,
                          const double                     swipe_force,
                          const RigidFoundationParameters &foundation,
                          const RigidMotion               &motion,
                          const unsigned int               iterations,
                          const double                     residual);

  /**
   * The one line of a load-controlled stage that stopped at a limit load:
   * its steps converged at ever smaller sizes until the next would be
   * below 2^-(Maximum step cuts) of a load step. `done` is the fraction of
   * the stage's loads carried, numbered as unconverged_step_message()
   * numbers it; `held` says they are the held loads (body force,
   * tractions, held foundation loads).
   */
  std::string
  limit_load_message(const std::string        &entry,
                     const double              done,
                     const unsigned int        n_steps,
                     const bool                held,
                     const LoadPathParameters &settings,
                     const unsigned int        converged_steps,
                     const std::string        &segment = "");

  /**
   * The one line of a load step that did not converge even after the
   * allowed step cuts (`entry` names the solver's parameter section). The
   * step is numbered as the user counts them, "load step 2 of 2 (after 4
   * cuts)": the one of the `n_steps` equal steps that the path was in
   * (`done`, the fraction of the stage completed), not the count of
   * converged cut steps; `held` says it is a step of the held loads;
   * `cuts` the cuts it had: Maximum step cuts, or fewer where the step size
   * reached its floor, which the line then names. `segment` follows the
   * step's number on a path of several targets (" of segment 2 of 3 (to
   * -0.01)").
   */
  std::string
  unconverged_step_message(const std::string        &entry,
                           const double              done,
                           const unsigned int        n_steps,
                           const bool                held,
                           const unsigned int        cuts,
                           const unsigned int        converged_steps,
                           const LoadPathParameters &settings,
                           const std::string        &segment = "");

  /**
   * The update of the correction load c <- c + dc of one iteration from
   * the force residual R = G(c) - c: dc = R (none), omega R with Aitken's
   * Delta^2 rule omega_k = -omega_{k-1} R_{k-1}^T (R_k - R_{k-1}) /
   * |R_k - R_{k-1}|^2 (restarted from omega = 1 where |R| stalls), or the
   * Anderson update on the last m residuals (doc/nonlinear-interfaces.md
   * section 5). One per load step.
   */
  class FixedPointAcceleration
  {
  public:
    using Kind = LoadPathParameters::Acceleration;

    FixedPointAcceleration(const Kind kind, const unsigned int anderson_depth);

    std::vector<Vector<double>>
    increment(const std::vector<Vector<double>> &load,
              const std::vector<Vector<double>> &residual);

  private:
    /**
     * Aitken restarts from omega = 1 after this many updates without a new
     * smallest |R|: a stalled factor, not a slow contraction.
     */
    static constexpr unsigned int stalled_aitken_updates = 10;

    void
    restart_aitken_if_stalled(const std::vector<Vector<double>> &residual);

    double
    aitken_factor(const std::vector<Vector<double>> &residual) const;

    Kind                        kind;
    AndersonAcceleration        anderson;
    double                      omega = 1.;
    std::vector<Vector<double>> previous_residual;
    double       best_residual_norm      = std::numeric_limits<double>::max();
    unsigned int updates_since_best_norm = 0;
  };
} // namespace FourierSSI

#endif
