/**
 * Zero-thickness interfaces in the harmonic system, part 1: the pairing of
 * the coincident boundary faces of the two sides (doc/interfaces-usage.md);
 * the laws and their .prm syntax are in interface_law.h. The double nodes
 * themselves come from the mesh: Mesh/Interface lines (interface_lines.h)
 * or a gmsh mesh with duplicated curves.
 *
 * An interface is a boundary id carried by the faces on BOTH sides of a
 * line whose vertices are duplicated (double nodes), so that the two sides
 * are separate boundaries of the mesh. Each face is paired with its
 * geometric twin; the pair becomes one 6-node (p = 2) or 10-node (p = 4)
 * interface element of Hernoune (2007), eqs 3.13-3.23 / 7.9-7.55 (see
 * include/fourier_ssi/interfaces/interface_element.h).
 */
#ifndef fourier_ssi_interface_pairing_h
#define fourier_ssi_interface_pairing_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <fourier_ssi/interfaces/interface_law.h>
#include <map>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * One interface element: a boundary face of one cell (side A) and its
   * coincident twin of another cell (side B). The unit normal n points from
   * A into B and is chosen with n_z > 0, or n_r > 0 on vertical faces; the
   * nodes are ordered along s = n rotated by -90 degrees, so that
   * interface_matrix()'s tangent (node 0 to node p) and normal are s and n.
   * Positive normal relative displacement is opening.
   */
  struct InterfacePair
  {
    types::boundary_id boundary_id;
    /** The p + 1 node positions, node 0 to node p. */
    std::vector<Point<2>> nodes;
    /** 6 (p + 1) global DoFs in interface_matrix() order: A nodes 0..p
     * (U_r, U_z, U_theta each), then B nodes 0..p. */
    std::vector<types::global_dof_index> dof_indices;
    types::material_id                   material_a, material_b;
    /** Active cell index of the cells of side A and side B (a parallel run
     * assembles the pair on the rank of cell A). */
    std::array<unsigned int, 2> cells = {{0, 0}};
    Point<2>                    center;
    double                      length;
    Tensor<1, 2>                tangent, normal;
  };

  /**
   * Pair the active boundary faces carrying any of the given ids (the
   * FESystem of dof_handler must be FE_Q(p)^3 with equidistant support
   * points). Throws a one-line error with the face centre if a face has no
   * twin, more than one, or a twin on the same cell, or if an id does not
   * exist on the mesh. Pairs come grouped by id in the order of `ids`, each
   * group in the active-cell order of the pair's first face.
   */
  std::vector<InterfacePair>
  pair_interface_faces(const DoFHandler<2>                   &dof_handler,
                       const std::vector<types::boundary_id> &ids,
                       const double                           tolerance);
} // namespace FourierSSI

#endif
