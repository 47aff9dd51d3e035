#include <deal.II/base/exceptions.h>
#include <fourier_ssi/linear_algebra/huge_page_allocation.h>
#include <fourier_ssi/linear_algebra/sparse_direct.h>
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
  SparseDirect::initialize(
    const SparseMatrix<double>                              &A,
    const std::vector<std::vector<types::global_dof_index>> &eliminated_blocks)
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
    // The kept system after the cell interiors are condensed, handed to
    // CHOLMOD as its upper triangle (stype = +1): the form its supernodal
    // factorization takes after one permuted transpose.
    StaticCondensation::UpperMatrix kept;
    condensation.initialize(A, eliminated_blocks, kept);
    cholmod_sparse view{};
    view.nrow   = condensation.n_kept();
    view.ncol   = condensation.n_kept();
    view.nzmax  = kept.value.size();
    view.p      = kept.column_start.data();
    view.i      = kept.row_index.data();
    view.x      = kept.value.data();
    view.stype  = 1;
    view.itype  = CHOLMOD_LONG;
    view.xtype  = CHOLMOD_REAL;
    view.dtype  = CHOLMOD_DOUBLE;
    view.sorted = 1;
    view.packed = 1;

    cholmod->factor     = cholmod_l_analyze(&view, &c);
    const bool analyzed = cholmod->factor != nullptr;
    if (analyzed)
      cholmod_l_factorize(&view, cholmod->factor, &c);
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
        initialize(A, {});
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
    const std::size_t n = condensation.n_kept();
    cholmod_dense    *rhs =
      cholmod_l_allocate_dense(n, x.size(), n, CHOLMOD_REAL, &c);
    AssertThrow(rhs, ExcMessage("Linear solver: out of memory (CHOLMOD)"));
    condensation.condense(x, static_cast<double *>(rhs->x));
    cholmod_dense *solution =
      cholmod_l_solve(CHOLMOD_A, cholmod->factor, rhs, &c);
    cholmod_l_free_dense(&rhs, &c);
    AssertThrow(solution, ExcMessage("Linear solver: CHOLMOD solve failed"));
    condensation.expand(static_cast<const double *>(solution->x), x);
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
