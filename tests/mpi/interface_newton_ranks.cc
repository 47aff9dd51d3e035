// Run with mpirun -np 2. Requirement "one nonlinear engine": Newton
// (Load path/Stiffness = tangent, doc/nonlinear-interfaces.md section 5b)
// with the harmonics distributed over the ranks (each rank fills the
// Jacobian columns of the harmonics it owns, one sum over the ranks, one
// rank solves and broadcasts the step; interface_condensation.cc)
// reproduces the serial Newton curve, which every rank also runs on
// MPI_COMM_SELF. The scene: the disc in a ring of prm/disc-gap.prm (rigid
// disc r0 = 0.5 m pushed along x to ubar = 1e-3 m in 4 displacement steps,
// G = E / (2 (1 + nu)) = 38462 kPa), harmonics n = 0..32 (17 on rank 0,
// 16 on rank 1), Theta samples = 2 n_max + 1 = 65, tensionless interface
// mu = tan(phi) = 0.3, as tests/coupled/interface_newton_disc.cc and
// interface_contact_disc.cc:
// 1. `coulomb` with kn = ks = 1e6 G / r0 (a stiff penalty: the
//    initial-stiffness iteration would need ~1e6 iterations);
// 2. `contact` (augmented Lagrangian, a Newton solve per multiplier
//    update).
// 3. The lateral pile of prm/pile-lateral-slip.prm (7 harmonics: 4 on rank
//    0, 3 on rank 1; 57 interface points) shortened to 4 steps to
//    u = 0.02 m, as in coupled_interface_ranks.cc: the slip spreads down
//    the shaft from step to step, so Newton iterates in every step, and
//    the pile head's rotation is a response (not controlled).
// At every step, 2 ranks against 1:
//  * the applied load H and the motion u to 1e-8 relative (u is the
//    controlled motion, on its target by the step's own check; H is the
//    test), and the pile's rotation (the disc's is zero up to round-off by
//    symmetry: not compared). Both runs
//    stop at |R| <= 1e-10 of the force scale; the distributed iterates are the
//    serial ones up to round-off (the same factorizations and Jacobian
//    columns, the columns summed exactly since each comes from one rank),
//    so the curves agree to round-off times the conditioning; a Jacobian
//    that lost the other rank's columns (no sum) takes other Newton steps
//    and lands elsewhere within the tolerance's reach, and shows in:
//  * the Newton iteration count and the contact multiplier updates, equal;
//  * the stick/slip/open counts, equal.
// TIMEOUT (tests/mpi/CMakeLists.txt): a rank that takes another decision
// than its peer waits forever in the next collective.
#include <check.h>
#include <cmath>
#include <coupled_interface_test_support.h>
#include <iomanip>
#include <sstream>
#include <two_ranks.h>

using namespace FourierSSI;

namespace
{
  const double G  = 1e5 / (2. * 1.3); // kPa
  const double r0 = 0.5;              // m

  /** prm/disc-gap.prm with `law` on boundary 5, n = 0..32, Newton. */
  std::string
  scene(const std::string &law)
  {
    const std::string text = coupled_test::disc_in_ring(law);
    // Maximum iterations = 50 (measured at most 7 per step): a wrong
    // Jacobian fails in seconds instead of running into the TIMEOUT.
    return text + "\nsubsection Load path\n  set Stiffness = tangent\n"
                  "  set Theta samples = 65\n"
                  "  set Maximum iterations = 50\nend\n";
  }

  /** The lateral pile to u = 0.02 m in 4 steps, Newton. */
  std::string
  pile_scene()
  {
    using test_support::with_entry;
    std::string text = test_support::bundled_prm("prm/pile-lateral-slip.prm");
    text             = with_entry(text, "Target", "0.02");
    text             = with_entry(text, "Load steps", "4");
    return text + "\nsubsection Load path\n  set Stiffness = tangent\n"
                  "  set Maximum iterations = 50\nend\n";
  }

  std::string
  friction_angle()
  {
    std::ostringstream phi;
    phi << std::setprecision(17) << std::atan(0.3) * 180. / M_PI;
    return phi.str();
  }

  void
  compare_step(const std::string    &step,
               const LoadStepResult &d,
               const LoadStepResult &r,
               const double          H_distributed,
               const double          H_serial,
               const bool            rotation_is_response)
  {
    check::relative(step + ": H [kN], 2 ranks vs 1",
                    H_distributed,
                    H_serial,
                    1e-8);
    check::relative(step + ": u [m], 2 ranks vs 1",
                    d.motion.horizontal_displacement,
                    r.motion.horizontal_displacement,
                    1e-8);
    if (rotation_is_response)
      check::relative(step + ": rotation [rad], 2 ranks vs 1",
                      d.motion.rotation,
                      r.motion.rotation,
                      1e-8);
    check::equal(step + ": Newton iterations, 2 ranks vs 1",
                 d.iterations,
                 r.iterations);
    check::equal(step + ": contact multiplier updates, 2 ranks vs 1",
                 d.multiplier_updates,
                 r.multiplier_updates);
    for (unsigned int k = 0; k < 3; ++k)
      check::equal(step + ": " +
                     std::string(k == 0 ? "stick" :
                                 k == 1 ? "slip" :
                                          "open") +
                     " samples, 2 ranks vs 1",
                   d.contact[k],
                   r.contact[k]);
    std::cout << "  " << step << ": H " << std::setprecision(15)
              << H_distributed << " vs " << H_serial << " kN (relative "
              << std::setprecision(3)
              << std::abs(H_distributed - H_serial) / std::abs(H_serial)
              << "), " << d.iterations << " iterations on 2 ranks, "
              << r.iterations << " on 1" << std::endl;
  }

  void
  compare(const std::string &name,
          const std::string &text,
          const bool         rotation_is_response)
  {
    const auto [serial, distributed] =
      coupled_test::solve_steps_serial_and_distributed(name, text);
    if (!two_ranks::is_root())
      return;
    check::equal(name + ": converged steps", serial.steps.size(), 4ul);
    const unsigned int n =
      std::min(distributed.steps.size(), serial.steps.size());
    for (unsigned int s = 0; s < n; ++s)
      compare_step(name + " step " + std::to_string(s + 1),
                   distributed.steps[s],
                   serial.steps[s],
                   distributed.applied[s],
                   serial.applied[s],
                   rotation_is_response);
    std::cout << "  " << name << ": load steps " << serial.seconds
              << " s on 1 rank, " << distributed.seconds << " s on 2"
              << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  return two_ranks::run(argc, argv, [] {
    std::ostringstream penalty;
    penalty << std::setprecision(17) << "coulomb, kn=" << 1e6 * G / r0
            << ", ks=" << 1e6 * G / r0 << ", c=0, phi=" << friction_angle()
            << ", sigma_t=0";
    compare("coulomb kn = 1e6 G/r0", scene(penalty.str()), false);
    compare("contact", scene("contact, c=0, phi=" + friction_angle()), false);
    compare("pile", pile_scene(), true);
  });
}
