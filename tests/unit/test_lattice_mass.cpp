// The lattice masses (scenes/lattice_mass.hpp): with the gradient mass the symmetric SPH pressure
// gradient (Monaghan 1992; Vukčević 2012, eq 117) of a linear field on the ideal square, cubic and
// hexagonal lattices is exact; with the summation mass the lattice's summed density is rho0 and the
// same gradient reads the field's slope a little off (0.998 for Wendland C2 at h = 2 dx in 2D).
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "sphmol/kernels/registry.hpp"
#include "sphmol/scenes/lattice_mass.hpp"

using namespace sphmol;

namespace {

constexpr double kRho0 = 1000.0;

// Points of the square/cubic lattice of spacing dx within radius of the origin (origin included).
template <int D>
std::vector<std::array<double, 3>> cubic_points(double dx, double radius) {
  const int n = static_cast<int>(std::ceil(radius / dx)) + 1;
  std::vector<std::array<double, 3>> out;
  for (int i = -n; i <= n; ++i)
    for (int j = D > 1 ? -n : 0; j <= (D > 1 ? n : 0); ++j)
      for (int k = D > 2 ? -n : 0; k <= (D > 2 ? n : 0); ++k) {
        const std::array<double, 3> x{i * dx, j * dx, k * dx};
        if (std::hypot(x[0], x[1], x[2]) < radius) out.push_back(x);
      }
  return out;
}

// The triangular lattice of edge dx written with the basis (dx, 0), (dx/2, dx sqrt(3)/2).
std::vector<std::array<double, 3>> hexagonal_points(double dx, double radius) {
  const int n = static_cast<int>(std::ceil(2.0 * radius / dx)) + 2;
  std::vector<std::array<double, 3>> out;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j) {
      const std::array<double, 3> x{(i + 0.5 * j) * dx, j * dx * std::sqrt(3.0) / 2.0, 0.0};
      if (std::hypot(x[0], x[1]) < radius) out.push_back(x);
    }
  return out;
}

// The symmetric pressure gradient at the origin, grad p_0 = rho_0 sum_j m (p_0 / rho_0^2 + p_j / rho_j^2)
// W'(r_j) (x_0 - x_j) / r_j, of p = p0 + a . x at uniform density rho0, over its slope |a| along a:
// 1 where the gradient is exact. Also checks that the gradient has no component across a.
template <int D>
double slope_read(const KernelInfo<D>& K, const std::vector<std::array<double, 3>>& pts, double m, double h, double dx) {
  const std::array<double, 3> a{1.7, D > 1 ? -0.6 : 0.0, D > 2 ? 0.9 : 0.0};
  // p_0 = p(x_0) != 0, half a spacing's rise: the p_i term cancels by the lattice's symmetry, to a
  // round-off of p0 / (|a| dx) times that of the p_j sum (a large p0 would hide the 1e-12).
  const double p0 = 0.5 * a[0] * dx;
  std::array<double, 3> g{};
  for (const auto& x : pts) {
    const double r = std::hypot(x[0], x[1], x[2]);
    if (r == 0.0) continue;
    const double pj = p0 + a[0] * x[0] + a[1] * x[1] + a[2] * x[2];
    const double f = kRho0 * m * (p0 + pj) / (kRho0 * kRho0) * K.dWdr(r, h) / r;
    for (int d = 0; d < 3; ++d) g[d] += f * (0.0 - x[d]);
  }
  const double a2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
  const double along = (g[0] * a[0] + g[1] * a[1] + g[2] * a[2]) / a2;
  double across2 = 0.0;
  for (int d = 0; d < 3; ++d) across2 += (g[d] - along * a[d]) * (g[d] - along * a[d]);
  CHECK(std::sqrt(across2 / a2) < 1e-12);
  return along;
}

template <int D>
void check_cubic(const std::string& kernel, double ratio) {
  INFO(D << "D " << kernel << " h = " << ratio << " dx");
  const auto K = kernel_info<D>(kernel);
  const double dx = 0.025, h = ratio * dx;
  const auto pts = cubic_points<D>(dx, K.support * h);
  const double m_grad = lattice_gradient_mass<D>(kernel, kRho0, dx, h);
  CHECK(std::abs(slope_read<D>(K, pts, m_grad, h, dx) - 1.0) < 1e-12);
  // The summation mass: summed density rho0 exactly, the gradient not exact.
  const double m_sum = lattice_particle_mass<D>(kernel, kRho0, dx, h);
  double rho = 0.0;
  for (const auto& x : pts) rho += m_sum * K.W(std::hypot(x[0], x[1], x[2]), h);
  CHECK(rho / kRho0 == Approx(1.0).epsilon(1e-13));
  // (B-splines at a whole h / dx reproduce the slope with either mass: the cubic spline and the
  // quintic at h = 2 dx in 1D. Wendland C2 never does: 1e-4 to 5e-2 off here.)
  if (kernel == "wendland_c2") CHECK(std::abs(slope_read<D>(K, pts, m_sum, h, dx) - 1.0) > 5e-5);
  // lattice_mass picks by the key's value.
  CHECK(lattice_mass<D>("gradient", kernel, kRho0, dx, h) == m_grad);
  CHECK(lattice_mass<D>("summation", kernel, kRho0, dx, h) == m_sum);
}

}  // namespace

TEST_CASE("lattice mass: the gradient mass makes the symmetric gradient of a linear field exact on the lattice", "[lattice_mass]") {
  for (const double ratio : {1.3, 2.0, 2.5})
    for (const std::string kernel : {"cubic_spline", "wendland_c2", "quintic_morris"}) {
      check_cubic<1>(kernel, ratio);
      check_cubic<2>(kernel, ratio);
      check_cubic<3>(kernel, ratio);
    }
}

TEST_CASE("lattice mass: the summation mass reads a linear field 0.2 % low in 2D, 0.11 % low in 3D (Wendland C2, h = 2 dx)", "[lattice_mass]") {
  const double dx = 0.025, h = 2.0 * dx;
  const auto K2 = kernel_info<2>("wendland_c2");
  const auto K3 = kernel_info<3>("wendland_c2");
  const double m2 = lattice_particle_mass<2>("wendland_c2", kRho0, dx, h);
  const double m3 = lattice_particle_mass<3>("wendland_c2", kRho0, dx, h);
  // The numbers that made a water column at rest settle with a gradient 0.20 % (2D) and 0.114 % (3D)
  // steeper than g rho (docs/verification.md, "The lattice mass"): 0.99800 on the square lattice,
  // 0.99886 on the cubic one.
  CHECK(slope_read<2>(K2, cubic_points<2>(dx, K2.support * h), m2, h, dx) == Approx(0.99800).margin(1e-5));
  CHECK(slope_read<3>(K3, cubic_points<3>(dx, K3.support * h), m3, h, dx) == Approx(0.99886).margin(1e-5));
  // Their ratio to the gradient mass is that reading.
  CHECK(m2 / lattice_gradient_mass<2>("wendland_c2", kRho0, dx, h) == Approx(0.99800).margin(1e-5));
  CHECK(m3 / lattice_gradient_mass<3>("wendland_c2", kRho0, dx, h) == Approx(0.99886).margin(1e-5));
  // Both masses are close to rho0 dx^D (the lattice sums are the kernel's integrals to O(1e-3)).
  CHECK(m2 == Approx(kRho0 * dx * dx).epsilon(2e-3));
  CHECK(lattice_gradient_mass<2>("wendland_c2", kRho0, dx, h) == Approx(kRho0 * dx * dx).epsilon(2e-3));
}

TEST_CASE("lattice mass: the hexagonal gradient and summation masses", "[lattice_mass]") {
  const double dx = 0.02, row = dx * std::sqrt(3.0) / 2.0;
  for (const double ratio : {1.3, 2.0})
    for (const std::string kernel : {"cubic_spline", "wendland_c2"}) {
      INFO(kernel << " h = " << ratio << " dx");
      const auto K = kernel_info<2>(kernel);
      const double h = ratio * dx;
      const auto pts = hexagonal_points(dx, K.support * h);
      const double m_grad = hexagonal_gradient_mass(kernel, kRho0, dx, h);
      CHECK(std::abs(slope_read<2>(K, pts, m_grad, h, dx) - 1.0) < 1e-12);
      const double m_sum = hexagonal_particle_mass(kernel, kRho0, dx, h);
      double rho = 0.0;
      for (const auto& x : pts) rho += m_sum * K.W(std::hypot(x[0], x[1]), h);
      CHECK(rho / kRho0 == Approx(1.0).epsilon(1e-13));
      CHECK(m_grad == Approx(kRho0 * dx * row).epsilon(0.01));
      CHECK(hexagonal_lattice_mass("gradient", kernel, kRho0, dx, h) == m_grad);
      CHECK(hexagonal_lattice_mass("summation", kernel, kRho0, dx, h) == m_sum);
    }
}
