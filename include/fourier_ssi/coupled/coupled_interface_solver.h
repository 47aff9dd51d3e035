/**
 * Nonlinear (Mohr-Coulomb, tension cut-off) interfaces on a set of Fourier
 * harmonics coupled through theta (doc/nonlinear-interfaces.md, section 5).
 *
 * Initial-stiffness (modified Newton) iteration on the kept elastic
 * factorizations of a HarmonicSet: every harmonic's matrix K_h holds the
 * closed-form interface matrices with the elastic kn, ks. With d_p the
 * plastic relative displacement (slip and gap) at the interface points, the
 * discrete equilibrium is, per harmonic h,
 *   K_h u_h = lambda F_h + c_h(d_p),   c_h = int int B_h^T D d_p r ds dtheta,
 * (the interface force int B^T (t - t0) = K_interface u - c). One iteration:
 *   1. the relative displacement at every interface Gauss point, summed over
 *      all harmonics at N theta samples (ThetaSampling::evaluate);
 *   2. the return mapping at every (point, theta) -> d_p, t;
 *   3. the out-of-balance load G_h = int B_h^T D d_p, theta-integrated with
 *      the trapezoidal rule against each harmonic's factor and through the
 *      element's shape functions (the same B that gives the closed-form K);
 *   4. force residual R = G - c; converged if |R| <= tolerance |lambda F|
 *      (|G| if lambda F = 0; 2-norms over all harmonics); else
 *   5. c <- c + dc, dc = omega R (Aitken's Delta^2 rule, or omega = 1) or
 *      the Anderson update (AndersonAcceleration), and v = K^-1 c follows
 *      through each harmonic's flexibility block on the interface DoFs
 *      (K^-1 restricted to the DoFs the relative displacements read x the
 *      DoFs c reaches, built once from the kept factorizations of the
 *      HarmonicSet): a dense product per iteration instead of a re-solve;
 *      the full K^-1 c is solved once per converged step.
 * With Maximum harmonic above the set's highest harmonic, harmonics whose
 * amplitude in the interface traction has not decayed below Harmonic
 * tolerance are added to the set after a converged step (HarmonicSet::add)
 * and the step is solved again.
 * Under mpirun the harmonics are distributed over the ranks
 * (HarmonicSet::distribute_over): each rank owns some harmonics, their
 * factorizations and flexibility blocks, and an iteration exchanges once
 * (one MPI_Allreduce) the interface amplitudes of every harmonic at the
 * Gauss points; each amplitude is non-zero on its owner only, so the sum is
 * exact and every rank samples, return-maps, accelerates and decides on
 * bitwise the same numbers (the decisions cannot diverge).
 * Load control scales the foundation's loads by lambda (load_factor_pattern;
 * all the scene's loads without a Rigid foundation); displacement control
 * chooses lambda in every iteration so that one rigid-foundation motion
 * equals its target (needed past the peak). Held loads (held_stage_load:
 * body force, tractions, Rigid foundation/Held ...) come first, in a held
 * stage at lambda = 0, and stay while lambda scales the foundation's loads. A
 * step that does not converge is cut in half (up to a limit); then the solve
 * stops with a one-line error, the converged steps kept.
 */
#ifndef fourier_ssi_coupled_interface_solver_h
#define fourier_ssi_coupled_interface_solver_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/initial_stress.h>
#include <fourier_ssi/coupled/load_path_states.h>
#include <fourier_ssi/coupled/load_step_result.h>
#include <fourier_ssi/coupled/nonlinear_interface_points.h>
#include <fourier_ssi/fourier/theta_sampling.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/input/load_path_parameters.h>
#include <fourier_ssi/input/parameters.h>
#include <fourier_ssi/interfaces/interface_law.h>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** Iteration state of a load step of the interfaces. */
  struct InterfaceStepState : CorrectionState
  {
    /** K^-1 c valid at the read DoFs only (the iteration's view). */
    std::vector<Vector<double>> interface_solution;
    /** The controlled motion of K^-1 c [m or rad]. */
    double controlled_motion = 0.;
    /** d_p, the return's origin and p_c per point and sample. */
    InterfaceState interfaces;
  };

  class CoupledInterfaceSolver : private LoadPathStates<InterfaceStepState>
  {
  public:
    /**
     * `set` must be assembled and factorized; its harmonics' matrices hold
     * the elastic interface stiffness kn, ks of every interface. With
     * `Load path/Maximum harmonic` above the highest harmonic of
     * the set, harmonics the interface tractions call for are added to it.
     */
    CoupledInterfaceSolver(HarmonicSet &set, const AllParameters &parameters);

    /**
     * All load steps. Returns normally if every step converged; otherwise
     * throws a one-line error after the step cuts, the converged steps kept
     * in get_steps().
     */
    void
    run(std::ostream &log);

    /**
     * CSV of the interface state at every (point, theta sample) of every
     * converged step: position, angle, stick/slip/open, traction and
     * relative displacement with their units in the header
     * (coupled_interface_solver_output.cc).
     */
    void
    write_interface_state_csv(const std::string &filename) const;

    /**
     * VTU (ParaView) of the last converged step's interface samples as
     * points in 3D, (r cos theta, r sin theta, z): state (0 stick, 1 slip,
     * 2 open), traction [kPa] and relative displacement [m] in the local
     * (s, n, theta) components, next to the revolved soil field.
     */
    void
    write_interface_state_vtu(const std::string &filename) const;

    /**
     * solution(i), applied_loads(), the step records get_steps() and their
     * load-displacement.csv write_csv() (load_path_states.h).
     */
    using LoadPathStates::applied_loads;
    using LoadPathStates::get_steps;
    using LoadPathStates::solution;
    using LoadPathStates::write_csv;

    /** N, the theta samples of the iteration. */
    unsigned int
    n_theta_samples() const
    {
      return sampling.n_samples();
    }

    /**
     * int int B_h^T D d r ds dtheta of the relative displacement d of the
     * given fields (one per harmonic), condensed: the elastic force of the
     * nonlinear interfaces computed through the theta sampling and the Gauss
     * points, which must equal the closed-form K_interface u (a check of the
     * projection that builds the out-of-balance loads).
     */
    std::vector<Vector<double>>
    interface_force(const std::vector<Vector<double>> &fields) const;

    /** Number of Gauss points of the nonlinear interfaces. */
    unsigned int
    n_interface_points() const
    {
      return points.size();
    }

  private:
    /**
     * The iteration condensed onto the interface (section 5 of the doc): c
     * is non-zero only at the DoFs its assembly reaches ("write": the
     * interface DoFs, or their masters where constrained), and an iteration
     * reads K^-1 c only at the interface DoFs ("read") and in the controlled
     * motion. So the flexibility block F = K^-1 restricted to read x write
     * (one solve per write DoF, once per harmonic) gives the iterate exactly,
     * a dense product instead of a sparse re-solve per iteration; the full
     * K^-1 c is solved once per converged step.
     */
    struct Condensation
    {
      std::vector<types::global_dof_index> write, read;
      /** F(i, j) = (K^-1 e_write[j])(read[i]). */
      FullMatrix<double> flexibility;
      /** Controlled motion of K^-1 e_write[j] (0 if not its harmonic). */
      std::vector<double> controlled_motion;
    };

    using StepState = InterfaceStepState;

    /**
     * F and F_held (held_stage_load), their elastic solutions (LoadPattern)
     * and what the iteration reads of them: their relative displacements
     * at the samples and their controlled motions (0 without held loads).
     */
    void
    solve_loads();

    /** LoadPath::Iteration: the trial step and its commit (load_path.h). */
    bool
    solve_trial(const double target, const bool holding) override;
    bool
    grows(std::ostream &log) override;
    void
    commit_trial(const LoadStep &step,
                 const bool      holding,
                 std::ostream   &log) override;

    /** Displacement control in the stage being solved (not the held one). */
    bool
    controls_motion() const;

    /** Condensation of the harmonics first, first + 1, ... */
    void
    condense(const unsigned int first);

    /** The entries of (condensed) loads at the write DoFs, per harmonic. */
    std::vector<Vector<double>>
    on_write_dofs(const std::vector<Vector<double>> &full) const;

    /**
     * c += dc (given at the write DoFs), and K^-1 c at the read DoFs and in
     * the controlled motion through the condensation.
     */
    void
    add_correction(const std::vector<Vector<double>> &dc_write,
                   StepState                         &state) const;

    /** The full K^-1 c of a converged state (one solve per harmonic). */
    void
    complete(StepState &state) const;

    /**
     * Secant predictor (LoadPathStates::extrapolate), the condensed view
     * K^-1 c at the interface and its controlled motion moved on with c:
     * every part of the state but the plastic slip is linear in c
     * (doc/nonlinear-interfaces.md section 5).
     */
    void
    extrapolate(const StepState &before_last,
                const double     ratio,
                StepState       &state) const override;

    /** The residual and the interface state at one iterate. */
    struct Evaluation
    {
      std::vector<LocalVector>  relative, plastic, traction;
      std::vector<ContactState> contact;
      ContactCounts             counts = {{0, 0, 0}};
      /** R = G - c per harmonic (condensed), and |R|. */
      std::vector<Vector<double>> residual;
      double                      residual_norm = 0.;
      /** |lambda F| and |G|: what |R| is measured against. */
      ForceScale scale;
    };

    /**
     * Steps 1-4 of an iteration at `state` (lambda set from the target
     * under displacement control): relative displacements, return mapping,
     * out-of-balance load and residual.
     */
    Evaluation
    evaluate(const double target, StepState &state) const;

    /**
     * A converged iterate (its evaluation moved from): complete the state,
     * fill the step record. The load path checks that the motion reached
     * its target.
     */
    void
    accept(Evaluation        &e,
           const unsigned int iteration,
           StepState         &state,
           LoadStepResult    &result) const;

    /** dc of (I - dG/dc) dc = R, the write DoFs of every harmonic in turn. */
    Vector<double>
    newton_direction(const Evaluation &e, const StepState &state) const;

    /** c += alpha dc (dc as newton_direction() orders it). */
    void
    add_scaled_correction(const double          alpha,
                          const Vector<double> &dc,
                          StepState            &state) const;

    /** dG/dc on the write DoFs of every harmonic, dense (column (h, j)). */
    FullMatrix<double>
    out_of_balance_jacobian(const Evaluation &e, const StepState &state) const;

    /**
     * The iteration (Newton or fixed point) at fixed contact multipliers
     * until the force test passes; `e` the converged evaluation,
     * `iterations` counts on. False if it does not converge.
     */
    bool
    iterate(const double  target,
            StepState    &state,
            Evaluation   &e,
            unsigned int &iterations) const;

    /**
     * Iterate one step to lambda (load control) or to a motion target;
     * with contact interfaces, Uzawa updates of the multipliers around
     * iterate() until the contact conditions hold to round-off.
     */
    bool
    solve_step(const double target, StepState &state, LoadStepResult &result);

    /**
     * Harmonics n <= Maximum harmonic, not solved, whose amplitude in the
     * traction change t - t0 of a converged state exceeds Harmonic
     * tolerance times the largest amplitude; each logged with its amplitude.
     */
    std::vector<Harmonic>
    harmonics_called_for(const InterfaceSnapshot &snapshot,
                         std::ostream            &log) const;

    /** Add harmonics to the set and extend the iteration state by zeros. */
    void
    grow(const std::vector<Harmonic> &added);

    HarmonicSet          &set;
    const AllParameters  &parameters;
    LoadPathParameters    settings;
    std::vector<Harmonic> harmonics;
    ThetaSampling         sampling;
    /** Every candidate harmonic n <= Maximum harmonic (growth only). */
    std::vector<Harmonic> candidates;
    ThetaSampling         spectrum;
    /** The Gauss points of the coulomb interfaces and their laws. */
    NonlinearInterfacePoints           interface;
    const std::vector<InterfacePoint> &points;
    std::vector<Condensation>          condensed;
    /** K^-1 F, loads.solution (its name in coupled_interface_newton.cc). */
    const std::vector<Vector<double>> &pattern_solution;
    /** The relative displacements of u_F and u_held at the samples. */
    InterfaceLoadCases cases;
    /** Controlled motions of u_F and u_held (0: no held loads). */
    double pattern_motion = 0., held_motion = 0.;
    /** True while the load path brings the held loads on. */
    bool holding_stage = false;
  };
} // namespace FourierSSI

#endif
