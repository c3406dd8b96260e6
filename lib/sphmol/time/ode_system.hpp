#pragma once
// What an integrator sees: dy/dt = f(t, y), the CFL-limited stable step, and (for the leapfrog)
// where the velocity block sits in y = [positions | velocities | other first-order fields].
#include <cstddef>

namespace sphmol {

class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  virtual std::size_t size() const = 0;
  virtual void rhs(double t, const double* y, double* ydot) = 0;
  // Largest stable step for the state of the most recent rhs() call (CFL: acoustic, force, viscous).
  virtual double stable_step() const = 0;
  // The same with every CFL coefficient at the top of its stable range (config/README.md, "CFL
  // coefficients"): a fixed step above it is outside every measured stability limit.
  virtual double widest_stable_step() const { return stable_step(); }
  virtual std::size_t velocities_begin() const = 0;
  virtual std::size_t velocities_end() const = 0;
  virtual long rhs_evaluations() const = 0;
  // Entries per particle block of y (the fluid particle count for an SPH state): element-wise loops
  // that split each block over threads the same way as the RHS splits particles keep a particle's
  // cache lines on one core (time/particle_split.hpp). The default, the whole position range, means
  // no block structure.
  virtual std::size_t block_length() const { return velocities_begin(); }
};

}  // namespace sphmol
