// Rigid foundation/Held motions (the rigid-motion probes: pure H with the
// rotation held at zero, pure M with the translation held at zero) on the
// bundled embedded footing (FE_Q(2), one cycle, exact 'tied' interface, so
// the footing's master node has soil twins), against independent references:
//  - the held motion is zero: V_A = 0 holds Theta exactly (0 to the bit);
//    U_h = U_A + V_A (z_A - z_ref) / r_A is a sum of two numbers of the size
//    of Theta, so |U_h| <= 1e-13 Theta a (round-off of one product);
//  - the n = 1 stiffness of the free footing, K = I^-1 from the unit H and
//    unit M solves of Stiffness coefficients (thesis eqs 4.2-4.5, the H-M
//    block of the 6x6 matrix): with Theta held, H = G a K_H u and the load
//    that holds it M = G a^2 K_MH u; with u held, M = G a^3 K_M Theta and
//    H = G a^2 K_MH Theta. Same mesh and matrix, so only round-off
//    separates them (measured <= 7e-15); tolerance 1e-11, a bound on the
//    round-off of these well-scaled systems (a wrong hold or a lost force
//    is an O(1) error);
//  - equilibrium: the support reactions (boundaries 1 and 2), the applied
//    load and the load that holds the held motion sum to zero (force and
//    moment about the origin); exact for the discrete system (measured
//    <= 1.3e-13; tolerance 1e-10 as tests/harmonic/reaction_equilibrium.cc
//    for tied interfaces).
// Without the held constraints Theta (u) is not zero and the H/u and M/Theta
// ratios are the free compliances' inverses, 20-60 % off; with the moment's
// nodal force left on a constrained master (the first version, z_ref = 3 m
// below) nothing moves and M / Theta is infinite.
#include "check.h"
#include "test_support.h"

using namespace FourierSSI;

namespace
{
  const double G = 1000., a = 1.; // the scene's normalisation

  struct SupportResultant
  {
    double force = 0., moment = 0.;
  };

  SupportResultant
  supports(const ResultsTable &r, const Harmonic &h)
  {
    SupportResultant s;
    for (const std::string id : {"1", "2"})
      {
        s.force += r.get("reaction_force_boundary_" + id, h, 0);
        s.moment += r.get("reaction_moment_boundary_" + id, h, 0);
      }
    return s;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Harmonic                   h{1, Family::symmetric};
  const ResultsTable               free = test_support::run(
    test_support::tied_footing(" set Stiffness coefficients = true\n"));
  const double K_H = free.get("K_H", h, 0), K_M = free.get("K_M", h, 0),
               K_MH = free.get("K_MH", h, 0);
  std::cout << "  free footing: K_H " << K_H << ", K_M " << K_M << ", K_MH "
            << K_MH << std::endl;

  // Pure H: rotation held.
  const double       H      = 100.;
  const ResultsTable pure_H = test_support::run(
    test_support::tied_footing(" set Stiffness coefficients = false\n"
                               " set Horizontal force = 100\n"
                               " set Held motions = rotation\n"));
  const double u      = pure_H.get("foundation_horizontal_displacement", h, 0);
  const double theta  = pure_H.get("foundation_rotation", h, 0);
  const double M_hold = pure_H.get("held_rotation_reaction", h, 0);
  check::small("pure H: rotation held", theta, 0.);
  check::relative("pure H: H / (G a u) vs K_H", H / (G * a * u), K_H, 1e-11);
  check::relative("pure H: holding M / (G a^2 u) vs K_MH",
                  M_hold / (G * a * a * u),
                  K_MH,
                  1e-11);
  const SupportResultant s_H = supports(pure_H, h);
  check::relative("pure H: support force vs -H", s_H.force, -H, 1e-10);
  check::relative("pure H: support moment vs -holding M",
                  s_H.moment,
                  -M_hold,
                  1e-10);

  // Pure M: horizontal translation held, about the surface (the master
  // node at the footing's base corner (1, -1): U_A is constrained to V_A)
  // and about z_ref = 3 m (|z_A - z_ref| = 4 r_A: V_A is constrained to
  // U_A, and the moment's nodal force on V_A must move onto U_A).
  for (const std::string z_ref : {"0", "3"})
    {
      const std::string at = " (z_ref = " + z_ref + " m)";
      const std::string reference =
        " set Reference elevation = " + z_ref + "\n";
      const ResultsTable free_here =
        test_support::run(test_support::tied_footing(
          " set Stiffness coefficients = true\n" + reference));
      const double K_M_here     = free_here.get("K_M", h, 0),
                   K_MH_here    = free_here.get("K_MH", h, 0);
      const double       M      = 50.;
      const ResultsTable pure_M = test_support::run(
        test_support::tied_footing(" set Stiffness coefficients = false\n"
                                   " set Moment = 50\n"
                                   " set Held motions = u\n" +
                                   reference));
      const double u_M = pure_M.get("foundation_horizontal_displacement", h, 0);
      const double theta_M = pure_M.get("foundation_rotation", h, 0);
      const double H_hold  = pure_M.get("held_u_reaction", h, 0);
      check::small("pure M: u held" + at, u_M, 1e-13 * std::abs(theta_M) * a);
      check::relative("pure M: M / (G a^3 Theta) vs K_M" + at,
                      M / (G * a * a * a * theta_M),
                      K_M_here,
                      1e-11);
      check::relative("pure M: holding H / (G a^2 Theta) vs K_MH" + at,
                      H_hold / (G * a * a * theta_M),
                      K_MH_here,
                      1e-11);
      // Moments about the origin (the supports' convention): the applied
      // M and the holding H acting at z_ref.
      const SupportResultant s_M = supports(pure_M, h);
      check::relative("pure M: support force vs -holding H" + at,
                      s_M.force,
                      -H_hold,
                      1e-10);
      check::relative("pure M: support moment vs -(M + z_ref H)" + at,
                      s_M.moment,
                      -(M + std::stod(z_ref) * H_hold),
                      1e-10);
    }
  return check::summary();
}
