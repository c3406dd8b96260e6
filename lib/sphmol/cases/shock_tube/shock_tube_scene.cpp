#include "sphmol/cases/shock_tube/shock_tube_scene.hpp"
#include "sphmol/cases/shock_tube/shock_tube_settings.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "sphmol/geometry/box_shape.hpp"
#include "sphmol/geometry/lattice.hpp"
#include "sphmol/geometry/wall_layers.hpp"
#include "sphmol/kernels/registry.hpp"

namespace sphmol {

template <int D>
ShockTubeScene<D> build_shock_tube_scene(const Config& config) {
  static_assert(D == 1 || D == 2, "the shock tube is a 1D or 2D scene");
  const auto& g = config.settings<ShockTubeSettings>();
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
  const auto& Ls = config.settings<ShockTubeSettings>().left;
  const auto& Rs = config.settings<ShockTubeSettings>().right;
  const double vol = std::pow(dx, D);

  ShockTubeScene<D> s;
  s.spacing = dx;
  s.columns = nx;
  s.rows = ny;
  s.wall_layers = layers;
  s.domain.lo[0] = -0.5 * L - layers * dx;
  s.domain.hi[0] = 0.5 * L + layers * dx;
  s.domain.periodic[0] = false;
  const std::string& boundary = disc.boundary;
  if constexpr (D == 2) {
    if (boundary == "wall_particles") {  // y periodic (see shock_tube_scene.hpp)
      s.domain.lo[1] = 0.0;
      s.domain.hi[1] = Wd;
      s.domain.periodic[1] = true;
    } else {  // walls at y = 0 and y = W; the box also holds the ghosts / virtual particles behind them
      s.domain.lo[1] = -layers * dx;
      s.domain.hi[1] = Wd + layers * dx;
      s.domain.periodic[1] = false;
    }
    // Free-slip (or, if configured, no-slip) ghost walls at y = 0 and y = W (Niedoba 2012, §3.2: "fixed
    // free-slip wall, v_n = 0"); the x ends stay closed by wall particles, so x has no ghost walls.
    for (int side = 0; side < 2; ++side) {
      auto& w = s.walls[1][side];
      w.present = boundary == "ghost";
      w.position = side == 0 ? 0.0 : Wd;
      w.no_slip = disc.wall_slip != "free_slip";
    }
  } else if (boundary != "wall_particles") {
    throw std::invalid_argument("discretization.boundary: the 1D shock tube has no side walls");
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
  // The tube [-L/2, L/2] (x [0, W] in y) on the lattice of cell centres (i + 1/2) dx from its lo corner.
  geometry::Vec<D> lo{}, hi{};
  lo[0] = -0.5 * L;
  hi[0] = 0.5 * L;
  if constexpr (D == 2) hi[1] = ny * dx;
  geometry::Lattice<D> lattice;
  lattice.spacing = dx;
  lattice.origin = lo;
  for (const auto& x : geometry::fill<D>(geometry::BoxShape<D>(lo, hi), lattice))
    place(Kind::Fluid, x[0], D == 2 ? x[D - 1] : 0.0, x[0] < 0.0 ? Ls : Rs, 0.0, 0.0);
  // With ghost y walls the end walls continue through the corners (behind y = 0 and y = W): the
  // ghosts image fluid particles only, and a corner particle without wall neighbours on that diagonal
  // is pushed out through the corner (seen as a blow-up at t = 0.02 without these layers).
  // The end walls are the walls of the tube with its y faces open, extended by those layers in y.
  std::array<bool, 2 * D> open{};
  if constexpr (D == 2) {
    const double ext = boundary == "ghost" ? layers * dx : 0.0;
    lo[1] -= ext;
    hi[1] += ext;
    open[2] = open[3] = true;
  }
  // Each end's layers continue the lattice from that end, so a wall particle sits exactly (k + 1/2) dx
  // beyond it. They are listed row by row, nearest layer first, the two ends alternately: the
  // adaptive 1D run's errors move in their third digit with the summation order (measured).
  std::vector<geometry::WallPoint<D>> ends;
  for (int side = 0; side < 2; ++side) {
    std::array<bool, 2 * D> open_side = open;
    open_side[1 - side] = true;
    geometry::Lattice<D> from_end = lattice;
    from_end.origin[0] = side == 0 ? lo[0] : hi[0];
    const auto w = geometry::box_container_walls<D>(lo, hi, open_side, from_end, layers * dx);
    ends.insert(ends.end(), w.begin(), w.end());
  }
  const auto order = [dx](const geometry::WallPoint<D>& w) {
    return std::make_tuple(D == 2 ? std::lround(w.x[D - 1] / dx - 0.5) : 0L, std::lround(w.depth / dx - 0.5), w.face);
  };
  std::stable_sort(ends.begin(), ends.end(), [&](const auto& a, const auto& b) { return order(a) < order(b); });
  for (const auto& w : ends)
    place(Kind::Wall, w.x[0], D == 2 ? w.x[D - 1] : 0.0, w.face == 0 ? Ls : Rs, w.normal[0], w.depth);
  if (D == 2 && boundary == "virtual_repulsive") {
    // Niedoba 2012, §3.3, Fig 3.3: virtual particles on the lines y = -dx and y = W + dx, i.e. the wall
    // rectangle enlarged by dx/2 beyond the domain boundary (which lies dx/2 outside the outermost
    // rows), so that with r0 = dx no particle is repelled in the initial state. Spacing dx/2 along
    // the wall. As in the textbook code the thesis builds on (Liu & Liu 2003, whose virtual particles
    // have m = rho dx^2 and enter every SPH sum), they carry mass, density and energy of their side
    // and so also push the gas by their pressure; massless ones (the box scenes' choice) leave the
    // wall rows with half a kernel, and with D = 1e-3 the rows cross at t = 0.011 (density < 0).
    // They span the tube and its end walls and stay fixed.
    const double x_lo = -0.5 * L - layers * dx, x_hi = 0.5 * L + layers * dx;
    const int steps = static_cast<int>(std::lround((x_hi - x_lo) / (0.5 * dx)));
    for (const double yw : {-dx, Wd + dx})
      for (int k = 0; k <= steps; ++k) {
        const double x = x_lo + k * 0.5 * dx;
        std::array<double, D> pos{}, vel{}, normal{};
        pos[0] = x;
        pos[D - 1] = yw;
        normal[D - 1] = yw < 0.0 ? 1.0 : -1.0;
        const ShockTubeState& q = x < 0.0 ? Ls : Rs;
        s.particles.add(Kind::Wall, pos, vel, q.density * vol, q.density, normal, 0.0);
        s.energy.push_back(q.pressure / (gm1 * q.density));
      }
  }
  return s;
}

template ShockTubeScene<1> build_shock_tube_scene<1>(const Config&);
template ShockTubeScene<2> build_shock_tube_scene<2>(const Config&);

}  // namespace sphmol
