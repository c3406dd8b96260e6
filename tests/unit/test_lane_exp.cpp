// The exponential of core/lane_exp.hpp and the smooth step built on it, and the viscosity switch (on
// the polynomial step of core/polynomial_step.hpp): within two ulp of std::exp, and (AVX2) four lanes at once give the scalar's numbers bit for bit, which the
// vectorised pair loops (physics/weakly_compressible_row.hpp) rely on to equal the scalar ones.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "sphmol/core/lane_exp.hpp"
#include "sphmol/core/smooth_step.hpp"
#include "sphmol/physics/artificial_viscosity.hpp"

using namespace sphmol;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Arguments across the whole range, the ends of the reduction's intervals and the special values.
std::vector<double> exp_arguments() {
  std::vector<double> u;
  for (int k = -70800; k <= 70800; k += 7) u.push_back(k * 0.01 + 0.003 * (k % 5));
  for (int k = -12; k <= 12; ++k) u.push_back((k + 0.5) * 0.6931471805599453);
  for (double x : {0.0, -0.0, 1e-300, -1e-300, 1e-17, -1e-17, 707.9, -707.9}) u.push_back(x);
  return u;
}

}  // namespace

TEST_CASE("lane exponential: within two ulp of std::exp, exact at 0, inf at +inf, below 1e-307 at -inf", "[smooth_step]") {
  double worst = 0.0;
  for (double u : exp_arguments()) {
    const double e = lane_exp(u), ref = std::exp(u);
    worst = std::max(worst, std::abs(e - ref) / ref);
  }
  INFO("largest relative error " << worst);
  CHECK(worst < 2.3e-16);  // two ulp (2^-52 per ulp at the top of a binade)
  CHECK(lane_exp(0.0) == 1.0);
  CHECK(lane_exp(std::numeric_limits<double>::infinity()) == std::numeric_limits<double>::infinity());
  CHECK(lane_exp(709.0) == std::numeric_limits<double>::infinity());
  const double tiny = lane_exp(-std::numeric_limits<double>::infinity());
  CHECK(tiny >= 0.0);
  CHECK(tiny < 1e-307);
  CHECK(1.0 / (1.0 + tiny) == 1.0);  // so S(1) = 1 exactly
}

#if defined(__AVX2__)
TEST_CASE("lane exponential, smooth step and viscosity switch: four lanes equal the scalar bit for bit", "[smooth_step]") {
  const auto lanes = [](auto f, const std::vector<double>& in) {
    for (std::size_t k = 0; k + 4 <= in.size(); k += 4) {
      alignas(32) double out[4];
      _mm256_store_pd(out, f(_mm256_loadu_pd(in.data() + k)));
      for (int l = 0; l < 4; ++l) {
        INFO("argument " << in[k + l]);
        CHECK(same_bits(out[l], f(in[k + l])));
      }
    }
  };
  std::vector<double> u = exp_arguments();
  u.resize(u.size() & ~std::size_t{3});
  lanes([](auto x) { return lane_exp(x); }, u);

  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> t;
  for (int k = -20; k <= 1020; ++k) t.push_back(k / 1000.0);
  for (double x : {-0.0, 0.0, 1e-300, 1e-3, 1.0 - 1e-16, 1.0, 1.0 + 1e-16, inf, -inf, nan, 0.5, 0.25}) t.push_back(x);
  t.resize(t.size() & ~std::size_t{3});
  lanes([](auto x) { return smooth_step_lanes(x); }, t);

  // The switch (both offsets the files use), through its band and outside it, signed zeros included.
  for (double offset : {0.0, 0.3}) {
    const double delta = 0.3 * 3.0 * 0.13;
    std::vector<double> vx;
    for (int k = -1100; k <= 1100; ++k) vx.push_back(delta * k / 1000.0);
    for (double x : {-0.0, 0.0, offset * delta, -(1.0 - offset) * delta, 1e-300, -1e-300})
      vx.push_back(x);
    vx.resize(vx.size() & ~std::size_t{3});
    INFO("offset " << offset);
    lanes(
        [&](auto x) {
          if constexpr (std::is_same_v<decltype(x), double>) return switched_vx(x, delta, offset);
          else return switched_vx_lanes(x, _mm256_set1_pd(delta), _mm256_set1_pd(offset));
        },
        vx);
  }
}
#endif
