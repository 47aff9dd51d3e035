// Rigid foundation/Motion direction (the displacement probe of the offshore
// literature: the foundation driven along a fixed ratio u : L theta) on the
// bundled embedded footing (FE_Q(2), one cycle, exact 'tied' interface, the
// scene of tests/harmonic/held_motions.cc), against independent references:
//  - the driven ratio: u / (L theta) = d_u / d_theta to round-off (the
//    constraint d_theta u - d_u L theta = 0 solved for one master DoF;
//    tolerance 1e-12, a few products of O(1) weights);
//  - linear elasticity: the H and M on the foundation (rows probe_H,
//    probe_M: the applied load plus the load that keeps the direction)
//    are [H; M] = K [u; theta] with K the n = 1 stiffness of the free
//    footing, K = I^-1 from the separate unit-H and unit-M solves of
//    Stiffness coefficients (thesis eqs 4.2-4.5). Same mesh and matrix,
//    so only round-off separates them; tolerance 1e-10 (a wrong
//    constraint or a lost reaction is an O(1) error);
//  - the load that keeps the direction does no work along it, so
//    H d_u + M d_theta / L equals the applied loads' work (tolerance
//    1e-10, round-off of a difference of O(1) terms);
//  - equilibrium: the support reactions (boundaries 1 and 2) balance H and
//    M + z_ref H about the origin (tolerance 1e-10 as held_motions.cc).
// Two probes: driven by H about the surface (the master node at the
// footing's base corner, U_A solved from V_A) and driven by M about
// z_ref = 3 m with a negative u component (V_A solved from U_A, and the
// moment's nodal force moved onto U_A). Measured: every check within
// 1e-13. Without the direction's constraint u / (L theta) is that of the
// free footing (the first check fails, 0.57 and 1 relative); rows read
// from the applied loads alone would miss the load that keeps the
// direction (H -9.90 kN, M 40.10 kN m against the applied 0 and 50 in the
// second probe), which the K [u; theta] checks see.
#include "check.h"
#include "test_support.h"

#include <sstream>

using namespace FourierSSI;

namespace
{
  const double G = 1000., a = 1.; // the scene's normalisation

  struct Probe
  {
    std::string z_ref;
    double      d_u, d_theta, L;
    double      H_applied, M_applied;
  };

  void
  check_probe(const Probe &p)
  {
    const Harmonic    h{1, Family::symmetric};
    const std::string at = " (z_ref = " + p.z_ref + " m)";
    const std::string reference =
      " set Reference elevation = " + p.z_ref + "\n";
    const ResultsTable free = test_support::run(test_support::tied_footing(
      " set Stiffness coefficients = true\n" + reference));
    const double       K_H = free.get("K_H", h, 0), K_M = free.get("K_M", h, 0),
                 K_MH = free.get("K_MH", h, 0);
    std::ostringstream direction;
    direction << std::setprecision(17) << " set Motion direction = u: " << p.d_u
              << ", rotation: " << p.d_theta
              << "\n set Direction length = " << p.L << "\n";
    std::ostringstream loads;
    loads << std::setprecision(17) << " set Horizontal force = " << p.H_applied
          << "\n set Moment = " << p.M_applied << "\n";
    const ResultsTable probe = test_support::run(
      test_support::tied_footing(" set Stiffness coefficients = false\n" +
                                 reference + direction.str() + loads.str()));
    const double u     = probe.get("foundation_horizontal_displacement", h, 0);
    const double theta = probe.get("foundation_rotation", h, 0);
    const double H     = probe.get("probe_H", h, 0);
    const double M     = probe.get("probe_M", h, 0);
    std::cout << "  probe" << at << ": u " << u << " m, theta " << theta
              << " rad, H " << H << " kN, M " << M << " kN m" << std::endl;
    check::relative("u d_theta vs d_u L theta" + at,
                    u * p.d_theta,
                    p.d_u * p.L * theta,
                    1e-12,
                    std::abs(p.d_u * p.L * theta) + std::abs(u * p.d_theta));
    // [H / (G a^2); M / (G a^3)] = K [u / a; theta].
    const double H_elastic = G * a * K_H * u + G * a * a * K_MH * theta;
    const double M_elastic = G * a * a * K_MH * u + G * a * a * a * K_M * theta;
    const double scale     = std::abs(H) * a + std::abs(M);
    check::relative(
      "H vs K [u; theta]" + at, H * a, H_elastic * a, 1e-10, scale);
    check::relative("M vs K [u; theta]" + at, M, M_elastic, 1e-10, scale);
    check::relative("work along the direction vs the applied loads'" + at,
                    H * p.d_u + M * p.d_theta / p.L,
                    p.H_applied * p.d_u + p.M_applied * p.d_theta / p.L,
                    1e-10,
                    (std::abs(H * p.d_u) + std::abs(M * p.d_theta / p.L)));
    double support_force = 0., support_moment = 0.;
    for (const std::string id : {"1", "2"})
      {
        support_force += probe.get("reaction_force_boundary_" + id, h, 0);
        support_moment += probe.get("reaction_moment_boundary_" + id, h, 0);
      }
    check::relative(
      "support force vs -H" + at, support_force * a, -H * a, 1e-10, scale);
    check::relative("support moment vs -(M + z_ref H)" + at,
                    support_moment,
                    -(M + std::stod(p.z_ref) * H),
                    1e-10,
                    scale);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_probe({"0", 1., 0.25, 2., 100., 0.});
  check_probe({"3", -0.5, 1., 2., 0., 50.});
  return check::summary();
}
