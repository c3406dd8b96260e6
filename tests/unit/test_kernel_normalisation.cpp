// Kernel normalisation checked by GSL quadrature: integral of W over R^D equals 1.
#include <catch2/catch.hpp>
#include <gsl/gsl_integration.h>

#include <cmath>
#include <numbers>

#include "sphmol/kernels/cubic_spline.hpp"

namespace {
template <class K>
double integrate_radial(double h) {
  // Integral of W over R^D for a radial kernel: (surface of the unit sphere) * int W(r) r^(D-1) dr.
  constexpr int D = K::dimension;
  const double surface = D == 1 ? 2.0 : D == 2 ? 2.0 * std::numbers::pi : 4.0 * std::numbers::pi;
  gsl_function f;
  struct P { double h; } p{h};
  f.function = [](double r, void* vp) {
    const double hh = static_cast<P*>(vp)->h;
    return K::W(r, hh) * std::pow(r, D - 1);
  };
  f.params = &p;
  gsl_integration_workspace* ws = gsl_integration_workspace_alloc(1000);
  // Break points at the spline knots so the quadrature sees smooth pieces.
  double pts[] = {0.0, h, K::support * h};
  double result = 0, err = 0;
  gsl_integration_qagp(&f, pts, 3, 1e-14, 1e-13, 1000, ws, &result, &err);
  gsl_integration_workspace_free(ws);
  return surface * result;
}
}  // namespace

TEMPLATE_TEST_CASE("cubic spline integrates to one", "[kernel]", sphmol::CubicSpline<1>,
                   sphmol::CubicSpline<2>, sphmol::CubicSpline<3>) {
  for (double h : {1e-5, 0.37, 2.0}) CHECK(integrate_radial<TestType>(h) == Approx(1.0).epsilon(1e-10));
}
