// plateau_error (the capacity's plateau error printed with every
// displacement-controlled plastic run): on curves with a known asymptote.
//  - a hyperbola P = u / (a + b u): the error is 1/b - P(u_last) exactly
//    (the fit through three points of it is exact; tolerance 1e-12,
//    round-off);
//  - the same curve with u and P negative (a footing pushed down): the same;
//  - a flat plateau (perfect plasticity in a homogeneous state): 0 (the
//    hyperbola u/P = u/P_ult has b = 1/P_ult; tolerance 1e-12 of P);
//  - a straight line through the origin (elastic, P = k u): no bend, b = 0:
//    infinite; and fewer than three steps: infinite.
#include "check.h"

#include <cmath>
#include <fourier_ssi/estimation/capacity_plateau.h>
#include <vector>

using namespace FourierSSI;

int
main()
{
  const double        a = 0.002, b = 0.01; // asymptote 100
  std::vector<double> u, P, u_down, P_down;
  for (const double x : {0.01, 0.02, 0.04, 0.06, 0.08, 0.1})
    {
      u.push_back(x);
      P.push_back(x / (a + b * x));
      u_down.push_back(-x);
      P_down.push_back(-x / (a + b * x));
    }
  const double exact = 1. / b - P.back();
  check::relative("hyperbola: error = asymptote - last load",
                  plateau_error(u, P),
                  exact,
                  1e-12);
  check::relative("hyperbola, u and P negative",
                  plateau_error(u_down, P_down),
                  exact,
                  1e-12);
  check::small("flat plateau: error",
               plateau_error({0.01, 0.02, 0.03}, {50., 50., 50.}),
               50. * 1e-12);
  check::that("straight line: infinite",
              std::isinf(plateau_error({0.01, 0.02, 0.03}, {1., 2., 3.})));
  check::that("two steps: infinite",
              std::isinf(plateau_error({0.01, 0.02}, {1., 2.})));
  return check::summary();
}
