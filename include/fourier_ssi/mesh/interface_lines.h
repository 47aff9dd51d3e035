/**
 * Double nodes along straight interface lines of the built-in rectangle
 * mesh (Mesh/Interface lines): the mesh surgery that makes the two sides of
 * an interface separate boundaries, done on the coarse mesh before any
 * refinement. The faces of both sides carry the line's boundary id;
 * pair_interface_faces() (interface_pairing.h) later turns each pair of
 * twin faces into one interface element.
 */
#ifndef fourier_ssi_interface_lines_h
#define fourier_ssi_interface_lines_h

#include <deal.II/grid/tria.h>
#include <fourier_ssi/input/mesh_parameters.h>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * Double nodes for the built-in rectangle: duplicate the vertices along the
   * given straight lines so that the cells on the two sides no longer share
   * them, and give the faces on both sides the line's boundary id. Around a
   * vertex, cells that still share a non-interface face keep sharing it
   * (interior line ends stay closed, crossings get up to four copies).
   * Vertices on the axis r = 0 are duplicated like any other: a shared axis
   * node would pin the two sides together there, and the axis conditions
   * (axis_constraints.h) constrain each copy by its own DoFs. Must be called
   * on a coarse (unrefined) mesh; the other boundary ids are kept. Throws if
   * a line is not on the breakpoints, lies on the mesh boundary, or runs
   * along no interior face.
   */
  void
  split_along_interface_lines(Triangulation<2>                 &triangulation,
                              const std::vector<InterfaceLine> &lines,
                              const std::vector<double>        &r_breakpoints,
                              const std::vector<double>        &z_breakpoints);
} // namespace FourierSSI

#endif
