// Exact interface ties ('tied', 'tied-normal') together with a rigid
// foundation, on the bundled embedded footing (FE_Q(2), one cycle; and
// FE_Q(4) graded toward the footing edges, so hanging nodes, ties and
// rigid-body constraints meet). The footing's master node sits on the
// interface (the tied node farthest from the axis, r = 1): tying it to its
// soil twin made every footing DoF follow one soil node and gave K_H about
// 200x too high, so the ties now leave the master DoFs free.
//  - tied is the limit kn = ks -> infinity of the penalty springs: the
//    penalty deficit K(tied) - K(k) falls like 1/k, so
//    [K(tied) - K(1e10)] / [K(tied) - K(1e8)] = 0.01 (checked in
//    [0.008, 0.012]: the asymptotic 1/k law; round-off of the 1e10 system,
//    ~1e-8 relative, is 4 % of that deficit) -- this fails for any error
//    that does not vanish with 1/k, as the old 200x did;
//  - tied-normal is the limit kn -> infinity with ks = 0: the same 1/k law
//    with kn = 1e10 and 1e8, ks = 0. (Against kn = 1e13 directly the values
//    differ by 0.4-1.5e-6: round-off of that system, whose cond * eps
//    bound is ~6e-4, not a deficit, which is ~2e-10 there.)
#include "check.h"
#include "test_support.h"

#include <fourier_ssi/driver/simulator.h>
#include <tuple>

using namespace FourierSSI;

namespace
{
  std::string
  scene(const std::string &law, const unsigned int degree)
  {
    return test_support::footing_one_cycle(degree) +
           "subsection Interfaces\n set Interfaces = 5: " + law + "\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Harmonic                   h{1, Family::symmetric};
  for (const unsigned int degree : {2u, 4u})
    {
      const std::string  at   = " (FE_Q(" + std::to_string(degree) + "))";
      const ResultsTable tied = test_support::run(scene("tied", degree));
      const ResultsTable k10 =
        test_support::run(scene("kn=1e10, ks=1e10", degree));
      const ResultsTable k8 =
        test_support::run(scene("kn=1e8, ks=1e8", degree));
      const ResultsTable normal =
        test_support::run(scene("tied-normal", degree));
      const ResultsTable n10 =
        test_support::run(scene("kn=1e10, ks=0", degree));
      const ResultsTable n8 = test_support::run(scene("kn=1e8, ks=0", degree));
      for (const std::string q : {"K_H", "K_M"})
        for (const auto &[law, exact, penalty_10, penalty_8] :
             {std::make_tuple("tied", &tied, &k10, &k8),
              std::make_tuple("tied-normal", &normal, &n10, &n8)})
          {
            const double K   = exact->get(q, h, 0);
            const double d10 = K - penalty_10->get(q, h, 0);
            const double d8  = K - penalty_8->get(q, h, 0);
            std::cout << "  " << q << at << ": " << law << " " << K
                      << ", penalty deficit at 1e10 " << d10 / K << ", at 1e8 "
                      << d8 / K << std::endl;
            check::in_range(q + ": " + law + ", deficit ratio 1e10 / 1e8" + at,
                            d10 / d8,
                            0.008,
                            0.012);
          }
    }
  return check::summary();
}
