#include <cmath>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <fourier_ssi/harmonic/stress_postprocessor.h>
#include <fourier_ssi/input/atomic_file.h>
#include <fourier_ssi/postprocess/field_reconstruction.h>
#include <fourier_ssi/postprocess/vtu_output.h>
#include <fstream>
#include <iomanip>

namespace FourierSSI
{
  namespace
  {
    /** Trig factors (of U, V and the in-plane stresses; of W) at theta. */
    std::pair<double, double>
    trig_factors(const Harmonic &h, const double theta)
    {
      const double c = std::cos(h.n * theta), s = std::sin(h.n * theta);
      return h.family == Family::symmetric ? std::make_pair(c, s) :
                                             std::make_pair(s, c);
    }
  } // namespace

  void
  FieldReconstruction::add(std::shared_ptr<const HarmonicProblem> problem)
  {
    problems.push_back(std::move(problem));
  }

  FieldValues
  FieldReconstruction::amplitudes(const HarmonicProblem &problem,
                                  const Point<2>        &point)
  {
    const DoFHandler<2> &dof_handler = problem.get_dof_handler();
    const MappingQ1<2>   mapping;
    const auto           found =
      GridTools::find_active_cell_around_point(mapping, dof_handler, point);
    AssertThrow(found.first.state() == IteratorState::valid,
                ExcMessage("3D reconstruction: point (" +
                           std::to_string(point[0]) + ", " +
                           std::to_string(point[1]) + ") is outside the mesh"));
    const auto &cell = found.first;
    FEValues<2> fe_values(mapping,
                          dof_handler.get_fe(),
                          Quadrature<2>(GeometryInfo<2>::project_to_unit_cell(
                            found.second)),
                          update_values | update_gradients);
    fe_values.reinit(cell);
    std::vector<Vector<double>>            values(1, Vector<double>(3));
    std::vector<std::vector<Tensor<1, 2>>> gradients(
      1, std::vector<Tensor<1, 2>>(3));
    fe_values.get_function_values(problem.get_solution(), values);
    fe_values.get_function_gradients(problem.get_solution(), gradients);

    FieldValues                 result;
    std::array<Tensor<1, 2>, 3> grad;
    for (unsigned int c = 0; c < 3; ++c)
      {
        result.displacement[c] = values[0](c);
        grad[c]                = gradients[0][c];
      }
    const MaterialLibrary &materials = problem.get_materials();
    const ElasticMaterial &material  = materials.get(cell->material_id());
    const double           depth     = materials.depth(point[1]);
    result.stress                    = hooke_stress(
      problem.output_strain(cell, point, result.displacement, grad),
      material.lambda(depth),
      material.shear_modulus(depth));
    return result;
  }

  FieldValues
  FieldReconstruction::evaluate(const Point<2> &point, const double theta) const
  {
    FieldValues sum;
    for (const auto &problem : problems)
      {
        const FieldValues a = amplitudes(*problem, point);
        const auto [in_plane, out_of_plane] =
          trig_factors(problem->get_operator().get_harmonic(), theta);
        sum.displacement[0] += a.displacement[0] * in_plane;
        sum.displacement[1] += a.displacement[1] * in_plane;
        sum.displacement[2] += a.displacement[2] * out_of_plane;
        for (unsigned int k = 0; k < 4; ++k)
          sum.stress[k] += a.stress[k] * in_plane;
        for (unsigned int k = 4; k < 6; ++k)
          sum.stress[k] += a.stress[k] * out_of_plane;
      }
    return sum;
  }

  void
  FieldReconstruction::write_lines_csv(const std::vector<OutputLine> &lines,
                                       const std::vector<double> &theta_degrees,
                                       const std::string &filename) const
  {
    AtomicFile    file(filename);
    std::ostream &out = file.stream();
    out << "line,point,r,z,theta_deg,x,y,u_r,u_z,u_theta,u_x,u_y,sigma_r,"
           "sigma_z,sigma_theta,tau_rz,tau_ztheta,tau_rtheta\n";
    out << std::setprecision(12);
    for (unsigned int l = 0; l < lines.size(); ++l)
      for (unsigned int i = 0; i < lines[l].n_points; ++i)
        {
          const double s =
            lines[l].n_points > 1 ? double(i) / (lines[l].n_points - 1) : 0.;
          const Point<2> p =
            lines[l].start + s * (lines[l].end - lines[l].start);
          // Amplitudes once per point, trig factors per angle.
          std::vector<FieldValues> a;
          for (const auto &problem : problems)
            a.push_back(amplitudes(*problem, p));
          for (const double degrees : theta_degrees)
            {
              const double theta = degrees * numbers::PI / 180.;
              FieldValues  v;
              for (unsigned int h = 0; h < problems.size(); ++h)
                {
                  const auto [c, s_] =
                    trig_factors(problems[h]->get_operator().get_harmonic(),
                                 theta);
                  for (unsigned int k = 0; k < 2; ++k)
                    v.displacement[k] += a[h].displacement[k] * c;
                  v.displacement[2] += a[h].displacement[2] * s_;
                  for (unsigned int k = 0; k < 6; ++k)
                    v.stress[k] += a[h].stress[k] * (k < 4 ? c : s_);
                }
              const double ct = std::cos(theta), st = std::sin(theta);
              out << l << ',' << i << ',' << p[0] << ',' << p[1] << ','
                  << degrees << ',' << p[0] * ct << ',' << p[0] * st << ','
                  << v.displacement[0] << ',' << v.displacement[1] << ','
                  << v.displacement[2] << ','
                  << v.displacement[0] * ct - v.displacement[2] * st << ','
                  << v.displacement[0] * st + v.displacement[2] * ct;
              for (const double sk : v.stress)
                out << ',' << sk;
              out << '\n';
            }
        }
    file.commit();
  }

  std::vector<std::array<double, 3>>
  FieldReconstruction::revolved_displacement(const unsigned int divisions) const
  {
    const unsigned int n_vertices =
      problems.front()->get_dof_handler().get_triangulation().n_vertices();
    // Amplitudes at the vertices, per harmonic: the vertex DoFs of FE_Q.
    std::vector<std::vector<std::array<double, 3>>> amplitude(
      problems.size(), std::vector<std::array<double, 3>>(n_vertices));
    for (unsigned int h = 0; h < problems.size(); ++h)
      for (const auto &cell :
           problems[h]->get_dof_handler().active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int c = 0; c < 3; ++c)
            amplitude[h][cell->vertex_index(v)][c] =
              problems[h]->get_solution()(cell->vertex_dof_index(v, c));

    std::vector<std::array<double, 3>> cylindrical(n_vertices * divisions,
                                                   {{0., 0., 0.}});
    for (unsigned int k = 0; k < divisions; ++k)
      for (unsigned int h = 0; h < problems.size(); ++h)
        {
          const auto [c, s] =
            trig_factors(problems[h]->get_operator().get_harmonic(),
                         2. * numbers::PI * k / divisions);
          for (unsigned int i = 0; i < n_vertices; ++i)
            {
              std::array<double, 3> &u = cylindrical[k * n_vertices + i];
              u[0] += amplitude[h][i][0] * c;
              u[1] += amplitude[h][i][1] * c;
              u[2] += amplitude[h][i][2] * s;
            }
        }
    return cylindrical;
  }

  void
  FieldReconstruction::write_revolved_vtu(const unsigned int divisions,
                                          const std::string &filename) const
  {
    AssertThrow(!problems.empty(), ExcMessage("3D VTU: nothing solved"));
    const Triangulation<2> &tria =
      problems.front()->get_dof_handler().get_triangulation();
    const std::vector<std::array<double, 3>> cylindrical =
      revolved_displacement(divisions);
    const unsigned int n_vertices = tria.n_vertices();
    // One hexahedron per cell and sector k: patch vertices 0-3 are the
    // cell's vertices at theta_k, 4-7 the same at theta_(k+1) (deal.II's
    // lexicographic order, which DataOutBase turns into VTK's).
    std::vector<DataOutBase::Patch<3, 3>> patches;
    for (unsigned int k = 0; k < divisions; ++k)
      for (const auto &cell : tria.active_cell_iterators())
        {
          DataOutBase::Patch<3, 3> patch;
          patch.patch_index    = patches.size();
          patch.reference_cell = ReferenceCells::Hexahedron;
          patch.data.reinit(6, 8);
          for (unsigned int v = 0; v < 8; ++v)
            {
              const unsigned int sector = (k + v / 4) % divisions;
              const Point<2>    &p      = cell->vertex(v % 4);
              const double       theta  = 2. * numbers::PI * sector / divisions;
              const double       ct = std::cos(theta), st = std::sin(theta);
              const std::array<double, 3> &u =
                cylindrical[sector * n_vertices + cell->vertex_index(v % 4)];
              patch.vertices[v] = revolved_point(p, theta);
              patch.data(0, v)  = u[0] * ct - u[2] * st;
              patch.data(1, v)  = u[0] * st + u[2] * ct;
              patch.data(2, v)  = u[1];
              for (unsigned int c = 0; c < 3; ++c)
                patch.data(3 + c, v) = u[c];
            }
          patches.push_back(std::move(patch));
        }
    write_patches_vtu(
      patches,
      {{"displacement", 3}, {"u_r", 1}, {"u_z", 1}, {"u_theta", 1}},
      filename);
  }
} // namespace FourierSSI
