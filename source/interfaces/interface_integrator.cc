#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <fourier_ssi/input/atomic_file.h>
#include <fourier_ssi/interfaces/interface_integrator.h>
#include <fstream>
#include <iomanip>
#include <set>

namespace FourierSSI
{
  InterfaceIntegrator::InterfaceIntegrator(
    const InterfaceParameters &parameters,
    const MaterialLibrary     &materials,
    const Harmonic            &harmonic)
    : parameters(parameters)
    , materials(materials)
    , harmonic(harmonic)
  {}

  std::vector<types::boundary_id>
  InterfaceIntegrator::boundary_ids() const
  {
    std::vector<types::boundary_id> ids;
    for (const auto &[id, law] : parameters.laws)
      ids.push_back(id);
    return ids;
  }

  const ElasticMaterial &
  InterfaceIntegrator::soil_of(const InterfacePair &pair,
                               const InterfaceLaw  &law) const
  {
    const double depth = materials.depth(pair.center[1]);
    const auto   check = [&](const int id) -> const ElasticMaterial   &{
      AssertThrow(materials.has(id),
                  ExcMessage("Interfaces/Interfaces: material " +
                             std::to_string(id) + " of interface " +
                             std::to_string(pair.boundary_id) +
                             " is not defined"));
      return materials.get(id);
    };
    if (law.material >= 0)
      return check(law.material);
    const ElasticMaterial &a = check(pair.material_a);
    const ElasticMaterial &b = check(pair.material_b);
    return a.shear_modulus(depth) <= b.shear_modulus(depth) ? a : b;
  }

  double
  InterfaceIntegrator::soil_scale(
    const InterfacePair &pair,
    const InterfaceLaw  &law,
    const std::map<types::boundary_id, std::pair<double, unsigned int>>
      &lengths) const
  {
    const auto &[sum, count] = lengths.at(pair.boundary_id);
    return soil_of(pair, law).shear_modulus(materials.depth(pair.center[1])) /
           (sum / count);
  }

  void
  InterfaceIntegrator::setup(const DoFHandler<2> &dof_handler)
  {
    pairs = pair_interface_faces(dof_handler,
                                 boundary_ids(),
                                 parameters.pairing_tolerance);
    // Mean face length per interface (Van Langen & Vermeer's l).
    std::map<types::boundary_id, std::pair<double, unsigned int>> lengths;
    for (const InterfacePair &pair : pairs)
      {
        lengths[pair.boundary_id].first += pair.length;
        ++lengths[pair.boundary_id].second;
      }
    stiffness.clear();
    law_stiffness.clear();
    soil_scales.clear();
    matrices.clear();
    for (const InterfacePair &pair : pairs)
      {
        const InterfaceLaw &law = parameters.laws.at(pair.boundary_id);
        // Tied laws are constraints, not springs.
        InterfaceStiffness k{law.is_exact_limit() ? 0. : law.normal,
                             law.is_exact_limit() ? 0. : law.shear};
        if (law.kind == InterfaceLaw::Kind::vermeer)
          {
            const ElasticMaterial &soil     = soil_of(pair, law);
            const double           G_over_l = soil_scale(pair, law, lengths);
            k.shear                         = law.mu * G_over_l;
            k.normal = law.mu * G_over_l / (1. - 2. * soil.poisson_ratio);
          }
        // G / l where a rule needs it (the springs of a nonlinear law are
        // compared with it in the log).
        const double G_over_l =
          law.is_nonlinear() ? soil_scale(pair, law, lengths) : 0.;
        soil_scales.push_back(G_over_l);
        if (law.automatic_normal)
          k.normal = automatic_interface_stiffness * G_over_l;
        if (law.automatic_shear)
          k.shear = automatic_interface_stiffness * G_over_l;
        if (law.kind == InterfaceLaw::Kind::contact)
          k.normal = k.shear = interface_iteration_stiffness * G_over_l;
        law_stiffness.push_back(k);
        if (law.kind == InterfaceLaw::Kind::coulomb &&
            parameters.iteration_stiffness_cap > 0.)
          {
            // Newton: K with springs no stiffer than the cap (the law's
            // kn, ks act through the multipliers, section 5b); a law whose
            // faces can open no stiffer than interface_iteration_stiffness
            // (soil_iteration_stiffness says why).
            const double cap =
              (law.can_open() ? std::min(parameters.iteration_stiffness_cap,
                                         interface_iteration_stiffness) :
                                parameters.iteration_stiffness_cap) *
              G_over_l;
            k.normal = std::min(k.normal, cap);
            k.shear  = std::min(k.shear, cap);
          }
        stiffness.push_back(k);
        const unsigned int degree = pair.nodes.size() - 1;
        matrices.push_back(law.is_nonlinear() && parameters.nodal_integration ?
                             interface_matrix_by_quadrature(
                               degree,
                               pair.nodes,
                               k,
                               harmonic,
                               nonlinear_interface_rule(degree, true)) :
                             interface_matrix(degree, pair.nodes, k, harmonic));
      }
  }

  namespace
  {
    using ConstraintTerms =
      std::vector<std::pair<types::global_dof_index, double>>;
    using NodeDoFs = std::array<types::global_dof_index, 3>;

    /**
     * Does the constraint chain of `dof` reach `target`? (A twin may already
     * follow its partner through another interface, e.g. where two
     * interfaces cross: tying the partner back would close a cycle.)
     */
    bool
    chain_reaches(const AffineConstraints<double> &constraints,
                  types::global_dof_index          dof,
                  const types::global_dof_index    target)
    {
      for (unsigned int step = 0; step < 64; ++step)
        {
          if (dof == target)
            return true;
          if (!constraints.is_constrained(dof))
            return false;
          const auto *entries = constraints.get_constraint_entries(dof);
          if (entries == nullptr || entries->size() != 1)
            return false;
          dof = (*entries)[0].first;
        }
      return false;
    }

    /** Writes the ties and counts them. */
    struct TieWriter
    {
      AffineConstraints<double>               &constraints;
      const std::set<types::global_dof_index> &keep_free;
      unsigned int                             n_added = 0;

      /** Constrain `slave` = sum of `terms` unless it is already constrained.
       */
      bool
      tie(const types::global_dof_index slave, const ConstraintTerms &terms)
      {
        if (constraints.is_constrained(slave) || keep_free.count(slave) > 0)
          return false;
        constraints.add_line(slave);
        constraints.add_entries(slave, terms);
        ++n_added;
        return true;
      }
    };

    /** tied: each component of one node of side B equals that of side A. */
    void
    tie_all_components(TieWriter &writer, const NodeDoFs &a, const NodeDoFs &b)
    {
      const AffineConstraints<double> &constraints = writer.constraints;
      for (unsigned int c = 0; c < 3; ++c)
        {
          if (a[c] == b[c] || chain_reaches(constraints, a[c], b[c]) ||
              chain_reaches(constraints, b[c], a[c]) ||
              (constraints.is_constrained(a[c]) &&
               constraints.is_constrained(b[c])))
            continue;
          if (!writer.tie(b[c], {{a[c], 1.}}))
            writer.tie(a[c], {{b[c], 1.}});
        }
    }

    /**
     * tied-normal: n . (u_B - u_A) = 0 with n = (n_r, n_z): solve for the
     * component along the larger normal entry.
     */
    void
    tie_normal_component(TieWriter          &writer,
                         const Tensor<1, 2> &normal,
                         const NodeDoFs     &a,
                         const NodeDoFs     &b)
    {
      const unsigned int m = std::abs(normal[0]) >= std::abs(normal[1]) ? 0 : 1;
      const unsigned int o = 1 - m;
      const double       ratio  = normal[o] / normal[m];
      ConstraintTerms    from_a = {{a[m], 1.}};
      ConstraintTerms    from_b = {{b[m], 1.}};
      if (ratio != 0.)
        {
          from_a.push_back({a[o], ratio});
          from_a.push_back({b[o], -ratio});
          from_b.push_back({b[o], ratio});
          from_b.push_back({a[o], -ratio});
        }
      if (a[m] != b[m] && !writer.tie(b[m], from_a))
        writer.tie(a[m], from_b);
    }
  } // namespace

  unsigned int
  InterfaceIntegrator::add_tie_constraints(
    AffineConstraints<double>               &constraints,
    const std::set<types::global_dof_index> &keep_free) const
  {
    TieWriter writer{constraints, keep_free};
    std::set<std::pair<types::global_dof_index, types::global_dof_index>> done;
    for (const InterfacePair &pair : pairs)
      {
        const InterfaceLaw &law = parameters.laws.at(pair.boundary_id);
        if (!law.is_exact_limit())
          continue;
        const unsigned int n_nodes = pair.nodes.size();
        for (unsigned int k = 0; k < n_nodes; ++k)
          {
            NodeDoFs a, b;
            for (unsigned int c = 0; c < 3; ++c)
              {
                a[c] = pair.dof_indices[3 * k + c];
                b[c] = pair.dof_indices[3 * (n_nodes + k) + c];
              }
            // Face ends belong to two pairs: tie each node pair once.
            if (!done.insert({a[0], b[0]}).second)
              continue;
            if (law.kind == InterfaceLaw::Kind::tied)
              tie_all_components(writer, a, b);
            else
              tie_normal_component(writer, pair.normal, a, b);
          }
      }
    return writer.n_added;
  }

  void
  InterfaceIntegrator::add_sparsity(
    const AffineConstraints<double> &constraints,
    DynamicSparsityPattern          &dsp) const
  {
    for (const InterfacePair &pair : pairs)
      {
        // Distinct indices only: deal.II's sorted insertion assumes them
        // (an interface line ending inside the mesh repeats its end node).
        std::vector<types::global_dof_index> dofs(pair.dof_indices);
        std::sort(dofs.begin(), dofs.end());
        dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
        constraints.add_entries_local_to_global(
          dofs,
          dsp,
          /*keep_constrained_dofs=*/false);
      }
  }

  void
  InterfaceIntegrator::merged_matrix(
    const unsigned int                    i,
    FullMatrix<double>                   &merged,
    std::vector<types::global_dof_index> &unique_dofs) const
  {
    // Where an interface line ends inside the mesh the last node pair is
    // one shared DoF set (the "crack tip" is closed): merge repeated
    // indices, since distribute_local_to_global expects distinct ones
    // (repeated ones corrupted the sparse matrix in release builds).
    const std::vector<types::global_dof_index> &dofs = pairs[i].dof_indices;
    unique_dofs                                      = dofs;
    std::sort(unique_dofs.begin(), unique_dofs.end());
    unique_dofs.erase(std::unique(unique_dofs.begin(), unique_dofs.end()),
                      unique_dofs.end());
    std::vector<unsigned int> position(dofs.size());
    for (unsigned int k = 0; k < dofs.size(); ++k)
      position[k] =
        std::lower_bound(unique_dofs.begin(), unique_dofs.end(), dofs[k]) -
        unique_dofs.begin();
    merged.reinit(unique_dofs.size(), unique_dofs.size());
    for (unsigned int a = 0; a < dofs.size(); ++a)
      for (unsigned int b = 0; b < dofs.size(); ++b)
        merged(position[a], position[b]) += matrices[i](a, b);
  }

  void
  InterfaceIntegrator::add_reactions(const Vector<double> &u,
                                     Vector<double>       &reactions) const
  {
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const auto    &dofs = pairs[i].dof_indices;
        Vector<double> local(dofs.size()), product(dofs.size());
        for (unsigned int k = 0; k < dofs.size(); ++k)
          local(k) = u(dofs[k]);
        matrices[i].vmult(product, local);
        for (unsigned int k = 0; k < dofs.size(); ++k)
          reactions(dofs[k]) += product(k);
      }
  }

  double
  InterfaceIntegrator::energy(const Vector<double> &u) const
  {
    double energy = 0.;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const auto    &dofs = pairs[i].dof_indices;
        Vector<double> local(dofs.size());
        for (unsigned int k = 0; k < dofs.size(); ++k)
          local(k) = u(dofs[k]);
        energy += 0.5 * matrices[i].matrix_norm_square(local);
      }
    return energy;
  }

  void
  InterfaceIntegrator::write_csv(const types::boundary_id boundary_id,
                                 const Vector<double>    &u,
                                 const std::string       &filename) const
  {
    AtomicFile    file(filename);
    std::ostream &out = file.stream();
    out << "face,node,r,z,relative_s,relative_n,relative_theta,traction_n,"
           "traction_s,traction_theta\n"
        << std::setprecision(12);
    unsigned int face = 0;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const InterfacePair &pair = pairs[i];
        if (pair.boundary_id != boundary_id)
          continue;
        const unsigned int n_nodes = pair.nodes.size();
        for (unsigned int k = 0; k < n_nodes; ++k)
          {
            Tensor<1, 2> jump;
            for (unsigned int c = 0; c < 2; ++c)
              jump[c] = u(pair.dof_indices[3 * (n_nodes + k) + c]) -
                        u(pair.dof_indices[3 * k + c]);
            const double d_s = jump * pair.tangent, d_n = jump * pair.normal;
            const double d_t = u(pair.dof_indices[3 * (n_nodes + k) + 2]) -
                               u(pair.dof_indices[3 * k + 2]);
            out << face << ',' << k << ',' << pair.nodes[k][0] << ','
                << pair.nodes[k][1] << ',' << d_s << ',' << d_n << ',' << d_t
                << ',' << stiffness[i].normal * d_n << ','
                << stiffness[i].shear * d_s << ',' << stiffness[i].shear * d_t
                << '\n';
          }
        ++face;
      }
    file.commit();
  }
} // namespace FourierSSI
