// Kernel derivatives, compact support and sign, for every kernel in every dimension offered.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>

#include "sphmol/kernels/registry.hpp"

namespace {
using AllKernels = decltype(std::tuple_cat(sphmol::KernelTypes<1>{}, sphmol::KernelTypes<2>{},
                                           sphmol::KernelTypes<3>{}));
// Every registered kernel type models the SphKernel concept.
static_assert([]<class... K>(std::tuple<K...>*) { return (sphmol::SphKernel<K> && ...); }(
    static_cast<AllKernels*>(nullptr)));
}

TEMPLATE_LIST_TEST_CASE("dW/dr matches a finite difference of W", "[kernel]", AllKernels) {
  using K = TestType;
  if constexpr (K::available && sphmol::kernel_derivative_is_exact<K>()) {
    INFO(K::name << " in " << K::dimension << "D");
    for (double h : {0.05, 1.0, 3.0}) {
      const double scale = std::abs(K::W(0.0, h)) / h;  // size of dW/dr
      for (int i = 1; i < 300; ++i) {
        const double q = K::support * i / 300.0;
        if (std::abs(q - std::round(q)) < 1e-3) continue;  // skip the knots
        const double r = q * h, dr = 1e-6 * h;
        const double fd = (K::W(r + dr, h) - K::W(r - dr, h)) / (2.0 * dr);
        INFO("q = " << q << " h = " << h);
        CHECK(std::abs(K::dWdr(r, h) - fd) <= 1e-7 * scale);
        double w, dw;
        K::eval(r, h, w, dw);
        CHECK(w == K::W(r, h));
        CHECK(dw == K::dWdr(r, h));
      }
    }
  }
}

TEMPLATE_LIST_TEST_CASE("compact support: W = dW/dr = 0 at and beyond support*h", "[kernel]", AllKernels) {
  using K = TestType;
  if constexpr (K::available) {
    INFO(K::name << " in " << K::dimension << "D");
    for (double h : {0.1, 1.0, 2.5})
      for (double f : {1.0, 1.0 + 1e-12, 1.01, 1.5, 10.0}) {
        const double r = f * K::support * h;
        CHECK(K::W(r, h) == 0.0);
        CHECK(K::dWdr(r, h) == 0.0);
        CHECK(sphmol::kernel_dWdr_k<K>(r, h, 1.1) == 0.0);
      }
    // ... and not identically zero just inside.
    CHECK(K::W(0.5 * K::support, 1.0) != 0.0);
  }
}

TEMPLATE_LIST_TEST_CASE("the kernel pass's W(q) and (dW/dr)/r are exactly 0 at and beyond the support",
                        "[kernel]", AllKernels) {
  // A fused pass whose terms take the skin pairs of the Verlet list (PairTerm::zero_beyond_support)
  // relies on this to leave every sum unchanged bit for bit (rhs/kernel_pass.hpp).
  using K = TestType;
  if constexpr (K::available) {
    INFO(K::name << " in " << K::dimension << "D");
    for (double f : {1.0, 1.0 + 1e-12, 1.01, 1.15, 1.5, 2.0}) {
      double w = -1.0, F = -1.0;
      sphmol::kernel_unit_over_r<K>(f * K::support, w, F);
      INFO("q = " << f * K::support);
      CHECK(w == 0.0);
      CHECK(F == 0.0);
    }
    double w = 0.0, F = 0.0;
    sphmol::kernel_unit_over_r<K>(0.5 * K::support, w, F);
    CHECK(w != 0.0);
  }
}

TEMPLATE_LIST_TEST_CASE("W >= 0 wherever the source says so", "[kernel]", AllKernels) {
  using K = TestType;
  if constexpr (K::available) {
    INFO(K::name << " in " << K::dimension << "D");
    double wmin = 0.0;
    for (int i = 0; i <= 3000; ++i) wmin = std::min(wmin, K::W(K::support * i / 3000.0, 1.0));
    if (K::name == "super_gaussian")
      CHECK(wmin < 0.0);  // (3/2 - q^2) e^-q^2 has a negative lobe beyond q = sqrt(3/2) (Potapov & Reshetnikova 2021, eq 6)
    else if (K::name == "quartic_liu")
      CHECK(wmin < 0.0);  // -5/32 (q-2)^2 (q^2 - 16/15 q - 16/15) < 0 for 1.6957 < q < 2 (Potapov & Reshetnikova 2021, eq 9)
    else
      CHECK(wmin >= 0.0);
  }
}

TEST_CASE("composite kernel derivative is Potapov & Reshetnikova 2021, eq 13b, not dW/dr of eq 13a", "[kernel]") {
  using K = sphmol::CompositeKernel<2>;
  const double pi = std::numbers::pi;
  // Eq 13b written out: dW/dr = -1369 k^2 / (28 pi (kd)^3 (74k - 63)) (84k/37 - 2 r/(kd)).
  for (double k : {0.8, 1.0, 1.2})
    for (double d : {0.01, 1.0})
      for (double q : {0.0, 0.3, 0.77, 0.999}) {
        const double h = k * d, r = q * h;
        const double expected = -1369.0 * k * k / (28.0 * pi * h * h * h * (74.0 * k - 63.0)) * (84.0 * k / 37.0 - 2.0 * q);
        CHECK(K::dWdr_k(r, h, k) == Approx(expected).epsilon(1e-13));
      }
  CHECK(K::dWdr(0.4, 1.0) == K::dWdr_k(0.4, 1.0, 1.0));
  // The separate derivative differs from d/dr of 13a (which vanishes at r = 0).
  const double dr = 1e-6;
  const double fd = (K::W(0.5 + dr, 1.0) - K::W(0.5 - dr, 1.0)) / (2 * dr);
  CHECK(std::abs(K::dWdr(0.5, 1.0) - fd) > 0.05);
  CHECK(K::dWdr(0.0, 1.0) < -1.0);
  // Eq 13a value: 15/(13 h^2) at r = 0 (no pi: the integral gives exactly 13/15).
  CHECK(K::W(0.0, 2.0) == Approx(15.0 / 52.0).epsilon(1e-15));
}

TEST_CASE("composite kernel is 2D only and says why", "[kernel][registry]") {
  CHECK(sphmol::kernel_info<2>("composite").name == "composite");
  for (int dim : {1, 3}) {
    std::string msg;
    try {
      if (dim == 1) sphmol::kernel_info<1>("composite");
      else sphmol::kernel_info<3>("composite");
    } catch (const std::invalid_argument& e) {
      msg = e.what();
    }
    INFO(msg);
    CHECK(msg.find("only for 2D") != std::string::npos);
  }
  CHECK_THROWS_WITH(sphmol::kernel_info<2>("no_such_kernel"), Catch::Contains("unknown kernel"));
}

TEST_CASE("registry lists every kernel by name", "[registry]") {
  const auto names = sphmol::kernel_names<2>();
  for (const char* n : {"cubic_spline", "lucy", "gaussian", "truncated_exponential", "quartic_liu", "quintic_morris",
                        "quadratic_johnson", "super_gaussian", "desbrun_spiky", "muller_poly6", "composite",
                        "wendland_c2"})
    CHECK(std::find(names.begin(), names.end(), std::string_view(n)) != names.end());
  CHECK(names.size() == 12);
  for (const auto& e : sphmol::kernel_catalogue<2>()) {
    INFO(e.name);
    CHECK(e.available);
    CHECK(!e.info.source.empty());
  }
  const auto c3 = sphmol::kernel_catalogue<3>();
  CHECK(std::count_if(c3.begin(), c3.end(), [](const auto& e) { return !e.available; }) == 1);
}
