// Patch test of the interface element: a uniform relative displacement Delta
// along s, n or theta (face B minus face A), superposed on an arbitrary
// displacement shared by both faces, must produce nodal forces whose sum on
// face B is k Delta w int r ds along that direction (and zero along the two
// others), with w the theta weight of the component and, for a straight
// face, int r ds = l (r_0 + r_p) / 2; face A carries the opposite resultant.

#include "interface_test_support.h"

#include <check.h>
#include <cmath>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/interfaces/interface_element.h>
#include <random>
#include <string>
#include <vector>

using namespace FourierSSI;

namespace
{
  struct Face
  {
    std::string      name;
    dealii::Point<2> start;
    double           angle;
    double           length;
  };
} // namespace

int
main()
{
  const double pi = dealii::numbers::PI;

  const std::vector<Face> faces = {
    {"vertical", dealii::Point<2>(0.6, -2.), 0.5 * pi, 1.2},
    {"inclined 40 deg", dealii::Point<2>(1.3, 0.4), 40. / 180. * pi, 0.9},
    {"inclined 200 deg", dealii::Point<2>(3.3, 0.4), 200. / 180. * pi, 2.1},
    {"radial from the axis", dealii::Point<2>(0., 0.7), 0., 1.6}};
  const std::vector<Harmonic> harmonics = {{0, Family::symmetric},
                                           {0, Family::antisymmetric},
                                           {1, Family::symmetric},
                                           {3, Family::antisymmetric}};
  const InterfaceStiffness    stiffness{6.4e5, 1.1e4};
  const double                delta             = 2.5e-3;
  const char *const           direction_name[3] = {"s", "n", "theta"};

  std::mt19937                           rng(1965);
  std::uniform_real_distribution<double> uniform(-1., 1.);

  for (const unsigned int degree : {2u, 4u})
    for (const Face &face : faces)
      {
        const std::vector<dealii::Point<2>> nodes =
          straight_face(degree, face.start, face.angle, face.length);
        const unsigned int m = degree + 1;
        // local unit vectors in global (r, z, theta) components
        const double c = std::cos(face.angle), s = std::sin(face.angle);
        const double frame[3][3] = {{c, s, 0.}, {-s, c, 0.}, {0., 0., 1.}};
        const double integral_r =
          face.length * (nodes.front()[0] + nodes.back()[0]) / 2.;

        for (const Harmonic &harmonic : harmonics)
          {
            const dealii::FullMatrix<double> k =
              interface_matrix(degree, nodes, stiffness, harmonic);
            const double weight[3]  = {harmonic.in_plane_weight(),
                                       harmonic.in_plane_weight(),
                                       harmonic.out_of_plane_weight()};
            const double k_local[3] = {stiffness.shear,
                                       stiffness.normal,
                                       stiffness.shear};
            // Force scale for the zero components and the vanishing weights.
            const double force_scale =
              stiffness.normal * 2. * pi * delta * integral_r;

            for (unsigned int dir = 0; dir < 3; ++dir)
              {
                dealii::Vector<double> u(6 * m), f(6 * m);
                for (unsigned int i = 0; i < m; ++i)
                  for (unsigned int g = 0; g < 3; ++g)
                    {
                      const double shared = 1e-2 * uniform(rng);
                      u[3 * i + g]       = shared - 0.5 * delta * frame[dir][g];
                      u[3 * (m + i) + g] = shared + 0.5 * delta * frame[dir][g];
                    }
                k.vmult(f, u);

                double resultant_a[3] = {0., 0., 0.};
                double resultant_b[3] = {0., 0., 0.};
                for (unsigned int i = 0; i < m; ++i)
                  for (unsigned int local = 0; local < 3; ++local)
                    for (unsigned int g = 0; g < 3; ++g)
                      {
                        resultant_a[local] += frame[local][g] * f[3 * i + g];
                        resultant_b[local] +=
                          frame[local][g] * f[3 * (m + i) + g];
                      }

                const std::string label = "p=" + std::to_string(degree) + " " +
                                          face.name + " " + harmonic.name() +
                                          " Delta_" + direction_name[dir];
                for (unsigned int local = 0; local < 3; ++local)
                  {
                    const double expected =
                      local == dir ?
                        k_local[dir] * delta * weight[dir] * integral_r :
                        0.;
                    // Tolerance 1e-13 relative to the force scale: the sum
                    // of the exact tables over k, i, j is 1 (partition of
                    // unity), so the resultant is exact up to round-off of
                    // O(10^2) operations, including the cancellation of the
                    // shared displacement.
                    check::relative(label + ": face B force along " +
                                      direction_name[local],
                                    resultant_b[local],
                                    expected,
                                    1e-13,
                                    force_scale);
                    check::relative(label + ": face A + face B along " +
                                      direction_name[local],
                                    resultant_a[local] + resultant_b[local],
                                    0.,
                                    1e-13,
                                    force_scale);
                  }
              }
          }
      }

  return check::summary();
}
