// The rigid pile of the coulomb-interface tests
// (tests/coupled/interface_coulomb_pile.cc, interface_held_traction.cc):
// radius a = 0.5 m, length L = 5 m, in soil 10 m deep and 10 m wide.
#ifndef fourier_ssi_tests_rigid_pile_scene_h
#define fourier_ssi_tests_rigid_pile_scene_h

#include <string>

namespace test_support
{
  /**
   * Harmonic n = 0 of `family`, FE_Q(2); soil G = 1e4 kPa, nu = 0.3
   * (material 0), the pile (material 1, G = 1e7 kPa) tied as a rigid
   * foundation; interface lines 5 (shaft r = a) and 6 (base z = -L);
   * geostatic stress gamma' = 10 kN/m^3, K0 = 0.5; outer boundary and
   * bottom fixed. No interface law, load or load path: the test appends
   * them (the parameter file keeps the last value an entry is given).
   */
  inline std::string
  rigid_pile_scene(const std::string &family = "symmetric")
  {
    return R"(
subsection Discretization
  set Harmonics         = 0
  set Family            = )" +
           family + R"(
  set Polynomial degree = 2
end
subsection Mesh
  set R breakpoints   = 0, 0.5, 10
  set R cells         = 2, 8
  set R growth        = 1, 1.4
  set Z breakpoints   = -10, -5, 0
  set Z cells         = 5, 6
  set Z growth        = 0.8, 1
  set Material regions = 1: 0, 0.5, -5, 0
  set Interface lines = 5: r=0.5, z=-5..0; 6: z=-5, r=0..0.5
end
subsection Materials
  set Materials = 0: G=10000, nu=0.3; 1: G=1e7, nu=0.2
end
subsection Initial stress
  set Effective unit weight = 10
  set K0                    = 0.5
end
subsection Boundary conditions
  set Dirichlet = 1: u=0, v=0, w=0; 2: u=0, v=0, w=0
end
subsection Rigid foundation
  set Enabled = true
  set Tie     = material
  set Id      = 1
end
)";
  }
} // namespace test_support

#endif
