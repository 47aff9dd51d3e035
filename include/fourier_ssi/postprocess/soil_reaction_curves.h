/**
 * Soil-reaction curves of a pile as the PISA design method uses them
 * (Byrne et al. 2020, Burd et al. 2020): at chosen depths the lateral
 * reaction p [kN/m] against the pile's displacement v there, the
 * distributed moment m [kN m/m] against the rotation psi, and the base
 * shear H_B and moment M_B against v and psi at the base; one point of
 * each curve per converged load step (doc/soil-reaction-curves.md).
 *
 * The reactions come from the soil's nodal forces on the pile's nodes
 * (CoupledSolver::soil_nodal_force, n = 1 symmetric: 3D virtual-work
 * coefficients). For a unit translation and rotation of the rigid pile
 * they give, node by node,
 *   P_i = f_U,i - f_W,i              (the work on u_x = 1),
 *   Q_i = -f_V,i r_i                 (the work on a rotation about y
 *                                     through the node's level, u_z = -x),
 * and p(z), m(z) are the fields of the shaft line's own finite element
 * (the trace of the soil's FE_Q) whose consistent nodal loads are P, Q:
 * M_line p = P with the line's mass matrix. The trace reproduces 1 and z,
 * so int p dz = sum P_i and int p z dz = sum P_i z_i exactly: the shaft
 * and base reactions balance the applied H and M to the iteration's
 * tolerance (what the test checks), unlike tractions read from the stress
 * at the quadrature points. The theta integrals of the stress amplitudes
 * behind P and Q are p = -pi R (S_rr - S_rtheta), m = pi R^2 S_rz
 * (doc/soil-reaction-curves.md section 2, doc/derivations/
 * soil_reaction_integrals.py).
 *
 * Signs: v and H along +x, psi = the rotation about +y (the rigid motion's
 * Theta, the head moving along +x relative to the toe); p, m, H_B, M_B are
 * the soil's resistance, positive when it opposes positive v and psi.
 *
 * A hollow pile (Output/Soil reaction pile names a tube's wall, r_i <= r
 * <= R): the shaft line collects the nodes of both faces, so p and m are
 * the net reactions of the soil outside and of the plug inside; the base
 * is the soil under the annular tip (the plug's base is not the pile's).
 * The same rigid-mode works P, Q hold for any body, so the balance holds
 * for a flexible pile too (its internal forces do no work on a rigid
 * mode). A flexible pile (a material other than the tied one) has v and
 * psi of its own cross-section (section_motion, doc/soil-reaction-
 * curves.md section 8).
 */
#ifndef fourier_ssi_soil_reaction_curves_h
#define fourier_ssi_soil_reaction_curves_h

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/harmonic/rigid_motion.h>
#include <fourier_ssi/input/parameters.h>
#include <fourier_ssi/postprocess/results_table.h>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  class SoilReactionCurves
  {
  public:
    /**
     * The pile (Output/Soil reaction pile, by default the tied material of
     * Rigid foundation) and its shaft line found in the mesh of `dofs` (the
     * n = 1 symmetric harmonic's). Throws one line naming the entry if the
     * scene is not one this can read yet (a boundary tie, a pile that is
     * not one rectangle in (r, z), soil without a plastic law or above the
     * pile touching it, soil touching the tied material of a flexible
     * pile, a depth outside the shaft).
     */
    SoilReactionCurves(const DoFHandler<2> &dofs,
                       const AllParameters &parameters);

    /**
     * The soil cells that touch the pile beside its shaft, the cell
     * diagonal to the toe's corner included (by centre).
     */
    bool
    beside_shaft(const Point<2> &cell_centre) const;

    /** The soil cells under the base's footprint (r < R) that touch it. */
    bool
    below_base(const Point<2> &cell_centre) const;

    /**
     * One converged step: the n = 1 symmetric nodal forces of the cells
     * beside the shaft and of those below the base, the n = 1 displacement
     * (read for a flexible pile only), the rigid motion and the applied H
     * and M (about the reference point).
     */
    void
    record(const Vector<double> &shaft_force,
           const Vector<double> &base_force,
           const Vector<double> &displacement,
           const RigidMotion    &motion,
           const double          applied_H,
           const double          applied_M);

    unsigned int
    n_steps() const
    {
      return steps.size();
    }

    /** Wall time spent on the curves [s] (the caller adds its part). */
    double wall_time = 0.;

    /** p [kN/m] and m [kN m/m] at elevation z of a recorded step. */
    std::pair<double, double>
    shaft_reaction(const unsigned int step, const double z) const;

    /** H_B [kN] and M_B [kN m] (about the base's centre) of a step. */
    std::pair<double, double>
    base_reaction(const unsigned int step) const;

    /**
     * p and m [kN/m, kN m/m] at elevation z from the soil beside the outer
     * face r = R only (the whole reaction for a solid pile).
     */
    std::pair<double, double>
    outer_face_reaction(const unsigned int step, const double z) const;

    /** The local displacement v [m] at elevation z of a step. */
    double
    displacement(const unsigned int step, const double z) const;

    /** The local rotation psi [rad] at elevation z of a step. */
    double
    rotation(const unsigned int step, const double z) const;

    /**
     * The largest imbalance over the steps, relative to |H|: of the
     * horizontal forces, |int p dz + H_B - H|, and of the moments about
     * the reference point, |int (m + p (z - z_ref)) dz + M_B + H_B (z_toe -
     * z_ref) - M_ref| / (|H| L) (the integrals by Gauss quadrature of the
     * recovered fields).
     */
    std::pair<double, double>
    largest_imbalance() const;

    /** The elevations of the shaft line's vertices, bottom to top. */
    const std::vector<double> &
    shaft_vertices() const
    {
      return vertex_z;
    }

    double
    radius() const
    {
      return pile_radius;
    }

    /** The inner face's radius r_i of a hollow pile (0 for a solid one). */
    double
    inner_radius() const
    {
      return bore_radius;
    }

    /** True if the pile is the Rigid foundation's tied material. */
    bool
    rigid() const
    {
      return rigid_pile;
    }

    /** The depths of the curves [m below the pile's head]. */
    const std::vector<double> &
    depths() const
    {
      return curve_depths;
    }

    /**
     * Rows of results.csv per depth d (cycle = the step): the normalised
     * reaction soil_reaction_p_normalised_at_<d>m = p/(s D) at the last
     * step, and the initial slope of the normalised p-v curve, the secant
     * soil_reaction_secant_at_<d>m = p/(G v) of the first step.
     */
    void
    add_result_rows(ResultsTable &results) const;

    /** soil-reaction-curves.csv: one row per step and depth, units named. */
    void
    write_csv(const std::string &filename) const;

  private:
    struct Step
    {
      double         applied_H = 0., applied_M = 0.;
      RigidMotion    motion;
      Vector<double> p, m; // on the shaft line's DoFs
      /** A hollow pile: the outer face's share of p and m. */
      Vector<double> p_outer, m_outer;
      /** A flexible pile: the section's v and psi on the line's DoFs. */
      Vector<double> v, psi;
      double         base_shear = 0., base_moment = 0.;
    };

    /** The strength or stress that normalises the curves at a depth. */
    struct Normalisation
    {
      bool   clay          = true; // Tresca: s_u; Mohr-Coulomb: sigma'_v
      double strength      = 0.;   // s_u or sigma'_v [kPa]
      double shear_modulus = 0.;
    };

    void
    find_pile(const Triangulation<2> &triangulation);
    void
    find_touching_cells(const Triangulation<2> &triangulation);
    /** The shaft's 1D mesh (r = R, toe to head) and its mass inverse. */
    void
    make_shaft_line(const DoFHandler<2> &dofs);
    void
    map_shaft_nodes(const DoFHandler<2> &dofs);

    /** The elevations z of the shaft line's DoFs (as 1D points). */
    std::vector<Point<1>>
    line_support_points() const;
    /** A flexible pile: the weights of section_motion at the line's DoFs. */
    void
    make_section_weights(const DoFHandler<2> &dofs);
    /** The section's v and psi at the shaft line's DoFs from u (n = 1). */
    void
    section_motion(const Vector<double> &u, Step &step) const;
    /** A node of the pile's outline: a face, or the base (annulus). */
    bool
    on_outline(const Point<2> &x) const;
    void
    choose_depths();
    /** s_u or sigma'_v and G of the soil beside the shaft at elevation z. */
    Normalisation
    normalisation_at(const double z, const bool base) const;
    /** The shaft line's field of DoF values `values` at elevation z. */
    double
    line_value(const Vector<double> &values, const double z) const;
    void
    write_row(std::ostream      &out,
              const Step        &step,
              const unsigned int s,
              const double       depth) const;

    const AllParameters &parameters;
    /** The pile's material: Output/Soil reaction pile or the tied one. */
    types::material_id pile_id;
    bool               rigid_pile = true, hollow = false;
    double             pile_radius = 0., bore_radius = 0., top = 0., toe = 0.;
    /** Centres of the touching soil cells and their material ids. */
    std::map<std::pair<double, double>, types::material_id> shaft_cells,
      base_cells;
    std::vector<double> vertex_z, curve_depths;
    /** The shaft line: 1D mesh, FE_Q of the soil's degree, mass inverse. */
    Triangulation<1>   line_mesh;
    FE_Q<1>            line_fe;
    DoFHandler<1>      line_dofs;
    FullMatrix<double> inverse_mass;
    /**
     * Per DoF of the n = 1 field: its shaft line DoF (or -1) and whether it
     * lies on the base (r <= R at the toe); its radius and component.
     */
    std::vector<int>          line_dof_of;
    std::vector<char>         on_base, on_outer_face;
    std::vector<double>       dof_radius;
    std::vector<unsigned int> dof_component;
    std::vector<Step>         steps;
    /**
     * A flexible pile, per line DoF: (n = 1 DoF, weight in v, weight in
     * psi) of the section integrals (section_motion).
     */
    std::vector<
      std::vector<std::tuple<types::global_dof_index, double, double>>>
      section_weights;
  };
} // namespace FourierSSI

#endif
