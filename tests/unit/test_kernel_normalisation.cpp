// Kernel normalisation checked by GSL quadrature: the integral of W over R^D equals 1 (or, for the
// deliberately unrenormalised truncated exponential, the mass it claims), in every dimension.
#include <catch2/catch.hpp>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <cmath>
#include <numbers>
#include <string_view>
#include <tuple>

#include "sphmol/kernels/registry.hpp"

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
  // Break points at every integer multiple of h (all knots of all kernels lie there).
  double pts[8];
  int n = 0;
  for (double q = 0.0; q < K::support; q += 1.0) pts[n++] = q * h;
  pts[n++] = K::support * h;
  double result = 0, err = 0;
  // Handler off: qagp may flag round-off while its result is already at machine precision
  // (the 3D super-Gaussian cancels a factor ~50); the comparison below is the real check.
  gsl_error_handler_t* old = gsl_set_error_handler_off();
  gsl_integration_qagp(&f, pts, n, 1e-14 / std::pow(h, D), 1e-13, 1000, ws, &result, &err);
  gsl_set_error_handler(old);
  gsl_integration_workspace_free(ws);
  return surface * result;
}

using AllKernels = decltype(std::tuple_cat(sphmol::KernelTypes<1>{}, sphmol::KernelTypes<2>{},
                                           sphmol::KernelTypes<3>{}));
}  // namespace

TEMPLATE_TEST_CASE("cubic spline integrates to one", "[kernel]", sphmol::CubicSpline<1>,
                   sphmol::CubicSpline<2>, sphmol::CubicSpline<3>) {
  for (double h : {1e-5, 0.37, 2.0}) CHECK(integrate_radial<TestType>(h) == Approx(1.0).epsilon(1e-10));
}

TEMPLATE_LIST_TEST_CASE("every kernel integrates to its claimed mass", "[kernel]", AllKernels) {
  using K = TestType;
  if constexpr (K::available) {
    INFO(K::name << " in " << K::dimension << "D");
    // Only the truncated exponential is (deliberately, Niedoba 2012, eq 2.43) not renormalised.
    if (K::name == "truncated_exponential") {
      CHECK(sphmol::kernel_mass<K>() < 1.0 - 1e-5);
      CHECK(sphmol::kernel_mass<K>() > 1.0 - 1e-3);
    } else {
      CHECK(sphmol::kernel_mass<K>() == 1.0);
    }
    for (double h : {1e-3, 0.37, 2.0})
      CHECK(integrate_radial<K>(h) == Approx(sphmol::kernel_mass<K>()).epsilon(1e-10));
  }
}

TEST_CASE("truncated exponential keeps the mass of Niedoba 2012, eq 2.43", "[kernel]") {
  // The source's constant is that of the untruncated Gaussian, pi^(-D/2) h^-D, so its mass is 1 minus
  // the tail beyond 3h (2D: exactly 1 - e^-9). The C1 cut-off keeps that mass: the kernel is the
  // renormalised Gaussian times it.
  CHECK(sphmol::kernel_mass<sphmol::TruncatedExponentialKernel<2>>() == Approx(1.0 - std::exp(-9.0)).epsilon(1e-14));
  const double h = 0.7;
  for (double r : {0.0, 0.3, 1.1, 2.0})
    CHECK(sphmol::TruncatedExponentialKernel<2>::W(r, h) ==
          Approx((1.0 - std::exp(-9.0)) * sphmol::GaussianKernel<2>::W(r, h)).epsilon(1e-14));
  // W(0) departs from the printed constant 9/(pi kappa^2 h^2) = 1/(pi h^2) by under 1 %.
  CHECK(sphmol::TruncatedExponentialKernel<2>::W(0.0, h) == Approx(1.0 / (std::numbers::pi * h * h)).epsilon(1e-2));
}

TEMPLATE_TEST_CASE("kernels are C1 at their support edge (no jump of W or dW/dr)", "[kernel][support]",
                   sphmol::GaussianKernel<1>, sphmol::GaussianKernel<2>, sphmol::GaussianKernel<3>,
                   sphmol::TruncatedExponentialKernel<1>, sphmol::TruncatedExponentialKernel<2>,
                   sphmol::TruncatedExponentialKernel<3>, sphmol::CubicSpline<2>, sphmol::WendlandC2Kernel<2>,
                   sphmol::QuinticMorrisKernel<2>, sphmol::LucyKernel<2>, sphmol::QuarticLiuKernel<2>,
                   sphmol::QuadraticJohnsonKernel<2>, sphmol::DesbrunSpikyKernel<2>, sphmol::MullerPoly6Kernel<2>) {
  // A jump at the support makes f(t, y) discontinuous in the positions: every pair crossing the
  // support edge, and every lattice pair sitting on it (decided by round-off), then leaves a time
  // error that does not shrink with the step. Relative to the values at q = 0 (W) and at q = 1 (dW).
  using K = TestType;
  const double h = 0.37, edge = K::support * h, below = std::nextafter(edge, 0.0), beyond = edge * (1.0 + 1e-15);
  const double w0 = K::W(0.0, h), dw1 = std::abs(K::dWdr(h, h)) + std::abs(K::dWdr(0.5 * h, h));
  INFO(K::name << " in " << K::dimension << "D");
  CHECK(std::abs(K::W(below, h)) < 1e-14 * w0);
  CHECK(std::abs(K::dWdr(below, h)) < 1e-12 * dw1);
  CHECK(K::W(beyond, h) == 0.0);
  CHECK(K::dWdr(beyond, h) == 0.0);
}

TEMPLATE_TEST_CASE("the Gaussian kernels are flat to every order at q = 3 (C-infinity taper)", "[kernel][support]",
                   sphmol::GaussianKernel<1>, sphmol::GaussianKernel<2>, sphmol::GaussianKernel<3>,
                   sphmol::TruncatedExponentialKernel<1>, sphmol::TruncatedExponentialKernel<2>,
                   sphmol::TruncatedExponentialKernel<3>) {
  // A kernel that is C^m at its edge caps every fixed-step integrator at order m + 1 (each pair
  // crossing the edge leaves O(dt^(m+2)); docs/verification.md). C^m means W(3 - e) ~ e^(m+1), i.e.
  // W(3 - e) / W(3 - 2e) -> 2^-(m+1); the taper's ratio falls below any such power (the shifted-force
  // cut-off, C1: 1/4).
  using K = TestType;
  const double h = 0.37;
  INFO(K::name << " in " << K::dimension << "D");
  for (double e : {0.025, 0.0125}) {
    CHECK(K::W((3.0 - e) * h, h) / K::W((3.0 - 2 * e) * h, h) < std::pow(2.0, -12));
    CHECK(K::dWdr((3.0 - e) * h, h) / K::dWdr((3.0 - 2 * e) * h, h) < std::pow(2.0, -11));
    CHECK(K::W((3.0 - e) * h, h) > 0.0);
  }
  // Inside the taper's start the kernel is the source's Gaussian, up to the normalisation.
  const double ratio = K::W(0.0, h);
  for (double q : {0.5, 1.3, 2.0, 2.5})
    CHECK(K::W(q * h, h) == Approx(ratio * std::exp(-q * q)).epsilon(1e-14));
}
