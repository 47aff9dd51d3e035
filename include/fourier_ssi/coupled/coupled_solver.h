/**
 * The coupled load path of every nonlinear scene (doc/driver.md): plastic
 * soil (Tresca, Mohr-Coulomb; soil_law.h, doc/soil-plasticity.md section 3)
 * and nonlinear interfaces (coulomb, contact; doc/nonlinear-interfaces.md
 * section 5) on a set of Fourier harmonics coupled through theta.
 *
 * Every harmonic keeps its elastic matrix K_h and factorization (HarmonicSet).
 * The discrete equilibrium of harmonic h is
 *   K_h u_h = lambda F_h + c_h,
 * c the correction load that balances the out-of-balance load G of the
 * nonlinear sources (R = G - c = 0). This class is the wiring of the
 * objects that solve it, each with one job:
 *   - LoadPath: the stages, step sizes, cuts and the secant predictor;
 *   - LoadPathStates: the committed, previous and trial states and the
 *     records of the converged steps;
 *   - NonlinearSources: the soil points and interface points, evaluating
 *     G and R at an iterate;
 *   - LoadControl: lambda, a swipe's mu and the held reactions;
 *   - Linearisation: how c moves (TangentLinearisation with plastic soil
 *     or a swipe, CondensedInterfaces with interfaces only);
 *   - StepIteration: one load step, top to bottom.
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
#include <fourier_ssi/coupled/linearisation.h>
#include <fourier_ssi/coupled/load_control.h>
#include <fourier_ssi/coupled/load_path.h>
#include <fourier_ssi/coupled/load_path_states.h>
#include <fourier_ssi/coupled/load_step_result.h>
#include <fourier_ssi/coupled/nonlinear_sources.h>
#include <fourier_ssi/coupled/step_iteration.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/input/parameters.h>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  class CoupledSolver : private LoadPath::Iteration
  {
  public:
    /**
     * `set` must be assembled and factorized; its harmonics' matrices hold
     * the elastic interface stiffness kn, ks of every interface. With
     * `Load path/Maximum harmonic` above the highest harmonic of the set,
     * harmonics the soil's stress or the interface tractions call for are
     * added to it.
     */
    CoupledSolver(HarmonicSet &set, const AllParameters &parameters);

    ~CoupledSolver() override;

    /** All load steps; throws one line if a step does not converge. */
    void
    run(std::ostream &log);

    /**
     * Total displacement amplitudes of harmonic i (last converged state;
     * a collective under MPI, LoadPathStates::solution).
     */
    Vector<double>
    solution(const unsigned int i) const
    {
      return states.solution(i);
    }

    /** LoadPathStates::last_step_increment (a collective under MPI). */
    Vector<double>
    last_step_increment(const unsigned int i) const
    {
      return states.last_step_increment(i);
    }

    /** The applied rigid-foundation loads (LoadPathStates::applied_loads). */
    std::array<double, 6>
    applied_loads(const double load_factor,
                  const double held_fraction = 0.) const
    {
      return states.applied_loads(load_factor, held_fraction);
    }

    /** The record of every converged step, in order. */
    const std::vector<LoadStepResult> &
    get_steps() const
    {
      return states.get_steps();
    }

    /** load-displacement.csv of the converged steps. */
    void
    write_csv(const std::string &filename) const
    {
      states.write_csv(filename);
    }

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
    out_of_balance_load(const std::vector<Vector<double>> &fields) const;

    /**
     * K_t(u) x: the coupled tangent (Stiffness = tangent) built at the
     * fields u and applied to x; K u - G(u) is the internal force, so
     * K_t x = K x - dG/du x (checked against differences of
     * out_of_balance_load in tests/coupled/soil_coupled_tangent.cc).
     * Scenes on the coupled tangent only.
     */
    std::vector<Vector<double>>
    tangent_product(const std::vector<Vector<double>> &fields,
                    const std::vector<Vector<double>> &x);

    unsigned int
    n_soil_points() const
    {
      return sources.soil_points().size();
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
     * solution(), soil_nodal_force(), committed_soil_samples()), before
     * the step's log line; several observers are called in the order they
     * were added (soil-reaction curves, the plastic field).
     */
    void
    add_step_observer(std::function<void(const LoadStepResult &)> observer)
    {
      step_observers.push_back(std::move(observer));
    }

    /** The soil's quadrature points (positions, cells, theta samples). */
    const NonlinearSoilPoints &
    soil_points() const
    {
      return sources.soil_points();
    }

    /**
     * The soil's samples [point * N + j] of the last converged step at the
     * points this rank owns (NonlinearSoilPoints::samples_of): stress,
     * plastic strain and its change over the step, f and whether the
     * step's return mapping yielded there.
     */
    std::vector<SoilSample>
    committed_soil_samples() const;

    /** True if the scene has nonlinear (coulomb, contact) interfaces. */
    bool
    has_nonlinear_interfaces() const
    {
      return sources.interface_points() != nullptr;
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

    /**
     * The interface state of converged step `step` (from 1) as a surface
     * revolved about the axis (interface_state_surface.h); returns its
     * stick / slip / open counts.
     */
    ContactCounts
    write_interface_state_surface(const unsigned int step,
                                  const std::string &filename) const;

  private:
    /** LoadPath::Iteration (load_path.h), on the states and the step. */
    void
    start_trial(const double ratio) override;
    bool
    solve_trial(const double target, const bool holding) override;
    RigidMotion
    trial_motion() const override;
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
    RigidMotion
    committed_motion() const override;
    double
    committed_load_factor() const override;
    unsigned int
    n_converged_steps() const override;
    bool
    holds_loads() const override;
    void
    write_held_loads(std::ostream &log) const override;

    /**
     * F, F_held (Rigid foundation/Held ...) and in a swipe e_V, their
     * elastic solutions (LoadPattern) and what the sources and the load
     * control read of them.
     */
    void
    solve_loads();

    /** Add harmonics to the set and extend the committed state by zeros. */
    void
    grow(const std::vector<Harmonic> &added);

    /** The log's first lines: the sources, the iteration and the loading. */
    void
    describe(std::ostream &log) const;

    HarmonicSet         &set;
    const AllParameters &parameters;
    /** The parameter section a step's one-line error names. */
    const std::string entry;
    LoadPathStates    states;
    NonlinearSources  sources;
    LoadControl       control;
    /** Plastic soil or a swipe: the coupled tangent; otherwise condensed. */
    std::unique_ptr<Linearisation> linearisation;
    StepIteration                  step_iteration;
    /** The trial is the retry after the last cut (retry_persistently). */
    bool                                                     persistent = false;
    std::vector<std::function<void(const LoadStepResult &)>> step_observers;
  };
} // namespace FourierSSI

#endif
