#pragma once
// Dynamic boundary particles (DBC; Crespo, Gomez-Gesteira & Dalrymple 2007, Comput. Mater. Continua
// 5:173): wall particles obey the same continuity equation as the fluid (Niedoba 2012, eq 2.61),
//   drho_a/dt = sum_j m_j v_aj . grad_a W_aj   over the fluid neighbours j of wall particle a,
// but do not move; their pressure follows from the same EOS. A fluid particle approaching a wall
// compresses the wall particles near it, whose pressure then pushes it back. Wall densities live in
// the ODE state (core/state_layout.hpp, block wall_density), so every integrator advances them with
// the fluid. Wall rows of the pair list hold exactly the fluid neighbours (neighbors/pair_list.hpp).
// DualSPHysics resets a wall density below rho0 to rho0 after every step, so that a wall never pulls
// fluid in with a negative pressure. A method-of-lines state cannot be reset between steps; the EOS
// reads max(rho, rho0) instead (rhs/sph_system.cpp), and the state itself follows the continuity
// equation above on both sides of rho0. Cutting the rate to zero at the floor would make f(t, y) jump
// where a decompressing wall reaches rho0: every such event leaves a first-order time error, the same
// for every integrator (measured on the dam break, dp = 0.05, t = 0.03 s: errors halving with the
// step, about 2e-5 at dt = 1.25e-5 s for leapfrog, Bogacki-Shampine and Verner alike). With the plain
// rate, f is continuous (the floor of the EOS input is a kink, not a jump).
// A wall that decompressed below rho0 is recompressed to rho0 before it pushes again; its pressure
// is zero meanwhile (after a reset it would rise at once).
// In a scene whose wall bodies differ in treatment, every wall density is in the state but only the
// walls a per-body mask marks (Particles::treatment_mask) evolve; the others keep their initial (rest)
// density.
#include <cstdint>
#include <vector>

#include "sphmol/physics/continuity_density.hpp"

namespace sphmol {

template <int D>
class DynamicWallDensity final : public PairTermFor<D, DynamicWallDensity<D>> {
 public:
  // mask: mask[body + 1] = 1 for the walls that evolve (Particles::treatment_mask); empty: all.
  explicit DynamicWallDensity(std::vector<std::uint8_t> mask = {}) : mask_(std::move(mask)) {}
  std::string_view name() const override { return "dynamic_wall_density"; }
  PairRows rows() const override { return PairRows::dynamic_walls; }
  bool zero_beyond_support() const override { return true; }  // m_j v_aj . x_aj F_aj
  void row_impl(Workspace<D>& w, std::size_t a, const PairRow<D>& r) const {
    if (!mask_.empty() && !mask_[static_cast<std::size_t>(w.particles->body[a] + 1)]) return;  // per row
    w.drhodt_wall[a - w.n_fluid] += continuity_rate(w, a, r);
  }

 private:
  std::vector<std::uint8_t> mask_;
};

}  // namespace sphmol
