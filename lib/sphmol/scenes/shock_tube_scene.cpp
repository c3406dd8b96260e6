#include "sphmol/scenes/shock_tube_scene.hpp"

#include <cmath>
#include <stdexcept>

#include "sphmol/kernels/registry.hpp"

namespace sphmol {

template <int D>
ShockTubeScene<D> build_shock_tube_scene(const Config& config) {
  static_assert(D == 1 || D == 2, "the shock tube is a 1D or 2D scene");
  const auto& g = config.geometry;
  const auto& disc = config.discretization;
  const double L = g.tube_length, Wd = g.tube_width;
  double dx = disc.spacing;
  if (disc.particles_across > 0) dx = Wd / disc.particles_across;  // particles across the width
  const int nx = static_cast<int>(std::lround(L / dx));
  if (nx <= 0 || std::abs(nx * dx - L) > 1e-6 * L)
    throw std::invalid_argument("geometry.tube_length: must be a whole number of particle spacings (" + std::to_string(dx) + ")");
  int ny = 1;
  if constexpr (D == 2) {
    ny = static_cast<int>(std::lround(Wd / dx));
    if (ny <= 0 || std::abs(ny * dx - Wd) > 1e-6 * Wd)
      throw std::invalid_argument("geometry.tube_width: must be a whole number of particle spacings (" + std::to_string(dx) + ")");
  }
  const double h = disc.smoothing_ratio * dx;
  // The end walls must fill the support; the gas next to them stays at rest (h stays h0) until t_end.
  const int layers = disc.wall_layers > 0 ? disc.wall_layers
                                          : static_cast<int>(std::ceil(kernel_info<D>(disc.kernel).support * h / dx)) + 1;
  const double gm1 = config.fluid.eos.gamma - 1.0;
  const auto& Ls = config.shock_tube.left;
  const auto& Rs = config.shock_tube.right;
  const double vol = std::pow(dx, D);

  ShockTubeScene<D> s;
  s.spacing = dx;
  s.columns = nx;
  s.rows = ny;
  s.wall_layers = layers;
  s.domain.lo[0] = -0.5 * L - layers * dx;
  s.domain.hi[0] = 0.5 * L + layers * dx;
  s.domain.periodic[0] = false;
  if constexpr (D == 2) {
    s.domain.lo[1] = 0.0;
    s.domain.hi[1] = Wd;
    s.domain.periodic[1] = true;
  }
  auto place = [&](Kind kind, double x, double y, const ShockTubeState& q, double sign, double depth) {
    std::array<double, D> pos{}, vel{}, normal{};
    pos[0] = x;
    if constexpr (D == 2) pos[1] = y;
    vel[0] = kind == Kind::Fluid ? q.velocity : 0.0;
    normal[0] = sign;
    s.particles.add(kind, pos, vel, q.density * vol, q.density, normal, depth);
    s.energy.push_back(q.pressure / (gm1 * q.density));
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = -0.5 * L + (i + 0.5) * dx;
      place(Kind::Fluid, x, (j + 0.5) * dx, x < 0.0 ? Ls : Rs, 0.0, 0.0);
    }
  for (int j = 0; j < ny; ++j)
    for (int k = 0; k < layers; ++k) {
      const double depth = (k + 0.5) * dx;
      place(Kind::Wall, -0.5 * L - depth, (j + 0.5) * dx, Ls, 1.0, depth);
      place(Kind::Wall, 0.5 * L + depth, (j + 0.5) * dx, Rs, -1.0, depth);
    }
  return s;
}

template ShockTubeScene<1> build_shock_tube_scene<1>(const Config&);
template ShockTubeScene<2> build_shock_tube_scene<2>(const Config&);

}  // namespace sphmol
