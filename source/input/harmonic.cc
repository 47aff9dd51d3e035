#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <fourier_ssi/input/choice.h>
#include <fourier_ssi/input/harmonic.h>

namespace FourierSSI
{
  namespace
  {
    const Choices<Family> &
    families()
    {
      static const Choices<Family> choices(
        {{"symmetric", Family::symmetric},
         {"antisymmetric", Family::antisymmetric}},
        {{"sym", Family::symmetric}, {"anti", Family::antisymmetric}});
      return choices;
    }
  } // namespace

  std::string
  to_string(const Family family)
  {
    return families().name_of(family);
  }

  Family
  family_from_string(const std::string &name)
  {
    const std::optional<Family> family = families().find(name);
    AssertThrow(family.has_value(),
                dealii::ExcMessage(families().unknown("Fourier family", name)));
    return *family;
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
