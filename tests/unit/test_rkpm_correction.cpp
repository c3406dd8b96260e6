// RKPM / moment-matrix correction (Vukčević 2012, eqs 92-99, Niedoba 2012, eqs 2.80-2.86): reproduces linear
// fields and their gradients exactly on a support truncated by a wall.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <vector>

#include "sphmol/analysis/particle_sets.hpp"
#include "sphmol/analysis/rkpm_correction.hpp"
#include "sphmol/kernels/registry.hpp"

using namespace sphmol::analysis;

template <int D>
void check_linear_reproduction(const ParticleSet<D>& set, const char* kernel, double h, std::array<double, D> xi) {
  const auto k = sphmol::kernel_info<D>(kernel);
  std::vector<std::array<double, D>> dx;
  std::vector<double> V, W, F, f;
  std::array<double, D> grad_f;
  for (int a = 0; a < D; ++a) grad_f[a] = 1.5 - 0.7 * a;
  auto field = [&](const std::array<double, D>& x) {
    double v = 2.0;
    for (int a = 0; a < D; ++a) v += grad_f[a] * x[a];
    return v;
  };
  for (std::size_t j = 0; j < set.x.size(); ++j) {
    std::array<double, D> d;
    double r2 = 0.0;
    for (int a = 0; a < D; ++a) {
      d[a] = xi[a] - set.x[j][a];
      r2 += d[a] * d[a];
    }
    const double r = std::sqrt(r2);
    if (r >= k.support * h) continue;
    dx.push_back(d);
    V.push_back(set.V[j]);
    W.push_back(k.W(r, h));
    F.push_back(r > 0 ? k.dWdr(r, h) / r : 0.0);  // grad_i W_ij = F_ij dx_ij
    f.push_back(field(set.x[j]));
  }
  std::vector<double> Wc(dx.size());
  std::vector<std::array<double, D>> Gc(dx.size());
  REQUIRE(rkpm_correct<D>(dx, V, W, F, Wc, Gc));
  double val = 0.0, val_raw = 0.0;
  std::array<double, D> g{}, g_raw{};
  for (std::size_t j = 0; j < dx.size(); ++j) {
    val += V[j] * f[j] * Wc[j];
    val_raw += V[j] * f[j] * W[j];
    for (int a = 0; a < D; ++a) {
      g[a] += V[j] * f[j] * Gc[j][a];
      g_raw[a] += V[j] * f[j] * F[j] * dx[j][a];
    }
  }
  const double fi = field(xi);
  CHECK(val == Approx(fi).epsilon(1e-12));
  CHECK(std::abs(val_raw - fi) > 0.02 * std::abs(fi));  // uncorrected SPH fails here
  double graw_err = 0.0;
  for (int a = 0; a < D; ++a) {
    CHECK(std::abs(g[a] - grad_f[a]) < 1e-10 * (1.0 + std::abs(grad_f[a])));
    graw_err = std::max(graw_err, std::abs(g_raw[a] - grad_f[a]));
  }
  CHECK(graw_err > 0.1);
}

TEST_CASE("RKPM correction reproduces linear fields next to a wall", "[rkpm]") {
  check_linear_reproduction<2>(wall_lattice<2>(6, 1.0), "cubic_spline", 1.3, {0.0, 0.0});
  check_linear_reproduction<2>(wall_lattice<2>(6, 0.01), "wendland_c2", 0.013, {0.0, 0.0});
  check_linear_reproduction<3>(wall_lattice<3>(5, 1.0), "quintic_morris", 1.2, {0.0, 0.0, 0.0});
  // Perturbed particles behind a wall, evaluated at a particle-free point.
  auto set = perturbed_lattice<2>(6, 1.0, 0.3, 7);
  ParticleSet<2> cut;
  for (std::size_t j = 0; j < set.x.size(); ++j)
    if (set.x[j][0] > 0.2) {
      cut.x.push_back(set.x[j]);
      cut.V.push_back(set.V[j]);
    }
  check_linear_reproduction<2>(cut, "quartic_liu", 1.4, {0.4, 0.1});
}

TEST_CASE("RKPM correction reports a singular moment matrix", "[rkpm]") {
  // Two neighbours on a line cannot fix a 2D linear field.
  std::vector<std::array<double, 2>> dx = {{0.0, 0.0}, {1.0, 0.0}};
  std::vector<double> V = {1.0, 1.0}, W = {1.0, 0.5}, F = {0.0, -0.3}, Wc(2);
  std::vector<std::array<double, 2>> Gc(2);
  CHECK_FALSE(sphmol::analysis::rkpm_correct<2>(dx, V, W, F, Wc, Gc));
}
