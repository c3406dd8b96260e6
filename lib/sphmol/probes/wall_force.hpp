#pragma once
// The force the fluid exerts on one wall body: minus the sum, over fluid particles i and the body's
// wall particles j within the kernel support, of the pair forces m_i a_ij of the momentum equation
// the run integrates (equal and opposite: what the fluid receives from the body, the body receives
// from the fluid). Included pair terms, as in rhs/assemble.cpp:
//   pressure, Vukčević 2012 eq 117:  a_ij = -m_j (p_i/rho_i^2 + p_j/rho_j^2) grad_i W_ij
//             or eq 116:             a_ij = -m_j (p_i + p_j)/(rho_i rho_j) grad_i W_ij
//   Morris, Fox & Zhu 1997 eq 8:      a_ij = m_j 2 mu/(rho_i rho_j) F_ij r^2/(r^2 + 0.01 h^2) beta (v_i - v_j)
//             (beta: the wall model's factor, boundary/morris_wall_velocity.hpp; 1 for prescribed walls)
//   Monaghan 1992 artificial viscosity, when enabled: a_ij = -m_j Pi_ij grad_i W_ij
// with grad_i W_ij = F_ij (x_i - x_j), F = (dW/dr)/r. Not included: the strain-rate viscosity, the
// transport-velocity stress, repulsive wall forces and ghost particles (the force probe needs
// boundary: wall_particles, with viscosity morris or none; probes/probe_observer.cpp checks it).
// In 2D the result is a force per unit depth [N/m].
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <optional>
#include <vector>

#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"
#include "sphmol/parallel/particle_selection.hpp"
#include "sphmol/physics/artificial_viscosity.hpp"
#include "sphmol/probes/point_bins.hpp"
#include "sphmol/run/owned_piece.hpp"

namespace sphmol {

struct WallForceModel {
  bool momentum_116 = false;        // eq 116 instead of eq 117
  bool viscous = false;             // the Morris term is on
  double dynamic_viscosity = 0.0;   // mu = rho0 nu of the Morris term (Particles::viscosity instead, when set)
  bool morris_wall_velocity = false;
  double beta_max = 8.0;
  bool artificial_viscosity = false;
  MonaghanPi pi{1.0, 1.0, 0.1};
};

// The current state, all particles in Particles order (fluid [0, n_fluid), walls after): positions
// and velocities (the fluid's; the walls' as the solver's terms read them at t: for a wall that
// follows a motion its Particles::wall_state at t, not Particles::v, which holds its velocity at
// t = 0), the walls' normals at t (read only with the Morris wall velocity; null: the as-built
// Particles::wall_normal, right when no wall turns), densities, pressures and sound speeds.
template <int D>
struct WallForceState {
  std::array<const double*, D> x{}, v{};
  std::array<const double*, D> n{};
  const double* rho = nullptr;
  const double* p = nullptr;
  const double* c = nullptr;  // read only with artificial viscosity
};

// One fluid particle or wall particle of a pair as the force sums read it: v its velocity and, of
// the wall particle, n its normal, both at the sampling time (Particles::wall_state), as the solver
// reads them (rhs/sph_system.cpp: the wall velocities and turned normals of each evaluation).
template <int D>
struct WallPairEnd {
  std::array<double, D> v{}, n{};
  double rho = 0.0, p = 0.0, c = 0.0;
};

// The body's part of one pair, -m_i a_ij (per axis; its sum over the pairs is the force): fluid
// particle i, its index in Pf (its mass and viscosity), and wall particle j, its index in Pw (its
// mass, depth and body; its normal at t is b.n), at distance r > 0 with dx = x_i - x_j. Serially
// both are the whole scene's particles; over ranks Pf is a rank's own system and Pw the body's
// walls (BodyWalls).
template <int D>
std::array<double, D> wall_pair_force(const Particles<D>& Pf, std::size_t i, const Particles<D>& Pw, std::size_t j,
                                      const WallPairEnd<D>& a, const WallPairEnd<D>& b, double r,
                                      const std::array<double, D>& dx, double (*dWdr)(double, double), double h,
                                      const WallForceModel& model) {
  const double eta2 = 0.01 * h * h;
  const double F = dWdr(r, h) / r;
  const double mj = Pw.mass[j];
  const double pi_i = a.p / (a.rho * a.rho);
  // Pressure: the coefficient of dx in a_ij.
  double cx = model.momentum_116 ? -mj * (a.p + b.p) / (a.rho * b.rho) * F : -mj * (pi_i + b.p / (b.rho * b.rho)) * F;
  double vx = 0.0;
  for (int d = 0; d < D; ++d) vx += (a.v[d] - b.v[d]) * dx[d];
  if (model.artificial_viscosity) cx -= mj * model.pi(vx, r * r, h, 0.5 * (a.c + b.c), 0.5 * (a.rho + b.rho)) * F;
  double cv = 0.0;
  if (model.viscous) {
    double beta = Pw.free_slip(j) ? 0.0 : 1.0;  // boundary/free_slip_walls.hpp
    if (model.morris_wall_velocity && beta > 0.0) {
      double dA = -Pw.wall_depth[j];
      for (int d = 0; d < D; ++d) dA += b.n[d] * dx[d];
      beta = dA > 0.0 ? std::min(model.beta_max, 1.0 + Pw.wall_depth[j] / dA) : model.beta_max;
    }
    // A wall pair takes the fluid particle's mu (physics/morris_viscosity.hpp).
    const double mu = Pf.viscosity.empty() ? model.dynamic_viscosity : Pf.viscosity[i];
    cv = mj * 2.0 * mu / (a.rho * b.rho) * F * r * r / (r * r + eta2) * beta;
  }
  std::array<double, D> f{};
  for (int d = 0; d < D; ++d) f[d] = Pf.mass[i] * (cx * dx[d] + cv * (a.v[d] - b.v[d]));
  return f;
}

// The wall particles of one body, copied out of the scene's particles P in ascending index order
// (every per-particle array; the per-body tables and the motions whole): what a force probe over
// ranks keeps of the scene, whose per-particle arrays the ranks other than 0 drop after the set-up.
// walls.n_fluid = 0, so WallBodyBins over `walls` lists them in the order it lists them in P.
template <int D>
struct BodyWalls {
  int body = -1;
  Particles<D> walls;
  std::vector<std::size_t> ids;  // walls' particle k is P's particle ids[k]
};

template <int D>
BodyWalls<D> body_walls(const Particles<D>& P, int body) {
  BodyWalls<D> B;
  B.body = body;
  // The scene's own walls: a particle generator (ghost images) extends mass, rho and kind beyond
  // `body`, and its images belong to no body.
  for (std::size_t j = P.n_fluid; j < P.body.size(); ++j)
    if (P.body[j] == body) B.ids.push_back(j);
  B.walls = parallel::select_particles(P, B.ids, 0);  // every per-particle array; n_fluid = 0
  return B;
}

// The same from the particles the ranks start a run with (run/start_piece.hpp), collective over its
// ranks: each rank's walls of the body, joined on every rank in global-id order (a rank building its
// share of the scene alone holds no other; one rank: body_walls of the whole scene).
// `body` kEveryWall: every wall particle, the domain's and every body's (the height gauges' walls).
inline constexpr int kEveryWall = -2;
template <int D>
BodyWalls<D> gather_body_walls(const OwnedPiece<D>& start, int body) {
  const Particles<D>& P = start.system->particles();
  std::vector<std::size_t> rows;
  std::vector<std::uint64_t> ids;
  for (std::size_t k = 0; k < start.wall_rows.size(); ++k)
    if (body == kEveryWall || P.body[start.wall_rows[k]] == body) {
      rows.push_back(start.wall_rows[k]);
      ids.push_back(static_cast<std::uint64_t>(start.wall_ids[k]));
    }
  const Particles<D> mine = parallel::select_particles(P, rows, 0);
  // This rank's part: the count, the ids, then each per-particle column as its byte count and bytes.
  std::vector<std::byte> bytes;
  const auto put = [&](const void* data, std::size_t n) {
    const auto* b = static_cast<const std::byte*>(data);
    bytes.insert(bytes.end(), b, b + n);
  };
  const std::uint64_t count = ids.size();
  put(&count, sizeof count);
  put(ids.data(), ids.size() * sizeof(std::uint64_t));
  parallel::for_each_particle_column(mine, [&](const auto& c) {
    const std::uint64_t n = c.size() * sizeof(c[0]);
    put(&n, sizeof n);
    put(c.data(), n);
  });
  const std::vector<std::byte> all = start.all_gather_bytes(bytes);
  BodyWalls<D> B;
  B.body = body;
  std::size_t at = 0;
  const auto get = [&](void* data, std::size_t n) {
    if (at + n > all.size()) throw std::logic_error("gather_body_walls: the ranks' walls are malformed");
    if (n > 0) std::memcpy(data, all.data() + at, n);
    at += n;
  };
  while (at < all.size()) {
    std::uint64_t n_rank = 0;
    get(&n_rank, sizeof n_rank);
    std::vector<std::uint64_t> rank_ids(n_rank);
    get(rank_ids.data(), n_rank * sizeof(std::uint64_t));
    B.ids.insert(B.ids.end(), rank_ids.begin(), rank_ids.end());
    parallel::for_each_particle_column(B.walls, [&](auto& c) {
      std::uint64_t n = 0;
      get(&n, sizeof n);
      const std::size_t old = c.size();
      c.resize(old + n / sizeof(c[0]));
      get(c.data() + old, n);
    });
  }
  parallel::copy_body_tables(B.walls, P);
  B.walls.n_fluid = 0;
  return B;
}

// The wall particles of one body, binned by the kernel support; x(d, j): coordinate d of wall
// particle j (index in P). Over ranks every rank builds them from the body's walls (BodyWalls),
// which it copied from the whole scene at the set-up.
template <int D>
class WallBodyBins {
 public:
  template <class X>
  WallBodyBins(const Particles<D>& P, int body, X&& x, double radius, const Domain<D>& domain) {
    for (std::size_t j = P.n_fluid; j < P.size(); ++j)
      if (P.body[j] == body) walls_.push_back(j);
    std::array<const double*, D> xp{};
    for (int d = 0; d < D; ++d) {
      for (const std::size_t j : walls_) x_[d].push_back(x(d, j));
      xp[d] = x_[d].data();
    }
    bins_.emplace(xp, walls_.size(), radius, domain);
  }
  // f(j, r, dx) for the body's walls j (indices in P) within the radius of xi, dx = xi - x_j, in
  // the order the force sums them.
  template <class F>
  void near(const geometry::Vec<D>& xi, F&& f) const {
    bins_->for_each_near(xi, [&](std::size_t k, double r, const std::array<double, D>& dx) { f(walls_[k], r, dx); });
  }

 private:
  std::vector<std::size_t> walls_;
  std::array<std::vector<double>, D> x_;
  std::optional<PointBins<D>> bins_;
};

// dWdr(r, h): the kernel's radial derivative; support: its radius in units of h. Sums over the
// fluid particles i in index order, and for each over its wall neighbours in the bins' order.
template <int D>
std::array<double, D> wall_body_force(const Particles<D>& P, const WallForceState<D>& s, int body,
                                      double (*dWdr)(double, double), double h, double support,
                                      const Domain<D>& domain, const WallForceModel& model) {
  const WallBodyBins<D> bins(P, body, [&](int d, std::size_t j) { return s.x[d][j]; }, support * h, domain);
  const auto end = [&](std::size_t k) {
    WallPairEnd<D> e;
    for (int d = 0; d < D; ++d) {
      e.v[d] = s.v[d][k];
      e.n[d] = s.n[d] ? s.n[d][k] : P.wall_normal[d][k];
    }
    e.rho = s.rho[k];
    e.p = s.p[k];
    e.c = model.artificial_viscosity ? s.c[k] : 0.0;
    return e;
  };
  std::array<double, D> force{};
  for (std::size_t i = 0; i < P.n_fluid; ++i) {
    if (P.kind[i] == Kind::Out) continue;  // taken out of the run (run/outflow.hpp): pairs with no wall
    geometry::Vec<D> xi;
    for (int d = 0; d < D; ++d) xi[d] = s.x[d][i];
    const WallPairEnd<D> a = end(i);
    bins.near(xi, [&](std::size_t j, double r, const std::array<double, D>& dx) {
      if (r == 0.0) return;  // coincident particles exert no force (dx = 0)
      const std::array<double, D> f = wall_pair_force<D>(P, i, P, j, a, end(j), r, dx, dWdr, h, model);
      // The body receives -m_i a_ij.
      for (int d = 0; d < D; ++d) force[d] -= f[d];
    });
  }
  return force;
}

}  // namespace sphmol
