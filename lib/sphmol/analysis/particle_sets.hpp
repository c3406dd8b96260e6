#pragma once
// Particle sets for the consistency diagnostics: positions and volumes, in D dimensions.
// Regular lattice, deterministically perturbed lattice, and a half-lattice cut by a wall.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sphmol::analysis {

template <int D>
struct ParticleSet {
  std::vector<std::array<double, D>> x;
  std::vector<double> V;  // volumes m/rho ("Delta x_beta" of Vukčević 2012, eq 90)
};

// (2n+1)^D points j*d, j = -n..n per axis, each with volume d^D; the origin is a particle.
template <int D>
ParticleSet<D> regular_lattice(int n, double d) {
  ParticleSet<D> s;
  std::array<int, D> idx;
  idx.fill(-n);
  const double vol = std::pow(d, D);
  while (true) {
    std::array<double, D> p;
    for (int a = 0; a < D; ++a) p[a] = idx[a] * d;
    s.x.push_back(p);
    s.V.push_back(vol);
    int a = 0;
    while (a < D && ++idx[a] > n) idx[a++] = -n;
    if (a == D) break;
  }
  return s;
}

// splitmix64: a portable, seedable generator, so the perturbed lattice is the same everywhere
// (std::uniform_real_distribution is implementation-defined).
inline double splitmix_uniform(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return double(z >> 11) * 0x1.0p-53;
}

// Every coordinate moved by amplitude*d*u, u uniform in [-1/2, 1/2); volumes unchanged.
template <int D>
ParticleSet<D> perturbed_lattice(int n, double d, double amplitude, std::uint64_t seed) {
  ParticleSet<D> s = regular_lattice<D>(n, d);
  std::uint64_t state = seed;
  for (auto& p : s.x)
    for (auto& c : p) c += amplitude * d * (splitmix_uniform(state) - 0.5);
  return s;
}

// The regular lattice with every particle at x_1 < 0 removed: a wall through the origin
// particle, which keeps only half of its support.
template <int D>
ParticleSet<D> wall_lattice(int n, double d) {
  ParticleSet<D> full = regular_lattice<D>(n, d), s;
  for (std::size_t j = 0; j < full.x.size(); ++j)
    if (full.x[j][0] > -1e-12 * d) {
      s.x.push_back(full.x[j]);
      s.V.push_back(full.V[j]);
    }
  return s;
}

}  // namespace sphmol::analysis
