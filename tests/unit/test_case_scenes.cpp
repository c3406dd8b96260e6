// The case scenes built with the geometry kit (fill, box_container_walls) hold the same particles as
// the lattice loops they are built from: each reference below is such a loop, written out once here,
// and every particle (position, kind, velocity, mass, density, normal, depth, stationary; the shock
// tube's energy too) must match, for several sizes and wall layer counts and every wall treatment.
#include <algorithm>
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <map>
#include <string>
#include <vector>

#include "sphmol/cases/channel/channel_scene.hpp"
#include "sphmol/cases/dam_break/dam_break_scene.hpp"
#include "sphmol/cases/shock_tube/shock_tube_scene.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/cases/channel/channel_settings.hpp"
#include "sphmol/cases/dam_break/dam_break_settings.hpp"
#include "sphmol/cases/hydrostatic/hydrostatic_settings.hpp"
#include "sphmol/cases/shock_tube/shock_tube_settings.hpp"
#include "sphmol/physics/eos_tait.hpp"
#include "sphmol/scenes/box_scene.hpp"
#include "sphmol/scenes/lattice_mass.hpp"

using namespace sphmol;

namespace {

std::string verification(const std::string& name) {
  std::ifstream in(std::string(SPHMOL_SOURCE_DIR) + "/verification/" + name + ".yaml");
  REQUIRE(in);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Positions may differ by round-off (a lattice point is origin + (i + 1/2) dx where a loop may have
// written L + (k + 1/2) dx); everything else must be equal.
constexpr double tol = 1e-12;

// Particle by particle. same_order: the i-th of each; else matched by lattice position (keys in
// half spacings, so the dx/2 rows of the repulsive walls have keys too).
template <int D>
void require_same(const Particles<D>& want, const Particles<D>& got, double dx, bool same_order,
                  const std::vector<double>& want_e = {}, const std::vector<double>& got_e = {}) {
  REQUIRE(got.size() == want.size());
  REQUIRE(got.n_fluid == want.n_fluid);
  REQUIRE(got_e.size() == want_e.size());
  std::map<std::array<long, D>, std::size_t> at;
  const auto key = [&](const Particles<D>& p, std::size_t i) {
    std::array<long, D> k{};
    for (int d = 0; d < D; ++d) k[d] = std::lround(2.0 * p.x[d][i] / dx);
    return k;
  };
  if (!same_order)
    for (std::size_t i = 0; i < got.size(); ++i) REQUIRE(at.emplace(key(got, i), i).second);
  for (std::size_t i = 0; i < want.size(); ++i) {
    std::size_t j = i;
    if (!same_order) {
      const auto it = at.find(key(want, i));
      REQUIRE(it != at.end());
      j = it->second;
    }
    INFO("particle " << i << " (matched " << j << ")");
    CHECK(got.kind[j] == want.kind[i]);
    for (int d = 0; d < D; ++d) {
      CHECK(std::abs(got.x[d][j] - want.x[d][i]) <= tol * dx);
      CHECK(got.x_ref[d][j] == got.x[d][j]);
      CHECK(got.v[d][j] == want.v[d][i]);
      CHECK(got.wall_normal[d][j] == want.wall_normal[d][i]);
    }
    CHECK(std::abs(got.wall_depth[j] - want.wall_depth[i]) <= tol * dx);
    CHECK(got.stationary[j] == want.stationary[i]);
    CHECK(got.mass[j] == want.mass[i]);
    CHECK(got.rho[j] == Approx(want.rho[i]).epsilon(1e-14));
    if (!want_e.empty()) CHECK(got_e[j] == want_e[i]);
  }
}

// As the builders count them: enough to fill the kernel support (plus `extra`), or wall_layers.
int layers_of(const Config& c, int extra, double support, double dx) {
  const auto& d = c.discretization;
  return d.wall_layers > 0 ? d.wall_layers : static_cast<int>(std::ceil(support * (d.smoothing_ratio * dx) / dx)) + extra;
}

// The 2D box scene's lattice loops: fluid rows, then every wall lattice point outside the box, the
// corners to the top face if it is present, else to the face the point lies deepest behind.
Particles<2> box_reference(const Config& c, double Lx, double Ly, double H, const BoxWalls<2>& walls) {
  const auto& disc = c.discretization;
  const int nx = disc.particles_across;
  const double dx = Lx / nx;
  const int ny = static_cast<int>(std::lround(H / dx)), ny_box = static_cast<int>(std::lround(Ly / dx));
  const double h = disc.smoothing_ratio * dx;
  const int layers = layers_of(c, 0, kernel_info<2>(disc.kernel).support, dx);
  const double rho0 = c.fluid.density, m = lattice_particle_mass<2>(disc.kernel, rho0, dx, h);
  Particles<2> p;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) p.add(Kind::Fluid, {(i + 0.5) * dx, (j + 0.5) * dx}, {0.0, 0.0}, m, rho0);
  const std::array<double, 2> L{Lx, Ly};
  if (disc.boundary == "wall_particles") {
    const int jtop = walls[1][1].present ? ny_box + layers : ny_box;
    for (int j = -layers; j < jtop; ++j)
      for (int i = -layers; i < nx + layers; ++i) {
        const std::array<double, 2> x{(i + 0.5) * dx, (j + 0.5) * dx};
        double depth[2][2];
        bool outside = false, allowed = true;
        for (int d = 0; d < 2; ++d) {
          depth[d][0] = -x[d];
          depth[d][1] = x[d] - L[d];
          for (int side = 0; side < 2; ++side)
            if (depth[d][side] > 0) {
              outside = true;
              allowed = allowed && walls[d][side].present;
            }
        }
        if (!outside || !allowed) continue;
        int bd = -1, bs = 0;
        if (depth[1][1] > 0) {
          bd = 1;
          bs = 1;
        } else {
          double best = 0.0;
          for (int d = 0; d < 2; ++d)
            for (int side = 0; side < 2; ++side)
              if (depth[d][side] >= best && depth[d][side] > 0) {
                best = depth[d][side];
                bd = d;
                bs = side;
              }
        }
        const auto& w = walls[bd][bs];
        std::array<double, 2> normal{};
        normal[bd] = bs == 0 ? 1.0 : -1.0;
        p.add(Kind::Wall, x, w.velocity, m, rho0, normal, depth[bd][bs]);
        if (w.velocity[0] != 0.0 || w.velocity[1] != 0.0) p.stationary.back() = 1;
      }
  } else if (disc.boundary == "virtual_repulsive") {
    const double ds = 0.5 * dx;
    for (int d = 0; d < 2; ++d)
      for (int side = 0; side < 2; ++side) {
        if (!walls[d][side].present) continue;
        const int o = 1 - d;
        const int steps = static_cast<int>(std::lround(L[o] / ds));
        for (int k = (d == 1 ? 1 : 0); k <= (d == 1 ? steps - 1 : steps); ++k) {
          std::array<double, 2> x{};
          x[d] = side == 0 ? 0.0 : L[d];
          x[o] = k * ds;
          p.add(Kind::Wall, x, {0.0, 0.0}, 0.0, rho0);
        }
      }
  }
  return p;
}

// The channel's loops: fluid rows, then layer by layer a wall row below y = 0 and one above y = l.
Particles<2> channel_reference(const Config& c, double l, double L, double wall_velocity) {
  const auto& disc = c.discretization;
  const int ny = disc.particles_across;
  const double dx = l / ny;
  const int nx = static_cast<int>(std::lround(L / dx));
  const double h = disc.smoothing_ratio * dx;
  const int layers = layers_of(c, 0, kernel_info<2>(disc.kernel).support, dx);
  const double rho0 = c.fluid.density, m = lattice_particle_mass<2>(disc.kernel, rho0, dx, h);
  Particles<2> p;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) p.add(Kind::Fluid, {(i + 0.5) * dx, (j + 0.5) * dx}, {0.0, 0.0}, m, rho0);
  for (int k = 0; k < layers; ++k)
    for (int i = 0; i < nx; ++i) {
      const double depth = (k + 0.5) * dx;
      p.add(Kind::Wall, {(i + 0.5) * dx, -depth}, {0.0, 0.0}, m, rho0, {0.0, 1.0}, depth);
      p.add(Kind::Wall, {(i + 0.5) * dx, l + depth}, {wall_velocity, 0.0}, m, rho0, {0.0, -1.0}, depth);
    }
  return p;
}

// The dam break's loops: the column at its hydrostatic density, then the floor (corners included)
// and the two side walls up to the tank height.
Particles<2> dam_break_reference(const Config& c, double Lx, double Ly, double a, double H) {
  const auto& disc = c.discretization;
  const double dx = disc.spacing;
  const int nx = static_cast<int>(std::lround(a / dx)), ny = static_cast<int>(std::lround(H / dx));
  const int nx_tank = static_cast<int>(std::lround(Lx / dx)), ny_tank = static_cast<int>(std::lround(Ly / dx));
  const double g = -c.fluid.body_force[1], rho0 = c.fluid.density;
  const TaitLaw law(c.fluid.eos.sound_speed, rho0, c.fluid.eos.gamma);
  const int layers = layers_of(c, 0, kernel_info<2>(disc.kernel).support, dx);
  const double m = rho0 * dx * dx;
  const auto hydrostatic = [&](double y) { return law.density(rho0 * g * std::max(0.0, H - y)); };
  Particles<2> p;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double y = (j + 0.5) * dx;
      p.add(Kind::Fluid, {(i + 0.5) * dx, y}, {0.0, 0.0}, m, hydrostatic(y));
    }
  for (int j = -layers; j < ny_tank; ++j)
    for (int i = -layers; i < nx_tank + layers; ++i) {
      const bool bottom = j < 0, left = i < 0, right = i >= nx_tank;
      if (!bottom && !left && !right) continue;
      const std::array<double, 2> x{(i + 0.5) * dx, (j + 0.5) * dx};
      std::array<double, 2> normal{0.0, 1.0};
      double depth = -x[1];
      if (!bottom) {
        normal = {left ? 1.0 : -1.0, 0.0};
        depth = left ? -x[0] : x[0] - Lx;
      }
      p.add(Kind::Wall, x, {0.0, 0.0}, m, x[0] < a ? hydrostatic(x[1]) : rho0, normal, depth);
    }
  return p;
}

// The shock tube's loops: the gas rows, then for each row the end walls layer by layer (through the
// corners with ghost y walls), then with virtual_repulsive the rows of virtual particles.
template <int D>
Particles<D> shock_tube_reference(const Config& c, double L, double W, std::vector<double>& energy) {
  const auto& disc = c.discretization;
  const double dx = disc.spacing;
  const int nx = static_cast<int>(std::lround(L / dx)), ny = D == 2 ? static_cast<int>(std::lround(W / dx)) : 1;
  const int layers = layers_of(c, 1, kernel_info<D>(disc.kernel).support, dx);
  const double gm1 = c.fluid.eos.gamma - 1.0, vol = std::pow(dx, D);
  const auto& st = c.settings<ShockTubeSettings>();
  Particles<D> p;
  auto place = [&](Kind kind, double x, double y, const ShockTubeState& q, double sign, double depth) {
    std::array<double, D> pos{}, vel{}, normal{};
    pos[0] = x;
    if constexpr (D == 2) pos[1] = y;
    vel[0] = kind == Kind::Fluid ? q.velocity : 0.0;
    normal[0] = sign;
    p.add(kind, pos, vel, q.density * vol, q.density, normal, depth);
    energy.push_back(q.pressure / (gm1 * q.density));
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = -0.5 * L + (i + 0.5) * dx;
      place(Kind::Fluid, x, (j + 0.5) * dx, x < 0.0 ? st.left : st.right, 0.0, 0.0);
    }
  const int j_ext = (D == 2 && disc.boundary == "ghost") ? layers : 0;
  for (int j = -j_ext; j < ny + j_ext; ++j)
    for (int k = 0; k < layers; ++k) {
      const double depth = (k + 0.5) * dx;
      place(Kind::Wall, -0.5 * L - depth, (j + 0.5) * dx, st.left, 1.0, depth);
      place(Kind::Wall, 0.5 * L + depth, (j + 0.5) * dx, st.right, -1.0, depth);
    }
  if (D == 2 && disc.boundary == "virtual_repulsive") {
    const double x_lo = -0.5 * L - layers * dx, x_hi = 0.5 * L + layers * dx;
    const int steps = static_cast<int>(std::lround((x_hi - x_lo) / (0.5 * dx)));
    for (const double yw : {-dx, W + dx})
      for (int k = 0; k <= steps; ++k) {
        const double x = x_lo + k * 0.5 * dx;
        std::array<double, D> pos{}, vel{}, normal{};
        pos[0] = x;
        pos[D - 1] = yw;
        normal[D - 1] = yw < 0.0 ? 1.0 : -1.0;
        const ShockTubeState& q = x < 0.0 ? st.left : st.right;
        p.add(Kind::Wall, pos, vel, q.density * vol, q.density, normal, 0.0);
        energy.push_back(q.pressure / (gm1 * q.density));
      }
  }
  return p;
}

}  // namespace

TEST_CASE("case scenes: the box scenes' kit particles equal the lattice loops", "[case_scenes]") {
  // The cavity (all four walls, a moving lid), the tank (open top, taller side walls), Taylor-Green
  // (periodic: fluid only).
  const std::string yaml = verification("cavity");
  for (const int across : {7, 12, 20})
    for (const int layers : {0, 1, 3})
      for (const std::string boundary : {"wall_particles", "virtual_repulsive", "ghost"})
        for (const int kind : {0, 1, 2}) {
          std::vector<std::string> set = {"discretization.particles_across=" + std::to_string(across),
                                          "discretization.position_noise=0"};
          if (layers > 0) set.push_back("discretization.wall_layers=" + std::to_string(layers));
          const Config c = load_config_string(yaml, set);
          Config cb = c;
          cb.discretization.boundary = boundary;
          BoxWalls<2> walls{};
          const double dx = 1.0 / across;
          double Ly = 1.0;
          if (kind != 2) walls[0][0].present = walls[0][1].present = walls[1][0].present = true;
          if (kind == 0) {
            walls[1][1].present = true;
            walls[1][1].velocity = {1.0, 0.0};
          }
          if (kind == 1) Ly = std::round(1.2 * across) * dx;
          INFO("across " << across << ", layers " << layers << ", " << boundary << ", scene " << kind);
          const BoxScene s = build_box_scene(cb, 1.0, Ly, 1.0, walls, kind == 2);
          const Particles<2> want = kind == 2 ? box_reference(cb, 1.0, 1.0, 1.0, BoxWalls<2>{})
                                              : box_reference(cb, 1.0, Ly, 1.0, walls);
          if (kind == 2) REQUIRE(s.particles.size() == s.particles.n_fluid);
          require_same<2>(want, s.particles, s.spacing, true);
        }
}

TEST_CASE("case scenes: the channel's kit particles equal the lattice loops", "[case_scenes]") {
  for (const std::string name : {"couette", "poiseuille"})
    for (const int across : {20, 30, 40})
      for (const int layers : {0, 1, 4}) {
        std::vector<std::string> set = {"discretization.particles_across=" + std::to_string(across)};
        if (layers > 0) set.push_back("discretization.wall_layers=" + std::to_string(layers));
        const Config c = load_config_string(verification(name), set);
        INFO(name << ", across " << across << ", layers " << layers);
        const ChannelScene s = build_channel_scene(c);
        const auto& g = c.settings<ChannelSettings>();
        require_same<2>(channel_reference(c, g.channel_height, g.channel_length, g.wall_velocity), s.particles,
                        s.spacing, true);
      }
}

TEST_CASE("case scenes: the dam break's kit particles equal the lattice loops", "[case_scenes]") {
  for (const double dx : {0.1, 0.05, 0.04})
    for (const int layers : {1, 2, 3}) {
      std::vector<std::string> set = {"discretization.spacing=" + std::to_string(dx)};
      if (layers > 0) set.push_back("discretization.wall_layers=" + std::to_string(layers));
      const Config c = load_config_string(verification("dam_break"), set);
      INFO("dx " << dx << ", layers " << layers);
      const DamBreakScene s = build_dam_break_scene(c);
      const auto& g = c.settings<DamBreakSettings>();
      require_same<2>(dam_break_reference(c, g.box[0], g.box[1], g.column[0], g.column[1]), s.particles, s.spacing,
                      true);
    }
}

TEST_CASE("case scenes: the shock tube's kit particles equal the lattice loops", "[case_scenes]") {
  for (const double dx : {0.0125, 0.005, 0.0025})
    for (const int layers : {0, 2, 5}) {
      std::vector<std::string> set = {"discretization.spacing=" + std::to_string(dx)};
      if (layers > 0) set.push_back("discretization.wall_layers=" + std::to_string(layers));
      for (const std::string boundary : {"ghost", "virtual_repulsive", "wall_particles"}) {
        // wall_particles makes y periodic over W, which needs W > two neighbour radii (6.4 dx).
        if (boundary == "wall_particles" && dx > 0.003) continue;
        // Facing ghost walls need gap + dx >= the support (3.9 dx): W = 0.025 m is 2 spacings at 0.0125.
        if (boundary == "ghost" && dx > 0.01) continue;
        std::vector<std::string> set2 = set;
        set2.push_back("discretization.boundary=" + boundary);
        if (boundary == "virtual_repulsive")
          for (const char* r : {"strength=1.0e-3", "p1=9.5", "p2=4.0", "r0=1.0"})
            set2.push_back(std::string("discretization.repulsive.") + r);
        const Config c = load_config_string(verification("shock_tube"), set2);
        INFO("2D, dx " << dx << ", layers " << layers << ", " << boundary);
        const auto s = build_shock_tube_scene<2>(c);
        const auto& g = c.settings<ShockTubeSettings>();
        std::vector<double> e;
        const auto want = shock_tube_reference<2>(c, g.tube_length, g.tube_width, e);
        require_same<2>(want, s.particles, s.spacing, true, e, s.energy);
      }
      const Config c1 = load_config_string(verification("shock_tube_1d"), set);
      INFO("1D, dx " << dx << ", layers " << layers);
      const auto s1 = build_shock_tube_scene<1>(c1);
      std::vector<double> e1;
      const auto want1 = shock_tube_reference<1>(c1, c1.settings<ShockTubeSettings>().tube_length, 0.0, e1);
      require_same<1>(want1, s1.particles, s1.spacing, true, e1, s1.energy);
    }
}

TEST_CASE("case scenes: the equal-mass shock tube (Sod data) spaces the light side (rho_L/rho_R)^(1/D) wider", "[case_scenes]") {
  for (const double smoothing : {0.0, 1.0}) {
    INFO("smoothing " << smoothing);
    const std::vector<std::string> set = {"shock_tube.smoothing=" + std::to_string(smoothing)};
    const Config c1 = load_config_string(verification("sod_1d"), set);
    const auto s1 = build_shock_tube_scene<1>(c1);
    const double dx = 1.25e-3, m = 1.0 * dx;
    std::vector<double> left, right;
    for (std::size_t i = 0; i < s1.particles.n_fluid; ++i) {
      CHECK(s1.particles.mass[i] == Approx(m).epsilon(1e-14));
      CHECK(s1.h0[i] == Approx(1.0 * m / s1.particles.rho[i]).epsilon(1e-14));
      (s1.particles.x[0][i] < 0.0 ? left : right).push_back(s1.particles.x[0][i]);
    }
    std::sort(left.begin(), left.end());
    std::sort(right.begin(), right.end());
    CHECK(left.size() + right.size() == 450);
    // Away from the jump: spacing dx on the left, 8 dx on the right; the tube ends within half a spacing.
    CHECK(left[1] - left[0] == Approx(dx).epsilon(1e-9));
    CHECK(right.back() - right[right.size() - 2] == Approx(8.0 * dx).epsilon(1e-9));
    CHECK(std::abs(left.front() + 0.5) < dx);
    CHECK(std::abs(right.back() - 0.5) < 8.0 * dx);
    if (smoothing == 0.0) {
      CHECK(left.front() == Approx(-0.5 + 0.5 * dx).margin(1e-12));
      CHECK(right.back() == Approx(0.5 - 4.0 * dx).margin(1e-9));
      CHECK(left.back() == Approx(-0.5 * dx).margin(1e-15));
      CHECK(right.front() == Approx(4.0 * dx).margin(1e-15));
      CHECK(s1.particles.rho[s1.particles.n_fluid - 1] == 0.125);
    }
    // 2D: 14 rows on the left, 5 across W = 0.035 on the right; equal masses everywhere.
    const Config c2 = load_config_string(verification("sod"), set);
    const auto s2 = build_shock_tube_scene<2>(c2);
    CHECK(s2.side_rows == std::array<int, 2>{14, 5});
    const double m2 = 2.5e-3 * 2.5e-3;
    std::size_t n_right = 0;
    for (std::size_t i = 0; i < s2.particles.n_fluid; ++i) {
      CHECK(s2.particles.mass[i] == Approx(m2).epsilon(1e-14));
      CHECK(s2.h0[i] == Approx(1.3 * std::sqrt(m2 / s2.particles.rho[i])).epsilon(1e-14));
      if (s2.particles.x[0][i] > 0.0) {
        ++n_right;
        const double row = s2.particles.x[1][i] / 7e-3 - 0.5;  // rows at (j + 1/2) W / 5
        CHECK(std::abs(row - std::round(row)) < 1e-9);
      }
    }
    CHECK(n_right % 5 == 0);
    if (smoothing == 0.0) CHECK(n_right == 5 * 70);
  }
}

TEST_CASE("case scenes: the 3D tank has the fluid block, four side walls and a floor", "[case_scenes]") {
  const Config c = load_config_string(verification("hydrostatic_3d"));
  BoxWalls<3> walls{};
  for (int d = 0; d < 3; ++d) walls[d][0].present = walls[d][1].present = true;
  walls[2][1].present = false;
  const auto& box = c.settings<HydrostaticSettings>().box;
  const double W = box[0], B = box[1], H = box[2];
  const int n = c.discretization.particles_across;
  const double dx = W / n, T = std::round(1.2 * H / dx) * dx;
  const auto s = build_box_scene<3>(c, {W, B, T}, H, walls, false);
  const int nx = n, ny = static_cast<int>(std::lround(B / dx)), nz = static_cast<int>(std::lround(H / dx));
  const int nz_tank = static_cast<int>(std::lround(T / dx)), L = s.wall_layers;
  REQUIRE(s.particles.n_fluid == static_cast<std::size_t>(nx * ny * nz));
  REQUIRE(s.particles.n_wall() == static_cast<std::size_t>((nx + 2 * L) * (ny + 2 * L) * (nz_tank + L) - nx * ny * nz_tank));
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    const std::array<double, 3> x{s.particles.x[0][i], s.particles.x[1][i], s.particles.x[2][i]};
    if (i < s.particles.n_fluid) {
      CHECK((x[0] > 0 && x[0] < W && x[1] > 0 && x[1] < B && x[2] > 0 && x[2] < H));
      continue;
    }
    // Each wall point belongs to the face it lies deepest behind (ties: the later face, the floor
    // last); nothing lies above the open top.
    const std::array<double, 5> depth{-x[0], x[0] - W, -x[1], x[1] - B, -x[2]};
    int face = -1;
    for (int f = 0; f < 5; ++f)
      if (depth[f] > 0 && (face < 0 || depth[f] >= depth[face])) face = f;
    REQUIRE(face >= 0);
    CHECK(x[2] < T);
    CHECK(s.particles.wall_depth[i] == Approx(depth[face]));
    CHECK(s.particles.wall_normal[face / 2][i] == (face % 2 == 0 ? 1.0 : -1.0));
  }
}

TEST_CASE("case scenes: the 3D tank's keys", "[case_scenes]") {
  // geometry.box has three lengths in 3D, the depth last; the tank has no repulsive-wall builder.
  const std::string yaml = verification("hydrostatic_3d");
  const Config c = load_config_string(yaml);
  CHECK(c.dimension == 3);
  CHECK(c.settings<HydrostaticSettings>().box.size() == 3);
  CHECK_THROWS_WITH(load_config_string(yaml, {"geometry.box=[0.5, 0.5]"}),
                    Catch::Contains("geometry.box: has 2 components, expected 3"));
  std::string no_wall_pressure = yaml;
  no_wall_pressure.erase(no_wall_pressure.find("  wall_pressure:"), std::string("  wall_pressure: extrapolated\n").size());
  CHECK_THROWS_WITH(load_config_string(no_wall_pressure,
                                       {"discretization.boundary=virtual_repulsive", "discretization.repulsive.strength=1",
                                        "discretization.repulsive.p1=12", "discretization.repulsive.p2=4",
                                        "discretization.repulsive.r0=0.5"}),
                    Catch::Contains("the 3D tank has no virtual_repulsive walls"));
  // The 2D tank keeps its two lengths [width, depth].
  CHECK_THROWS_WITH(load_config_string(verification("hydrostatic"), {"geometry.box=[1, 0.5, 0.9]"}),
                    Catch::Contains("geometry.box: has 3 components, expected 2"));
}
