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

  void
  ResultsTable::write_csv(const std::string &filename) const
  {
    AtomicFile    file(filename);
    std::ostream &out = file.stream();
    out << "quantity,n,family,cycle,value,unit\n" << std::setprecision(12);
    for (const ResultRow &row : table)
      out << row.quantity << ',' << row.harmonic.n << ','
          << to_string(row.harmonic.family) << ',' << row.cycle << ','
          << row.value << ',' << row.unit << '\n';
    file.commit();
  }
} // namespace FourierSSI
