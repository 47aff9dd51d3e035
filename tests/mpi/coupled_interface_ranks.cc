// Run with mpirun -np 2. The coupled interface iteration with its harmonics
// distributed over the 2 ranks (HarmonicSet::distribute_over: each rank
// assembles, factorizes and condenses its own harmonics, one MPI_Allreduce of
// the interface amplitudes per iteration) follows the same load-displacement
// curve as the serial solve, which every rank also runs on MPI_COMM_SELF:
//
// 1. the lateral pile (prm/pile-lateral-slip.prm, 7 harmonics: 4 on rank 0,
//    3 on rank 1) shortened to 4 steps to u = 0.02 m: H and u at every step,
//    the stick/slip/open counts;
// 2. the tensionless disc (prm/disc-gap.prm) listing n = 1 only with
//    Maximum harmonic = 16: the harmonics the interface calls for are added
//    during the solve and assigned to the ranks, to the same 17 harmonics;
//    P at every step, and the equilibrium of the interface tractions with
//    the applied load (the disc is the interface's own material).
//
// Tolerances. Both runs stop at a force residual below Tolerance = 1e-10 of
// the load; the distributed iterates are the serial ones up to round-off
// (the same factorizations, the flexibility blocks solved in other batches
// and thread counts), so the converged curves differ by the residual
// tolerance amplified by the conditioning of the slipping/open modes, as the
// serial solves with and without condensation do. 1e-7 relative on H, P and
// u is three decades above the iteration tolerance and far below what a
// lost or doubled harmonic does (even the six harmonics n = 7..12 together
// move the pile's final H by 7e-5, doc/nonlinear-interfaces.md section 5; a
// harmonic counted on both ranks doubles its share). u is the controlled
// motion (its target, to 1e-8 by the step's own check); H is the test.
// Equilibrium: 1e-8, as in interface_disc_gap_homogeneity (the residual
// tolerance times the stiffness ratio of the open modes).
#include <check.h>
#include <coupled_interface_test_support.h>
#include <two_ranks.h>

using namespace FourierSSI;

namespace
{
  void
  compare(const std::string &name,
          const std::string &text,
          const bool         equilibrium)
  {
    const auto [serial, distributed] =
      coupled_test::solve_steps_serial_and_distributed(name, text);
    if (!two_ranks::is_root())
      return;
    check::equal(name + ": harmonics after the solve, 2 ranks vs 1",
                 distributed.n_harmonics,
                 serial.n_harmonics);
    const unsigned int n =
      std::min(distributed.steps.size(), serial.steps.size());
    for (unsigned int s = 0; s < n; ++s)
      {
        const LoadStepResult &d = distributed.steps[s], &r = serial.steps[s];
        const std::string     step = name + " step " + std::to_string(s + 1);
        check::relative(step + ": applied load [kN], 2 ranks vs 1",
                        distributed.applied[s],
                        serial.applied[s],
                        1e-7);
        check::relative(step + ": u [m], 2 ranks vs 1",
                        d.motion.horizontal_displacement,
                        r.motion.horizontal_displacement,
                        1e-7);
        for (unsigned int k = 0; k < 3; ++k)
          check::equal(step + ": " +
                         std::string(k == 0 ? "stick" :
                                     k == 1 ? "slip" :
                                              "open") +
                         " samples, 2 ranks vs 1",
                       d.contact[k],
                       r.contact[k]);
        std::cout << "  " << step << ": iterations " << d.iterations
                  << " on 2 ranks, " << r.iterations << " on 1" << std::endl;
        if (equilibrium)
          check::small(step + ": |resultant_x - P| / P on 2 ranks",
                       (d.resultant[0] - distributed.applied[s]) /
                         distributed.applied[s],
                       1e-8);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  return two_ranks::run(argc, argv, [] {
    using test_support::with_entry;
    std::string pile = test_support::bundled_prm("prm/pile-lateral-slip.prm");
    pile             = with_entry(pile, "Target", "0.02");
    pile             = with_entry(pile, "Load steps", "4");
    compare("pile", pile, false);
    std::string disc = test_support::bundled_prm("prm/disc-gap.prm");
    disc             = with_entry(disc, "Harmonics", "1");
    disc += "subsection Load path\n"
            "  set Maximum harmonic = 16\n"
            "end\n";
    compare("disc grown from n = 1", disc, true);
  });
}
