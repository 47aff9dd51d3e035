#include <cmath>
#include <cstdlib>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <fourier_ssi/input/prm_values.h>

namespace FourierSSI
{
  double
  number_in_entry(const std::string &text, const std::string &entry)
  {
    const std::string t = dealii::Utilities::trim(text);
    // strtod also reads hexadecimal ("0x4E20" = 20000), "inf" and "nan":
    // none of them is a number a .prm means.
    const bool decimal =
      !t.empty() && t.find_first_not_of("0123456789.eE+-") == std::string::npos;
    char        *end = nullptr;
    const double v   = decimal ? std::strtod(t.c_str(), &end) : 0.;
    AssertThrow(decimal && end == t.c_str() + t.size(),
                dealii::ExcMessage(entry + ": '" + t + "' is not a number"));
    AssertThrow(std::isfinite(v),
                dealii::ExcMessage(entry + ": '" + t +
                                   "' is beyond the range of a double"));
    return v;
  }

  dealii::types::boundary_id
  boundary_id_in_entry(const std::string &text, const std::string &entry)
  {
    // ": coulomb, ..." (the id forgotten) would otherwise read as "'' is
    // not a number", which does not say what is missing.
    AssertThrow(!dealii::Utilities::trim(text).empty(),
                dealii::ExcMessage(entry + ": an item has no id before ':'"));
    const double v = number_in_entry(text, entry);
    AssertThrow(v >= 0. && v < 255. && v == std::floor(v),
                dealii::ExcMessage(entry + ": boundary id '" +
                                   dealii::Utilities::trim(text) +
                                   "' is not an integer in [0, 254]"));
    return static_cast<dealii::types::boundary_id>(v);
  }

  void
  record_key_once(std::set<std::string> &keys_given,
                  const std::string     &key,
                  const std::string     &entry,
                  const std::string     &item)
  {
    AssertThrow(keys_given.insert(key).second,
                dealii::ExcMessage(entry + ": '" + key + "' given twice in '" +
                                   dealii::Utilities::trim(item) + "'"));
  }
} // namespace FourierSSI
