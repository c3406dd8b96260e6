#pragma once
// Particle sets for the MPI tests, the same on every rank (a seeded generator): random points in a
// box of unequal sides, fluid first and a fifth of them walls, with every per-particle array of
// Particles<D> filled from the global id, so that a value shows where it came from after it moved.
#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"
#include "sphmol/neighbors/cell_list_search.hpp"
#include "sphmol/parallel/communicator.hpp"

namespace sphmol::test {

// The value every array of particle g holds (column c of the visiting order, component d).
inline double tagged(std::uint64_t g, int c) { return 1000.0 * static_cast<double>(c + 1) + 0.001 * static_cast<double>(g); }

template <int D>
struct GlobalSet {
  Domain<D> domain;
  Particles<D> particles;        // particle k has global id k
  std::vector<std::uint64_t> gid;
};

template <int D>
GlobalSet<D> random_set(std::size_t n, std::array<bool, D> periodic, unsigned seed) {
  GlobalSet<D> s;
  const double L[3] = {1.0, 0.8, 0.6};
  for (int d = 0; d < D; ++d) {
    s.domain.lo[d] = 0.0;
    s.domain.hi[d] = L[d];
    s.domain.periodic[d] = periodic[d];
  }
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::size_t n_wall = n / 5;
  for (std::size_t k = 0; k < n; ++k) {
    std::array<double, D> x{}, v{}, normal{};
    for (int d = 0; d < D; ++d) {
      x[d] = L[d] * u(rng);
      v[d] = tagged(k, 10 + d);
      normal[d] = tagged(k, 20 + d);
    }
    const Kind kind = k < n - n_wall ? Kind::Fluid : Kind::Wall;
    s.particles.add(kind, x, v, tagged(k, 0), tagged(k, 1), normal, tagged(k, 2));
    for (int d = 0; d < D; ++d) s.particles.x_ref[d].back() = tagged(k, 30 + d);
    s.particles.stationary.back() = static_cast<std::uint8_t>(k % 2);
    s.particles.body.back() = static_cast<std::int32_t>(k % 5) - 1;
    s.particles.motion.back() = static_cast<std::int32_t>(k % 3) - 1;
    s.particles.rest_density.push_back(tagged(k, 3));
    s.particles.viscosity.push_back(tagged(k, 4));
    s.gid.push_back(k);
  }
  return s;
}

// This rank's share before any partition: every size-th particle, a scattered (bad) decomposition.
template <int D>
void take_share(const GlobalSet<D>& s, const parallel::Communicator& comm, Particles<D>& p, std::vector<std::uint64_t>& gid) {
  p = Particles<D>{};
  gid.clear();
  for (std::size_t k = 0; k < s.particles.size(); ++k) {
    if (static_cast<int>(k % static_cast<std::size_t>(comm.size())) != comm.rank()) continue;
    const auto& q = s.particles;
    std::array<double, D> x{}, v{}, normal{};
    for (int d = 0; d < D; ++d) {
      x[d] = q.x[d][k];
      v[d] = q.v[d][k];
      normal[d] = q.wall_normal[d][k];
    }
    p.add(q.kind[k], x, v, q.mass[k], q.rho[k], normal, q.wall_depth[k]);
    for (int d = 0; d < D; ++d) p.x_ref[d].back() = q.x_ref[d][k];
    p.stationary.back() = q.stationary[k];
    p.body.back() = q.body[k];
    p.motion.back() = q.motion[k];
    if (!q.rest_density.empty()) p.rest_density.push_back(q.rest_density[k]);
    if (!q.viscosity.empty()) p.viscosity.push_back(q.viscosity[k]);
    gid.push_back(s.gid[k]);
  }
}

template <int D>
std::array<const double*, D> positions(const Particles<D>& p) {
  std::array<const double*, D> x{};
  for (int d = 0; d < D; ++d) x[d] = p.x[d].data();
  return x;
}

// The serial neighbour rows (cell list) of n particles.
template <int D>
PairList serial_pairs(const std::array<const double*, D>& x, const Kind* kind, std::size_t n, const Domain<D>& domain,
                      double radius) {
  SearchInput<D> in;
  in.x = x;
  in.kind = kind;
  in.n = n;
  in.domain = &domain;
  in.radius = radius;
  PairList out;
  CellListSearch<D> search;
  search.build(in, out);
  return out;
}

}  // namespace sphmol::test
