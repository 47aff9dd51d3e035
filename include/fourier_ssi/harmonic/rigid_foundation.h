/**
 * A rigid foundation as exact rigid-body kinematics (no "very stiff material"
 * trick): every tied DoF is constrained to the motion of two (n = 1) or one
 * (n = 0) master DoFs of one foundation node A = (r_A, z_A), r_A > 0.
 *
 * Rigid motions per harmonic (doc/theory.md, rigid-body modes), with the
 * reference point on the axis at elevation z_ref, s = +1 (symmetric) or -1:
 *   n = 1: U = U_h + Theta (z - z_ref),  W = -s U,  V = -Theta r
 *          (U_h: horizontal translation, Theta: rotation; symmetric family:
 *          translation along x, rotation about +y: M_y = M)
 *   n = 0, symmetric:     U = 0, V = W_v            (vertical translation)
 *   n = 0, antisymmetric: W = Phi r                 (torsion about z)
 *   n >= 2: a rigid body does not move (U = V = W = 0).
 * Loads (H, M), V, T act on the masters through their virtual work:
 * H dU_h + M dTheta with U_h = U_A + V_A (z_A - z_ref) / r_A,
 * Theta = -V_A / r_A, i.e. nodal forces H on U_A and (H (z_A - z_ref) - M)/r_A
 * on V_A. The harmonic system's nodal forces are 3D virtual-work coefficients
 * (theta weights included), so these are the physical 3D loads.
 */
#ifndef fourier_ssi_rigid_foundation_h
#define fourier_ssi_rigid_foundation_h

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/harmonic/rigid_motion.h>
#include <fourier_ssi/input/harmonic.h>
#include <fourier_ssi/input/rigid_foundation_parameters.h>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  class RigidFoundation
  {
  public:
    RigidFoundation(const RigidFoundationParameters &parameters,
                    const Harmonic                  &harmonic);

    /**
     * Constrain the tied DoFs to the master DoFs. Call before the axis
     * conditions (a rigid motion satisfies them, so the axis DoFs of the
     * foundation are simply tied). DoFs already constrained (hanging nodes,
     * Dirichlet) are left alone. Throws if nothing is tied.
     */
    void
    add_constraints(const DoFHandler<2>       &dof_handler,
                    AffineConstraints<double> &constraints);

    /** Add the foundation loads of this harmonic to the global load vector. */
    void
    add_loads(Vector<double> &rhs) const;

    /**
     * Add the held loads of this harmonic (Held vertical force, ...: the
     * part of a combined loading path kept constant, plastic soil).
     */
    void
    add_held_loads(Vector<double> &rhs) const;

    RigidMotion
    motion(const Vector<double> &solution) const;

    /**
     * Hold the motions of Held motions that this harmonic carries at zero:
     * a master DoF with weight in that motion is constrained to the others (U_A
     * = -V_A (z_A - z_ref) / r_A holds U_h; V_A = 0 holds Theta); the w of a
     * swipe is left free (swipes(): held by the solver, reported here). Call
     * after every other constraint and before close(): the constraints without
     * the hold are kept for the reactions.
     */
    void
    add_held_motion_constraints(AffineConstraints<double> &constraints);

    /**
     * True if this harmonic holds some motion or carries the Motion
     * direction: held_reactions() has loads to report.
     */
    bool
    holds_motion() const
    {
      return !held_here.empty() || direction_here;
    }

    /**
     * The load that holds each held motion of this harmonic [kN or kN m;
     * M about the reference point], a load applied to the foundation: the
     * virtual work phi . r of the nodal forces r = K u - f of the body
     * (unconstrained, one entry per DoF) on the unit held motion phi (the
     * other rigid motions of the harmonic zero), phi = C e through the
     * constraints without the hold. The applied foundation loads do no
     * work on a held motion (a load on it is refused), so phi . r is all
     * of it. In a direction probe also the H and M on the foundation, the
     * work of r on the unit u and the unit rotation: the applied loads plus
     * the load that keeps the direction.
     */
    std::vector<std::pair<FoundationMotion, double>>
    held_reactions(const Vector<double> &nodal_forces) const;

    /**
     * The load vector of a unit horizontal force (load_case 0) or a unit
     * moment (load_case 1); n = 1 only.
     */
    Vector<double>
    unit_load(const unsigned int load_case, const unsigned int n_dofs) const;

    /**
     * The load vector of a unit vertical force (n = 0 symmetric) or a unit
     * torque (n = 0 antisymmetric); n = 0 only.
     */
    Vector<double>
    unit_axial_load(const unsigned int n_dofs) const;

    /**
     * The motion along the unit axial load: W_v under a unit V (n = 0
     * symmetric), Phi under a unit T (n = 0 antisymmetric).
     */
    double
    axial_motion(const RigidMotion &m) const;

    /**
     * Influence and stiffness coefficients from the motions (U_h, Theta) under
     * unit H and under unit M.
     */
    FoundationCoefficients
    coefficients(const RigidMotion &under_unit_H,
                 const RigidMotion &under_unit_M) const;

    /**
     * Throw a one-line "singular" error if the foundation moves more than
     * 1e6 times the largest displacement of the free (untied, unconstrained)
     * DoFs: nothing resists that motion (e.g. a smooth interface under a
     * horizontal load on a surface footing), and the direct solver returned
     * an arbitrary multiple of the free rigid-body mode.
     */
    void
    check_supported(const Vector<double>            &solution,
                    const AffineConstraints<double> &constraints) const;

    unsigned int
    n_tied_dofs() const
    {
      return n_tied;
    }

    /** The master node's DoFs (the rigid motion's unknowns). */
    std::set<types::global_dof_index>
    master_dofs() const
    {
      return {master_U, master_V, master_W};
    }

  private:
    /** Amplitudes (U_A, V_A, W_A) of the master node, or forces on them. */
    using MasterValues = std::array<double, 3>;
    /** Tied nodes: position (r, z) -> DoF of each component. */
    using TiedNodes = std::map<std::pair<double, double>,
                               std::array<types::global_dof_index, 3>>;

    /** Steps of add_constraints(). */
    TiedNodes
    tied_nodes(const DoFHandler<2> &dof_handler) const;
    void
    choose_master(const TiedNodes                 &nodes,
                  const AffineConstraints<double> &constraints);
    void
    tie_to_master(const TiedNodes           &nodes,
                  AffineConstraints<double> &constraints);
    void
    fix_unmoved_masters(AffineConstraints<double> &constraints);
    /** Constrain a free master DoF so that sum_k g_k m_k = 0 (`what` names it).
     */
    void
    hold_combination(const MasterValues        &g,
                     const std::string         &what,
                     AffineConstraints<double> &constraints);
    /** True if this harmonic carries the Motion direction (n = 1 symmetric). */
    bool
    carries_direction() const;

    /**
     * The rigid-body kinematics of this harmonic (the table above), the one
     * place it is written: the amplitudes (U, V, W) at x of the rigid body
     * whose master node moves by `master`. The constraint weights, the
     * motion read back and the loads' nodal forces all follow from it.
     */
    std::array<double, 3>
    displacement_at(const Point<2> &x, const MasterValues &master) const;

    /** The rigid motion (U_h, Theta, W_v, Phi) for the master amplitudes. */
    RigidMotion
    motion_of(const MasterValues &master) const;

    /**
     * Nodal forces on the master DoFs that do the virtual work of the
     * resultants H, M, V, T on every rigid motion.
     */
    MasterValues
    master_forces(const double horizontal_force,
                  const double moment,
                  const double vertical_force,
                  const double torque) const;

    /** rhs(master DoF k) += forces[k]. */
    void
    add_master_forces(Vector<double> &rhs, const MasterValues &forces) const;

    /** rhs(dof) += force, moved onto the masters of a held master. */
    void
    add_force(Vector<double>               &rhs,
              const types::global_dof_index dof,
              const double                  force) const;

    /** The value of a held motion's component in a rigid motion. */
    static double
    component(const RigidMotion &m, const FoundationMotion motion);

    /**
     * Master amplitudes of the unit rigid motion along `motion`: that
     * motion 1, the other motions of this harmonic 0.
     */
    MasterValues
    unit_motion(const FoundationMotion motion) const;

    const RigidFoundationParameters &parameters;
    const Harmonic                   harmonic;
    /** The held motions that this harmonic carries. */
    std::vector<FoundationMotion> held_here;
    /** This harmonic carries the Motion direction's constraint. */
    bool direction_here = false;
    /** The constraint of each held master DoF: (master, weight) entries. */
    std::map<types::global_dof_index,
             std::vector<std::pair<types::global_dof_index, double>>>
      held_lines;
    /** The closed constraints before the hold: a rigid motion's DoFs. */
    AffineConstraints<double> constraints_without_hold;
    Point<2>                  master_position;
    types::global_dof_index   master_U = numbers::invalid_dof_index;
    types::global_dof_index   master_V = numbers::invalid_dof_index;
    types::global_dof_index   master_W = numbers::invalid_dof_index;
    unsigned int              n_tied   = 0;
  };
} // namespace FourierSSI

#endif
