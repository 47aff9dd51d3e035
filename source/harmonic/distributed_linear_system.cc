#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/affine_constraints.templates.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <fourier_ssi/harmonic/assembly_loop.h>
#include <fourier_ssi/harmonic/distributed_linear_system.h>

namespace FourierSSI
{
  DistributedLinearSystem::DistributedLinearSystem(
    const MPI_Comm                communicator,
    const LinearSolverParameters &solver_parameters)
    : communicator(communicator)
    , parameters(solver_parameters)
    , rank(Utilities::MPI::this_mpi_process(communicator))
  {}

  void
  DistributedLinearSystem::setup(const DoFHandler<2>             &dof_handler,
                                 const AffineConstraints<double> &constraints,
                                 const InterfaceIntegrator       *interfaces)
  {
    this->dof_handler = &dof_handler;
    this->constraints = &constraints;
    this->interfaces  = interfaces;
    amg.reset();
    direct.reset();
    const Triangulation<2> &triangulation = dof_handler.get_triangulation();
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);

    // Cell partition: METIS on the face graph, computed on rank 0 and
    // broadcast so that every rank holds the same one (the pairs straddling
    // the interface are not face neighbours: the graph is cut there anyway).
    cell_partition.assign(triangulation.n_active_cells(), 0);
    if (rank == 0 && n_ranks > 1)
      {
        DynamicSparsityPattern connectivity;
        GridTools::get_face_connectivity_of_cells(triangulation, connectivity);
        SparsityPattern graph;
        graph.copy_from(connectivity);
        SparsityTools::partition(graph,
                                 n_ranks,
                                 cell_partition,
                                 SparsityTools::Partitioner::metis);
      }
    cell_partition =
      Utilities::MPI::broadcast(communicator, cell_partition, /*root=*/0);

    // A DoF belongs to the lowest rank among the cells that touch it.
    std::vector<unsigned int> dof_owner(dof_handler.n_dofs(), n_ranks);
    std::vector<types::global_dof_index> dof_indices(
      dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dof_indices);
        for (const auto i : dof_indices)
          dof_owner[i] =
            std::min(dof_owner[i], cell_partition[cell->active_cell_index()]);
      }
    owned_dofs = IndexSet(dof_handler.n_dofs());
    for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
      if (dof_owner[i] == rank)
        owned_dofs.add_index(i);
    owned_dofs.compress();

    n_straddling = 0;
    if (interfaces)
      for (const InterfacePair &pair : interfaces->get_pairs())
        if (cell_partition[pair.cells[0]] != cell_partition[pair.cells[1]])
          ++n_straddling;

    // The owned rows, complete: loop over all cells and pairs (the mesh is
    // replicated) and let the pattern drop the rows of other ranks.
    DynamicSparsityPattern dsp(dof_handler.n_dofs(),
                               dof_handler.n_dofs(),
                               owned_dofs);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    dsp,
                                    constraints,
                                    /*keep_constrained_dofs=*/false);
    if (interfaces)
      interfaces->add_sparsity(constraints, dsp);
    matrix.reinit(owned_dofs, owned_dofs, dsp, communicator);
  }

  double
  DistributedLinearSystem::assemble(const LocalMatrixFactory &local_matrix,
                                    Vector<double>           &rhs)
  {
    matrix = 0.;
    Vector<double> local_rhs(dof_handler->n_dofs());
    const double   interface_time = assemble_owned(
      *dof_handler,
      *constraints,
      interfaces,
      [this](const unsigned int cell) { return cell_partition[cell] == rank; },
      local_matrix,
      1, // MPI ranks fill the cores
      matrix,
      local_rhs);
    // Rows written on other ranks are summed into their owners here.
    matrix.compress(VectorOperation::add);
    // The load is replicated (postprocessing needs it whole): sum the parts.
    rhs.reinit(dof_handler->n_dofs());
    Utilities::MPI::sum(make_array_view(std::as_const(local_rhs)),
                        communicator,
                        make_array_view(rhs));
    return interface_time;
  }

  SolverReport
  DistributedLinearSystem::solve(Vector<double> &x, const Vector<double> &b)
  {
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    SolverReport       report;
    report.method = parameters.method_name() + " (" + std::to_string(n_ranks) +
                    " ranks, " +
                    (parameters.is_direct() ? "MUMPS" : "Trilinos") + ")";
    // Same shortcut as the serial solver: a zero load has the zero solution.
    if (b.l2_norm() == 0.)
      {
        x = 0.;
        report.method += " (scene load zero: its solution is 0, not solved)";
        return report;
      }
    TrilinosWrappers::MPI::Vector b_owned(owned_dofs, communicator);
    TrilinosWrappers::MPI::Vector x_owned(owned_dofs, communicator);
    for (const auto i : owned_dofs)
      {
        b_owned[i] = b(i);
        x_owned[i] = x(i); // the initial guess, as in the serial cg-amg
      }
    b_owned.compress(VectorOperation::insert);
    x_owned.compress(VectorOperation::insert);

    if (parameters.is_direct())
      solve_direct(x_owned, b_owned);
    else
      report.iterations = solve_cg_amg(x_owned, b_owned);

    TrilinosWrappers::MPI::Vector residual(owned_dofs, communicator);
    matrix.vmult(residual, x_owned);
    residual -= b_owned;
    report.relative_residual =
      LinearSolver(parameters)
        .checked_relative_residual(residual.l2_norm(), b_owned.l2_norm());

    // Replicate the solution: every rank runs the serial postprocessing.
    Vector<double> part(x.size());
    for (const auto i : owned_dofs)
      part(i) = x_owned[i];
    Utilities::MPI::sum(make_array_view(std::as_const(part)),
                        communicator,
                        make_array_view(x));
    return report;
  }

  void
  DistributedLinearSystem::solve_direct(TrilinosWrappers::MPI::Vector       &x,
                                        const TrilinosWrappers::MPI::Vector &b)
  {
    if (!direct)
      {
        // MUMPS through Amesos: a distributed multifrontal factorization,
        // reused for the unit-H and unit-M cases.
        direct = std::make_unique<TrilinosWrappers::SolverDirect>(
          direct_control,
          TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                         "Amesos_Mumps"));
        try
          {
            direct->initialize(matrix);
          }
        catch (const std::exception &)
          {
            AssertThrow(false,
                        ExcMessage(
                          "Linear solver: MUMPS could not factorize the "
                          "matrix (singular system: is the body free to "
                          "move? check the supports)"));
          }
      }
    direct->solve(x, b);
  }

  unsigned int
  DistributedLinearSystem::solve_cg_amg(TrilinosWrappers::MPI::Vector       &x,
                                        const TrilinosWrappers::MPI::Vector &b)
  {
    if (!amg)
      {
        // The serial cg-amg settings (linear_solver.cc): ML with a
        // constant per component as near-null space (global-size masks;
        // deal.II picks the owned entries).
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.higher_order_elements = dof_handler->get_fe().degree > 1;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        std::vector<std::vector<bool>> constant_modes;
        DoFTools::extract_constant_modes(*dof_handler,
                                         ComponentMask(3, true),
                                         constant_modes);
        data.constant_modes = constant_modes;
        amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        amg->initialize(matrix, data);
      }
    SolverControl control(parameters.max_iterations,
                          parameters.tolerance * b.l2_norm());
    // deal.II's CG, as in the serial path: AztecOO's CG stops with "loss
    // of precision" on the stiff-interface systems (kn = 1e10).
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    try
      {
        cg.solve(matrix, x, b, *amg);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        LinearSolver::fail_to_converge(e);
      }
    return control.last_step();
  }
} // namespace FourierSSI
