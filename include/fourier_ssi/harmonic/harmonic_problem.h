/**
 * One Fourier harmonic (n, family) as a 2D (r, z) elasticity problem:
 *   K = integral B^T W D B r dr dz   (doc/theory.md, thesis eq. 3.3),
 * W holding the theta-integrals of the squared trig factors (pi, 2 pi, 0).
 * Unknowns: FESystem(FE_Q(p), 3) amplitudes (U, V, W), p = 2 or 4 with
 * equidistant support points (they carry the 6- and 10-node interface
 * elements of the thesis).
 */
#ifndef fourier_ssi_harmonic_problem_h
#define fourier_ssi_harmonic_problem_h

#include <deal.II/base/function_parser.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <fourier_ssi/fourier/harmonic_operator.h>
#include <fourier_ssi/fourier/load_decomposition.h>
#include <fourier_ssi/harmonic/assembly_loop.h>
#include <fourier_ssi/harmonic/distributed_linear_system.h>
#include <fourier_ssi/harmonic/rigid_motion.h>
#include <fourier_ssi/harmonic/stress_postprocessor.h>
#include <fourier_ssi/input/parameters.h>
#include <fourier_ssi/interfaces/interface_integrator.h>
#include <fourier_ssi/linear_algebra/linear_solver.h>
#include <fourier_ssi/linear_algebra/sparse_direct.h>
#include <map>
#include <memory>

namespace FourierSSI
{
  using namespace dealii;

  /** The 3D force and moment resultants of the reactions on a boundary. */
  struct BoundaryResultant
  {
    /** Sums of nodal reaction amplitudes per component (r, z, theta). */
    std::array<double, 3> component_sums = {{0., 0., 0.}};
    /**
     * n = 0 symmetric: vertical force F_z. n = 1: horizontal force H along x
     * (symmetric) or y (antisymmetric). Otherwise 0.
     */
    double force = 0.;
    /**
     * n = 1: overturning moment about the y axis (symmetric) or the -x axis
     * (antisymmetric), about the origin (r, z) = (0, 0); n = 0 antisymmetric:
     * torque about z. Otherwise 0.
     */
    double moment = 0.;
    /** Sum of reaction times displacement over the boundary DoFs [kJ]. */
    double work = 0.;
  };

  struct ErrorNorms
  {
    double l2          = 0.; // (int |u_h - u|^2 r dr dz)^(1/2)
    double h1_seminorm = 0.; // (int |grad(u_h - u)|^2 r dr dz)^(1/2)
    double l2_exact    = 0.; // same norms of the exact amplitudes
    double h1_exact    = 0.;
  };

  /** Create FESystem(FE_Q(degree), 3) with equidistant support points. */
  std::unique_ptr<FESystem<2>>
  make_displacement_element(const unsigned int degree);

  class RigidFoundation;

  class HarmonicProblem
  {
  public:
    /**
     * `loads`: the scene's theta-dependent loads (ScenePlan); their
     * amplitudes for this harmonic join the amplitude expressions of the
     * Boundary conditions subsection. On a communicator of more than one
     * rank the linear system is distributed (DistributedLinearSystem); the
     * default is the serial code.
     */
    HarmonicProblem(const AllParameters     &parameters,
                    const Harmonic          &harmonic,
                    const Triangulation<2>  &triangulation,
                    const LoadDecomposition *loads        = nullptr,
                    const MPI_Comm           communicator = MPI_COMM_SELF);

    /** Out of line: the RigidFoundation it owns is only declared here. */
    ~HarmonicProblem();

    /**
     * Threads for the cell loop of the assembly: the cores this harmonic
     * does not share with other harmonics or ranks (HarmonicSet). The
     * results are the same bit for bit on any number.
     */
    void
    set_assembly_threads(const unsigned int n_threads)
    {
      assembly_threads = std::max(1u, n_threads);
    }

    /** DoFs, constraints (hanging nodes, Dirichlet, axis), sparsity. */
    void
    setup_system();

    /** Stiffness matrix and load vector, constraints applied. */
    void
    assemble_system();

    SolverReport
    solve();

    /**
     * Factorize the assembled matrix once and keep the factorization for
     * every later solve of this harmonic (direct methods; a distributed
     * system keeps its own MUMPS factorization or AMG hierarchy, and the
     * serial cg-amg method re-solves iteratively). Idempotent.
     */
    void
    factorize();

    /** Factorizations this problem has computed (the harmonic-set test). */
    unsigned int
    n_factorizations() const
    {
      return factorization_count;
    }

    /**
     * x_i = K^-1 b_i for loads b_i in the condensed numbering (rows of
     * constrained DoFs zero, e.g. assembled through the homogeneous
     * constraints), using the kept factorization; the constraints are then
     * distributed with zero inhomogeneity, so x_i is a displacement
     * increment. b is overwritten by x.
     */
    void
    solve_increments(std::vector<Vector<double>> &b_to_x) const;

    /** The constraints with every inhomogeneity set to zero. */
    const AffineConstraints<double> &
    get_homogeneous_constraints() const
    {
      return homogeneous_constraints;
    }

    /** The condensed scene load (after assemble_system()). */
    const Vector<double> &
    get_system_rhs() const
    {
      return system_rhs;
    }

    /**
     * Replace the solution (e.g. the converged state of a coupled
     * iteration); stresses are re-projected for output.
     */
    void
    set_solution(const Vector<double> &new_solution);

    /** setup + assemble + solve. */
    SolverReport
    run();

    /**
     * Stiffness coefficients of the rigid foundation: solves the unit H and
     * unit M cases with one factorization of the assembled matrix; the two
     * fields go to `unit_solutions` if given (adaptivity needs them).
     */
    FoundationCoefficients
    foundation_coefficients(
      std::vector<Vector<double>> *unit_solutions = nullptr);

    /**
     * The rigid foundation's stiffness along the n = 0 motion of this
     * harmonic: 1 / W_v under a unit V (symmetric, kN/m) or 1 / Phi under a
     * unit T (antisymmetric, kN.m/rad), with the kept factorization (built
     * here if the scene solve did not need one).
     */
    double
    foundation_axial_stiffness();

    /**
     * solve() and foundation_coefficients() with ONE factorization of the
     * matrix for the scene's load and the unit-H and unit-M loads (direct
     * solver; with cg-amg the scene load is solved iteratively and the unit
     * cases share one factorization, as in foundation_coefficients()).
     */
    SolverReport
    solve_with_unit_loads(FoundationCoefficients      &coefficients,
                          std::vector<Vector<double>> *unit_solutions);

    /** Half the 3D strain energy product: 1/2 x^T K x (unconstrained K). */
    double
    strain_energy(const Vector<double> &field) const;

    /**
     * Cell-wise energy products of two fields x, y (distributed vectors of
     * this DoFHandler): xx_K = x_K^T A_K x_K, yy_K = y_K^T A_K y_K,
     * xy_K = x_K^T A_K y_K with A_K the cell stiffness (interfaces left out),
     * indexed by active cell index. The goal-oriented estimator uses them as
     * a_K(e_H, e_H), a_K(e_M, e_M), a_K(e_H, e_M).
     */
    void
    cell_energy_products(const Vector<double> &x,
                         const Vector<double> &y,
                         Vector<double>       &xx,
                         Vector<double>       &yy,
                         Vector<double>       &xy) const;

    /**
     * Reaction amplitudes K u - f without constraints (nodal forces), with
     * the force at each hanging DoF moved to the DoFs it hangs from.
     */
    Vector<double>
    nodal_reactions() const;

    /**
     * The nodal forces K u - body_force_factor f_cells of the field u (K
     * the elastic matrix, f_cells the cells' body-force loads), one entry
     * per DoF, before any constraint: what nodal_reactions() computes for
     * the solution, for any field (a plastic run subtracts its plastic
     * load from it).
     */
    Vector<double>
    nodal_forces(const Vector<double> &u,
                 const double          body_force_factor = 1.) const;

    /**
     * Resultant of the reactions on one boundary. Each constrained DoF is
     * counted once: on the lowest Dirichlet boundary id whose entry fixes
     * that DoF's component (a corner shared by ids 1 and 2 belongs to 1 for
     * the components 1 fixes, to 2 for the others), so that the resultants
     * of all Dirichlet ids sum to the total support reaction, which balances
     * the applied loads. An id without a Dirichlet entry gets every DoF on
     * it.
     */
    BoundaryResultant
    boundary_resultant(const types::boundary_id boundary_id,
                       const Vector<double>    &reactions) const;

    ErrorNorms
    compute_errors() const;

    /**
     * Write the amplitudes (and stresses) to `filename`, with the
     * displacement amplitudes of the `extra` fields (e.g. a stiffness
     * scene's unit-H and unit-M solutions) named by prefix; on a
     * distributed system this rank's piece and, on rank 0, the .pvtu record.
     * The stresses are C eps(u) (Output/Write stresses), unless
     * `elastic_stresses` is false: the stress of plastic soil is not
     * C eps(u). Returns the files this rank wrote (removed again if the run
     * fails).
     */
    std::vector<std::string>
    write_vtu(const std::string &filename,
              const std::vector<std::pair<std::string, const Vector<double> *>>
                        &extra            = {},
              const bool elastic_stresses = true) const;

    /**
     * The strain of the solution at x in cell, as the stresses are output:
     * with B-bar, its dilatation is the cell's projected one.
     */
    StrainVector
    output_strain(const typename Triangulation<2>::active_cell_iterator &cell,
                  const Point<2>                                        &x,
                  const std::array<double, 3>                           &values,
                  const std::array<Tensor<1, 2>, 3> &gradients) const;

    const DoFHandler<2> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    const Vector<double> &
    get_solution() const
    {
      return solution;
    }

    /** The rigid foundation, or nullptr if the scene has none. */
    const RigidFoundation *
    get_foundation() const
    {
      return foundation.get();
    }

    /** The assembled (condensed) matrix: condition estimates, tests. */
    const SparseMatrix<double> &
    get_system_matrix() const
    {
      return system_matrix;
    }

    const AffineConstraints<double> &
    get_constraints() const
    {
      return constraints;
    }

    /** The distributed system, or nullptr on one rank. */
    const DistributedLinearSystem *
    get_distributed() const
    {
      return distributed.get();
    }

    /** The zero-thickness interfaces, or nullptr if none are declared. */
    const InterfaceIntegrator *
    get_interfaces() const
    {
      return interfaces.get();
    }

    const HarmonicOperator &
    get_operator() const
    {
      return harmonic_operator;
    }

    const MaterialLibrary &
    get_materials() const
    {
      return parameters.materials;
    }

    /**
     * Free the matrix, load vector and factorization once everything that
     * needs them is done; the solution and DoFs stay for post-processing.
     */
    void
    free_system();

    unsigned int n_axis_nodes = 0;
    /** Wall time of the interface part of the last assemble_system() [s]. */
    double time_interface_assembly = 0.;

  private:
    /** Parallel output: this rank's cells and, on rank 0, the .pvtu. */
    std::vector<std::string>
    write_vtu_pieces(DataOut<2> &data_out, const std::string &filename) const;

    /** Local stiffness of one cell and, if requested, its body-force load. */
    void
    local_matrix(const typename DoFHandler<2>::active_cell_iterator &cell,
                 FullMatrix<double>                                 &matrix,
                 Vector<double>                                     *rhs) const;

    /** The same on given scratch objects (one set per assembly thread). */
    void
    local_matrix(FEValues<2>     &fe_values,
                 FEFaceValues<2> &fe_face_values,
                 const typename DoFHandler<2>::active_cell_iterator &cell,
                 FullMatrix<double>                                 &matrix,
                 Vector<double>                                     *rhs) const;

    /** A local_matrix() with scratch objects of its own (assembly_loop.h). */
    LocalMatrixFactory
    local_matrix_factory() const;

    /** Strains of every shape function at every quadrature point. */
    std::vector<std::vector<StrainVector>>
    shape_function_strains(const FEValues<2>               &fe_values,
                           const std::vector<unsigned int> &component) const;

    /**
     * The (7 n_q) x dofs table G of the square roots of the energy density's
     * squares, so that the local stiffness is G^T G.
     */
    void
    energy_factor_table(const FEValues<2>                            &fe_values,
                        const ElasticMaterial                        &material,
                        const std::vector<std::vector<StrainVector>> &strain_at,
                        FullMatrix<double> &factor_table) const;

    /** Add the body force of one cell to its local load. */
    void
    local_body_force(const FEValues<2>               &fe_values,
                     const std::vector<unsigned int> &component,
                     Vector<double>                  &rhs) const;

    /** Every boundary id named in the .prm must exist on the mesh. */
    void
    check_boundary_ids() const;

    /**
     * Hanging nodes, Dirichlet and prescribed motions, the rigid foundation,
     * interface ties, axis and held-motion constraints, closed; and their
     * homogeneous copy.
     */
    void
    make_constraints();

    /** The sparsity pattern and matrix of the serial system. */
    void
    make_serial_matrix();

    /** Threads of the cell loop (assembly_loop.h), not of the results. */
    unsigned int assembly_threads = 1;

    /** The unit-H and unit-M cases with a given factorization. */
    FoundationCoefficients
    unit_load_coefficients(const SparseDirect          &direct,
                           std::vector<Vector<double>> *unit_solutions) const;

    /**
     * B-bar: replace the dilatation in the strains of every shape function
     * by its projection onto the cell's linear polynomials (p = 2 only).
     */
    void
    replace_dilatation(const FEValues<2>                      &fe_values,
                       std::vector<std::vector<StrainVector>> &strain_at) const;

    /**
     * B-bar (p = 2): the projected dilatation of the solution per cell, so
     * that output stresses use the strain the equations were solved with.
     */
    void
                                      project_solution_dilatation();
    std::vector<DilatationProjection> dilatation_projection;

    /** Add the surface tractions of one cell to its local load. */
    void
    local_traction(FEFaceValues<2> &fe_face_values,
                   const typename DoFHandler<2>::active_cell_iterator &cell,
                   Vector<double> &rhs) const;

    const AllParameters             &parameters;
    const HarmonicOperator           harmonic_operator;
    std::unique_ptr<FESystem<2>>     fe;
    DoFHandler<2>                    dof_handler;
    AffineConstraints<double>        constraints;
    AffineConstraints<double>        homogeneous_constraints;
    SparsityPattern                  sparsity_pattern;
    SparseMatrix<double>             system_matrix;
    Vector<double>                   system_rhs;
    Vector<double>                   solution;
    double                           axis_tolerance;
    std::unique_ptr<RigidFoundation> foundation;
    /** Scratch objects of the cell and face loops (serial code). */
    std::unique_ptr<FEValues<2>>       cell_values;
    std::unique_ptr<FEFaceValues<2>>   face_values;
    std::unique_ptr<FunctionParser<2>> body_force;
    /** Traction amplitudes per boundary id (expressions and theta loads). */
    std::map<types::boundary_id, std::vector<std::unique_ptr<Function<2>>>>
                                         tractions;
    const LoadDecomposition             *loads;
    std::unique_ptr<InterfaceIntegrator> interfaces;
    /** The kept factorization (serial direct methods), see factorize(). */
    std::unique_ptr<SparseDirect> factorization;
    unsigned int                  factorization_count = 0;
    /** Mutable: the stiffness solves reuse its factorization/AMG. */
    mutable std::unique_ptr<DistributedLinearSystem> distributed;
  };
} // namespace FourierSSI

#endif
