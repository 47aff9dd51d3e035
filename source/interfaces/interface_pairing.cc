#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping_q1.h>
#include <fourier_ssi/interfaces/interface_pairing.h>
#include <fourier_ssi/mesh/coordinate_tolerance.h>
#include <limits>
#include <numeric>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    /**
     * Two points of a face of length `length` near `center` coincide within
     * `relative` of the length, but never closer than the round-off of the
     * coordinates themselves (coordinate_tolerance.h;
     * tests/accuracy/graded_25_levels.prm).
     */
    double
    match_tolerance(const double    relative,
                    const double    length,
                    const Point<2> &center)
    {
      return coincidence_tolerance(relative, length, center.norm());
    }
  } // namespace

  namespace
  {
    std::string
    point_text(const Point<2> &x)
    {
      std::ostringstream out;
      out << "(r, z) = (" << x[0] << ", " << x[1] << ")";
      return out.str();
    }
  } // namespace

  namespace
  {
    const std::string interfaces_entry = "Interfaces/Interfaces";

    struct FaceRecord
    {
      DoFHandler<2>::active_cell_iterator cell;
      unsigned int                        face_no;
      Point<2>                            a, b, center;
      double                              length;
    };

    std::vector<FaceRecord>
    faces_with_id(const DoFHandler<2> &dof_handler, const types::boundary_id id)
    {
      std::vector<FaceRecord> faces;
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == id)
            {
              const auto face = cell->face(f);
              faces.push_back({cell,
                               f,
                               face->vertex(0),
                               face->vertex(1),
                               face->center(),
                               face->vertex(0).distance(face->vertex(1))});
            }
      AssertThrow(!faces.empty(),
                  ExcMessage(interfaces_entry + ": boundary id " +
                             std::to_string(id) +
                             " does not exist on the mesh"));
      return faces;
    }

    /**
     * The twin of each face: the one other face with the same end points
     * (searched among the faces whose centers lie within the tolerance in r).
     */
    std::vector<int>
    find_twins(const std::vector<FaceRecord> &faces,
               const types::boundary_id       id,
               const double                   tolerance)
    {
      const std::string        &entry = interfaces_entry;
      std::vector<unsigned int> order(faces.size());
      std::iota(order.begin(), order.end(), 0u);
      std::sort(order.begin(),
                order.end(),
                [&](unsigned int i, unsigned int j) {
                  return faces[i].center[0] < faces[j].center[0];
                });
      std::vector<double> sorted_r(faces.size());
      for (unsigned int k = 0; k < order.size(); ++k)
        sorted_r[k] = faces[order[k]].center[0];
      std::vector<int> twin(faces.size(), -1);

      for (unsigned int i = 0; i < faces.size(); ++i)
        {
          const FaceRecord &fi = faces[i];
          const double tol = match_tolerance(tolerance, fi.length, fi.center);
          const std::string where = "interface " + std::to_string(id) +
                                    ": the face at " + point_text(fi.center);
          int        found = -1;
          const auto begin = std::lower_bound(sorted_r.begin(),
                                              sorted_r.end(),
                                              fi.center[0] - tol);
          for (auto k = begin - sorted_r.begin();
               k < static_cast<long>(order.size()) &&
               sorted_r[k] <= fi.center[0] + tol;
               ++k)
            {
              const unsigned int j = order[k];
              if (j == i)
                continue;
              const FaceRecord &fj = faces[j];
              const bool        same =
                (fi.a.distance(fj.a) <= tol && fi.b.distance(fj.b) <= tol) ||
                (fi.a.distance(fj.b) <= tol && fi.b.distance(fj.a) <= tol);
              if (!same)
                continue;
              AssertThrow(found < 0,
                          ExcMessage(entry + ": " + where +
                                     " has more than one twin (ambiguous "
                                     "pairing)"));
              AssertThrow(fj.cell != fi.cell,
                          ExcMessage(entry + ": " + where +
                                     " coincides with a face of its own cell"));
              found = j;
            }
          AssertThrow(found >= 0,
                      ExcMessage(entry + ": " + where +
                                 " has no twin (both sides must carry the id, "
                                 "have double nodes and be refined alike)"));
          twin[i] = found;
        }
      return twin;
    }

    /** Unit normal (pointing up, or outward in r on a vertical face) and
     * tangent of the pair, from the end points of one of its faces. */
    void
    set_orientation(InterfacePair &pair, const FaceRecord &face)
    {
      const Tensor<1, 2> along = (face.b - face.a) / pair.length;
      Tensor<1, 2>       n;
      n[0] = -along[1];
      n[1] = along[0];
      if (n[1] < -1e-12 || (std::abs(n[1]) <= 1e-12 && n[0] < 0.))
        n = -n;
      pair.normal     = n;
      pair.tangent[0] = n[1];
      pair.tangent[1] = -n[0];
    }

    /**
     * The DoFs of the pair's nodes, side A then side B, node k then
     * component c: each face DoF is placed by its support point on the
     * equidistant layout starting at `start`.
     */
    void
    set_dof_indices(InterfacePair          &pair,
                    const FaceRecord       &side_a,
                    const FaceRecord       &side_b,
                    const Point<2>         &start,
                    const FiniteElement<2> &fe,
                    const MappingQ1<2>     &mapping,
                    const double            tolerance)
    {
      const unsigned int p = fe.degree;
      const std::string  about_face =
        interfaces_entry + ": interface " + std::to_string(pair.boundary_id);
      pair.dof_indices.assign(6 * (p + 1), numbers::invalid_dof_index);
      const double tol = match_tolerance(tolerance, pair.length, pair.center);
      for (unsigned int side = 0; side < 2; ++side)
        {
          const FaceRecord &face = side == 0 ? side_a : side_b;
          std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
          face.cell->get_dof_indices(dofs);
          for (unsigned int d = 0; d < fe.n_dofs_per_cell(); ++d)
            {
              if (!fe.has_support_on_face(d, face.face_no))
                continue;
              const Point<2> x = mapping.transform_unit_to_real_cell(
                face.cell, fe.get_unit_support_points()[d]);
              const double t = (x - start) * pair.tangent / pair.length;
              const long   k = std::lround(t * p);
              AssertThrow(k >= 0 && k <= static_cast<long>(p) &&
                            x.distance(pair.nodes[k]) <= tol,
                          ExcMessage(about_face + ": a node of the face at " +
                                     point_text(pair.center) +
                                     " is not on its equidistant layout"));
              const unsigned int c = fe.system_to_component_index(d).first;
              pair.dof_indices[3 * ((p + 1) * side + k) + c] = dofs[d];
            }
        }
      for (const auto d : pair.dof_indices)
        AssertThrow(d != numbers::invalid_dof_index,
                    ExcMessage(about_face +
                               ": cannot match the nodes of the face at " +
                               point_text(pair.center)));
    }

    /** The pair of twin faces i and j: geometry, sides, nodes and DoFs. */
    InterfacePair
    make_interface_pair(const std::vector<FaceRecord> &faces,
                        const unsigned int             i,
                        const unsigned int             j,
                        const types::boundary_id       id,
                        const FiniteElement<2>        &fe,
                        const MappingQ1<2>            &mapping,
                        const double                   tolerance)
    {
      const unsigned int p = fe.degree;
      InterfacePair      pair;
      pair.boundary_id = id;
      pair.center      = faces[i].center;
      pair.length      = faces[i].length;
      set_orientation(pair, faces[i]);
      // Side A is the one the normal points away from.
      unsigned int a = i, b = j;
      if ((faces[i].cell->center() - pair.center) * pair.normal > 0.)
        std::swap(a, b);
      pair.material_a      = faces[a].cell->material_id();
      pair.material_b      = faces[b].cell->material_id();
      pair.cells           = {{faces[a].cell->active_cell_index(),
                               faces[b].cell->active_cell_index()}};
      const Point<2> start = (faces[i].a - pair.center) * pair.tangent < 0. ?
                               faces[i].a :
                               faces[i].b;
      for (unsigned int k = 0; k <= p; ++k)
        pair.nodes.push_back(start + (pair.length * k / p) * pair.tangent);
      set_dof_indices(pair, faces[a], faces[b], start, fe, mapping, tolerance);
      return pair;
    }
  } // namespace

  std::vector<InterfacePair>
  pair_interface_faces(const DoFHandler<2>                   &dof_handler,
                       const std::vector<types::boundary_id> &ids,
                       const double                           tolerance)
  {
    const FiniteElement<2>    &fe = dof_handler.get_fe();
    const MappingQ1<2>         mapping;
    std::vector<InterfacePair> pairs;
    for (const types::boundary_id id : ids)
      {
        const std::vector<FaceRecord> faces = faces_with_id(dof_handler, id);
        const std::vector<int>        twin  = find_twins(faces, id, tolerance);
        for (unsigned int i = 0; i < faces.size(); ++i)
          {
            const unsigned int j = twin[i];
            AssertThrow(twin[j] == static_cast<int>(i),
                        ExcMessage(interfaces_entry + ": interface " +
                                   std::to_string(id) + ": the face at " +
                                   point_text(faces[i].center) +
                                   " is paired twice"));
            if (j < i)
              continue;
            pairs.push_back(
              make_interface_pair(faces, i, j, id, fe, mapping, tolerance));
          }
      }
    return pairs;
  }
} // namespace FourierSSI
