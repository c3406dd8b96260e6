#pragma once
// Free-slip wall bodies: the pairs between fluid and the particles of a free-slip body get the
// factor 0 on their velocity difference (Workspace::vfac), so the body exerts no viscous stress and
// the fluid slides along it; its pressure still keeps the fluid out. Dropping the wall's viscous
// pairs is the usual free-slip condition for wall particles (the velocity seen behind a flat wall
// equals the fluid particle's own, so the normal derivative of the tangential velocity vanishes).
// Runs after the wall model, which sets the factor of every wall pair first.
#include <cstdint>
#include <vector>

#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

template <int D>
class FreeSlipWalls final : public PairTermFor<D, FreeSlipWalls<D>> {
 public:
  // free_slip_body: per wall body, 1 = free slip (Particles::free_slip_body). wall_rows: also in the
  // wall particles' own rows (the strain-rate viscosity sums over them).
  FreeSlipWalls(const std::vector<std::uint8_t>& free_slip_body, bool wall_rows) : wall_rows_(wall_rows) {
    // keep_[b + 1]: the factor for body b; index 0 is "no body" (domain walls), which are no-slip.
    keep_.assign(free_slip_body.size() + 1, 1.0);
    for (std::size_t b = 0; b < free_slip_body.size(); ++b) keep_[b + 1] = free_slip_body[b] ? 0.0 : 1.0;
  }
  std::string_view name() const override { return "free_slip_walls"; }
  PairRows rows() const override { return wall_rows_ ? PairRows::all : PairRows::fluid; }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& body = w.particles->body;
    if (i >= w.n_fluid) {  // a wall row: all its pairs are with fluid (rows list only fluid neighbours)
      const double f = factor(body[i]);
      for (std::uint32_t k = 0; k < r.n; ++k) r.vfac[k] *= f;
      return;
    }
    for (std::uint32_t k = r.first_wall(w.n_fluid); k < r.n; ++k) r.vfac[k] *= factor(body[r.j[k]]);
  }

 private:
  double factor(std::int32_t b) const {
    const std::size_t k = static_cast<std::size_t>(b + 1);
    return k < keep_.size() ? keep_[k] : 1.0;
  }
  std::vector<double> keep_;
  bool wall_rows_;
};

}  // namespace sphmol
