/**
 * Scalar results of a run as CSV rows "quantity,n,family,cycle,value,unit":
 * the machine-readable output that tests, benchmarks and plot scripts read.
 */
#ifndef fourier_ssi_results_table_h
#define fourier_ssi_results_table_h

#include <fourier_ssi/input/harmonic.h>
#include <string>
#include <vector>

namespace FourierSSI
{
  struct ResultRow
  {
    std::string  quantity;
    Harmonic     harmonic;
    unsigned int cycle;
    double       value;
    std::string  unit;
  };

  class ResultsTable
  {
  public:
    void
    add(const std::string &quantity,
        const Harmonic    &harmonic,
        const unsigned int cycle,
        const double       value,
        const std::string &unit);

    /** Value of the last row with this quantity and harmonic; throws if none.
     */
    double
    get(const std::string &quantity,
        const Harmonic    &harmonic,
        const unsigned int cycle) const;

    void
    write_csv(const std::string &filename) const;

    const std::vector<ResultRow> &
    rows() const
    {
      return table;
    }

  private:
    std::vector<ResultRow> table;
  };
} // namespace FourierSSI

#endif
