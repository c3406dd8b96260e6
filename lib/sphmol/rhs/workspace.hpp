#pragma once
// Everything one RHS evaluation reads and writes. Per-particle arrays cover all particles (fluid
// then wall); per-pair arrays follow the CSR pair list. Kernel values W and F = (dW/dr)/r are
// computed once per pair per evaluation (grad_i W_ij = F_ij * (x_i - x_j)) and reused by every term.
#include <array>
#include <vector>

#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"
#include "sphmol/neighbors/pair_list.hpp"

namespace sphmol {

template <int D>
struct Workspace {
  std::size_t n = 0, n_fluid = 0;
  const Particles<D>* particles = nullptr;  // mass, kind, wall motion
  const Domain<D>* domain = nullptr;
  const PairList* pairs = nullptr;
  double h = 0.0;
  double W0 = 0.0;  // W(0, h): the self-contribution to summation density

  std::array<std::vector<double>, D> x, v;  // current positions (wrapped) and velocities
  std::vector<double> rho, p;
  std::vector<double> W, F;                 // per pair
  // Per pair: the factor on the velocity difference seen by viscous terms. 1 between fluid particles;
  // for a fluid-wall pair it is set by the wall model (1 for prescribed wall velocities, Morris'
  // extrapolation factor beta otherwise), so terms need no branch on particle kind or configuration.
  std::vector<double> vfac;
  std::array<std::vector<double>, D * D> strain;  // strain-rate tensor eps_ab, row-major

  // Outputs for fluid particles (point into the caller's ydot).
  std::array<double*, D> dxdt{}, dvdt{};

  double separation(int d, std::size_t i, std::size_t j) const { return domain->min_image(d, x[d][i] - x[d][j]); }
};

}  // namespace sphmol
