#include <deal.II/base/exceptions.h>
#include <fourier_ssi/linear_algebra/umfpack_lu.h>
#include <suitesparse/umfpack.h>

namespace FourierSSI
{
  UmfpackLU::UmfpackLU(const std::string &what)
    : what(what)
    , control(UMFPACK_CONTROL)
  {
    umfpack_dl_defaults(control.data());
    control[UMFPACK_IRSTEP] = 0;
  }

  UmfpackLU::~UmfpackLU()
  {
    if (numeric)
      umfpack_dl_free_numeric(&numeric);
    if (symbolic)
      umfpack_dl_free_symbolic(&symbolic);
  }

  void
  UmfpackLU::set_pattern(std::vector<long> new_row_start,
                         std::vector<long> new_columns)
  {
    if (numeric)
      umfpack_dl_free_numeric(&numeric);
    if (symbolic)
      umfpack_dl_free_symbolic(&symbolic);
    row_start = std::move(new_row_start);
    columns   = std::move(new_columns);
    matrix_values.assign(columns.size(), 0.);
  }

  void
  UmfpackLU::factorize()
  {
    const long n = static_cast<long>(row_start.size()) - 1;
    if (numeric)
      umfpack_dl_free_numeric(&numeric);
    // The pattern's column order, once: the values do not enter it (the
    // default strategy orders by the pattern of A^T + A or A^T A).
    if (!symbolic)
      {
        const long status = umfpack_dl_symbolic(n,
                                                n,
                                                row_start.data(),
                                                columns.data(),
                                                matrix_values.data(),
                                                &symbolic,
                                                control.data(),
                                                nullptr);
        AssertThrow(status == UMFPACK_OK,
                    dealii::ExcMessage(what +
                                       ": UMFPACK's analysis failed "
                                       "(status " +
                                       std::to_string(status) + ")"));
      }
    const long status = umfpack_dl_numeric(row_start.data(),
                                           columns.data(),
                                           matrix_values.data(),
                                           symbolic,
                                           &numeric,
                                           control.data(),
                                           nullptr);
    AssertThrow(status == UMFPACK_OK,
                dealii::ExcMessage(
                  what + (status == UMFPACK_WARNING_singular_matrix ?
                            std::string(": the matrix is singular") :
                            ": UMFPACK's factorization failed (status " +
                              std::to_string(status) + ")")));
  }

  void
  UmfpackLU::solve(const std::vector<double> &b, std::vector<double> &x) const
  {
    x.resize(b.size());
    // The arrays hold the rows of A, i.e. the columns of A^T: UMFPACK_At
    // solves (A^T)^T x = A x = b.
    const long status = umfpack_dl_solve(UMFPACK_At,
                                         row_start.data(),
                                         columns.data(),
                                         matrix_values.data(),
                                         x.data(),
                                         b.data(),
                                         numeric,
                                         control.data(),
                                         nullptr);
    AssertThrow(status == UMFPACK_OK,
                dealii::ExcMessage(what + ": UMFPACK's solve failed (status " +
                                   std::to_string(status) + ")"));
  }
} // namespace FourierSSI
