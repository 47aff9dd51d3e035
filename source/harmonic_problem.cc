#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>
#include <fourier_ssi/axis_constraints.h>
#include <fourier_ssi/harmonic_problem.h>
#include <fourier_ssi/sparse_direct.h>
#include <fourier_ssi/stress_postprocessor.h>
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
    // (Library users and unit tests may not have initialized MPI.)
    if (Utilities::MPI::job_supports_mpi() &&
        (Utilities::MPI::n_mpi_processes(communicator) > 1 ||
         parameters.solver.distributed == "always"))
      distributed =
        std::make_unique<DistributedLinearSystem>(communicator,
                                                  parameters.solver);
  }

  void
  HarmonicProblem::setup_system()
  {
    dof_handler.distribute_dofs(*fe);

    // Every boundary id named in the .prm must exist on the mesh.
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
    constraints.close();

    system_rhs.reinit(dof_handler.n_dofs());
    solution.reinit(dof_handler.n_dofs());
    if (distributed)
      {
        if (interfaces)
          interfaces->setup(dof_handler);
        distributed->setup(dof_handler, constraints, interfaces.get());
        return;
      }
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

  void
  HarmonicProblem::local_matrix(
    const typename DoFHandler<2>::active_cell_iterator &cell,
    FullMatrix<double>                                 &matrix,
    Vector<double>                                     *rhs) const
  {
    FEValues<2> &fe_values = *cell_values;
    fe_values.reinit(cell);
    const unsigned int dofs_per_cell = fe->n_dofs_per_cell();
    matrix.reinit(dofs_per_cell, dofs_per_cell);
    if (rhs)
      rhs->reinit(dofs_per_cell);

    const ElasticMaterial &material =
      parameters.materials.get(cell->material_id());
    std::vector<StrainVector> strain(dofs_per_cell), stress(dofs_per_cell);
    std::vector<unsigned int> component(dofs_per_cell);
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      component[i] = fe->system_to_component_index(i).first;
    Vector<double> force(3);

    // Strains of every shape function at every quadrature point.
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
    if (parameters.discretization.volumetric == "bbar" && fe->degree == 2)
      replace_dilatation(fe_values, strain_at);

    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const Point<2> &x      = fe_values.quadrature_point(q);
        const double    r      = x[0];
        const double    depth  = parameters.materials.depth(x[1]);
        const double    mu     = material.shear_modulus(depth);
        const double    lambda = material.lambda(depth);
        const double    dV     = r * fe_values.JxW(q);

        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            strain[i] = strain_at[q][i];
            // Stress weighted with the theta integral of each strain's trig
            // factor, so that strain[i] . stress[j] is the 3D energy product.
            stress[i] = hooke_stress(strain[i], lambda, mu);
            for (unsigned int k = 0; k < 6; ++k)
              stress[i][k] *= harmonic_operator.weight(k) * dV;
          }
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (unsigned int j = 0; j <= i; ++j)
            {
              double sum = 0.;
              for (unsigned int k = 0; k < 6; ++k)
                sum += strain[i][k] * stress[j][k];
              matrix(i, j) += sum;
            }

        if (rhs)
          {
            body_force->vector_value(x, force);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                const unsigned int c = component[i];
                const double       w = c == Component::circumferential ?
                                         harmonic_operator.weight(StrainIndex::zt) :
                                         harmonic_operator.weight(StrainIndex::rr);
                (*rhs)(i) += w * force(c) * fe_values.shape_value(i, q) * dV;
              }
          }
      }
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      for (unsigned int j = i + 1; j < dofs_per_cell; ++j)
        matrix(i, j) = matrix(j, i);

    if (rhs)
      local_traction(cell, *rhs);
  }

  namespace
  {
    /**
     * The L2(r dr dz) projection of one cell onto the linear polynomials
     * {1, r - r_c, z - z_c} (r_c, z_c: the cell's r-weighted centroid), from
     * the cell's quadrature: the volumetric space of the stable Q2-P1disc
     * mixed element, used by B-bar.
     */
    struct LinearProjection
    {
      explicit LinearProjection(const FEValues<2> &fe_values)
        : n_q(fe_values.n_quadrature_points)
        , dV(n_q)
        , points(n_q)
        , inverse(3, 3)
      {
        double volume = 0.;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            points[q] = fe_values.quadrature_point(q);
            dV[q]     = points[q][0] * fe_values.JxW(q);
            center += dV[q] * points[q];
            volume += dV[q];
          }
        valid = volume > 0.; // a degenerate cell (zero r-weighted volume)
        if (!valid)
          return;
        center /= volume;
        FullMatrix<double> mass(3, 3);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const auto p = basis(points[q]);
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = 0; b < 3; ++b)
                mass(a, b) += p[a] * p[b] * dV[q];
          }
        inverse.invert(mass);
      }

      std::array<double, 3>
      basis(const Point<2> &x) const
      {
        const Tensor<1, 2> d = x - center;
        return {{1., d[0], d[1]}};
      }

      /** Coefficients of the projection of f, given at the quadrature points.
       */
      std::array<double, 3>
      project(const std::vector<double> &f) const
      {
        std::array<double, 3> moments = {{0., 0., 0.}}, c = {{0., 0., 0.}};
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const auto p = basis(points[q]);
            for (unsigned int a = 0; a < 3; ++a)
              moments[a] += p[a] * f[q] * dV[q];
          }
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            c[a] += inverse(a, b) * moments[b];
        return c;
      }

      unsigned int          n_q;
      std::vector<double>   dV;
      std::vector<Point<2>> points;
      Point<2>              center;
      FullMatrix<double>    inverse;
      bool                  valid = false;
    };
  } // namespace

  void
  HarmonicProblem::replace_dilatation(
    const FEValues<2>                      &fe_values,
    std::vector<std::vector<StrainVector>> &strain_at) const
  {
    // B-bar (Hughes 1980): the dilatation e_r + e_z + e_t of each shape
    // function is replaced by its projection onto the cell's linear
    // polynomials (LinearProjection); the deviatoric part is kept. The
    // dilatation carries the in-plane trig factor for every n, so the same
    // projection serves every harmonic.
    const LinearProjection projection(fe_values);
    if (!projection.valid)
      return; // a degenerate cell: leave the strains alone
    const unsigned int  n_q           = strain_at.size();
    const unsigned int  dofs_per_cell = strain_at[0].size();
    std::vector<double> dilatation(n_q);
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      {
        for (unsigned int q = 0; q < n_q; ++q)
          dilatation[q] =
            strain_at[q][i][0] + strain_at[q][i][1] + strain_at[q][i][2];
        const DilatationProjection projected{projection.center,
                                             projection.project(dilatation)};
        for (unsigned int q = 0; q < n_q; ++q)
          strain_at[q][i] =
            with_dilatation(strain_at[q][i],
                            projected.value(projection.points[q]));
      }
  }

  void
  HarmonicProblem::project_solution_dilatation()
  {
    dilatation_projection.clear();
    if (parameters.discretization.volumetric != "bbar" || fe->degree != 2)
      return;
    FEValues<2>                           &fe_values = *cell_values;
    const unsigned int                     n_q = fe_values.n_quadrature_points;
    std::vector<Vector<double>>            values(n_q, Vector<double>(3));
    std::vector<std::vector<Tensor<1, 2>>> gradients(
      n_q, std::vector<Tensor<1, 2>>(3));
    std::vector<double> dilatation(n_q);
    dilatation_projection.resize(
      dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        const LinearProjection projection(fe_values);
        if (!projection.valid)
          continue; // no correction: value() of a default projection is NaN
        fe_values.get_function_values(solution, values);
        fe_values.get_function_gradients(solution, gradients);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            std::array<double, 3>       v;
            std::array<Tensor<1, 2>, 3> g;
            for (unsigned int c = 0; c < 3; ++c)
              {
                v[c] = values[q](c);
                g[c] = gradients[q][c];
              }
            const StrainVector e =
              harmonic_operator.strain(v, g, projection.points[q][0]);
            dilatation[q] = e[0] + e[1] + e[2];
          }
        dilatation_projection[cell->active_cell_index()] = {
          projection.center, projection.project(dilatation)};
      }
  }

  StrainVector
  HarmonicProblem::output_strain(
    const typename Triangulation<2>::active_cell_iterator &cell,
    const Point<2>                                        &x,
    const std::array<double, 3>                           &values,
    const std::array<Tensor<1, 2>, 3>                     &gradients) const
  {
    return bbar_strain(harmonic_operator.strain(values, gradients, x[0]),
                       dilatation_projection,
                       cell->active_cell_index(),
                       x);
  }

  void
  HarmonicProblem::local_traction(
    const typename DoFHandler<2>::active_cell_iterator &cell,
    Vector<double>                                     &rhs) const
  {
    if (tractions.empty())
      return;
    FEFaceValues<2> &fe_face_values = *face_values;
    Vector<double>   traction(3);
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
        time_interface_assembly = distributed->assemble(
          [this](const auto &cell, auto &matrix, auto *rhs) {
            local_matrix(cell, matrix, rhs);
          },
          system_rhs);
        if (foundation)
          foundation->add_loads(system_rhs);
        return;
      }
    system_matrix = 0.;
    system_rhs    = 0.;
    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_rhs;
    std::vector<types::global_dof_index> dof_indices(fe->n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        local_matrix(cell, cell_matrix, &cell_rhs);
        cell->get_dof_indices(dof_indices);
        constraints.distribute_local_to_global(
          cell_matrix, cell_rhs, dof_indices, system_matrix, system_rhs);
      }
    if (interfaces)
      {
        Timer timer;
        interfaces->assemble(constraints, system_matrix, system_rhs);
        time_interface_assembly = timer.wall_time();
      }
    // Foundation loads act on the (unconstrained) master DoFs.
    if (foundation)
      foundation->add_loads(system_rhs);
  }

  SolverReport
  HarmonicProblem::solve()
  {
    const SolverReport report = distributed ?
                                  distributed->solve(solution, system_rhs) :
                                  parameters.solver.solve(system_matrix,
                                                          solution,
                                                          system_rhs,
                                                          dof_handler);
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
    std::vector<Vector<double>> *unit_solutions) const
  {
    AssertThrow(foundation, ExcMessage("Rigid foundation is not enabled"));
    SparseDirect direct(parameters.solver.direct_backend());
    if (!distributed)
      direct.initialize(system_matrix);
    return unit_load_coefficients(direct, unit_solutions);
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
    SparseDirect direct(parameters.solver.direct_backend());
    direct.initialize(system_matrix);
    SolverReport report;
    report.method = parameters.solver.method +
                    " (factorization shared with the unit H, M cases)";
    direct.vmult(solution, system_rhs);
    Vector<double> residual(system_rhs.size());
    system_matrix.vmult(residual, solution);
    residual -= system_rhs;
    report.relative_residual =
      parameters.solver.checked_relative_residual(residual.l2_norm(),
                                                  system_rhs.l2_norm());
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
    system_matrix.clear();
    sparsity_pattern.reinit(0, 0, 0);
    system_rhs.reinit(0);
  }

  double
  HarmonicProblem::strain_energy(const Vector<double> &field) const
  {
    FullMatrix<double>                   cell_matrix;
    std::vector<types::global_dof_index> dof_indices(fe->n_dofs_per_cell());
    Vector<double> local(fe->n_dofs_per_cell()), product(fe->n_dofs_per_cell());
    double         energy = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < dof_indices.size(); ++i)
          local(i) = field(dof_indices[i]);
        // A cell at rest stores no energy (e.g. the zero scene field of a
        // stiffness run): skip its matrix.
        if (local.linfty_norm() == 0.)
          continue;
        local_matrix(cell, cell_matrix, nullptr);
        cell_matrix.vmult(product, local);
        energy += 0.5 * (local * product);
      }
    if (interfaces)
      energy += interfaces->energy(field);
    return energy;
  }

  void
  HarmonicProblem::cell_energy_products(const Vector<double> &x,
                                        const Vector<double> &y,
                                        Vector<double>       &xx,
                                        Vector<double>       &yy,
                                        Vector<double>       &xy) const
  {
    const unsigned int n_cells =
      dof_handler.get_triangulation().n_active_cells();
    xx.reinit(n_cells);
    yy.reinit(n_cells);
    xy.reinit(n_cells);
    FullMatrix<double>                   cell_matrix;
    std::vector<types::global_dof_index> dof_indices(fe->n_dofs_per_cell());
    Vector<double> local_x(fe->n_dofs_per_cell()), local_y(local_x),
      product_x(local_x), product_y(local_x);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        local_matrix(cell, cell_matrix, nullptr);
        cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < dof_indices.size(); ++i)
          {
            local_x(i) = x(dof_indices[i]);
            local_y(i) = y(dof_indices[i]);
          }
        cell_matrix.vmult(product_x, local_x);
        cell_matrix.vmult(product_y, local_y);
        const unsigned int c = cell->active_cell_index();
        xx(c)                = local_x * product_x;
        yy(c)                = local_y * product_y;
        xy(c)                = local_x * product_y;
      }
  }

  Vector<double>
  HarmonicProblem::nodal_reactions() const
  {
    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_rhs;
    std::vector<types::global_dof_index> dof_indices(fe->n_dofs_per_cell());
    Vector<double> local(fe->n_dofs_per_cell()), product(fe->n_dofs_per_cell());
    Vector<double> reactions(dof_handler.n_dofs());
    // Without a body force, a cell at rest exerts no nodal force.
    const bool body_force_given =
      !parameters.boundary_conditions.body_force.is_zero();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < dof_indices.size(); ++i)
          local(i) = solution(dof_indices[i]);
        if (!body_force_given && local.linfty_norm() == 0.)
          continue;
        local_matrix(cell, cell_matrix, &cell_rhs);
        cell_matrix.vmult(product, local);
        product -= cell_rhs;
        for (unsigned int i = 0; i < dof_indices.size(); ++i)
          reactions(dof_indices[i]) += product(i);
      }
    if (interfaces)
      interfaces->add_reactions(solution, reactions);
    // The nodal force at a hanging DoF acts on the DoFs it hangs from
    // (C^T r), some of which may be supports: move it there, or the support
    // reactions miss it (0.3 % of F_z with a corner grading next to fixed
    // boundaries, tests/reaction_equilibrium.cc). A separate set of only
    // the hanging-node constraints keeps supports as masters (the full set
    // eliminates Dirichlet DoFs from the lines).
    AffineConstraints<double> hanging_nodes;
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_nodes);
    hanging_nodes.close();
    for (const auto &line : hanging_nodes.get_lines())
      {
        for (const auto &[master, weight] : line.entries)
          reactions(master) += weight * reactions(line.index);
        reactions(line.index) = 0.;
      }
    return reactions;
  }

  BoundaryResultant
  HarmonicProblem::boundary_resultant(const types::boundary_id boundary_id,
                                      const Vector<double>    &reactions) const
  {
    BoundaryResultant result;
    // Each constrained DoF's reaction belongs to one boundary: the lowest
    // Dirichlet id whose entry fixes that DoF's component (the one whose
    // value interpolate_boundary_values kept). A corner DoF shared by ids 1
    // and 2 thus counts once, on 1, and the resultants of all Dirichlet ids
    // add up to the total reaction. An id without a Dirichlet entry keeps
    // every DoF on it.
    const auto &dirichlet        = parameters.boundary_conditions.dirichlet;
    const auto  fixed_components = [](const ComponentExpressions &e) {
      return ComponentMask(std::vector<bool>(e.given.begin(), e.given.end()));
    };
    const auto entry = dirichlet.find(boundary_id);
    IndexSet   boundary_dofs =
      DoFTools::extract_boundary_dofs(dof_handler,
                                      entry == dirichlet.end() ?
                                        ComponentMask() :
                                        fixed_components(entry->second),
                                      {boundary_id});
    if (entry != dirichlet.end())
      for (auto lower = dirichlet.begin(); lower != entry; ++lower)
        boundary_dofs.subtract_set(DoFTools::extract_boundary_dofs(
          dof_handler, fixed_components(lower->second), {lower->first}));
    std::map<types::global_dof_index, Point<2>> positions;
    DoFTools::map_dofs_to_support_points(MappingQ1<2>(),
                                         dof_handler,
                                         positions);

    const Harmonic &h    = harmonic_operator.get_harmonic();
    const double    sign = family_sign(h.family);
    // Component of each DoF: the FESystem numbering is not component-wise,
    // so look it up per cell once.
    std::vector<unsigned int>            component_of(dof_handler.n_dofs());
    std::vector<types::global_dof_index> dof_indices(fe->n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < dof_indices.size(); ++i)
          component_of[dof_indices[i]] = fe->system_to_component_index(i).first;
      }
    for (const auto i : boundary_dofs)
      {
        const unsigned int c = component_of[i];
        const double       R = reactions(i);
        const Point<2>    &x = positions[i];
        result.component_sums[c] += R;
        result.work += R * solution(i);
        if (h.n == 1)
          {
            // H = sum R_r - s R_theta; M = sum z (R_r - s R_theta) - r R_z,
            // from the resultant of t_r, t_theta, t_z over the full circle.
            const double horizontal =
              (c == 0 ? R : 0.) - (c == 2 ? sign * R : 0.);
            result.force += horizontal;
            result.moment += x[1] * horizontal - (c == 1 ? x[0] * R : 0.);
          }
        else if (h.n == 0 && h.family == Family::symmetric && c == 1)
          result.force += R;
        else if (h.n == 0 && h.family == Family::antisymmetric && c == 2)
          result.moment += x[0] * R;
      }
    return result;
  }

  ErrorNorms
  HarmonicProblem::compute_errors() const
  {
    ErrorNorms errors;
    AssertThrow(parameters.exact_solution.enabled,
                ExcMessage("Exact solution/Enabled is false"));
    FunctionParser<2> exact(3, 0., 1e-4);
    {
      const auto &e = parameters.exact_solution.amplitudes.expression;
      exact.initialize("r,z",
                       std::vector<std::string>(e.begin(), e.end()),
                       {{"pi", numbers::PI},
                        {"n", double(harmonic_operator.get_harmonic().n)}});
      exact.set_formula(AutoDerivativeFunction<2>::FourthOrder);
    }
    const QGauss<2>             quadrature(fe->degree + 3);
    FEValues<2>                 fe_values(*fe,
                          quadrature,
                          update_values | update_gradients |
                            update_quadrature_points | update_JxW_values);
    std::vector<Vector<double>> values(quadrature.size(), Vector<double>(3));
    std::vector<std::vector<Tensor<1, 2>>> gradients(
      quadrature.size(), std::vector<Tensor<1, 2>>(3));
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values.get_function_values(solution, values);
        fe_values.get_function_gradients(solution, gradients);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const Point<2> &x  = fe_values.quadrature_point(q);
            const double    dV = x[0] * fe_values.JxW(q);
            for (unsigned int c = 0; c < 3; ++c)
              {
                const double       u  = exact.value(x, c);
                const Tensor<1, 2> du = exact.gradient(x, c);
                errors.l2 += (values[q](c) - u) * (values[q](c) - u) * dV;
                errors.h1_seminorm += (gradients[q][c] - du).norm_square() * dV;
                errors.l2_exact += u * u * dV;
                errors.h1_exact += du.norm_square() * dV;
              }
          }
      }
    errors.l2          = std::sqrt(errors.l2);
    errors.h1_seminorm = std::sqrt(errors.h1_seminorm);
    errors.l2_exact    = std::sqrt(errors.l2_exact);
    errors.h1_exact    = std::sqrt(errors.h1_exact);
    return errors;
  }

  std::vector<std::string>
  HarmonicProblem::write_vtu(const std::string &filename) const
  {
    StressPostprocessor postprocessor(harmonic_operator,
                                      parameters.materials,
                                      dilatation_projection);
    DataOut<2>          data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(solution,
                             std::vector<std::string>{"U_radial",
                                                      "V_axial",
                                                      "W_circumferential"});
    if (parameters.output.write_stresses)
      data_out.add_data_vector(solution, postprocessor);
    Vector<float> material_ids(
      dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      material_ids(cell->active_cell_index()) = cell->material_id();
    data_out.add_data_vector(material_ids, "material_id");
    if (distributed)
      return write_vtu_pieces(data_out, filename);
    data_out.build_patches(fe->degree);
    std::ofstream out(filename);
    AssertThrow(out, ExcMessage("Output: cannot write '" + filename + "'"));
    data_out.write_vtu(out);
    return {filename};
  }

  std::vector<std::string>
  HarmonicProblem::write_vtu_pieces(DataOut<2>        &data_out,
                                    const std::string &filename) const
  {
    // Each rank writes its own cells as NAME.rankR.vtu; rank 0 writes the
    // NAME.pvtu record that ParaView opens.
    const unsigned int rank = distributed->this_rank();
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(distributed->get_communicator());
    Vector<float> ranks(dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      ranks(cell->active_cell_index()) =
        distributed->cell_owner(cell->active_cell_index());
    data_out.add_data_vector(ranks, "rank");
    data_out.set_cell_selection(
      [this, rank](const typename Triangulation<2>::cell_iterator &cell) {
        return cell->is_active() &&
               distributed->cell_owner(cell->active_cell_index()) == rank;
      });
    data_out.build_patches(fe->degree);
    const std::string base =
      filename.size() > 4 && filename.substr(filename.size() - 4) == ".vtu" ?
        filename.substr(0, filename.size() - 4) :
        filename;
    const auto piece = [&](const unsigned int r) {
      return base + ".rank" + std::to_string(r) + ".vtu";
    };
    std::vector<std::string> written = {piece(rank)};
    std::ofstream            out(piece(rank));
    AssertThrow(out, ExcMessage("Output: cannot write '" + piece(rank) + "'"));
    data_out.write_vtu(out);
    if (rank == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < n_ranks; ++r)
          {
            const std::string p = piece(r);
            pieces.push_back(p.substr(p.find_last_of('/') + 1));
          }
        std::ofstream record(base + ".pvtu");
        AssertThrow(record,
                    ExcMessage("Output: cannot write '" + base + ".pvtu'"));
        data_out.write_pvtu_record(record, pieces);
        written.push_back(base + ".pvtu");
      }
    return written;
  }
} // namespace FourierSSI
