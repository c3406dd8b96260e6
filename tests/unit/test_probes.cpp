// Probes: Shepard interpolation reproduces constant and linear fields inside a lattice of fluid
// particles, gives NaN outside the fluid, wraps periodic directions, and the free-surface gauge
// finds the top of a resting column within a fraction of a spacing (2D and 3D).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "sphmol/kernels/registry.hpp"
#include "sphmol/probes/fluid_sampler.hpp"
#include "sphmol/probes/height_gauge.hpp"

using namespace sphmol;

namespace {

// A block of n[0] x ... particles at cell centres of spacing dx from the origin.
template <int D>
struct Block {
  std::array<std::vector<double>, D> x;
  std::vector<double> volume, f_const, f_linear;
  Block(const std::array<int, D>& n, double dx) {
    std::array<int, D> i{};
    while (true) {
      double lin = 0.0;
      for (int d = 0; d < D; ++d) {
        x[d].push_back((i[d] + 0.5) * dx);
        lin += (d + 1.0) * x[d].back();
      }
      volume.push_back(std::pow(dx, D));
      f_const.push_back(3.0);
      f_linear.push_back(1.0 + lin);
      int d = 0;
      for (; d < D; ++d) {
        if (++i[d] < n[d]) break;
        i[d] = 0;
      }
      if (d == D) break;
    }
  }
  std::array<const double*, D> pos() const {
    std::array<const double*, D> p;
    for (int d = 0; d < D; ++d) p[d] = x[d].data();
    return p;
  }
};

template <int D>
FluidSampler<D> sampler(const Block<D>& b, double h, const Domain<D>& dom) {
  const auto K = kernel_info<D>("wendland_c2");
  return FluidSampler<D>(b.pos(), b.volume.data(), b.volume.size(), K.W, h, K.support, dom);
}

}  // namespace

TEST_CASE("probes: Shepard interpolation is exact for constants and accurate for linear fields", "[probes]") {
  const double dx = 0.05, h = 1.3 * dx;
  const Block<2> b({20, 20}, dx);
  Domain<2> dom;
  dom.lo = {-1, -1};
  dom.hi = {2, 2};
  const auto s = sampler(b, h, dom);
  for (const geometry::Vec<2> p : {geometry::Vec<2>{0.5, 0.5}, geometry::Vec<2>{0.512, 0.377}, geometry::Vec<2>{0.02, 0.9}}) {
    CHECK(s.interpolate(p, b.f_const.data()) == Approx(3.0).epsilon(1e-12));
    const double exact = 1.0 + p[0] + 2.0 * p[1];
    // Inside the block the lattice is symmetric about p to within the kernel's reach: near exact.
    if (p[0] > 3 * h && p[1] > 3 * h) CHECK(s.interpolate(p, b.f_linear.data()) == Approx(exact).epsilon(1e-3));
  }
  CHECK(s.kernel_sum({0.5, 0.5}) == Approx(1.0).epsilon(0.02));
  CHECK(std::isnan(s.interpolate({1.5, 0.5}, b.f_const.data())));  // no fluid within the support
  CHECK(s.kernel_sum({1.5, 0.5}) == 0.0);
}

TEST_CASE("probes: the sampler wraps periodic directions", "[probes]") {
  const double dx = 0.05, h = 1.3 * dx;
  const Block<2> b({20, 10}, dx);
  Domain<2> dom;
  dom.lo = {0, -1};
  dom.hi = {1, 2};
  dom.periodic = {true, false};
  const auto s = sampler(b, h, dom);
  // Near x = 0 the kernel reaches particles at x ~ 1: the sum is as full as in the middle.
  CHECK(s.kernel_sum({0.001, 0.25}) == Approx(s.kernel_sum({0.5, 0.25})).epsilon(0.02));
  CHECK(s.kernel_sum({0.999, 0.25}) == Approx(s.kernel_sum({0.5, 0.25})).epsilon(0.02));
  // Brute force over all particles with the minimum image gives the same sum.
  const auto K = kernel_info<2>("wendland_c2");
  double brute = 0.0;
  for (std::size_t j = 0; j < b.volume.size(); ++j) {
    const double ddx = dom.min_image(0, 0.001 - b.x[0][j]), ddy = 0.25 - b.x[1][j];
    const double r = std::hypot(ddx, ddy);
    if (r < K.support * h) brute += b.volume[j] * K.W(r, h);
  }
  CHECK(s.kernel_sum({0.001, 0.25}) == Approx(brute).epsilon(1e-12));
}

TEST_CASE("probes: the free-surface gauge finds the top of a column", "[probes]") {
  const double dx = 0.02, h = 1.3 * dx;
  {
    const Block<2> b({25, 30}, dx);  // top at y = 0.6
    Domain<2> dom;
    dom.lo = {-1, -1};
    dom.hi = {2, 2};
    const auto s = sampler(b, h, dom);
    const double z = free_surface_height<2>(s, {0.25, 0.0}, 0.0, 1.0, dx / 4);
    CHECK(z == Approx(0.6).margin(0.5 * dx));
    CHECK(std::isnan(free_surface_height<2>(s, {0.8, 0.0}, 0.0, 1.0, dx / 4)));  // beside the column
  }
  {
    const Block<3> b({10, 10, 15}, dx);  // top at z = 0.3
    Domain<3> dom;
    dom.lo = {-1, -1, -1};
    dom.hi = {2, 2, 2};
    const auto s = sampler(b, h, dom);
    CHECK(free_surface_height<3>(s, {0.1, 0.1, 0.0}, 0.0, 0.6, dx / 4) == Approx(0.3).margin(0.5 * dx));
  }
}
