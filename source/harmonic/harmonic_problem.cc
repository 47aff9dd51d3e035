// HarmonicProblem, part 1: the element, DoFs and constraints, the assembly
// (cells and closed-form interface pairs through one loop), the solves and
// the kept factorization. Parts 2-4: bbar_projection.cc,
// harmonic_postprocessing.cc, harmonic_output.cc.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_templates.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>
#include <fourier_ssi/harmonic/assembly_loop.h>
#include <fourier_ssi/harmonic/axis_constraints.h>
#include <fourier_ssi/harmonic/harmonic_problem.h>
#include <fourier_ssi/harmonic/rigid_foundation.h>
#include <fourier_ssi/harmonic/stress_postprocessor.h>
#include <fourier_ssi/linear_algebra/sparse_direct.h>
#include <fstream>

namespace FourierSSI
{
  std::unique_ptr<FESystem<2>>
  make_displacement_element(const unsigned int degree)
  {
    AssertThrow(degree == 2 || degree == 4,
                ExcMessage("Discretization/Polynomial degree must be 2 or 4"));
    // Equidistant support points: the interface elements of the thesis
    // (3 and 5 node pairs) are defined on equally spaced nodes.
    const FE_Q<2> fe_q(QIterated<1>(QTrapezoid<1>(), degree));
    return std::make_unique<FESystem<2>>(fe_q, 3);
  }

  HarmonicProblem::HarmonicProblem(const AllParameters     &parameters,
                                   const Harmonic          &harmonic,
                                   const Triangulation<2>  &triangulation,
                                   const LoadDecomposition *loads,
                                   const MPI_Comm           communicator)
    : parameters(parameters)
    , harmonic_operator(harmonic)
    , fe(make_displacement_element(parameters.discretization.degree))
    , dof_handler(triangulation)
    , loads(loads)
  {
    AssertThrow(loads || !parameters.loads.any(),
                ExcMessage("the Loads subsection needs a scene plan"));
    const auto &bc = parameters.boundary_conditions;
    body_force     = BoundaryConditions::make_function(bc.body_force,
                                                   harmonic.n,
                                                   "Body force");
    for (const auto &[id, e] : bc.traction)
      tractions[id].push_back(BoundaryConditions::make_function(
        e, harmonic.n, "Boundary conditions/Traction"));
    if (loads)
      for (const auto &[id, load] : loads->traction)
        tractions[id].push_back(load->amplitude_function(harmonic));
    axis_tolerance = 1e-10 * GridTools::diameter(triangulation);
    // Gauss rule exact for the polynomial part of the integrands; the 1/r
    // terms are smooth on cells away from the axis and integrable on it.
    cell_values =
      std::make_unique<FEValues<2>>(*fe,
                                    QGauss<2>(fe->degree + 2),
                                    update_values | update_gradients |
                                      update_quadrature_points |
                                      update_JxW_values);
    face_values = std::make_unique<FEFaceValues<2>>(*fe,
                                                    QGauss<1>(fe->degree + 2),
                                                    update_values |
                                                      update_quadrature_points |
                                                      update_JxW_values);
    if (parameters.rigid_foundation.enabled)
      foundation =
        std::make_unique<RigidFoundation>(parameters.rigid_foundation,
                                          harmonic);
    if (parameters.interfaces.enabled())
      interfaces = std::make_unique<InterfaceIntegrator>(parameters.interfaces,
                                                         parameters.materials,
                                                         harmonic);
    if (uses_distributed_solve(parameters.solver, communicator))
      distributed =
        std::make_unique<DistributedLinearSystem>(communicator,
                                                  parameters.solver);
  }

  HarmonicProblem::~HarmonicProblem() = default;

  void
  HarmonicProblem::setup_system()
  {
    dof_handler.distribute_dofs(*fe);
    check_boundary_ids();
    make_constraints();
    factorization.reset();

    system_rhs.reinit(dof_handler.n_dofs());
    solution.reinit(dof_handler.n_dofs());
    if (distributed)
      {
        if (interfaces)
          interfaces->setup(dof_handler);
        distributed->setup(dof_handler, constraints, interfaces.get());
        return;
      }
    make_serial_matrix();
  }

  void
  HarmonicProblem::check_boundary_ids() const
  {
    const auto boundary_ids =
      dof_handler.get_triangulation().get_boundary_ids();
    const auto check_id = [&](const types::boundary_id id,
                              const std::string       &entry) {
      AssertThrow(std::find(boundary_ids.begin(), boundary_ids.end(), id) !=
                    boundary_ids.end(),
                  ExcMessage(entry + ": boundary id " + std::to_string(id) +
                             " does not exist on the mesh"));
    };
    for (const auto &[id, e] : parameters.boundary_conditions.dirichlet)
      check_id(id, "Boundary conditions/Dirichlet");
    for (const auto &[id, e] : parameters.boundary_conditions.traction)
      check_id(id, "Boundary conditions/Traction");
  }

  void
  HarmonicProblem::make_constraints()
  {
    constraints.clear();
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    for (const auto &[id, e] : parameters.boundary_conditions.dirichlet)
      {
        const auto function =
          BoundaryConditions::make_function(e,
                                            harmonic_operator.get_harmonic().n,
                                            "Boundary conditions/Dirichlet");
        VectorTools::interpolate_boundary_values(
          dof_handler,
          id,
          *function,
          constraints,
          ComponentMask(std::vector<bool>(e.given.begin(), e.given.end())));
      }
    if (loads)
      for (const auto &[id, load] : loads->displacement)
        {
          const std::array<bool, 3> &given =
            loads->displacement_components.at(id);
          VectorTools::interpolate_boundary_values(
            dof_handler,
            id,
            *load->amplitude_function(harmonic_operator.get_harmonic()),
            constraints,
            ComponentMask(std::vector<bool>(given.begin(), given.end())));
        }
    // The rigid foundation first: its motion satisfies the axis conditions.
    if (foundation)
      foundation->add_constraints(dof_handler, constraints);
    // Exact interface ties next: a tied twin then follows the foundation or
    // the axis condition of its partner.
    if (interfaces)
      {
        interfaces->setup(dof_handler);
        interfaces->add_tie_constraints(constraints,
                                        foundation ?
                                          foundation->master_dofs() :
                                          std::set<types::global_dof_index>());
      }
    n_axis_nodes = add_axis_constraints(dof_handler,
                                        harmonic_operator.get_harmonic(),
                                        axis_tolerance,
                                        constraints);
    // Held motions last: the foundation keeps the constraints without them
    // to read the load that holds them.
    if (foundation)
      foundation->add_held_motion_constraints(constraints);
    constraints.close();
    homogeneous_constraints.clear();
    homogeneous_constraints.copy_from(constraints);
    for (const auto &line : constraints.get_lines())
      homogeneous_constraints.set_inhomogeneity(line.index, 0.);
  }

  void
  HarmonicProblem::make_serial_matrix()
  {
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler,
                                    dsp,
                                    constraints,
                                    /*keep_constrained_dofs=*/false);
    if (interfaces)
      {
        interfaces->add_sparsity(constraints, dsp);
      }
    sparsity_pattern.copy_from(dsp);
    system_matrix.reinit(sparsity_pattern);
  }

  namespace
  {
    /** Squares of the energy density (energy_factor_table()). */
    constexpr unsigned int energy_squares = 7;

    /**
     * matrix = G^T G (G: rows x columns, stored by rows) by BLAS syrk.
     * Stored by rows, G is G^T by columns and matrix's lower triangle is
     * the upper triangle syrk fills by columns; it is mirrored: exactly
     * symmetric, as the direct solvers read one triangle only.
     */
    void
    gram_matrix(const FullMatrix<double> &G, FullMatrix<double> &matrix)
    {
      const types::blas_int n = G.n(), k = G.m();
      const double          one = 1., zero = 0.;
      matrix.reinit(n, n, /*omit_default_initialization=*/true);
      syrk("U", "N", &n, &k, &one, &G(0, 0), &n, &zero, &matrix(0, 0), &n);
      for (types::blas_int i = 0; i < n; ++i)
        for (types::blas_int j = i + 1; j < n; ++j)
          matrix(i, j) = matrix(j, i);
    }
  } // namespace

  void
  HarmonicProblem::local_matrix(
    const typename DoFHandler<2>::active_cell_iterator &cell,
    FullMatrix<double>                                 &matrix,
    Vector<double>                                     *rhs) const
  {
    local_matrix(*cell_values, *face_values, cell, matrix, rhs);
  }

  LocalMatrixFactory
  HarmonicProblem::local_matrix_factory() const
  {
    return [this]() -> LocalMatrix {
      auto values =
        std::make_shared<FEValues<2>>(cell_values->get_mapping(),
                                      cell_values->get_fe(),
                                      cell_values->get_quadrature(),
                                      cell_values->get_update_flags());
      auto face =
        std::make_shared<FEFaceValues<2>>(face_values->get_mapping(),
                                          face_values->get_fe(),
                                          face_values->get_quadrature(),
                                          face_values->get_update_flags());
      return [this, values, face](const auto &cell, auto &matrix, auto *rhs) {
        local_matrix(*values, *face, cell, matrix, rhs);
      };
    };
  }

  void
  HarmonicProblem::local_matrix(
    FEValues<2>                                        &fe_values,
    FEFaceValues<2>                                    &fe_face_values,
    const typename DoFHandler<2>::active_cell_iterator &cell,
    FullMatrix<double>                                 &matrix,
    Vector<double>                                     *rhs) const
  {
    fe_values.reinit(cell);
    const unsigned int dofs_per_cell = fe->n_dofs_per_cell();
    if (rhs)
      rhs->reinit(dofs_per_cell);

    const ElasticMaterial &material =
      parameters.materials.get(cell->material_id());
    std::vector<unsigned int> component(dofs_per_cell);
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      component[i] = fe->system_to_component_index(i).first;

    const std::vector<std::vector<StrainVector>> strain_at =
      shape_function_strains(fe_values, component);
    FullMatrix<double> factor_table(energy_squares *
                                      fe_values.n_quadrature_points,
                                    dofs_per_cell);
    energy_factor_table(fe_values, material, strain_at, factor_table);
    gram_matrix(factor_table, matrix);

    if (rhs)
      {
        local_body_force(fe_values, component, *rhs);
        local_traction(fe_face_values, cell, *rhs);
      }
  }

  std::vector<std::vector<StrainVector>>
  HarmonicProblem::shape_function_strains(
    const FEValues<2>               &fe_values,
    const std::vector<unsigned int> &component) const
  {
    const unsigned int                     dofs_per_cell = component.size();
    const unsigned int                     n_q = fe_values.n_quadrature_points;
    std::vector<std::vector<StrainVector>> strain_at(
      n_q, std::vector<StrainVector>(dofs_per_cell));
    for (const unsigned int q : fe_values.quadrature_point_indices())
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        strain_at[q][i] =
          harmonic_operator.strain_of_component(component[i],
                                                fe_values.shape_value(i, q),
                                                fe_values.shape_grad(i, q),
                                                fe_values.quadrature_point(
                                                  q)[0]);
    if (parameters.discretization.volumetric == VolumetricStrain::bbar &&
        fe->degree == 2)
      replace_dilatation(fe_values, strain_at);
    return strain_at;
  }

  void
  HarmonicProblem::energy_factor_table(
    const FEValues<2>                            &fe_values,
    const ElasticMaterial                        &material,
    const std::vector<std::vector<StrainVector>> &strain_at,
    FullMatrix<double>                           &factor_table) const
  {
    // matrix = sum over q of strain_q^T W D strain_q dV (W: the theta
    // integral of each strain's trig factor, equal on rr, zz, tt, rz). With
    // the bulk modulus K = lambda + 2 mu / 3 > 0 (nu > -1) the energy
    // density is K tr^2 + 2 mu |dev e_normal|^2 + mu (e_rz^2 + e_zt^2 +
    // e_rt^2) per weight, a sum of 7 squares: matrix = G^T G with G the
    // stacked (7 n_q) x dofs table of their square roots, one BLAS syrk
    // (half the flops of the general product of the 6-row strain and
    // stress tables it replaces; doc/accuracy-vs-time.md, "Where the time
    // goes").
    constexpr unsigned int squares       = energy_squares;
    const unsigned int     dofs_per_cell = factor_table.n();
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const Point<2> &x     = fe_values.quadrature_point(q);
        const double    r     = x[0];
        const double    depth = parameters.materials.depth(x[1]);
        const double    mu    = material.shear_modulus(depth);
        const double    bulk  = material.lambda(depth) + 2. * mu / 3.;
        const double    dV    = r * fe_values.JxW(q);
        const double    in    = harmonic_operator.weight(StrainIndex::rr) * dV;
        const double    out   = harmonic_operator.weight(StrainIndex::rt) * dV;
        const std::array<double, squares> scale = {{std::sqrt(bulk * in),
                                                    std::sqrt(2. * mu * in),
                                                    std::sqrt(2. * mu * in),
                                                    std::sqrt(2. * mu * in),
                                                    std::sqrt(mu * in),
                                                    std::sqrt(mu * out),
                                                    std::sqrt(mu * out)}};
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            const StrainVector               &e     = strain_at[q][i];
            const double                      trace = e[0] + e[1] + e[2];
            const std::array<double, squares> part  = {{trace,
                                                        e[0] - trace / 3.,
                                                        e[1] - trace / 3.,
                                                        e[2] - trace / 3.,
                                                        e[StrainIndex::rz],
                                                        e[StrainIndex::zt],
                                                        e[StrainIndex::rt]}};
            for (unsigned int k = 0; k < squares; ++k)
              factor_table(squares * q + k, i) = scale[k] * part[k];
          }
      }
  }

  void
  HarmonicProblem::local_body_force(const FEValues<2>               &fe_values,
                                    const std::vector<unsigned int> &component,
                                    Vector<double>                  &rhs) const
  {
    Vector<double> force(3);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const Point<2> &x  = fe_values.quadrature_point(q);
        const double    dV = x[0] * fe_values.JxW(q);
        body_force->vector_value(x, force);
        for (unsigned int i = 0; i < component.size(); ++i)
          {
            const unsigned int c = component[i];
            const double       w = c == Component::circumferential ?
                                     harmonic_operator.weight(StrainIndex::zt) :
                                     harmonic_operator.weight(StrainIndex::rr);
            rhs(i) += w * force(c) * fe_values.shape_value(i, q) * dV;
          }
      }
  }

  void
  HarmonicProblem::local_traction(
    FEFaceValues<2>                                    &fe_face_values,
    const typename DoFHandler<2>::active_cell_iterator &cell,
    Vector<double>                                     &rhs) const
  {
    if (tractions.empty())
      return;
    Vector<double> traction(3);
    for (const auto f : cell->face_indices())
      {
        if (!cell->face(f)->at_boundary())
          continue;
        const auto it = tractions.find(cell->face(f)->boundary_id());
        if (it == tractions.end())
          continue;
        fe_face_values.reinit(cell, f);
        for (const unsigned int q : fe_face_values.quadrature_point_indices())
          {
            const Point<2> &x = fe_face_values.quadrature_point(q);
            traction          = 0.;
            for (const auto &function : it->second)
              {
                Vector<double> part(3);
                function->vector_value(x, part);
                traction += part;
              }
            const double dA = x[0] * fe_face_values.JxW(q);
            for (unsigned int i = 0; i < fe->n_dofs_per_cell(); ++i)
              {
                const unsigned int c = fe->system_to_component_index(i).first;
                const double       w = c == Component::circumferential ?
                                         harmonic_operator.weight(StrainIndex::zt) :
                                         harmonic_operator.weight(StrainIndex::rr);
                rhs(i) +=
                  w * traction(c) * fe_face_values.shape_value(i, q) * dA;
              }
          }
      }
  }

  void
  HarmonicProblem::assemble_system()
  {
    if (distributed)
      {
        time_interface_assembly =
          distributed->assemble(local_matrix_factory(), system_rhs);
        if (foundation)
          foundation->add_loads(system_rhs);
        return;
      }
    system_matrix           = 0.;
    system_rhs              = 0.;
    time_interface_assembly = assemble_owned(
      dof_handler,
      constraints,
      interfaces.get(),
      [](const unsigned int) { return true; },
      local_matrix_factory(),
      assembly_threads,
      system_matrix,
      system_rhs);
    // Foundation loads act on the (unconstrained) master DoFs.
    if (foundation)
      foundation->add_loads(system_rhs);
  }

  SolverReport
  HarmonicProblem::solve()
  {
    const SolverReport report =
      distributed ? distributed->solve(solution, system_rhs) :
                    LinearSolver(parameters.solver)
                      .solve(system_matrix, solution, system_rhs, dof_handler);
    if (foundation)
      foundation->check_supported(solution, constraints);
    constraints.distribute(solution);
    project_solution_dilatation();
    return report;
  }

  SolverReport
  HarmonicProblem::run()
  {
    setup_system();
    assemble_system();
    return solve();
  }

  FoundationCoefficients
  HarmonicProblem::foundation_coefficients(
    std::vector<Vector<double>> *unit_solutions)
  {
    AssertThrow(foundation, ExcMessage("Rigid foundation is not enabled"));
    if (distributed)
      {
        const SparseDirect unused(parameters.solver.direct_backend());
        return unit_load_coefficients(unused, unit_solutions);
      }
    // The kept factorization, built here if the scene solve did not need
    // one (a zero scene load, or cg-amg for the scene load).
    factorize();
    if (!factorization)
      {
        SparseDirect direct(parameters.solver.direct_backend());
        direct.initialize(system_matrix, cell_interior_dofs(dof_handler));
        return unit_load_coefficients(direct, unit_solutions);
      }
    return unit_load_coefficients(*factorization, unit_solutions);
  }

  double
  HarmonicProblem::foundation_axial_stiffness()
  {
    AssertThrow(foundation, ExcMessage("Rigid foundation is not enabled"));
    std::vector<Vector<double>> x = {
      foundation->unit_axial_load(dof_handler.n_dofs())};
    if (distributed)
      {
        const Vector<double> load(x[0]);
        x[0] = 0.; // the CG initial guess
        distributed->solve(x[0], load);
      }
    else
      {
        factorize();
        if (factorization)
          factorization->solve(x);
        else
          {
            SparseDirect direct(parameters.solver.direct_backend());
            direct.initialize(system_matrix, cell_interior_dofs(dof_handler));
            direct.solve(x);
          }
      }
    // The master DoFs are unconstrained: their values are final.
    foundation->check_supported(x[0], constraints);
    return 1. / foundation->axial_motion(foundation->motion(x[0]));
  }

  void
  HarmonicProblem::factorize()
  {
    if (distributed || factorization || !parameters.solver.is_direct())
      return;
    factorization =
      std::make_unique<SparseDirect>(parameters.solver.direct_backend());
    factorization->initialize(system_matrix, cell_interior_dofs(dof_handler));
    ++factorization_count;
  }

  void
  HarmonicProblem::solve_increments(std::vector<Vector<double>> &b_to_x) const
  {
    if (distributed)
      for (Vector<double> &x : b_to_x)
        {
          const Vector<double> b(x);
          x = 0.;
          distributed->solve(x, b);
        }
    else if (factorization)
      factorization->solve(b_to_x);
    else
      for (Vector<double> &x : b_to_x)
        {
          const Vector<double> b(x);
          LinearSolver(parameters.solver)
            .solve(system_matrix, x, b, dof_handler);
        }
    for (Vector<double> &x : b_to_x)
      homogeneous_constraints.distribute(x);
  }

  void
  HarmonicProblem::set_solution(const Vector<double> &new_solution)
  {
    solution = new_solution;
    project_solution_dilatation();
  }

  SolverReport
  HarmonicProblem::solve_with_unit_loads(
    FoundationCoefficients      &coefficients,
    std::vector<Vector<double>> *unit_solutions)
  {
    AssertThrow(foundation, ExcMessage("Rigid foundation is not enabled"));
    if (distributed || !parameters.solver.is_direct() ||
        system_rhs.l2_norm() == 0.)
      {
        // Nothing to share here: a distributed system (it keeps its own
        // factorization for the unit loads), an iterative scene solve, or a
        // zero load (its factorization is skipped).
        const SolverReport report = solve();
        coefficients              = foundation_coefficients(unit_solutions);
        return report;
      }
    factorize();
    const SparseDirect &direct = *factorization;
    SolverReport        report;
    report.method = parameters.solver.method_name() +
                    " (factorization shared with the unit H, M cases)";
    direct.vmult(solution, system_rhs);
    Vector<double> residual(system_rhs.size());
    system_matrix.vmult(residual, solution);
    residual -= system_rhs;
    report.relative_residual =
      LinearSolver(parameters.solver)
        .checked_relative_residual(residual.l2_norm(), system_rhs.l2_norm());
    foundation->check_supported(solution, constraints);
    constraints.distribute(solution);
    project_solution_dilatation();
    coefficients = unit_load_coefficients(direct, unit_solutions);
    return report;
  }

  FoundationCoefficients
  HarmonicProblem::unit_load_coefficients(
    const SparseDirect          &direct,
    std::vector<Vector<double>> *unit_solutions) const
  {
    std::vector<Vector<double>> x;
    for (const unsigned int load_case : {0u, 1u})
      x.push_back(foundation->unit_load(load_case, dof_handler.n_dofs()));
    // The master DoFs are unconstrained: their values are final without
    // distributing the constraints (which would add Dirichlet data).
    if (distributed)
      for (Vector<double> &v : x)
        {
          const Vector<double> load(v);
          v = 0.; // the CG initial guess
          distributed->solve(v, load);
        }
    else
      direct.solve(x); // both loads in one sweep
    std::array<RigidMotion, 2> motions;
    for (const unsigned int load_case : {0u, 1u})
      {
        foundation->check_supported(x[load_case], constraints);
        motions[load_case] = foundation->motion(x[load_case]);
        if (unit_solutions)
          {
            constraints.distribute(x[load_case]);
            unit_solutions->push_back(x[load_case]);
          }
      }
    return foundation->coefficients(motions[0], motions[1]);
  }

  void
  HarmonicProblem::free_system()
  {
    factorization.reset();
    system_matrix.clear();
    sparsity_pattern.reinit(0, 0, 0);
    system_rhs.reinit(0);
  }

} // namespace FourierSSI
