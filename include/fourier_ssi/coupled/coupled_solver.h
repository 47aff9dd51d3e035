/**
 * The coupled load path of every nonlinear scene (doc/driver.md): plastic
 * soil (Tresca, Mohr-Coulomb; soil_law.h, doc/soil-plasticity.md section 3)
 * and nonlinear interfaces (coulomb, contact; doc/nonlinear-interfaces.md
 * section 5) on a set of Fourier harmonics coupled through theta. Both are
 * nonlinear sources of one iteration; a scene of interfaces on elastic soil
 * is one with no soil points.
 *
 * Every harmonic keeps its elastic matrix K_h and factorization (HarmonicSet).
 * With s_p = D eps_p the "plastic stress" at every (soil point, theta
 * sample) and d_p the plastic relative displacement (slip and gap) at every
 * (interface point, theta sample), the discrete equilibrium of harmonic h is
 *   K_h u_h = lambda F_h + c_h,
 *   c_h = int Bbar_h^T [int factor_h s_p dtheta] r dr dz
 *       + int int B_h^T D d_p r ds dtheta
 * (the internal force K u - c). One evaluation of an iterate:
 *   1. strain amplitudes of every harmonic at every soil point (Bbar u_h,
 *      the dilatation projected per cell) and relative displacements at
 *      every interface point, summed at N theta samples
 *      (ThetaSampling::evaluate);
 *   2. the return mapping at every (point, theta) from the last converged
 *      state;
 *   3. G_h, the theta-integrated plastic parts through the same B that
 *      gives K;
 *   4. R = G - c, converged if |R| <= tolerance times the force scale
 *      (ForceScale: |lambda F| and the interfaces' |G|). Otherwise c moves
 *      by Newton (closed-form tangents, the globalisation of
 *      safeguarded_newton.h) or by the accelerated initial-stiffness
 *      update.
 * The linearisation is the one decision that differs between scenes
 * (AllParameters::linearises_on_coupled_tangent):
 *   - plastic soil (or a swipe): K^-1 dc re-solved for every harmonic with
 *     the kept factorizations; Newton on the coupled tangent K_t of every
 *     harmonic (Soil plasticity/Stiffness = tangent, coupled_tangent.h);
 *   - interfaces only: condensed onto the interface DoFs
 *     (InterfaceCondensation): K^-1 dc a dense product with the flexibility
 *     blocks, Newton on the dense condensed Jacobian (Load path/Stiffness =
 *     tangent), and harmonics added where the interface traction calls for
 *     them (Load path/Maximum harmonic).
 * Loading (load or displacement control of the rigid foundation), the held
 * stage, the predictor and step cutting are the LoadPath's (load_path.h);
 * contact and stiff coulomb laws iterate with their augmented Lagrangian's
 * multipliers around the iteration (NonlinearInterfacePoints).
 * A swipe test (Rigid foundation/Held motions = w with a Held vertical
 * force) adds mu e_V to the loads, e_V the unit vertical force on the
 * rigid foundation: after the held stage mu is a second unknown beside
 * lambda, chosen with it so that w stays where the held stage left it
 * (swipe_multipliers); no constraint changes along the path.
 *
 * Under mpirun the harmonics are distributed over the ranks
 * (HarmonicSet::distribute_over): each rank re-solves its own harmonics and
 * computes their strain amplitudes and interface amplitudes, and
 * return-maps every P-th soil point. Sums over the ranks (MPI_Allreduce)
 * give every rank all of them; each entry is non-zero on one rank only, so
 * the sums are exact, and every rank assembles G, tests convergence and
 * updates c on the same bits as a serial run (doc/soil-plasticity.md
 * section 3c). The coupled tangent: each rank integrates the softening of
 * its points, a sum gives every rank all of them, each rank assembles the
 * block rows of its harmonics, a sum completes the block matrix, and one
 * rank factorizes and solves it for every rank (coupled_tangent.h); all
 * exact, so Newton too takes the serial run's steps bit for bit.
 */
#ifndef fourier_ssi_coupled_solver_h
#define fourier_ssi_coupled_solver_h

#include <array>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/coupled_tangent.h>
#include <fourier_ssi/coupled/interface_condensation.h>
#include <fourier_ssi/coupled/load_path_states.h>
#include <fourier_ssi/coupled/load_step_result.h>
#include <fourier_ssi/coupled/nonlinear_interface_points.h>
#include <fourier_ssi/coupled/nonlinear_soil_points.h>
#include <fourier_ssi/coupled/soil_law.h>
#include <fourier_ssi/fourier/theta_sampling.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/input/load_path_parameters.h>
#include <fourier_ssi/input/parameters.h>
#include <functional>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  class CoupledSolver : private LoadPathStates
  {
  public:
    /**
     * `set` must be assembled and factorized; its harmonics' matrices hold
     * the elastic interface stiffness kn, ks of every interface. Interfaces
     * only, with `Load path/Maximum harmonic` above the highest harmonic of
     * the set, harmonics the interface tractions call for are added to it.
     */
    CoupledSolver(HarmonicSet &set, const AllParameters &parameters);

    /** All load steps; throws one line if a step does not converge. */
    void
    run(std::ostream &log);

    /**
     * solution(i), applied_loads(), the step records get_steps() and their
     * load-displacement.csv write_csv() (load_path_states.h).
     */
    using LoadPathStates::applied_loads;
    using LoadPathStates::get_steps;
    using LoadPathStates::solution;
    using LoadPathStates::write_csv;

    /**
     * The work of the applied loads on the last converged displacement,
     * sum over harmonics of (lambda F_h + rho F_held,h) . u_h [kJ]: the
     * goal of a load-controlled path (the stiffness and the forces carry
     * the theta integral, so the sum is the 3D work). Homogeneous
     * constraints only (the condensed load vector is then the work's).
     */
    double
    load_work() const;

    /**
     * int Bbar_h^T D eps(fields) over the plastic soil, theta by sampling:
     * equals the soil part of K_h u (a check of the projection that builds
     * the out-of-balance loads).
     */
    std::vector<Vector<double>>
    soil_force(const std::vector<Vector<double>> &fields) const;

    /**
     * The out-of-balance load G(u) = int Bbar^T (D eps(u) - sigma(u)) of
     * the displacement fields u (one per harmonic), the return mapping from
     * the committed state: what the iteration balances.
     */
    std::vector<Vector<double>>
    out_of_balance_load(const std::vector<Vector<double>> &fields);

    /**
     * K_t(u) x: the coupled tangent (Stiffness = tangent) built at the
     * fields u and applied to x; K u - G(u) is the internal force, so
     * K_t x = K x - dG/du x (checked against differences of
     * out_of_balance_load in tests/coupled/soil_coupled_tangent.cc).
     */
    std::vector<Vector<double>>
    tangent_product(const std::vector<Vector<double>> &fields,
                    const std::vector<Vector<double>> &x);

    unsigned int
    n_soil_points() const
    {
      return soil.size();
    }

    /** The theta samples of the soil (of the interfaces without soil). */
    unsigned int
    n_theta_samples() const
    {
      return sampling.n_samples();
    }

    /** Number of Gauss points of the nonlinear interfaces. */
    unsigned int
    n_interface_points() const
    {
      return interface ? interface->size() : 0;
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

    /**
     * The soil's nodal forces int Bbar_h^T (sigma - sigma_0) r dr dz of the
     * last converged step, every harmonic, over the soil cells whose centre
     * is `selected`, NOT condensed: the force each node of those cells
     * exerts on the soil, 3D virtual-work coefficients as the load vectors
     * (theta weights included). At a node of a rigid foundation it is the
     * force the foundation exerts on those cells (soil-reaction curves,
     * doc/soil-reaction-curves.md). The geostatic sigma_0 is left out: it
     * is balanced by the self-weight. Serial runs only.
     */
    std::vector<Vector<double>>
    soil_nodal_force(
      const std::function<bool(const Point<2> &)> &selected) const;

    /**
     * Called after every converged step (the state then is that step's:
     * solution(), soil_nodal_force()), before the step's log line.
     */
    void
    set_step_observer(std::function<void(const LoadStepResult &)> observer)
    {
      step_observer = std::move(observer);
    }

    /** True if the scene has nonlinear (coulomb, contact) interfaces. */
    bool
    has_nonlinear_interfaces() const
    {
      return interface != nullptr;
    }

    /**
     * CSV of the nonlinear interfaces' state at every (point, theta) of
     * every converged step: position, angle, stick/slip/open, traction and
     * relative displacement with their units in the header
     * (NonlinearInterfacePoints::write_state_csv).
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

  private:
    using StepState = CoupledStepState;

    /**
     * F, F_held (Rigid foundation/Held ...) and in a swipe e_V, their
     * elastic solutions (LoadPattern) and what the sources read of them:
     * their strains at the soil points and relative displacements at the
     * interfaces' samples.
     */
    void
    solve_loads();

    /** |lambda F + rho F_held| (2-norm over the harmonics). */
    double
    applied_load_norm(const StepState &state) const;

    /** LoadPath::Iteration: the trial step and its commit (load_path.h). */
    bool
    solve_trial(const double target, const bool holding) override;
    bool
    grows(std::ostream &log) override;
    /**
     * Newton's retry of a step that failed after the last cut: where it
     * finds no descent it takes one initial-stiffness update and goes on
     * (a tensionless frictional shaft whose contact states chatter, the
     * same at every step size), until |R| stalls.
     */
    bool
    retry_persistently(std::ostream &log) override;
    void
    commit_trial(const LoadStep &step,
                 const bool      holding,
                 std::ostream   &log) override;

    /**
     * Total strain samples [point * N + j] at lambda, rho and a swipe's mu,
     * at the points this rank owns (NonlinearSoilPoints::strain_samples;
     * zero at the others).
     */
    std::vector<StrainVector>
    strain_samples(const std::vector<Vector<double>> &correction,
                   const double                       load_factor,
                   const double                       held_fraction,
                   const double                       swipe_force = 0.) const;

    /**
     * Condensed: K^-1 c complete (InterfaceCondensation::complete), and the
     * controlled motion from it.
     */
    void
    complete(StepState &state) const;

    /**
     * Secant predictor (LoadPathStates::extrapolate); condensed, the
     * controlled motion of K^-1 c moves on with c too.
     */
    void
    extrapolate(const StepState &before_last,
                const double     ratio,
                StepState       &state) const override;

    /**
     * The load that holds each held motion (Rigid foundation/Held motions)
     * in a converged state: the work of the internal force K u - G(u)
     * (G unconstrained: load_of(plastic, false)) minus the body force
     * lambda f on the unit held motion (RigidFoundation::held_reactions).
     * The nonlinear interfaces' part of G is that of their tractions in
     * `interface_state` (NonlinearInterfacePoints::spring_plastic). Empty
     * without held motions.
     */
    std::vector<std::pair<FoundationMotion, double>>
    held_reactions(const StepState         &state,
                   const InterfaceSnapshot &interface_state) const;

    /**
     * lambda that puts the controlled motion of the state at target: the
     * motion of K^-1 c (the condensed one, or from the field) and of the
     * held loads, and of the pattern (pattern_motion, held_motion).
     */
    double
    controlled_load_factor(const StepState &state, const double target) const;

    /**
     * A swipe (RigidFoundationParameters::swipes()): the multipliers
     * (lambda, mu) of the load pattern F and of the unit vertical load e_V
     * that move the foundation from the motion `now` to the controlled
     * motion `target` (load control: lambda = target) and to w =
     * `settlement`, where F moves it by `by_pattern` and e_V by `by_swipe`:
     *   [m(by_pattern)  m(by_swipe)] [lambda]   [target - m(now)]
     *   [w(by_pattern)  w(by_swipe)] [mu    ] = [settlement - w(now)],
     * the first row [1 0 | target] under load control. The motions are
     * linear in the fields, so this holds them exactly: the swipe's
     * counterpart of controlled_load_factor, with the elastic patterns for
     * an iterate and the tangent ones for a Newton update.
     */
    std::array<double, 2>
    swipe_multipliers(const RigidMotion &now,
                      const RigidMotion &by_pattern,
                      const RigidMotion &by_swipe,
                      const double       target,
                      const double       settlement,
                      const bool         displacement_control) const;

    /**
     * The state's lambda and mu from its correction (swipe_multipliers with
     * K^-1 F and K^-1 e_V): the controlled motion at target and w where the
     * held stage left it.
     */
    void
    set_swipe_multipliers(StepState   &state,
                          const double target,
                          const bool   displacement_control) const;

    /** The residual and the state of the soil and interfaces at an iterate. */
    struct Evaluation
    {
      /** Total strain and s_p per (point, theta). */
      std::vector<StrainVector> strain, plastic;
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
     * Steps 1-4 of an iteration at `state`: strains and relative
     * displacements, return mapping, out-of-balance load and residual (the
     * soil's counts into `result`).
     */
    Evaluation
    evaluate(const StepState &state, LoadStepResult &result) const;

    /**
     * The nonlinear interfaces' part of an evaluation: their relative
     * displacements, return mapping and load added to the residual (the
     * residual, if empty: no soil); returns the norm of that load (part of
     * the force scale).
     */
    double
    add_interface_residual(const StepState &state, Evaluation &e) const;

    /** A converged iterate: its plastic state and the step's records. */
    void
    accept(Evaluation        &e,
           const unsigned int iteration,
           StepState         &state,
           LoadStepResult    &result) const;

    /**
     * A change of c and the displacement K^-1 dc it makes (per harmonic);
     * condensed, dc at the write DoFs only and no displacement (the
     * condensation gives it where it is read).
     */
    struct Correction
    {
      std::vector<Vector<double>> load, solution;
    };

    /**
     * Steps 1-4 at `state` after its load factor (or a swipe's multipliers)
     * is set from `target` for the control (evaluate()).
     */
    Evaluation
    evaluate_at(const double    target,
                const bool      holding,
                StepState      &state,
                LoadStepResult &result);

    /**
     * Stiffness = tangent: the Newton correction at an iterate, the tangent
     * rebuilt there (tangent_correction), with its K^-1 dc; condensed, the
     * update of the condensed Jacobian (InterfaceCondensation).
     */
    Correction
    newton_correction(const Evaluation &e,
                      const StepState  &state,
                      const bool        displacement_control);

    /**
     * The initial-stiffness update of an iterate (Load path/Acceleration on
     * c and R): dc and its K^-1 dc (one solve per harmonic), condensed at
     * the write DoFs.
     */
    Correction
    initial_stiffness_correction(FixedPointAcceleration &acceleration,
                                 const StepState        &state,
                                 const Evaluation       &e) const;

    /** dc and its K^-1 dc (one solve per harmonic). */
    Correction
    correction_of(std::vector<Vector<double>> load) const;

    /** c <- c + alpha dc and v <- v + alpha K^-1 dc (condensed: its view). */
    void
    add_correction(const double      alpha,
                   const Correction &correction,
                   StepState        &state) const;

    /**
     * Solve one step to `target`: the held fraction (holding), else the
     * load factor (load control) or the controlled motion.
     */
    bool
    solve_step(const double    target,
               const bool      holding,
               StepState      &state,
               LoadStepResult &result);

    /**
     * The iteration of solve_step() at fixed contact multipliers: Newton
     * (Stiffness = tangent) or the accelerated initial-stiffness iteration
     * until the force test holds (true; `e` the converged evaluation,
     * `iterations` raised by the iterations taken) or the step must be cut.
     */
    bool
    iterate(const double    target,
            const bool      holding,
            StepState      &state,
            LoadStepResult &result,
            Evaluation     &e,
            unsigned int   &iterations);

    /**
     * Interfaces only, Maximum harmonic above the set's: harmonics n <=
     * Maximum harmonic, not solved, whose amplitude in the traction change
     * t - t0 of a converged state exceeds Harmonic tolerance times the
     * largest amplitude; each logged with its amplitude
     * (coupled_solver_growth.cc).
     */
    std::vector<Harmonic>
    harmonics_called_for(const InterfaceSnapshot &snapshot,
                         std::ostream            &log) const;

    /** Add harmonics to the set and extend the committed state by zeros. */
    void
    grow(const std::vector<Harmonic> &added);

    /** The log's first lines: the sources, the iteration and the loading. */
    void
    describe(std::ostream &log) const;

    /**
     * F_held,h: the held loads of harmonic h (held_stage_load: Rigid
     * foundation/Held ..., body force and tractions; zero without).
     */
    Vector<double>
    held_load(const unsigned int h) const;

    /** The coupled tangent's sparsity: the soil cells and interface pairs. */
    void
    make_tangent();

    /**
     * Stiffness = tangent: K_t,hg = delta_hg K_h - int Bbar_h^T
     * [theta integral of factor_h (D_e - D_ep) factor_g] Bbar_g
     * (coupled_tangent.h) at the strain samples given; factorized, with
     * K_t^-1 F.
     */
    void
    update_tangent(const std::vector<StrainVector> &strain,
                   const std::vector<LocalVector>  &relative,
                   const std::vector<LocalVector>  &interface_origin,
                   const bool displacement_control = false);

    /**
     * Displacement control: add alpha c c^T to K_t, c the controlled motion
     * as a functional of the controlled harmonic's master DoFs (m(u) =
     * c^T u), and in a swipe the same for w (kept by mu). The update du keeps
     * m(du) = 0, so alpha c c^T du = 0 and no update changes; but at a limit
     * load the collapse mechanism, which moves the foundation, is a null vector
     * of K_t, and K_t^-1 R and K_t^-1 F lose their digits there while K_t +
     * alpha c c^T stays regular (the bordered system of Riks-type control,
     * solved with one factorization).
     */
    void
    add_control_stiffening();

    /**
     * alpha c c^T on the master DoFs of the harmonic `wanted`, c_k =
     * component(motion of a unit master DoF k), alpha scaling it to the
     * masters' own stiffness (add_control_stiffening).
     */
    void
    stiffen_motion(const Harmonic                                   &wanted,
                   const std::function<double(const RigidMotion &)> &component);

    /**
     * The out-of-balance load correction of one tangent (Newton) step:
     * du = K_t^-1 (R + dlambda F), dlambda keeping the controlled motion
     * (displacement control; 0 under load control); returns
     * dc = K du - dlambda F, the change of the correction load that moves
     * the total displacement by du. In a swipe du = K_t^-1 (R + dlambda F +
     * dmu e_V), (dlambda, dmu) keeping the controlled motion and w
     * (swipe_multipliers with K_t^-1 F and K_t^-1 e_V), and dc = K du -
     * dlambda F - dmu e_V.
     */
    std::vector<Vector<double>>
    tangent_correction(const std::vector<Vector<double>> &residual,
                       const bool displacement_control) const;

    HarmonicSet         &set;
    const AllParameters &parameters;
    LoadPathParameters   settings;
    /**
     * Plastic soil or a swipe: the coupled tangent; otherwise condensed
     * (AllParameters::linearises_on_coupled_tangent).
     */
    const bool condensed;
    /** Newton (Stiffness = tangent) rather than initial stiffness. */
    const bool newton;
    /** The parameter section a step's one-line error names. */
    const std::string     entry;
    std::vector<Harmonic> harmonics;
    ThetaSampling         sampling;
    /** Every candidate harmonic n <= Maximum harmonic (growth only). */
    std::vector<Harmonic> candidates;
    ThetaSampling         spectrum;
    /**
     * The nonlinear interfaces' samples: those of the soil, but with
     * `contact` or a stiff coulomb law that can open (through the
     * multipliers) always 2 n_max + 1, one per value of the band-limited
     * gap (minimum_theta_samples(); more make the multipliers drift,
     * constrained_theta_samples()), while Theta samples sets the soil's.
     */
    ThetaSampling interface_sampling;
    /** The plastic soil's quadrature points and their laws. */
    NonlinearSoilPoints soil;
    StrainAmplitudes    held_strain;
    /** A swipe: the strain amplitudes of K^-1 e_V. */
    StrainAmplitudes swipe_strain;
    /** A swipe: the rigid motions of u_F and of u_V = K^-1 e_V. */
    RigidMotion pattern_rigid_motion, swipe_rigid_motion;
    /** A swipe: w where the held stage left it [m], the value held. */
    double swipe_settlement = 0.;
    /** The step solved is a swipe's (not in its held stage): mu keeps w. */
    bool swiping = false;
    /** The trial is the retry after the last cut (retry_persistently). */
    bool persistent = false;
    /** Strain amplitudes of the load pattern. */
    StrainAmplitudes pattern_strain;
    /** Controlled motions of u_F and u_held (0: no held loads). */
    double pattern_motion = 0., held_motion = 0.;
    /** Stiffness = tangent: the coupled tangent and K_t^-1 F. */
    std::unique_ptr<CoupledTangent> tangent;
    std::vector<Vector<double>>     tangent_pattern;
    /**
     * Nonlinear interfaces (null: none): their points, and the relative
     * displacements of the loads' elastic solutions.
     */
    std::unique_ptr<NonlinearInterfacePoints> interface;
    InterfaceLoadCases                        interface_cases;
    /** Interfaces only: the condensed linearisation (null otherwise). */
    std::unique_ptr<InterfaceCondensation>      condensation;
    std::function<void(const LoadStepResult &)> step_observer;
  };
} // namespace FourierSSI

#endif
