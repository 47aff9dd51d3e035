// The out-of-balance loads of the plastic soil (include/fourier_ssi/
// coupled_solver.h, doc/soil-plasticity.md section 3) on the bundled
// scene prm/footing-capacity.prm (FE_Q(2) + B-bar, nu = 0.49):
//  (0) projection: with s_p = D eps (the whole strain "plastic") the
//      out-of-balance load is int Bbar^T D eps = K u, for random fields of
//      n = 0..3, both families, N = 9 theta samples: 1e-11 relative (both
//      are the same Gauss sums with the same B-bar projection; the theta
//      rule is exact for N > 2 n_max);
//  (1) elastic limit: s_u = 1e9 kPa, load control: 0 out-of-balance
//      iterations and the linear solution to 1e-13 relative (the same
//      factorization: a scene that stays elastic gives the linear answer).
#include "soil_test_support.h"

#include <random>

using namespace FourierSSI;
using namespace soil_test;

namespace
{
  void
  check_projection()
  {
    std::cout << "(0) int Bbar^T D eps = K u, n = 0..3, both families"
              << std::endl;
    Run          run(scene({{"Harmonics", "0, 1, 2, 3"},
                            {"Family", "both"},
                            {"Theta samples", "9"}}));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1., 1.);
    std::vector<Vector<double>>            fields;
    for (unsigned int h = 0; h < run.set->size(); ++h)
      {
        Vector<double> x(run.set->problem(h).get_dof_handler().n_dofs());
        for (double &v : x)
          v = u(rng);
        run.set->problem(h).get_homogeneous_constraints().distribute(x);
        fields.push_back(x);
      }
    const auto force = run.solver->soil_force(fields);
    double     error = 0., norm = 0.;
    for (unsigned int h = 0; h < run.set->size(); ++h)
      {
        Vector<double> Ku(fields[h].size());
        run.set->problem(h).get_system_matrix().vmult(Ku, fields[h]);
        const auto &constraints = run.set->problem(h).get_constraints();
        for (unsigned int i = 0; i < Ku.size(); ++i)
          if (!constraints.is_constrained(i))
            {
              error = std::max(error, std::abs(Ku[i] - force[h][i]));
              norm  = std::max(norm, std::abs(Ku[i]));
            }
      }
    check::small("max |G - K u| / max |K u|", error / norm, 1e-11);
  }

  void
  check_elastic_limit()
  {
    std::cout << "(1) elastic limit: s_u = 1e9 kPa" << std::endl;
    Run run(scene({{"Laws", "0: tresca, su=1e9"},
                   {"Control", "load"},
                   {"Load steps", "2"},
                   {"Vertical force", "-100"}}));
    run.solver->run(std::cout);
    unsigned int iterations = 0;
    for (const LoadStepResult &s : run.solver->get_steps())
      iterations += s.iterations;
    check::equal("out-of-balance iterations", iterations, 0);
    std::vector<std::vector<Vector<double>>> b = {
      {run.set->problem(0).get_system_rhs()}};
    run.set->solve_increments(b);
    Vector<double> difference = run.solver->solution(0);
    difference -= b[0][0];
    check::small("|u - u_linear| / |u_linear|",
                 difference.l2_norm() / b[0][0].l2_norm(),
                 1e-13);
  }

} // namespace

int
main()
{
  check_projection();
  check_elastic_limit();
  return check::summary();
}
