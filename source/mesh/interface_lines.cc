#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/tria_description.h>
#include <fourier_ssi/mesh/interface_lines.h>
#include <functional>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    const std::string interface_lines_entry = "Mesh/Interface lines";

    using Edge = std::pair<unsigned int, unsigned int>;

    Edge
    edge_key(const unsigned int a, const unsigned int b)
    {
      return std::make_pair(std::min(a, b), std::max(a, b));
    }

    /** The coarse mesh as plain arrays, with the ids of its edges. */
    struct CoarseMesh
    {
      std::vector<Point<2>>                    vertices;
      std::vector<std::array<unsigned int, 4>> cell_vertices;
      std::vector<types::material_id>          materials;
      std::map<Edge, types::boundary_id>       boundary_ids, interface_ids;
    };

    bool
    on_interface_line(const InterfaceLine &line,
                      const Point<2>      &x,
                      const double         tol)
    {
      const unsigned int c = line.fixed_coordinate, o = 1 - c;
      return std::abs(x[c] - line.value) <= tol && x[o] >= line.from - tol &&
             x[o] <= line.to + tol;
    }

    void
    check_lines_on_breakpoints(const std::vector<InterfaceLine> &lines,
                               const std::vector<double>        &r_breakpoints,
                               const std::vector<double>        &z_breakpoints,
                               const double                      tol)
    {
      const std::string         &entry          = interface_lines_entry;
      const std::vector<double> *breakpoints[2] = {&r_breakpoints,
                                                   &z_breakpoints};
      const auto on_breakpoint = [&](const unsigned int c, const double x) {
        for (const double b : *breakpoints[c])
          if (std::abs(b - x) <= tol)
            return true;
        return false;
      };
      const char *name[2] = {"r", "z"};
      for (const InterfaceLine &line : lines)
        {
          const unsigned int c = line.fixed_coordinate, o = 1 - c;
          std::ostringstream text;
          text << "line " << line.boundary_id << ": " << name[c] << "="
               << line.value << ", " << name[o] << "=" << line.from << ".."
               << line.to;
          AssertThrow(on_breakpoint(c, line.value) &&
                        on_breakpoint(o, line.from) &&
                        on_breakpoint(o, line.to),
                      ExcMessage(entry + ": " + text.str() +
                                 " is not on the mesh breakpoints (" + name[c] +
                                 " and both ends of the " + name[o] +
                                 " range must be " + name[c] + "/" + name[o] +
                                 " breakpoints)"));
          AssertThrow(line.value > breakpoints[c]->front() + tol &&
                        line.value < breakpoints[c]->back() - tol &&
                        line.from >= breakpoints[o]->front() - tol &&
                        line.to <= breakpoints[o]->back() + tol,
                      ExcMessage(entry + ": " + text.str() +
                                 " is on the mesh boundary or outside it"));
        }
    }

    /**
     * The coarse cells and their vertices; boundary faces keep their ids,
     * interior faces on a line get the line's id.
     */
    CoarseMesh
    read_coarse_mesh(const Triangulation<2>           &triangulation,
                     const std::vector<InterfaceLine> &lines,
                     const double                      tol)
    {
      CoarseMesh mesh;
      mesh.vertices = triangulation.get_vertices();
      std::vector<unsigned int> faces_on_line(lines.size(), 0);
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          std::array<unsigned int, 4> v;
          for (unsigned int i = 0; i < 4; ++i)
            v[i] = cell->vertex_index(i);
          mesh.cell_vertices.push_back(v);
          mesh.materials.push_back(cell->material_id());
          for (const unsigned int f : cell->face_indices())
            {
              const auto         face = cell->face(f);
              const unsigned int a    = face->vertex_index(0),
                                 b    = face->vertex_index(1);
              if (face->at_boundary())
                {
                  mesh.boundary_ids[edge_key(a, b)] = face->boundary_id();
                  continue;
                }
              for (unsigned int l = 0; l < lines.size(); ++l)
                if (on_interface_line(lines[l], mesh.vertices[a], tol) &&
                    on_interface_line(lines[l], mesh.vertices[b], tol))
                  {
                    mesh.interface_ids[edge_key(a, b)] = lines[l].boundary_id;
                    ++faces_on_line[l];
                  }
            }
        }
      for (unsigned int l = 0; l < lines.size(); ++l)
        AssertThrow(faces_on_line[l] > 0,
                    ExcMessage(interface_lines_entry + ": line " +
                               std::to_string(lines[l].boundary_id) +
                               " runs along no interior mesh face"));
      return mesh;
    }

    /**
     * Split one vertex of an interface face: the cells around it, grouped
     * into the sets that stay connected through non-interface faces; every
     * set but the first gets its own copy of the vertex.
     */
    void
    split_vertex(const unsigned int               v,
                 const std::vector<unsigned int> &around,
                 CoarseMesh                      &mesh,
                 std::vector<unsigned int>       &original_of)
    {
      // Cell edges (as vertex pairs) in deal.II's face numbering.
      const auto edges_of = [&](const unsigned int c) {
        const auto &w = mesh.cell_vertices[c];
        return std::array<Edge, 4>{{edge_key(w[0], w[2]),
                                    edge_key(w[1], w[3]),
                                    edge_key(w[0], w[1]),
                                    edge_key(w[2], w[3])}};
      };
      std::vector<unsigned int> group(around.size());
      std::iota(group.begin(), group.end(), 0u);
      const std::function<unsigned int(unsigned int)> find =
        [&](unsigned int i) {
          return group[i] == i ? i : group[i] = find(group[i]);
        };
      for (unsigned int i = 0; i < around.size(); ++i)
        for (unsigned int j = i + 1; j < around.size(); ++j)
          for (const auto &e : edges_of(around[i]))
            {
              if ((e.first != v && e.second != v) ||
                  mesh.interface_ids.count(e))
                continue;
              const auto other = edges_of(around[j]);
              if (std::find(other.begin(), other.end(), e) != other.end())
                group[find(i)] = find(j);
            }
      std::map<unsigned int, unsigned int> copy_of_group;
      for (unsigned int i = 0; i < around.size(); ++i)
        {
          const unsigned int g = find(i);
          if (copy_of_group.empty())
            copy_of_group[g] = v;
          if (copy_of_group.count(g) == 0)
            {
              copy_of_group[g] = mesh.vertices.size();
              mesh.vertices.push_back(mesh.vertices[v]);
              original_of.push_back(v);
            }
          for (unsigned int &w : mesh.cell_vertices[around[i]])
            if (w == v)
              w = copy_of_group[g];
        }
    }

    /**
     * Give every vertex of an interface face one copy per side; returns the
     * original vertex of each (old and new) vertex.
     */
    std::vector<unsigned int>
    split_interface_vertices(CoarseMesh &mesh)
    {
      std::map<unsigned int, std::vector<unsigned int>> cells_at;
      for (unsigned int c = 0; c < mesh.cell_vertices.size(); ++c)
        for (const unsigned int v : mesh.cell_vertices[c])
          cells_at[v].push_back(c);
      std::set<unsigned int> split_vertices;
      // Axis vertices are split too: a shared axis node would pin the two
      // sides together at r = 0 (a spurious point restraint that, e.g., gave
      // a smooth surface footing a mesh-dependent horizontal stiffness). Each
      // copy gets the axis conditions (axis_constraints.cc keys nodes by DoF).
      for (const auto &[edge, id] : mesh.interface_ids)
        for (const unsigned int v : {edge.first, edge.second})
          split_vertices.insert(v);
      std::vector<unsigned int> original_of(mesh.vertices.size());
      std::iota(original_of.begin(), original_of.end(), 0u);
      for (const unsigned int v : split_vertices)
        split_vertex(v, cells_at[v], mesh, original_of);
      return original_of;
    }

    /**
     * Recreate the triangulation from the split mesh; faces take the ids
     * of the original edges they lie on (interface ids first).
     */
    void
    rebuild_triangulation(Triangulation<2>                &triangulation,
                          const CoarseMesh                &mesh,
                          const std::vector<unsigned int> &original_of)
    {
      std::vector<CellData<2>> cells(mesh.cell_vertices.size());
      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          cells[c].vertices    = {mesh.cell_vertices[c].begin(),
                                  mesh.cell_vertices[c].end()};
          cells[c].material_id = mesh.materials[c];
        }
      triangulation.clear();
      triangulation.create_triangulation(mesh.vertices, cells, SubCellData());
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const auto k = edge_key(original_of[face->vertex_index(0)],
                                      original_of[face->vertex_index(1)]);
              const auto i = mesh.interface_ids.find(k);
              if (i != mesh.interface_ids.end())
                face->set_boundary_id(i->second);
              else
                face->set_boundary_id(mesh.boundary_ids.at(k));
            }
    }
  } // namespace

  void
  split_along_interface_lines(Triangulation<2>                 &triangulation,
                              const std::vector<InterfaceLine> &lines,
                              const std::vector<double>        &r_breakpoints,
                              const std::vector<double>        &z_breakpoints)
  {
    AssertThrow(triangulation.n_levels() == 1,
                ExcMessage(interface_lines_entry +
                           ": the mesh must not be refined yet"));
    const double extent =
      std::max(r_breakpoints.back() - r_breakpoints.front(),
               z_breakpoints.back() - z_breakpoints.front());
    const double tol = 1e-10 * extent;
    check_lines_on_breakpoints(lines, r_breakpoints, z_breakpoints, tol);
    CoarseMesh mesh = read_coarse_mesh(triangulation, lines, tol);
    const std::vector<unsigned int> original_of =
      split_interface_vertices(mesh);
    rebuild_triangulation(triangulation, mesh, original_of);
  }
} // namespace FourierSSI
