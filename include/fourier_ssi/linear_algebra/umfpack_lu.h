/**
 * UMFPACK's sparse LU of one fixed sparsity pattern, refactorized for new
 * values (the Newton tangent of the coupled harmonics, coupled_tangent.h).
 * Two differences from deal.II's SparseDirectUMFPACK, both measured on the
 * rough disc with 17 harmonics (doc/soil-plasticity.md section 8):
 *  - the symbolic analysis (the fill-reducing column order) is done once
 *    for the pattern and kept; every factorization is numeric only;
 *  - the solves skip UMFPACK's iterative refinement (Control[IRSTEP] = 0):
 *    each refinement step costs a product with the matrix, and a Newton
 *    direction needs no refinement (the next residual judges it).
 * The matrix is given by rows (CSR, columns sorted in each row); UMFPACK
 * reads that as the columns of the transpose, so the solve asks for the
 * transposed system.
 */
#ifndef fourier_ssi_umfpack_lu_h
#define fourier_ssi_umfpack_lu_h

#include <array>
#include <string>
#include <vector>

namespace FourierSSI
{
  class UmfpackLU
  {
  public:
    /** `what`: the start of the one-line message if a factorization fails. */
    explicit UmfpackLU(const std::string &what);
    ~UmfpackLU();
    UmfpackLU(const UmfpackLU &) = delete;
    UmfpackLU &
    operator=(const UmfpackLU &) = delete;

    /**
     * The pattern: row_start[i]..row_start[i+1] index `columns` (sorted in
     * each row) for the n = row_start.size() - 1 rows.
     */
    void
    set_pattern(std::vector<long> row_start, std::vector<long> columns);

    /** The values in the order of `columns` (set them, then factorize). */
    std::vector<double> &
    values()
    {
      return matrix_values;
    }

    /** LU of the current values; one line if the matrix is singular. */
    void
    factorize();

    /** x := A^-1 b (b and x of size n, distinct). */
    void
    solve(const std::vector<double> &b, std::vector<double> &x) const;

  private:
    std::string         what;
    std::vector<long>   row_start, columns;
    std::vector<double> matrix_values;
    std::vector<double> control;
    void               *symbolic = nullptr;
    void               *numeric  = nullptr;
  };
} // namespace FourierSSI

#endif
