#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <fourier_ssi/input/harmonic.h>

namespace FourierSSI
{
  std::string
  to_string(const Family family)
  {
    return family == Family::symmetric ? "symmetric" : "antisymmetric";
  }

  Family
  family_from_string(const std::string &name)
  {
    if (name == "symmetric" || name == "sym")
      return Family::symmetric;
    if (name == "antisymmetric" || name == "anti")
      return Family::antisymmetric;
    AssertThrow(false,
                dealii::ExcMessage("unknown Fourier family '" + name +
                                   "' (expected symmetric or antisymmetric)"));
    return Family::symmetric;
  }

  double
  Harmonic::in_plane_weight() const
  {
    if (n > 0)
      return dealii::numbers::PI;
    return family == Family::symmetric ? 2. * dealii::numbers::PI : 0.;
  }

  double
  Harmonic::out_of_plane_weight() const
  {
    if (n > 0)
      return dealii::numbers::PI;
    return family == Family::antisymmetric ? 2. * dealii::numbers::PI : 0.;
  }

  std::string
  Harmonic::name() const
  {
    return "n=" + std::to_string(n) + " " + to_string(family);
  }
} // namespace FourierSSI
