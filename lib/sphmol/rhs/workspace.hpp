#pragma once
// Everything one RHS evaluation reads and writes. Per-particle arrays cover all particles (fluid
// then wall). The kernel pass compacts the Verlet list (which includes the skin) into the pairs
// actually inside the support, `pairs`, and stores per pair the separation dx = x_i - x_j (minimum
// image), W and F = (dW/dr)/r, so that grad_i W_ij = F_ij dx_ij. Terms read these and never
// recompute a distance or a kernel.
#include <array>
#include <cstdint>
#include <vector>

#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"
#include "sphmol/neighbors/pair_list.hpp"
#include "sphmol/time/viscous_operator.hpp"

namespace sphmol {

template <int D>
struct Workspace {
  std::size_t n = 0, n_fluid = 0;
  const Particles<D>* particles = nullptr;  // mass, kind, wall motion
  const Domain<D>* domain = nullptr;
  // Workspace index -> particle (state) index when the workspace is reordered for locality
  // (rhs/sph_system.hpp, set_reorder); null when the two agree. Only a term that keeps its own
  // per-particle data needs it.
  const std::uint32_t* order = nullptr;
  const PairList* verlet = nullptr;  // the Verlet list (with skin) of this evaluation
  long verlet_rebuilds = 0;           // how often that list has been rebuilt: tables made from it are current while this holds
  // Wall normals at this evaluation's time, per workspace index: set by SphSystem when walls turn
  // (core/wall_motion.hpp); null: the particles' own normals (walls that do not turn).
  std::array<const double*, D> wall_normal{};
  // Seconds each OpenMP thread has spent on rows of fused pair passes, summed over evaluations (index:
  // thread number): equal entries mean balanced threads, and their sum against the 1-thread time shows
  // how much slower a thread runs beside the other (rhs/fused_pair_pass.hpp).
  std::vector<double> pair_thread_seconds;
  PairList pairs;  // active pairs (r < support), same row structure as the Verlet list
  double h = 0.0;
  double W0 = 0.0;  // W(0, h): the self-contribution to summation density
  double t = 0.0;   // time of this evaluation (time-dependent terms: ramped body force)

  std::array<std::vector<double>, D> x, v;  // current positions (wrapped) and velocities
  std::vector<double> rho, p;
  std::array<std::vector<double>, D> dx;    // per pair: x_i - x_j
  std::vector<double> W, F;                 // per pair
  // Per pair: the factor on the velocity difference seen by viscous terms. 1 between fluid particles;
  // for a fluid-wall pair it is set by the wall model (1 for prescribed wall velocities, Morris'
  // extrapolation factor beta otherwise), so terms need no branch on particle kind or configuration.
  std::vector<double> vfac;
  // Velocities the viscous terms read for the other particle of a pair, for a wall model that gives
  // wall particles a velocity of their own for the viscous term (boundary/adami_wall_velocity.hpp);
  // empty: the velocities v.
  std::array<std::vector<double>, D> v_viscous;
  std::array<std::vector<double>, D * D> strain;  // strain-rate tensor eps_ab, row-major

  // Set for an evaluation of the explicit part of an IMEX split (SphSystem::rhs_explicit): the implicit
  // terms (Term::implicit) record their linear operator here and leave dv/dt to the explicit terms.
  ViscousOperator* implicit = nullptr;

  // Outputs for fluid particles (point into the caller's ydot).
  std::array<double*, D> dxdt{}, dvdt{};

  // Compressible flow (Niedoba 2012, §2.2.4-2.2.5). Per particle: sound speed (set by the EOS, read
  // by the artificial viscosity and the CFL limit), specific internal energy (state, or fixed for
  // walls), smoothing length h_i (all equal to h unless the scene varies h).
  std::vector<double> c, e, hs;
  // Outputs of the optional state blocks (into ydot; null when the block is not in the state).
  double* drhodt = nullptr;
  double* dedt = nullptr;
  double* dhdt = nullptr;
  // Dynamic boundary particles: rate of the wall densities in the state, indexed i - n_fluid for the
  // wall particles i in [n_fluid, n_fluid + n_wall_density); null otherwise.
  double* drhodt_wall = nullptr;
  std::size_t n_wall_density = 0;

  // After a kernel pass has counted each row's active pairs into pairs.offset[i + 1]: turns the
  // counts into row offsets and sizes every per-pair array for the total.
  void size_active_pairs(std::size_t rows) {
    auto& po = pairs.offset;
    for (std::size_t i = 0; i < rows; ++i) po[i + 1] += po[i];
    const std::size_t n_active = po[rows];
    pairs.j.resize(n_active);
    for (int d = 0; d < D; ++d) dx[d].resize(n_active);
    W.resize(n_active);
    F.resize(n_active);
    vfac.resize(n_active);
  }
};

}  // namespace sphmol
