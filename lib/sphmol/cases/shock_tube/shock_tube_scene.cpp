#include "sphmol/cases/shock_tube/shock_tube_scene.hpp"
#include "sphmol/cases/shock_tube/shock_tube_settings.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

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
  const auto& Ls = g.left;
  const auto& Rs = g.right;
  const double vol = std::pow(dx, D);
  const bool equal_mass = g.setup == "equal_mass";
  const double rho_dense = std::max(Ls.density, Rs.density);
  const double m_equal = rho_dense * vol;

  ShockTubeScene<D> s;
  s.spacing = dx;
  s.columns = nx;
  s.rows = ny;
  s.wall_layers = layers;
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
  // The initial state at x: a step, or the smoothed step of shock_tube.smoothing.
  const double width = g.smoothing * dx;
  auto state_at = [&](double x) {
    const double f = width > 0.0 ? 1.0 / (1.0 + std::exp(-x / width)) : (x < 0.0 ? 0.0 : 1.0);
    return ShockTubeState{Ls.density + (Rs.density - Ls.density) * f, Ls.pressure + (Rs.pressure - Ls.pressure) * f,
                          Ls.velocity + (Rs.velocity - Ls.velocity) * f};
  };
  // One point of the scene before it is sorted into the particle list.
  struct Point {
    Kind kind;
    double x, y, mass, depth;  // depth: beyond the end of the fluid (walls)
    ShockTubeState q;
    long row, layer;  // row index across the tube (2D), wall layer beyond the end (walls)
    int face;         // 0: left end, 1: right end
  };
  std::vector<Point> points;
  const double y_ext = D == 2 && boundary == "ghost" ? 1.0 : 0.0;  // end walls continue behind the ghost walls
  for (int side = 0; side < 2; ++side) {
    const ShockTubeState& q_side = side == 0 ? Ls : Rs;
    const double sign = side == 0 ? -1.0 : 1.0;
    // Rows across the tube and their spacing: the denser side's lattice, or (equal mass) the whole
    // number of rows nearest to the lighter side's spacing.
    int rows = ny;
    double dy = dx;
    if (D == 2 && equal_mass) {
      const double a = dx * std::pow(rho_dense / q_side.density, 1.0 / D);
      rows = std::max(1, static_cast<int>(std::lround(Wd / a)));
      dy = Wd / rows;
    }
    s.side_rows[static_cast<std::size_t>(side)] = rows;
    // The column width that gives each particle its mass at density rho.
    auto column_width = [&](double rho) {
      if (!equal_mass) return dx;
      return D == 2 ? m_equal / (rho * dy) : m_equal / rho;
    };
    auto mass_of = [&](double rho) { return equal_mass ? m_equal : rho * vol; };
    auto add_column = [&](Kind kind, double xc, const ShockTubeState& q, long layer, double depth) {
      const long lo_row = kind == Kind::Wall ? -static_cast<long>(y_ext * layers) : 0;
      const long hi_row = kind == Kind::Wall ? rows + static_cast<long>(y_ext * layers) : rows;
      for (long j = lo_row; j < hi_row; ++j)
        points.push_back({kind, xc, D == 2 ? (static_cast<double>(j) + 0.5) * dy : 0.0, mass_of(q.density), depth, q, j, layer, side});
    };
    // Fluid columns from the diaphragm outwards while their centres lie inside the tube.
    double edge = 0.0;
    const double half = 0.5 * L;
    for (long k = 0;; ++k) {
      double xc;
      if (width > 0.0) {  // the width at the column's own centre, by two fixed-point steps
        double w = column_width(state_at(edge).density);
        for (int it = 0; it < 2; ++it) w = column_width(state_at(edge + sign * 0.5 * w).density);
        xc = edge + sign * 0.5 * w;
        if (std::abs(xc) > half) break;
        edge += sign * w;
      } else {  // a uniform lattice from x = 0: centres (k + 1/2) w exactly
        const double w = column_width(q_side.density);
        xc = sign * (static_cast<double>(k) + 0.5) * w;
        if (std::abs(xc) > half) break;
        edge = sign * (static_cast<double>(k) + 1.0) * w;
      }
      add_column(Kind::Fluid, xc, width > 0.0 ? state_at(xc) : q_side, 0, 0.0);
    }
    // The end walls: `layers` more columns at the end state, continuing the last column's lattice.
    const ShockTubeState q_end = width > 0.0 ? state_at(edge) : q_side;
    const double w_end = column_width(q_end.density);
    for (long k = 0; k < layers; ++k)
      add_column(Kind::Wall, edge + sign * (static_cast<double>(k) + 0.5) * w_end, q_end, k, (static_cast<double>(k) + 0.5) * w_end);
    const double x_far = edge + sign * layers * w_end;
    if (side == 0) s.domain.lo[0] = x_far;
    else s.domain.hi[0] = x_far;
  }
  // Fluid first, row by row in x (the lattice fill's order); then the end walls row by row, nearest
  // layer first, the two ends alternately: the adaptive 1D run's errors move in their third digit
  // with the summation order (measured).
  std::stable_sort(points.begin(), points.end(), [](const Point& a, const Point& b) {
    if (a.kind != b.kind) return a.kind == Kind::Fluid;
    if (a.kind == Kind::Fluid) return std::tie(a.y, a.x) < std::tie(b.y, b.x);
    return std::make_tuple(a.row, a.layer, a.face) < std::make_tuple(b.row, b.layer, b.face);
  });
  for (const auto& pt : points) {
    std::array<double, D> pos{}, vel{}, normal{};
    pos[0] = pt.x;
    if constexpr (D == 2) pos[1] = pt.y;
    vel[0] = pt.kind == Kind::Fluid ? pt.q.velocity : 0.0;
    if (pt.kind == Kind::Wall) normal[0] = pt.face == 0 ? 1.0 : -1.0;  // out of the end wall, into the tube
    s.particles.add(pt.kind, pos, vel, pt.mass, pt.q.density, normal, pt.depth);
    s.energy.push_back(pt.q.pressure / (gm1 * pt.q.density));
    s.h0.push_back(disc.smoothing_ratio * std::pow(pt.mass / pt.q.density, 1.0 / D));
  }
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
        s.h0.push_back(disc.smoothing_ratio * dx);
      }
  }
  return s;
}

template ShockTubeScene<1> build_shock_tube_scene<1>(const Config&);
template ShockTubeScene<2> build_shock_tube_scene<2>(const Config&);

}  // namespace sphmol
