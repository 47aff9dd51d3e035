/**
 * Zero-thickness interfaces in the harmonic system, part 1 (the laws and
 * their .prm syntax are in interface_law.h): the double-node splitting of the
 * built-in rectangle along straight interface lines, and the pairing of the
 * coincident boundary faces of the two sides (doc/interfaces-usage.md).
 *
 * An interface is a boundary id carried by the faces on BOTH sides of a
 * line whose vertices are duplicated (double nodes), so that the two sides
 * are separate boundaries of the mesh. Each face is paired with its
 * geometric twin; the pair becomes one 6-node (p = 2) or 10-node (p = 4)
 * interface element of Hernoune (2007), eqs 3.13-3.23 / 7.9-7.55 (see
 * include/fourier_ssi/interface_element.h).
 */
#ifndef fourier_ssi_interface_pairing_h
#define fourier_ssi_interface_pairing_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <fourier_ssi/interface_law.h>
#include <fourier_ssi/mesh_builder.h>
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
   * exist on the mesh. Pairs are sorted by id, then by face centre.
   */
  std::vector<InterfacePair>
  pair_interface_faces(const DoFHandler<2>                   &dof_handler,
                       const std::vector<types::boundary_id> &ids,
                       const double                           tolerance);

  /**
   * Parse Mesh/Interface lines, "id: r=1, z=-2..0; id: z=-2, r=0..1" (empty:
   * none). Throws a one-line message naming the entry.
   */
  std::vector<InterfaceLine>
  parse_interface_lines(const std::string &text);

  /**
   * Double nodes for the built-in rectangle: duplicate the vertices along the
   * given straight lines so that the cells on the two sides no longer share
   * them, and give the faces on both sides the line's boundary id. Around a
   * vertex, cells that still share a non-interface face keep sharing it
   * (interior line ends stay closed, crossings get up to four copies);
   * vertices on the axis r = 0 are not duplicated (the axis constraints key
   * axis nodes by z). Must be called on a coarse (unrefined) mesh; the other
   * boundary ids are kept. Throws if a line is not on the breakpoints.
   */
  void
  split_along_interface_lines(Triangulation<2>                 &triangulation,
                              const std::vector<InterfaceLine> &lines,
                              const std::vector<double>        &r_breakpoints,
                              const std::vector<double>        &z_breakpoints);
} // namespace FourierSSI

#endif
