#include <array>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <fourier_ssi/harmonic/axis_constraints.h>
#include <map>

namespace FourierSSI
{
  namespace
  {
    using AxisNode = std::array<types::global_dof_index, 3>;

    void
    constrain_to_zero(AffineConstraints<double>    &constraints,
                      const types::global_dof_index i)
    {
      if (!constraints.is_constrained(i))
        constraints.add_line(i);
    }

    /** n = 0: one part of the field has no stiffness at all. */
    void
    constrain_unused_components(const DoFHandler<2>       &dof_handler,
                                const Harmonic            &harmonic,
                                AffineConstraints<double> &constraints)
    {
      const std::vector<bool> unused = harmonic.family == Family::symmetric ?
                                         std::vector<bool>{false, false, true} :
                                         std::vector<bool>{true, true, false};
      const IndexSet          dofs =
        DoFTools::extract_dofs(dof_handler, ComponentMask(unused));
      for (const auto i : dofs)
        constrain_to_zero(constraints, i);
    }

    /**
     * The axis nodes with the DoF of each component. A node is keyed
     * by its radial DoF, not by its position: where an interface meets the
     * axis the two sides have distinct nodes at the same point, and each
     * obeys the axis conditions on its own.
     */
    std::map<types::global_dof_index, AxisNode>
    collect_axis_nodes(const DoFHandler<2> &dof_handler,
                       const double         axis_tolerance)
    {
      const FiniteElement<2>                     &fe = dof_handler.get_fe();
      std::map<types::global_dof_index, AxisNode> axis_nodes;
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      const FiniteElement<2>              &base = fe.base_element(0);
      const std::vector<Point<2>> &unit_points = base.get_unit_support_points();
      const MappingQ1<2>           mapping;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          bool touches_axis = false;
          for (const unsigned int v : cell->vertex_indices())
            touches_axis |= cell->vertex(v)[0] <= axis_tolerance;
          if (!touches_axis)
            continue;
          cell->get_dof_indices(dof_indices);
          for (unsigned int k = 0; k < base.n_dofs_per_cell(); ++k)
            {
              // Straight-sided cells: the bilinear map gives the position.
              const Point<2> p =
                mapping.transform_unit_to_real_cell(cell, unit_points[k]);
              if (p[0] > axis_tolerance)
                continue;
              AxisNode node;
              for (unsigned int c = 0; c < 3; ++c)
                node[c] = dof_indices[fe.component_to_system_index(c, k)];
              axis_nodes[node[0]] = node;
            }
        }
      return axis_nodes;
    }

    /** The axis conditions of harmonic n on one node's U, V, W. */
    void
    constrain_axis_node(const AxisNode            &dofs,
                        const Harmonic            &harmonic,
                        AffineConstraints<double> &constraints)
    {
      const double sign = family_sign(harmonic.family);
      const auto   U = dofs[0], V = dofs[1], W = dofs[2];
      Assert(U != numbers::invalid_dof_index &&
               V != numbers::invalid_dof_index &&
               W != numbers::invalid_dof_index,
             ExcInternalError());
      if (harmonic.n == 0)
        constrain_to_zero(constraints,
                          harmonic.family == Family::symmetric ? U : W);
      else if (harmonic.n == 1)
        {
          constrain_to_zero(constraints, V);
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
          constrain_to_zero(constraints, U);
          constrain_to_zero(constraints, V);
          constrain_to_zero(constraints, W);
        }
    }
  } // namespace

  unsigned int
  add_axis_constraints(const DoFHandler<2>       &dof_handler,
                       const Harmonic            &harmonic,
                       const double               axis_tolerance,
                       AffineConstraints<double> &constraints)
  {
    if (harmonic.n == 0)
      constrain_unused_components(dof_handler, harmonic, constraints);
    const std::map<types::global_dof_index, AxisNode> axis_nodes =
      collect_axis_nodes(dof_handler, axis_tolerance);
    for (const auto &[key, dofs] : axis_nodes)
      constrain_axis_node(dofs, harmonic, constraints);
    return axis_nodes.size();
  }
} // namespace FourierSSI
