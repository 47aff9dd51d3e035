// Rigid foundation/Held motions with plastic soil: the pure-H probe (the
// rotation held at zero, the footing pushed sideways by displacement
// control) on the rough footing on Tresca soil (prm/footing-capacity.prm,
// a = 1 m, s_u = 10 kPa, G = 3000 kPa; the coarse mesh of
// soil_footing_held_loads, n = 0 and 1, 8 theta samples), to u = 0.01 m
// (about 5 elastic yield displacements) in 4 steps. The checks and their
// reasons: tests/support/held_rotation_check.h (the held rotation stays 0,
// the holding moment and H balance the far supports).
// A lost plastic load shows as a moment mismatch of the size of the
// plastic part: with G left out the holding moment reads -28.9 kN m
// against the supports' 3.39 kN m (measured).
// The same checks on the free-head rigid pile of prm/pile-free-head.prm
// (n = 0, 1) with a nonlinear shaft interface, coulomb (c = 5 kPa,
// tensionless, kn = ks = 1e5 kPa/m) and exact contact (smooth,
// tensionless: a gap opens behind the pile): the interface's part of G
// (NonlinearInterfacePoints::spring_plastic, the nodal force of its
// tractions) enters the holding moment as the soil's does. Measured
// 1.8e-14 and 1.4e-12; with the interface's part left out the holding
// moment reads -88 023 and -3 024 523 kN m against the supports' 3111 and
// 3144 kN m.
#include "held_rotation_check.h"
#include "soil_test_support.h"

using namespace FourierSSI;
using namespace soil_test;

namespace
{
  /** free_head_pile() with 8 theta samples and its rotation held. */
  std::string
  pile_with_shaft(const std::string &law)
  {
    return free_head_pile(law, {{"Theta samples", "8"}}) +
           test_support::entries("Rigid foundation",
                                 {{"Held motions", "rotation"}});
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // The footing's entries changed in place; the new ones appended.
  Run footing(scene(joined(footing_mesh(true),
                           {{"Harmonics", "0, 1"},
                            {"Vertical force", "0"},
                            {"Capacity normalisation", ""},
                            {"Theta samples", "8"},
                            {"Controlled motion", "horizontal"},
                            {"Target", "0.01"},
                            {"Load steps", "4"}})) +
              "subsection Rigid foundation\n"
              "  set Horizontal force = 1\n"
              "  set Held motions     = rotation\n"
              "end\n");
  footing.solver->run(std::cout);
  held_rotation::check("footing", *footing.solver, *footing.set, 1.);
  // The holding moment through a nonlinear shaft interface: its tractions'
  // part of G (NonlinearInterfacePoints::spring_plastic) enters the
  // foundation's internal force as the soil's does.
  Run slipping(
    pile_with_shaft("coulomb, kn=1e5, ks=1e5, c=5, phi=0, sigma_t=0"));
  slipping.solver->run(std::cout);
  held_rotation::check("pile, coulomb shaft",
                       *slipping.solver,
                       *slipping.set,
                       10.);
  Run gapping(pile_with_shaft("contact, phi=0"));
  gapping.solver->run(std::cout);
  held_rotation::check("pile, contact shaft",
                       *gapping.solver,
                       *gapping.set,
                       10.);
  return check::summary();
}
