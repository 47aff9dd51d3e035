// The 6-node (p = 2) and 10-node (p = 4) interface elements on the same face,
// loaded by the same quadratic relative displacement field (which both
// interpolate exactly), must give the same traction resultant (sum of the
// nodal forces of each face) and the same energy, both equal to their
// closed-form values
//   R_c = w_c k_c int_0^l Delta_c r ds,  E = sum_c w_c k_c int_0^l Delta_c^2 r
//   ds
// (c = s, n, theta; w_c the theta weight of the component).

#include <array>
#include <check.h>
#include <cmath>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/interfaces/interface_element.h>
#include <string>
#include <vector>

using namespace FourierSSI;

namespace
{
  using Polynomial = std::vector<double>; // coefficients of xi^0, xi^1, ...

  Polynomial
  multiply(const Polynomial &a, const Polynomial &b)
  {
    Polynomial c(a.size() + b.size() - 1, 0.);
    for (unsigned int i = 0; i < a.size(); ++i)
      for (unsigned int j = 0; j < b.size(); ++j)
        c[i + j] += a[i] * b[j];
    return c;
  }

  double
  evaluate(const Polynomial &a, const double xi)
  {
    double v = 0.;
    for (unsigned int i = a.size(); i-- > 0;)
      v = v * xi + a[i];
    return v;
  }

  /** int_0^1 a(xi) dxi, exactly. */
  double
  integral(const Polynomial &a)
  {
    double v = 0.;
    for (unsigned int i = 0; i < a.size(); ++i)
      v += a[i] / (i + 1);
    return v;
  }

  struct Response
  {
    std::array<double, 3> resultant_a; // global (r, z, theta) components
    std::array<double, 3> resultant_b;
    double                energy; // u^T K u
  };

  Response
  respond(const unsigned int               degree,
          const dealii::Point<2>          &start,
          const double                     angle,
          const double                     length,
          const std::array<Polynomial, 3> &delta,
          const std::array<double, 3>     &shared,
          const Harmonic                  &harmonic,
          const InterfaceStiffness        &stiffness)
  {
    const unsigned int m = degree + 1;
    const double       c = std::cos(angle), s = std::sin(angle);
    const double       frame[3][3] = {{c, s, 0.}, {-s, c, 0.}, {0., 0., 1.}};
    std::vector<dealii::Point<2>> nodes(m);
    dealii::Vector<double>        u(6 * m), f(6 * m);
    for (unsigned int k = 0; k < m; ++k)
      {
        const double xi = static_cast<double>(k) / degree;
        nodes[k] = start + dealii::Point<2>(xi * length * c, xi * length * s);
        for (unsigned int g = 0; g < 3; ++g)
          {
            double relative = 0.;
            for (unsigned int local = 0; local < 3; ++local)
              relative += evaluate(delta[local], xi) * frame[local][g];
            u[3 * k + g]       = shared[g] - 0.5 * relative;
            u[3 * (m + k) + g] = shared[g] + 0.5 * relative;
          }
      }
    const dealii::FullMatrix<double> matrix =
      interface_matrix(degree, nodes, stiffness, harmonic);
    matrix.vmult(f, u);
    Response response{{{0., 0., 0.}}, {{0., 0., 0.}}, f * u};
    for (unsigned int k = 0; k < m; ++k)
      for (unsigned int g = 0; g < 3; ++g)
        {
          response.resultant_a[g] += f[3 * k + g];
          response.resultant_b[g] += f[3 * (m + k) + g];
        }
    return response;
  }
} // namespace

int
main()
{
  const double                pi = dealii::numbers::PI;
  const InterfaceStiffness    stiffness{3.2e5, 4.7e4};
  const std::vector<Harmonic> harmonics = {{0, Family::symmetric},
                                           {0, Family::antisymmetric},
                                           {2, Family::symmetric}};

  struct Face
  {
    std::string      name;
    dealii::Point<2> start;
    double           angle;
    double           length;
  };
  const std::vector<Face> faces = {
    {"inclined", dealii::Point<2>(0.9, -0.3), 1.9, 0.8},
    {"radial from the axis", dealii::Point<2>(0., 0.), 0., 2.},
    {"vertical", dealii::Point<2>(1.4, 2.), -0.5 * pi, 3.}};

  // Quadratic relative displacements along s, n, theta (xi in [0, 1]).
  const std::array<Polynomial, 3> delta  = {{{1.0e-3, -2.0e-3, 3.5e-3},
                                             {-4.0e-4, 1.5e-3, 2.0e-3},
                                             {2.0e-3, 0., -1.2e-3}}};
  const std::array<double, 3>     shared = {{1.0e-2, -5.0e-3, 2.0e-2}};

  for (const Face &face : faces)
    for (const Harmonic &harmonic : harmonics)
      {
        const Response quadratic = respond(2,
                                           face.start,
                                           face.angle,
                                           face.length,
                                           delta,
                                           shared,
                                           harmonic,
                                           stiffness);
        const Response quartic   = respond(4,
                                         face.start,
                                         face.angle,
                                         face.length,
                                         delta,
                                         shared,
                                         harmonic,
                                         stiffness);

        // Closed-form references.
        const double     r0         = face.start[0];
        const double     r1         = r0 + face.length * std::cos(face.angle);
        const Polynomial r          = {r0, r1 - r0};
        const double     weight[3]  = {harmonic.in_plane_weight(),
                                       harmonic.in_plane_weight(),
                                       harmonic.out_of_plane_weight()};
        const double     k_local[3] = {stiffness.shear,
                                       stiffness.normal,
                                       stiffness.shear};
        const double     c = std::cos(face.angle), s = std::sin(face.angle);
        const double     frame[3][3] = {{c, s, 0.}, {-s, c, 0.}, {0., 0., 1.}};
        std::array<double, 3> resultant{{0., 0., 0.}};
        double                energy = 0.;
        for (unsigned int local = 0; local < 3; ++local)
          {
            const double force = weight[local] * k_local[local] * face.length *
                                 integral(multiply(delta[local], r));
            for (unsigned int g = 0; g < 3; ++g)
              resultant[g] += force * frame[local][g];
            energy +=
              weight[local] * k_local[local] * face.length *
              integral(multiply(multiply(delta[local], delta[local]), r));
          }
        double force_scale = 0.;
        for (const double x : resultant)
          force_scale = std::max(force_scale, std::abs(x));

        // Tolerances: both elements represent the quadratic field exactly
        // and integrate exactly; 1e-13 relative (to the largest resultant
        // component / the energy) covers the round-off of the tables and of
        // the nodal values: the shared displacement (~10 times the relative
        // one) is rounded together with it in u, which costs ~10 eps
        // relative on the relative displacement (errors measured <= 4e-15).
        const std::string label   = face.name + ", " + harmonic.name();
        const char *const name[3] = {"r", "z", "theta"};
        for (unsigned int g = 0; g < 3; ++g)
          {
            check::relative(label + ": resultant_" + name[g] + " p=4 vs p=2",
                            quartic.resultant_b[g],
                            quadratic.resultant_b[g],
                            1e-13,
                            force_scale);
            check::relative(label + ": resultant_" + name[g] +
                              " p=2 vs closed form",
                            quadratic.resultant_b[g],
                            resultant[g],
                            1e-13,
                            force_scale);
            check::relative(label + ": face A resultant_" + name[g] +
                              " = -face B (p=4)",
                            quartic.resultant_a[g],
                            -quartic.resultant_b[g],
                            1e-13,
                            force_scale);
          }
        check::relative(label + ": energy p=4 vs p=2",
                        quartic.energy,
                        quadratic.energy,
                        1e-13);
        check::relative(label + ": energy p=2 vs closed form",
                        quadratic.energy,
                        energy,
                        1e-13);
      }

  return check::summary();
}
