/**
 * Zero-thickness interfaces in the harmonic system, part 2: the paired faces
 * of one DoFHandler become closed-form interface elements (interface_matrix(),
 * Hernoune 2007 eqs 3.13-3.23 and 7.9-7.55) that are added to the sparsity
 * pattern, the stiffness matrix, the nodal reactions K u - f and the strain
 * energy of one harmonic, and whose relative displacements and tractions are
 * written as CSV (doc/interfaces-usage.md).
 */
#ifndef fourier_ssi_interface_integrator_h
#define fourier_ssi_interface_integrator_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/input/harmonic.h>
#include <fourier_ssi/input/material.h>
#include <fourier_ssi/interfaces/interface_element.h>
#include <fourier_ssi/interfaces/interface_pairing.h>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  class InterfaceIntegrator
  {
  public:
    InterfaceIntegrator(const InterfaceParameters &parameters,
                        const MaterialLibrary     &materials,
                        const Harmonic            &harmonic);

    /**
     * Pair the interface faces of dof_handler and compute each pair's
     * stiffness (eq. 3.8d, or Van Langen & Vermeer's rule) and element matrix.
     */
    void
    setup(const DoFHandler<2> &dof_handler);

    /**
     * The exact limits of the tied laws as constraints: each twin DoF of a
     * node pair equals its partner (tied), or the normal displacements of
     * the twins are equal (tied-normal). Call after setup() and before the
     * axis conditions; DoFs already constrained (hanging nodes, Dirichlet,
     * rigid foundation) are left alone and the partner is constrained
     * instead, and so are the DoFs in `keep_free` (a rigid foundation's
     * master DoFs: every footing DoF depends on them, so they must stay
     * unknowns). Returns the number of constraints added.
     */
    unsigned int
    add_tie_constraints(
      AffineConstraints<double>               &constraints,
      const std::set<types::global_dof_index> &keep_free = {}) const;

    void
    add_sparsity(const AffineConstraints<double> &constraints,
                 DynamicSparsityPattern          &dsp) const;

    /**
     * The element matrix of pair i on its distinct DoFs (repeated indices of
     * an interface ending inside the mesh merged), ready for
     * distribute_local_to_global.
     */
    void
    merged_matrix(const unsigned int                    i,
                  FullMatrix<double>                   &merged,
                  std::vector<types::global_dof_index> &unique_dofs) const;

    /** reactions += K_interface u (the interface part of K u - f). */
    void
    add_reactions(const Vector<double> &u, Vector<double> &reactions) const;

    /** 1/2 u^T K_interface u: the energy stored in the springs. */
    double
    energy(const Vector<double> &u) const;

    /** Interface boundary ids, ascending. */
    std::vector<types::boundary_id>
    boundary_ids() const;

    /**
     * CSV of one interface, one row per face and node: face, node, r, z,
     * relative displacement amplitudes B - A along s, n, theta (m) and
     * tractions kn d_n, ks d_s, ks d_theta (kPa).
     */
    void
    write_csv(const types::boundary_id boundary_id,
              const Vector<double>    &u,
              const std::string       &filename) const;

    const std::vector<InterfacePair> &
    get_pairs() const
    {
      return pairs;
    }

    /** The springs assembled into K, per pair. */
    const std::vector<InterfaceStiffness> &
    get_stiffness() const
    {
      return stiffness;
    }

    /**
     * The springs of each pair's law (kn, ks resolved: vermeer's rule, the
     * augmentation of contact); get_stiffness() but where Newton caps a
     * coulomb interface's springs in K (InterfaceParameters::
     * iteration_stiffness_cap; the law's own springs then act through the
     * augmented Lagrangian, NonlinearInterfacePoints).
     */
    const std::vector<InterfaceStiffness> &
    get_law_stiffness() const
    {
      return law_stiffness;
    }

    /** G / l of each pair [kPa/m] (soil_scale()). */
    const std::vector<double> &
    get_soil_scale() const
    {
      return soil_scales;
    }

  private:
    /**
     * The soil of a pair: the law's material, or the side of lower G at
     * the face centre's depth.
     */
    const ElasticMaterial &
    soil_of(const InterfacePair &pair, const InterfaceLaw &law) const;

    /** G / l [kPa/m]: the soil's G at the face, l the mean face length. */
    double
    soil_scale(const InterfacePair                             &pair,
               const InterfaceLaw                              &law,
               const std::map<types::boundary_id,
                              std::pair<double, unsigned int>> &lengths) const;

    const InterfaceParameters      &parameters;
    const MaterialLibrary          &materials;
    const Harmonic                  harmonic;
    std::vector<InterfacePair>      pairs;
    std::vector<InterfaceStiffness> stiffness, law_stiffness;
    std::vector<double>             soil_scales;
    std::vector<FullMatrix<double>> matrices;
  };
} // namespace FourierSSI

#endif
