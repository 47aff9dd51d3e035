#include <deal.II/base/exceptions.h>
#include <fourier_ssi/huge_page_allocation.h>
#include <fourier_ssi/sparse_direct.h>
#include <mutex>
#include <suitesparse/cholmod.h>


namespace FourierSSI
{
  namespace
  {
    // CHOLMOD's large arrays (the matrix copies of its analysis, the
    // permuted matrix, the factor) on huge pages, as the program's other
    // large blocks (huge_page_allocation.h).
    void
    use_huge_pages_in_suitesparse()
    {
      static std::once_flag once;
      std::call_once(once, [] {
        SuiteSparse_config.malloc_func = huge_page_malloc;
        SuiteSparse_config.calloc_func = huge_page_calloc;
      });
    }
  } // namespace

  // CHOLMOD state of one factorization; the 64-bit-index interface
  // (cholmod_l_*) so that large factors do not overflow.
  struct SparseDirect::Cholmod
  {
    cholmod_common  common;
    cholmod_factor *factor = nullptr;

    Cholmod()
    {
      use_huge_pages_in_suitesparse();
      cholmod_l_start(&common);
      // The caller reports failures in one line; CHOLMOD stays quiet.
      common.print = 0;
    }
    ~Cholmod()
    {
      if (factor)
        cholmod_l_free_factor(&factor, &common);
      cholmod_l_finish(&common);
    }
  };

  SparseDirect::SparseDirect(const std::string &backend)
    : backend(backend)
  {
    AssertThrow(backend == "cholesky" || backend == "lu",
                ExcMessage("SparseDirect: unknown back end '" + backend + "'"));
  }

  SparseDirect::~SparseDirect() = default;

  void
  SparseDirect::initialize(const SparseMatrix<double> &A)
  {
    const std::string singular =
      "Linear solver: the system matrix is singular (is the body free to "
      "move? check the supports and interface stiffness)";
    if (backend == "lu")
      {
        try
          {
            umfpack.initialize(A);
          }
        catch (const std::exception &)
          {
            AssertThrow(false, ExcMessage(singular + " [UMFPACK]"));
          }
        return;
      }

    cholmod           = std::make_unique<Cholmod>();
    cholmod_common &c = cholmod->common;
    // deal.II stores rows (CSR) with the diagonal first, then the other
    // columns in ascending order. The lower triangle of row j (columns
    // i <= j) is column j of the upper triangle in CSC: handed to CHOLMOD
    // as a symmetric matrix with stype = +1 (upper), sorted with the
    // diagonal last. The upper form is the one CHOLMOD's supernodal
    // factorization takes after one permuted transpose; the lower form
    // needed two.
    const types::global_dof_index n       = A.m();
    std::size_t                   n_upper = 0;
    for (types::global_dof_index j = 0; j < n; ++j)
      for (auto entry = A.begin(j); entry != A.end(j); ++entry)
        if (entry->column() <= j)
          ++n_upper;
    cholmod_sparse *upper = cholmod_l_allocate_sparse(
      n, n, n_upper, /*sorted=*/1, /*packed=*/1, 1, CHOLMOD_REAL, &c);
    AssertThrow(upper, ExcMessage("Linear solver: out of memory (CHOLMOD)"));
    auto       *column_start = static_cast<SuiteSparse_long *>(upper->p);
    auto       *row_index    = static_cast<SuiteSparse_long *>(upper->i);
    auto       *value        = static_cast<double *>(upper->x);
    std::size_t k            = 0;
    for (types::global_dof_index j = 0; j < n; ++j)
      {
        column_start[j]     = k;
        double diagonal     = 0.;
        bool   has_diagonal = false;
        for (auto entry = A.begin(j); entry != A.end(j); ++entry)
          if (entry->column() < j)
            {
              row_index[k] = entry->column();
              value[k]     = entry->value();
              ++k;
            }
          else if (entry->column() == j)
            {
              diagonal     = entry->value();
              has_diagonal = true;
            }
        if (has_diagonal)
          {
            row_index[k] = j;
            value[k]     = diagonal;
            ++k;
          }
      }
    column_start[n] = k;

    cholmod->factor     = cholmod_l_analyze(upper, &c);
    const bool analyzed = cholmod->factor != nullptr;
    if (analyzed)
      cholmod_l_factorize(upper, cholmod->factor, &c);
    cholmod_l_free_sparse(&upper, &c);
    AssertThrow(analyzed && c.status != CHOLMOD_OUT_OF_MEMORY,
                ExcMessage("Linear solver: out of memory (CHOLMOD)"));
    if (c.status == CHOLMOD_NOT_POSDEF)
      {
        // A zero or negative pivot: a rigid-body mode left free, or a
        // penalty so large that round-off broke positivity. UMFPACK's LU
        // then either fails (singular, reported) or gives a solution that
        // the callers' residual and foundation-support checks judge, with
        // the diagnosis that names the cause.
        cholmod.reset();
        backend = "lu";
        initialize(A);
        return;
      }
    AssertThrow(c.status == CHOLMOD_OK,
                ExcMessage("Linear solver: CHOLMOD failed (status " +
                           std::to_string(c.status) + ")"));
  }

  void
  SparseDirect::solve(std::vector<Vector<double>> &x) const
  {
    if (x.empty())
      return;
    if (backend == "lu")
      {
        for (Vector<double> &v : x)
          umfpack.solve(v);
        return;
      }
    Assert(cholmod && cholmod->factor, ExcMessage("not initialized"));
    cholmod_common   &c = cholmod->common;
    const std::size_t n = x[0].size();
    cholmod_dense    *rhs =
      cholmod_l_allocate_dense(n, x.size(), n, CHOLMOD_REAL, &c);
    AssertThrow(rhs, ExcMessage("Linear solver: out of memory (CHOLMOD)"));
    auto *b = static_cast<double *>(rhs->x);
    for (std::size_t j = 0; j < x.size(); ++j)
      std::copy(x[j].begin(), x[j].end(), b + j * n);
    cholmod_dense *solution =
      cholmod_l_solve(CHOLMOD_A, cholmod->factor, rhs, &c);
    cholmod_l_free_dense(&rhs, &c);
    AssertThrow(solution, ExcMessage("Linear solver: CHOLMOD solve failed"));
    const auto *s = static_cast<const double *>(solution->x);
    for (std::size_t j = 0; j < x.size(); ++j)
      std::copy(s + j * n, s + (j + 1) * n, x[j].begin());
    cholmod_l_free_dense(&solution, &c);
  }

  void
  SparseDirect::solve(Vector<double> &x) const
  {
    if (backend == "lu")
      {
        umfpack.solve(x);
        return;
      }
    std::vector<Vector<double>> one(1);
    one[0].swap(x);
    solve(one);
    x.swap(one[0]);
  }

  void
  SparseDirect::vmult(Vector<double> &x, const Vector<double> &b) const
  {
    x = b;
    solve(x);
  }
} // namespace FourierSSI
