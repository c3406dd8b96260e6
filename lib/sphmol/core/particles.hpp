#pragma once
// All particles of a scene in structure-of-arrays form. Fluid particles occupy [0, n_fluid) and are
// integrated; boundary (wall) particles follow and move by prescription, never by the ODE.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sphmol {

enum class Kind : std::uint8_t { Fluid = 0, Wall = 1 };

template <int D>
struct Particles {
  std::size_t n_fluid = 0;
  std::array<std::vector<double>, D> x;  // positions
  std::array<std::vector<double>, D> v;  // velocities (walls: the prescribed velocity)
  std::vector<double> mass;
  std::vector<double> rho;               // density (walls: fixed rest density)
  std::vector<Kind> kind;
  // Walls move rigidly with their prescribed velocity: x(t) = x_ref + v t.
  std::array<std::vector<double>, D> x_ref;
  // For a wall particle: the unit normal of its wall surface, pointing into the fluid, and its depth
  // below that surface (>= 0). Zero for fluid particles. Used by the Morris wall-velocity model.
  std::array<std::vector<double>, D> wall_normal;
  std::vector<double> wall_depth;
  // 1 for a wall that stays at x_ref while carrying the velocity v (a belt, such as the lid of a
  // driven cavity: its surface moves, its particles must not leave the box). 0 otherwise.
  std::vector<std::uint8_t> stationary;
  // The solid body a wall particle belongs to (an index into the scene's list of wall bodies, for
  // force probes and per-body motion); -1 for fluid particles and for walls of no named body.
  std::vector<std::int32_t> body;

  std::size_t size() const { return mass.size(); }
  // Where wall particle i is at time t: the one rule the solver and every writer share.
  double wall_position(int d, std::size_t i, double t) const { return x_ref[d][i] + (stationary[i] ? 0.0 : v[d][i] * t); }
  std::size_t n_wall() const { return size() - n_fluid; }

  void add(Kind k, const std::array<double, D>& pos, const std::array<double, D>& vel, double m, double density,
           const std::array<double, D>& normal = {}, double depth = 0.0) {
    for (int d = 0; d < D; ++d) {
      x[d].push_back(pos[d]);
      v[d].push_back(vel[d]);
      x_ref[d].push_back(pos[d]);
      wall_normal[d].push_back(normal[d]);
    }
    wall_depth.push_back(depth);
    stationary.push_back(0);
    body.push_back(-1);
    mass.push_back(m);
    rho.push_back(density);
    kind.push_back(k);
    if (k == Kind::Fluid) ++n_fluid;
  }
};

}  // namespace sphmol
