#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <fourier_ssi/axis_constraints.h>
#include <map>

namespace FourierSSI
{
  unsigned int
  add_axis_constraints(const DoFHandler<2>       &dof_handler,
                       const Harmonic            &harmonic,
                       const double               axis_tolerance,
                       AffineConstraints<double> &constraints)
  {
    const FiniteElement<2> &fe   = dof_handler.get_fe();
    const auto constrain_to_zero = [&](const types::global_dof_index i) {
      if (!constraints.is_constrained(i))
        constraints.add_line(i);
    };

    // n = 0: one part of the field has no stiffness at all.
    if (harmonic.n == 0)
      {
        const std::vector<bool> unused =
          harmonic.family == Family::symmetric ?
            std::vector<bool>{false, false, true} :
            std::vector<bool>{true, true, false};
        const IndexSet dofs =
          DoFTools::extract_dofs(dof_handler, ComponentMask(unused));
        for (const auto i : dofs)
          constrain_to_zero(i);
      }

    // Collect, per axis node (keyed by z), the DoF of each component.
    std::map<double, std::array<types::global_dof_index, 3>> axis_nodes;
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    const std::vector<Point<2>> &unit_points = fe.get_unit_support_points();
    const MappingQ1<2>           mapping;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        bool touches_axis = false;
        for (const unsigned int v : cell->vertex_indices())
          touches_axis |= cell->vertex(v)[0] <= axis_tolerance;
        if (!touches_axis)
          continue;
        cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            // Straight-sided cells: the bilinear map gives the position.
            const Point<2> p =
              mapping.transform_unit_to_real_cell(cell, unit_points[i]);
            if (p[0] > axis_tolerance)
              continue;
            // Round z so the three components of one node share a key.
            const double key =
              std::round(p[1] / axis_tolerance) * axis_tolerance;
            auto it = axis_nodes.find(key);
            if (it == axis_nodes.end())
              it = axis_nodes
                     .emplace(key,
                              std::array<types::global_dof_index, 3>{
                                {numbers::invalid_dof_index,
                                 numbers::invalid_dof_index,
                                 numbers::invalid_dof_index}})
                     .first;
            it->second[fe.system_to_component_index(i).first] = dof_indices[i];
          }
      }

    const double sign = family_sign(harmonic.family);
    for (const auto &[z, dofs] : axis_nodes)
      {
        const auto U = dofs[0], V = dofs[1], W = dofs[2];
        Assert(U != numbers::invalid_dof_index &&
                 V != numbers::invalid_dof_index &&
                 W != numbers::invalid_dof_index,
               ExcInternalError());
        if (harmonic.n == 0)
          constrain_to_zero(harmonic.family == Family::symmetric ? U : W);
        else if (harmonic.n == 1)
          {
            constrain_to_zero(V);
            // symmetric: U + W = 0; antisymmetric: U - W = 0.
            if (!constraints.is_constrained(W))
              {
                constraints.add_line(W);
                constraints.add_entry(W, U, -sign);
              }
            else if (!constraints.is_constrained(U))
              {
                constraints.add_line(U);
                constraints.add_entry(U, W, -sign);
              }
          }
        else
          {
            constrain_to_zero(U);
            constrain_to_zero(V);
            constrain_to_zero(W);
          }
      }
    return axis_nodes.size();
  }
} // namespace FourierSSI
