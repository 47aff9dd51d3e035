#include <deal.II/dofs/dof_handler.h>
#include <fourier_ssi/harmonic/stress_postprocessor.h>

namespace FourierSSI
{
  StrainVector
  hooke_stress(const StrainVector &e, const double lambda, const double mu)
  {
    StrainVector s;
    const double trace = e[0] + e[1] + e[2];
    for (unsigned int k = 0; k < 3; ++k)
      s[k] = lambda * trace + 2. * mu * e[k];
    for (unsigned int k = 3; k < 6; ++k)
      s[k] = mu * e[k];
    return s;
  }

  StrainVector
  compliance_strain(const StrainVector &s, const double lambda, const double mu)
  {
    StrainVector e;
    const double trace = (s[0] + s[1] + s[2]) / (3. * lambda + 2. * mu);
    for (unsigned int k = 0; k < 3; ++k)
      e[k] = (s[k] - lambda * trace) / (2. * mu);
    for (unsigned int k = 3; k < 6; ++k)
      e[k] = s[k] / mu;
    return e;
  }

  StressPostprocessor::StressPostprocessor(
    const HarmonicOperator                  &harmonic_operator,
    const MaterialLibrary                   &materials,
    const std::vector<DilatationProjection> &dilatation)
    : harmonic_operator(harmonic_operator)
    , materials(materials)
    , dilatation(dilatation)
  {}

  void
  StressPostprocessor::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<2> &inputs,
    std::vector<Vector<double>>              &computed_quantities) const
  {
    const auto             cell     = inputs.template get_cell<2>();
    const ElasticMaterial &material = materials.get(cell->material_id());
    for (unsigned int q = 0; q < inputs.evaluation_points.size(); ++q)
      {
        const Point<2>             &x = inputs.evaluation_points[q];
        std::array<double, 3>       values;
        std::array<Tensor<1, 2>, 3> gradients;
        for (unsigned int c = 0; c < 3; ++c)
          {
            values[c]    = inputs.solution_values[q](c);
            gradients[c] = inputs.solution_gradients[q][c];
          }
        const double       depth = materials.depth(x[1]);
        const StrainVector e =
          bbar_strain(harmonic_operator.strain(values, gradients, x[0]),
                      dilatation,
                      cell->active_cell_index(),
                      x);
        const StrainVector s = hooke_stress(e,
                                            material.lambda(depth),
                                            material.shear_modulus(depth));
        for (unsigned int k = 0; k < 6; ++k)
          computed_quantities[q](k) = s[k];
      }
  }

  std::vector<std::string>
  StressPostprocessor::get_names() const
  {
    return {"sigma_r",
            "sigma_z",
            "sigma_theta",
            "tau_rz",
            "tau_ztheta",
            "tau_rtheta"};
  }

  UpdateFlags
  StressPostprocessor::get_needed_update_flags() const
  {
    return update_values | update_gradients | update_quadrature_points;
  }
} // namespace FourierSSI
