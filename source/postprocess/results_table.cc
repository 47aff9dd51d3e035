#include <cmath>
#include <deal.II/base/exceptions.h>
#include <fourier_ssi/input/atomic_file.h>
#include <fourier_ssi/postprocess/results_table.h>
#include <fstream>
#include <iomanip>

namespace FourierSSI
{
  void
  ResultsTable::add(const std::string &quantity,
                    const Harmonic    &harmonic,
                    const unsigned int cycle,
                    const double       value,
                    const std::string &unit)
  {
    table.push_back({quantity, harmonic, cycle, value, unit});
  }

  double
  ResultsTable::get(const std::string &quantity,
                    const Harmonic    &harmonic,
                    const unsigned int cycle) const
  {
    for (auto it = table.rbegin(); it != table.rend(); ++it)
      if (it->quantity == quantity && it->harmonic.n == harmonic.n &&
          it->harmonic.family == harmonic.family && it->cycle == cycle)
        return it->value;
    AssertThrow(false,
                dealii::ExcMessage("no result '" + quantity + "' for " +
                                   harmonic.name()));
    return 0.;
  }

  namespace
  {
    /** An error estimate that is not finite was not estimated (a bar from
     * one mesh, a plateau from fewer than three steps): it has no row. */
    bool
    is_missing_estimate(const ResultRow &row)
    {
      return !std::isfinite(row.value) &&
             row.quantity.find("_error") != std::string::npos;
    }
  } // namespace

  void
  ResultsTable::write_csv(const std::string &filename) const
  {
    // results.csv holds finite numbers only; a result itself that is not
    // finite is a failed run, not a row.
    for (const ResultRow &row : table)
      AssertThrow(std::isfinite(row.value) || is_missing_estimate(row),
                  dealii::ExcMessage(
                    filename + ": the result '" + row.quantity + "' of " +
                    row.harmonic.name() + " is not a finite number"));
    AtomicFile    file(filename);
    std::ostream &out = file.stream();
    out << "quantity,n,family,cycle,value,unit\n" << std::setprecision(12);
    for (const ResultRow &row : table)
      if (!is_missing_estimate(row))
        out << row.quantity << ',' << row.harmonic.n << ','
            << to_string(row.harmonic.family) << ',' << row.cycle << ','
            << row.value << ',' << row.unit << '\n';
    file.commit();
  }
} // namespace FourierSSI
