// HarmonicProblem, part 2: B-bar for FE_Q(2) (Volumetric strain = bbar):
// the dilatation of every shape function, and of the solution for output,
// projected onto the cell's linear polynomials (the Q2-P1disc pressure
// space), doc/robustness.md.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>
#include <fourier_ssi/harmonic/bbar_projection.h>
#include <fourier_ssi/harmonic/harmonic_problem.h>
#include <fourier_ssi/harmonic/stress_postprocessor.h>
#include <fstream>

namespace FourierSSI
{
  LinearProjection::LinearProjection(const FEValues<2> &fe_values)
    : n_q(fe_values.n_quadrature_points)
    , dV(n_q)
    , points(n_q)
    , inverse(3, 3)
  {
    double volume = 0.;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        points[q] = fe_values.quadrature_point(q);
        dV[q]     = points[q][0] * fe_values.JxW(q);
        center += dV[q] * points[q];
        volume += dV[q];
      }
    valid = volume > 0.; // a degenerate cell (zero r-weighted volume)
    if (!valid)
      return;
    center /= volume;
    FullMatrix<double> mass(3, 3);
    for (unsigned int q = 0; q < n_q; ++q)
      {
        const auto p = basis(points[q]);
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            mass(a, b) += p[a] * p[b] * dV[q];
      }
    inverse.invert(mass);
  }

  std::array<double, 3>
  LinearProjection::project(const std::vector<double> &f) const
  {
    std::array<double, 3> moments = {{0., 0., 0.}}, c = {{0., 0., 0.}};
    for (unsigned int q = 0; q < n_q; ++q)
      {
        const auto p = basis(points[q]);
        for (unsigned int a = 0; a < 3; ++a)
          moments[a] += p[a] * f[q] * dV[q];
      }
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        c[a] += inverse(a, b) * moments[b];
    return c;
  }


  StrainVector
  with_dilatation(const StrainVector &strain, const double dilatation)
  {
    StrainVector e     = strain;
    const double shift = (dilatation - (e[0] + e[1] + e[2])) / 3.;
    for (unsigned int k = 0; k < 3; ++k)
      e[k] += shift;
    return e;
  }

  StrainVector
  bbar_strain(const StrainVector                      &strain,
              const std::vector<DilatationProjection> &dilatation,
              const unsigned int                       cell_index,
              const Point<2>                          &x)
  {
    if (dilatation.empty() || !dilatation[cell_index].valid())
      return strain;
    return with_dilatation(strain, dilatation[cell_index].value(x));
  }

  void
  HarmonicProblem::replace_dilatation(
    const FEValues<2>                      &fe_values,
    std::vector<std::vector<StrainVector>> &strain_at) const
  {
    // B-bar (Hughes 1980): the dilatation e_r + e_z + e_t of each shape
    // function is replaced by its projection onto the cell's linear
    // polynomials (LinearProjection); the deviatoric part is kept. The
    // dilatation carries the in-plane trig factor for every n, so the same
    // projection serves every harmonic.
    const LinearProjection projection(fe_values);
    if (!projection.valid)
      return; // a degenerate cell: leave the strains alone
    const unsigned int  n_q           = strain_at.size();
    const unsigned int  dofs_per_cell = strain_at[0].size();
    std::vector<double> dilatation(n_q);
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      {
        for (unsigned int q = 0; q < n_q; ++q)
          dilatation[q] =
            strain_at[q][i][0] + strain_at[q][i][1] + strain_at[q][i][2];
        const DilatationProjection projected{projection.center,
                                             projection.project(dilatation)};
        for (unsigned int q = 0; q < n_q; ++q)
          strain_at[q][i] =
            with_dilatation(strain_at[q][i],
                            projected.value(projection.points[q]));
      }
  }

  void
  HarmonicProblem::project_solution_dilatation()
  {
    dilatation_projection.clear();
    if (parameters.discretization.volumetric != VolumetricStrain::bbar ||
        fe->degree != 2)
      return;
    FEValues<2>                           &fe_values = *cell_values;
    const unsigned int                     n_q = fe_values.n_quadrature_points;
    std::vector<Vector<double>>            values(n_q, Vector<double>(3));
    std::vector<std::vector<Tensor<1, 2>>> gradients(
      n_q, std::vector<Tensor<1, 2>>(3));
    std::vector<double> dilatation(n_q);
    dilatation_projection.resize(
      dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        const LinearProjection projection(fe_values);
        if (!projection.valid)
          continue; // no correction: value() of a default projection is NaN
        fe_values.get_function_values(solution, values);
        fe_values.get_function_gradients(solution, gradients);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            std::array<double, 3>       v;
            std::array<Tensor<1, 2>, 3> g;
            for (unsigned int c = 0; c < 3; ++c)
              {
                v[c] = values[q](c);
                g[c] = gradients[q][c];
              }
            const StrainVector e =
              harmonic_operator.strain(v, g, projection.points[q][0]);
            dilatation[q] = e[0] + e[1] + e[2];
          }
        dilatation_projection[cell->active_cell_index()] = {
          projection.center, projection.project(dilatation)};
      }
  }

  StrainVector
  HarmonicProblem::output_strain(
    const typename Triangulation<2>::active_cell_iterator &cell,
    const Point<2>                                        &x,
    const std::array<double, 3>                           &values,
    const std::array<Tensor<1, 2>, 3>                     &gradients) const
  {
    return bbar_strain(harmonic_operator.strain(values, gradients, x[0]),
                       dilatation_projection,
                       cell->active_cell_index(),
                       x);
  }
} // namespace FourierSSI
