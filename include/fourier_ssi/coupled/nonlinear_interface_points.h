/**
 * The Gauss points of the nonlinear (coulomb) interfaces of a set of
 * harmonics and what a coupled iteration does there
 * (doc/nonlinear-interfaces.md section 5): the relative displacement of
 * fields given per harmonic, summed at the theta samples; the return
 * mapping from a committed plastic state; the out-of-balance load
 *   G_h = int int B_h^T D d_p r ds dtheta
 * of a plastic relative displacement d_p (theta by the trapezoidal rule,
 * s by Gauss p + 1 points through the element's own shape functions); and
 * the tangent's interface part
 *   -int B_h^T [int factor_h (D - D_t) factor_g dtheta] B_g r ds
 * (D_t the tangent of the return mapping). The coupled load path
 * (coupled_solver.h) iterates on it, condensed or on the coupled tangent.
 */
#ifndef fourier_ssi_nonlinear_interface_points_h
#define fourier_ssi_nonlinear_interface_points_h

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/coupled/coupled_tangent.h>
#include <fourier_ssi/coupled/load_pattern.h>
#include <fourier_ssi/fourier/theta_sampling.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/input/parameters.h>
#include <fourier_ssi/interfaces/interface_law.h>
#include <fourier_ssi/interfaces/interface_pairing.h>
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** One Gauss point of a nonlinear interface pair. */
  struct InterfacePoint
  {
    /** Index of the pair (InterfaceIntegrator::get_pairs()). */
    unsigned int pair = 0;
    /** w_q l r(xi_q): area per radian of theta [m^2]. */
    double              area_per_radian = 0.;
    std::vector<double> shape;
    Point<2>            position;
    /**
     * The part of the face (start, end) the point's weight stands for: the
     * face cut at the cumulative weights of the rule, which enclose the
     * point (interface_state_surface.h draws it).
     */
    std::array<Point<2>, 2> share;
    /** t0 of the Initial stress, local (s, n, theta) [kPa]. */
    LocalVector initial_traction = {{0., 0., 0.}};
    /** Index into the laws. */
    unsigned int law = 0;
  };

  /**
   * The interface at every (point, theta sample) of one converged step,
   * index i * N + j for point i and angle theta_j.
   */
  struct InterfaceSnapshot
  {
    /** Relative displacement d = u_B - u_A, local (s, n, theta) [m]. */
    std::vector<LocalVector> relative;
    /** Traction t (total, initial stress included), (s, n, theta) [kPa]. */
    std::vector<LocalVector>  traction;
    std::vector<ContactState> state;
  };

  /** Counts of (point, theta) samples sticking, slipping, open. */
  using ContactCounts = std::array<unsigned int, 3>;

  /**
   * What a coupled state keeps of the interfaces at every (point, theta
   * sample), index i * N + j (NonlinearInterfacePoints::at_rest, commit).
   */
  struct InterfaceState
  {
    /** d_p: the plastic relative displacement (slip and gap) [m]. */
    std::vector<LocalVector> plastic;
    /**
     * What the return mapping starts from: the committed d_p, at augmented
     * samples shifted by the multipliers (update_multipliers) [m].
     */
    std::vector<LocalVector> origin;
    /** Committed slip p_c of the augmented samples (zero elsewhere) [m]. */
    std::vector<LocalVector> slip;
  };

  /**
   * The relative displacement at every sample of each elastic solution an
   * iterate combines (LoadPattern): u_F of the load pattern, u_held of the
   * held loads, u_V = K^-1 e_V of a swipe; empty where the scene has no
   * such load (NonlinearInterfacePoints::load_cases).
   */
  struct InterfaceLoadCases
  {
    std::vector<LocalVector> pattern, held, swipe;
  };

  class NonlinearInterfacePoints
  {
  public:
    /**
     * The Gauss points of every pair whose boundary id has a coulomb law;
     * one line if there is none. `set` may grow later (harmonics added):
     * every call reads its current harmonics. `augment_stiff_laws`: a
     * coulomb law stiffer than the springs in K (Newton's cap) is solved by
     * the augmented Lagrangian on K's springs (update_multipliers);
     * otherwise Newton iterates on its own springs through the return
     * mapping (iteration_plastic).
     */
    NonlinearInterfacePoints(const HarmonicSet   &set,
                             const AllParameters &parameters,
                             const bool           augment_stiff_laws = false);

    /**
     * The one rule for whether a pair's law is solved by the augmented
     * Lagrangian: `contact`, or (augment_stiff_laws) a coulomb law whose own
     * springs `own` are stiffer than those assembled into K, `in_K`
     * (Newton's cap).
     */
    static bool
    augments(const InterfaceLaw       &law,
             const InterfaceStiffness &own,
             const InterfaceStiffness &in_K,
             const bool                augment_stiff_laws);

    const std::vector<InterfacePoint> &
    get_points() const
    {
      return points;
    }

    unsigned int
    size() const
    {
      return points.size();
    }

    /** The pair of point i (in harmonic 0's numbering). */
    const InterfacePair &
    pair_of(const InterfacePoint &point) const;

    /** Some coulomb law has c = 0 and there is no Initial stress. */
    bool
    without_strength() const
    {
      return strengthless;
    }

    /**
     * Relative displacement d = u_B - u_A, local (s, n, theta), at every
     * (point i, sample j), index i * N + j, of fields given per harmonic:
     * the amplitudes of the harmonics this rank owns, summed over the
     * ranks (a collective), then sampled in theta.
     */
    std::vector<LocalVector>
    relative_displacements(const std::vector<Vector<double>> &fields,
                           const ThetaSampling               &sampling) const;

    /**
     * relative_displacements() of the harmonics this rank owns only, not
     * summed over the ranks: local (not a collective), exact for fields
     * that are zero outside this rank's harmonics (a column of the Newton
     * Jacobian, interface_condensation.cc).
     */
    std::vector<LocalVector>
    owned_relative_displacements(const std::vector<Vector<double>> &fields,
                                 const ThetaSampling &sampling) const;

    /**
     * The relative displacements of the loads' elastic solutions (those
     * `loads` has) at the angles of `sampling` (a collective).
     */
    InterfaceLoadCases
    load_cases(const LoadPattern &loads, const ThetaSampling &sampling) const;

    /**
     * The relative displacement at every sample of an iterate u = v +
     * lambda u_F + rho u_held + mu u_V (the coupled solvers' state): that
     * of the fields v (K^-1 c, or the part of it an iteration keeps), plus
     * the loads' part summed first from `cases` (a collective).
     */
    std::vector<LocalVector>
    iterate_relative(const std::vector<Vector<double>> &correction,
                     const ThetaSampling               &sampling,
                     const InterfaceLoadCases          &cases,
                     const double                       load_factor,
                     const double                       held_fraction,
                     const double                       swipe_force = 0.) const;

    /**
     * The return mapping at every sample from the committed plastic
     * relative displacements; fills plastic, traction (total, t0
     * included) and state; returns the counts.
     */
    ContactCounts
    return_map(const std::vector<LocalVector> &relative,
               const std::vector<LocalVector> &committed_plastic,
               std::vector<LocalVector>       &plastic,
               std::vector<LocalVector>       &traction,
               std::vector<ContactState>      &state) const;

    /**
     * At every sample, dd_p/dd = I - D_K^-1 D_t (row-major; D_K the
     * springs in K, iteration_plastic()) of the return
     * from committed_plastic: how the plastic part follows a change of the
     * relative displacement (0 where it sticks, I where it is open), D_t
     * the consistent tangent (interface_law.h). load_of() of the plastic
     * change dd_p is then the exact change of G (Newton).
     */
    std::vector<LocalTangent>
    plastic_tangents(const std::vector<LocalVector> &relative,
                     const std::vector<LocalVector> &committed_plastic) const;

    /**
     * d_p of the springs assembled into K at every sample,
     * d - D_K^-1 (t - t0): load_of() of it is the correction load c =
     * int B^T (D_K d - (t - t0)) that makes K u = lambda F + c carry the
     * law's traction t. Where the return mapping has K's springs (no cap;
     * an augmented law) that is its plastic part, taken as it is (the
     * difference d - (d - d_p) would add round-off of d to it, which
     * slowed the fixed-point iteration 2.3 times at kappa = 1e4); under
     * Newton's cap without augmentation it holds what the law's stiffer
     * response adds.
     */
    std::vector<LocalVector>
    iteration_plastic(const std::vector<LocalVector> &relative,
                      const std::vector<LocalVector> &traction,
                      const std::vector<LocalVector> &plastic) const;

    /**
     * One line per nonlinear interface with the rule that ties its springs,
     * the theta samples and the harmonics (doc/nonlinear-interfaces.md
     * section 5e): kn, ks against G / l, the estimated compliance error
     * against rigid contact C G / (kn l) (an upper bound of C G / (kn r0)
     * for a foundation r0 >= l), and the samples 2 n_max + 1 that carry
     * the band-limited gap; for contact, the augmentation.
     */
    void
    describe(std::ostream      &log,
             const unsigned int n_samples,
             const unsigned int highest_harmonic) const;

    /**
     * Some nonlinear interface is solved by the augmented Lagrangian:
     * `contact`, or a coulomb law stiffer than the springs in K (Newton's
     * cap, interface_iteration_stiffness).
     */
    bool
    any_augmented() const;

    /**
     * Uzawa update of the multipliers (doc/nonlinear-interfaces.md section
     * 5d): at every augmented sample the return starts from the origin
     * p_c - a (lambda - t0) (p_c the committed slip, r the springs in K,
     * k the law's own, a = 1/r - 1/k, 1/r for contact), so its trial
     * traction is lambda + r (d - p_c) - (r/k) (lambda - t0); here lambda
     * <- t. Where it stops, t - t0 = k (d - p): exact contact for k
     * infinite, the stiff coulomb law's own springs otherwise, while every
     * Newton iteration sees only the moderate r. The origin moves by a
     * (lambda - t): for contact the penetration and elastic slip the
     * augmentation still allowed. Returns that change per sample [m] (zero
     * at the samples of other laws).
     */
    std::vector<LocalVector>
    update_multipliers(const std::vector<LocalVector> &traction,
                       const std::vector<LocalVector> &slip,
                       std::vector<LocalVector>       &origin) const;

    /** Uzawa updates of the multipliers before a step is cut. */
    static constexpr unsigned int maximum_multiplier_updates = 50;

    /** What an update of the multipliers left. */
    enum class MultiplierUpdate
    {
      /** the change no longer acts on the displacements (its nodal force) */
      converged,
      /** iterate again at the moved multipliers */
      again,
      /** maximum_multiplier_updates reached: cut the step */
      too_many
    };

    /**
     * The update_multipliers() that follows the `update`-th (from 0)
     * converged iteration of a step (the augmented Lagrangian of both
     * coupled solvers), and its test. Converged when the nodal force of the
     * change, int B^T r (change of the origin) at the samples, is within
     * `allowed_force` (Load path/Tolerance times the force scale of the
     * converged iteration): the next iteration would then pass the force
     * test as it stands, so further updates cannot move the displacements.
     * A test on the change at each sample instead asks for what the
     * samples cannot give where they outnumber the displacements they
     * constrain (3 Gauss points of a quadratic face against its 2 new
     * nodes). There an update moves a multiplier by the same amount every
     * time, without force, and never settles (the free-head pile with
     * contact, phi = 20: a sample next to the bonded tip, 1.3e-7 m at
     * every one of 50 updates; doc/nonlinear-interfaces.md section 5d).
     */
    MultiplierUpdate
    update_and_test_multipliers(const std::vector<LocalVector> &traction,
                                const std::vector<LocalVector> &slip,
                                const ThetaSampling            &sampling,
                                std::vector<LocalVector>       &origin,
                                const double                    allowed_force,
                                const unsigned int              update) const;

    /** The state before the first step: every d_p, origin and p_c zero. */
    InterfaceState
    at_rest(const ThetaSampling &sampling) const;

    /**
     * A converged step becomes `state`: its d_p (`plastic`, moved in); at
     * the augmented samples p_c <- (d_s, 0, d_theta) for contact (no
     * elastic slip), d - (t - t0) / k for a stiff coulomb law (its own
     * elastic part), and d_p from lambda = t; the next step's return starts
     * from there.
     */
    void
    commit(const std::vector<LocalVector> &relative,
           const std::vector<LocalVector> &traction,
           std::vector<LocalVector>      &&plastic,
           InterfaceState                 &state) const;

    /**
     * The largest f(t) = tau + t_n tan(phi) - c over the samples given
     * (index i * N + j) [kPa]: <= 0 where every traction is admissible.
     */
    double
    largest_yield_value(const std::vector<LocalVector> &traction) const;

    /**
     * The largest penetration -d_n over the contact samples, over the
     * largest |d| of any sample (0 without contact): what the samples that
     * outnumber the displacements keep (update_and_test_multipliers).
     */
    double
    largest_penetration(const std::vector<LocalVector> &relative) const;

    /**
     * "; N contact multiplier updates, penetration P of the largest
     * relative displacement" for a step's log line, "; N multiplier
     * updates" where only stiff coulomb laws are augmented (nothing
     * without updates).
     */
    void
    write_multiplier_updates(std::ostream                   &log,
                             const unsigned int              updates,
                             const std::vector<LocalVector> &relative) const;

    /**
     * G_h = int int B_h^T D d_p of the plastic samples, every harmonic,
     * with the homogeneous constraints of each harmonic applied
     * (distribute_local_to_global), or at the DoFs as they are
     * (`condensed` false: a nodal force, as HarmonicProblem::nodal_forces
     * gives them). Points without plastic part cost nothing.
     */
    std::vector<Vector<double>>
    load_of(const std::vector<LocalVector> &plastic,
            const ThetaSampling            &sampling,
            const bool                      condensed = true) const;

    /**
     * The resultant of the traction change t - t0 on the rigid foundation's
     * material (Rigid foundation/Tie = material): force (x, y, z) [kN] and
     * moment about the origin (x, y, z) [kN m], the samples' theta weights
     * integrating it around the axis; zeros without such a foundation.
     */
    std::array<double, 6>
    foundation_resultant(const std::vector<LocalVector>  &traction,
                         const ThetaSampling             &sampling,
                         const RigidFoundationParameters &foundation) const;

    /**
     * d - D_K^-1 (t - t0) at every sample of a converged state, D_K the
     * springs in K: K_i d minus load_of() of it is the nodal force of the
     * tractions t - t0 the interface carries, whatever the law (for
     * contact the committed origin is not that plastic part).
     */
    std::vector<LocalVector>
    spring_plastic(const InterfaceSnapshot &state) const;

    /**
     * CSV of the interface state at every (point, theta sample) of every
     * converged step (snapshots[s] of step s + 1): position, angle,
     * stick/slip/open, traction and relative displacement with their units
     * in the header.
     */
    void
    write_state_csv(const std::string                    &filename,
                    const std::vector<InterfaceSnapshot> &snapshots,
                    const ThetaSampling                  &sampling) const;

    /**
     * The DoFs [pair][h] of every pair with a coulomb law: the couplings
     * between harmonics the tangent's interface part adds.
     */
    std::vector<std::vector<std::vector<types::global_dof_index>>>
    pair_dofs() const;

    /**
     * Adds the interface part of the coupled tangent at the relative
     * displacements given (return mapping from committed_plastic) to every
     * block (h, g) of `tangent`; D - D_t with D_t the closed-form
     * consistent tangent of the return mapping (interface_law.h).
     * Returns the number of samples that slip or open.
     */
    unsigned int
    add_softening(const std::vector<LocalVector> &relative,
                  const std::vector<LocalVector> &committed_plastic,
                  const ThetaSampling            &sampling,
                  CoupledTangent                 &tangent) const;

  private:
    /**
     * The amplitudes of (d_s, d_n, d_theta) of the harmonics this rank
     * owns at every point, index (i * 3 + c) * H + h (zero for the others).
     */
    std::vector<double>
    owned_amplitudes(const std::vector<Vector<double>> &fields) const;

    /** Relative displacements at every (point, theta) from amplitudes. */
    std::vector<LocalVector>
    sampled(const std::vector<double> &amplitudes,
            const ThetaSampling       &sampling) const;

    /**
     * The return mapping at every (point i, theta sample) k = i N + j from
     * its committed plastic relative displacement, handed to use(k, i, r).
     */
    void
    for_each_return(
      const std::vector<LocalVector>                         &relative,
      const std::vector<LocalVector>                         &committed_plastic,
      const std::function<void(const unsigned int,
                               const unsigned int,
                               const ReturnMappingResult &)> &use) const;
    /** D - D_t at one sample (row-major 3 x 3); false where it sticks. */
    bool
    softening_at(const InterfacePoint  &point,
                 const LocalVector     &relative,
                 const LocalVector     &committed_plastic,
                 std::array<double, 9> &softening) const;

    /**
     * B of harmonic h's pair: row a (s, n, theta) of the relative
     * displacement at point, column i of pair.dof_indices.
     */
    void
    relative_displacement_operator(const InterfacePoint &point,
                                   const InterfacePair  &pair,
                                   FullMatrix<double>   &B) const;

    const HarmonicSet                &set;
    std::vector<MohrCoulombInterface> laws;
    /** (ks, kn, ks) assembled into K, per law (one law per pair) [kPa/m]. */
    std::vector<LocalVector> stiffness;
    /** Per law: contact (augmented Lagrangian) rather than coulomb. */
    std::vector<bool> contact;
    /**
     * Per law: 1/r - 1/k of each spring of an augmented law (r in K and
     * in the return mapping, k the law's own, infinite for contact), zero
     * elsewhere (augmented_flexibility in the source).
     */
    std::vector<LocalVector> flexibility;

    /**
     * The law's multipliers move between converged iterations (augmented
     * Lagrangian): contact, and a coulomb law stiffer than K's springs.
     */
    bool
    augmented(const unsigned int law) const
    {
      return flexibility[law] != LocalVector{{0., 0., 0.}};
    }
    /** Per law: its springs (ks, kn, ks) and G / l of its pair. */
    std::vector<LocalVector>    law_springs;
    std::vector<double>         soil_scale;
    std::vector<InterfacePoint> points;
    /** The pairs with a coulomb law (indices into get_pairs()). */
    std::vector<unsigned int> nonlinear_pairs;
    bool                      strengthless = false;
  };
} // namespace FourierSSI

#endif
