// Drained triaxial tests on a soil sample that starts from a geostatic
// state (Initial stress: Surcharge q, K0; doc/soil-plasticity.md section
// 3d). A cylinder a = 0.5 m, height 1 m, n = 0, G = 10000 kPa, nu = 0.3:
// smooth base (v = 0), free lateral face, a smooth rigid platen on top
// (Tie = boundary 3, Tied components = normal) pushed down (compression) or
// pulled up (extension) by displacement control. The lateral face keeps its
// initial traction (only increments are solved), so the radial stress stays
// sigma'_h = K0 q and the vertical stress changes uniformly until the
// sample yields as a whole (compression positive in these formulas):
//   Mohr-Coulomb, Kp = (1 + sin phi) / (1 - sin phi):
//     compression  sigma_v = Kp sigma_h + 2 c sqrt(Kp)
//     extension    sigma_h = Kp sigma_v + 2 c sqrt(Kp)
//   Tresca:        |sigma_v - sigma_h| = 2 s_u.
// The initial stress is what makes compression and extension differ: with
// K0 q = 0.6 q and s_u = 30 kPa, q = 100 kPa, Tresca yields after +20 kPa in
// compression and -100 kPa in extension; without the initial stress both
// would be 60 kPa.
// Checks, with their reasons:
//  - the vertical stress change F_z / (pi a^2) at the last step against the
//    closed form within 1e-7: the field is homogeneous, which Q2 represents
//    exactly, so only the iteration tolerance (1e-10 of the load) and
//    round-off remain;
//  - a plateau: the last two steps within 1e-7 of each other (perfect
//    plasticity, a homogeneous state);
//  - every converged step in equilibrium to 1e-8 and on or inside the yield
//    surface.
#include "soil_test_support.h"

#include <iomanip>

using namespace FourierSSI;
using namespace soil_test;

namespace
{
  std::string
  triaxial_scene(const std::string &law,
                 const double       surcharge,
                 const double       k0,
                 const double       platen_motion)
  {
    std::ostringstream prm;
    prm << std::setprecision(17) << R"(
subsection Discretization
  set Harmonics         = 0
  set Family            = symmetric
  set Polynomial degree = 2
end
subsection Mesh
  set Type          = rectangle
  set R breakpoints = 0, 0.5
  set R cells       = 2
  set Z breakpoints = -1, 0
  set Z cells       = 4
end
subsection Materials
  set Materials = 0: G=10000, nu=0.3
end
subsection Soil plasticity
  set Laws = 0: )"
        << law << R"(
end
subsection Initial stress
  set Surcharge = )"
        << surcharge << R"(
  set K0        = )"
        << k0 << R"(
end
subsection Rigid foundation
  set Enabled         = true
  set Tie             = boundary
  set Id              = 3
  set Tied components = normal
  set Vertical force  = -1
end
subsection Load path
  set Theta samples      = 1
  set Control            = displacement
  set Controlled motion  = vertical
  set Target             = )"
        << platen_motion << R"(
  set Load steps         = 5
  set Tolerance          = 1e-10
  set Maximum iterations = 3000
end
subsection Boundary conditions
  set Dirichlet = 2: v=0
end
)";
    return prm.str();
  }

  /**
   * The vertical stress change [kPa, tension positive] the platen carries
   * at the end of the path, after the checks on every step.
   */
  double
  vertical_stress_change(const std::string &name,
                         const std::string &law,
                         const double       surcharge,
                         const double       k0,
                         const double       platen_motion,
                         const double       strength_scale)
  {
    std::cout << name << std::endl;
    Run run(triaxial_scene(law, surcharge, k0, platen_motion));
    run.solver->run(std::cout);
    const auto  &steps         = run.solver->get_steps();
    const double area          = numbers::PI * 0.25;
    const auto   stress_change = [&](const unsigned int s) {
      return run.solver->applied_loads(steps[s].load_factor)[2] / area;
    };
    const double last   = stress_change(steps.size() - 1),
                 before = stress_change(steps.size() - 2);
    check::relative(name + ": plateau, last two steps", before, last, 1e-7);
    check_equilibrium_and_yield(name + " ", steps, strength_scale);
    return last;
  }
} // namespace

int
main()
{
  const double q = 100., phi = 30. * numbers::PI / 180., c = 5.;
  const double kp = (1. + std::sin(phi)) / (1. - std::sin(phi));
  {
    const double      k0 = 0.5, sigma_h = k0 * q;
    const std::string mc          = "mohr-coulomb, c=5, phi=30, psi=0";
    const double      compression = vertical_stress_change(
      "Mohr-Coulomb compression, K0 = 0.5", mc, q, k0, -0.01, 2. * c);
    check::relative("Mohr-Coulomb compression: change of sigma_v [kPa]",
                    compression,
                    -(kp * sigma_h + 2. * c * std::sqrt(kp) - q),
                    1e-7);
    const double extension = vertical_stress_change(
      "Mohr-Coulomb extension, K0 = 0.5", mc, q, k0, 0.01, 2. * c);
    check::relative("Mohr-Coulomb extension: change of sigma_v [kPa]",
                    extension,
                    q - (sigma_h - 2. * c * std::sqrt(kp)) / kp,
                    1e-7);
    // Associated flow (psi = phi): the same limit (in a homogeneous state
    // the flow rule changes the plastic strain, not the stress at yield).
    const double associated =
      vertical_stress_change("Mohr-Coulomb compression, psi = phi",
                             "mohr-coulomb, c=5, phi=30, psi=30",
                             q,
                             k0,
                             -0.01,
                             2. * c);
    check::relative("Mohr-Coulomb compression, psi = phi [kPa]",
                    associated,
                    compression,
                    1e-7);
  }
  {
    const double      k0 = 0.6, su = 30.;
    const std::string tresca      = "tresca, su=30";
    const double      compression = vertical_stress_change(
      "Tresca compression, K0 = 0.6", tresca, q, k0, -0.01, 2. * su);
    check::relative("Tresca compression: change of sigma_v [kPa]",
                    compression,
                    -(k0 * q + 2. * su - q),
                    1e-7);
    const double extension = vertical_stress_change(
      "Tresca extension, K0 = 0.6", tresca, q, k0, 0.01, 2. * su);
    check::relative("Tresca extension: change of sigma_v [kPa]",
                    extension,
                    q - (k0 * q - 2. * su),
                    1e-7);
  }
  return check::summary();
}
