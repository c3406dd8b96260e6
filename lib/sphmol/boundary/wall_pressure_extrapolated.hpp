#pragma once
// Wall-particle pressure extrapolated from the fluid (Adami, Hu & Adams 2012, J. Comput. Phys.
// 231:7057, eq. 27), for a wall at rest or moving uniformly:
//   p_w = (sum_f p_f W_wf + g . sum_f rho_f (x_w - x_f) W_wf) / sum_f W_wf
// and the wall density from the inverse EOS. A wall held at rest density has p = 0 (Tait, gauge EOS),
// which under a hydrostatic column is a pressure jump at the wall: the symmetric gradient (Vukčević
// 2012, eq 117) turns it into a force drawing the first fluid rows into the wall (the walls' p = 0
// pushes less than the fluid they stand for would; tests/unit/test_boundaries_3d.cpp). Wall rows list only fluid
// neighbours. Wall particles without fluid neighbours keep their pressure of the EOS pass.
#include <array>
#include <functional>

#include "sphmol/physics/body_force.hpp"
#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class WallPressureExtrapolated final : public Term<D> {
 public:
  WallPressureExtrapolated(const std::array<double, D>& g, double ramp, std::function<double(double)> density_of_pressure)
      : g_(g), ramp_(ramp), rho_of_p_(std::move(density_of_pressure)) {}
  std::string_view name() const override { return "wall_pressure_extrapolated"; }
  bool reads_stored_pairs() const override { return true; }
  void apply(Workspace<D>& w) const override {
    const auto& P = w.pairs;
    const double f = body_force_ramp_factor(w.t, ramp_);
    for (std::size_t i = w.n_fluid; i < w.n; ++i) {
      if (w.particles->kind[i] != Kind::Wall || P.offset[i] == P.offset[i + 1]) continue;
      double sw = 0.0, sp = 0.0;
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
        const std::uint32_t j = P.j[k];
        double gr = 0.0;  // dx = x_w - x_f
        for (int d = 0; d < D; ++d) gr += f * g_[d] * w.dx[d][k];
        sw += w.W[k];
        sp += (w.p[j] + w.rho[j] * gr) * w.W[k];
      }
      if (sw <= 0.0) continue;
      w.p[i] = sp / sw;
      w.rho[i] = rho_of_p_(w.p[i]);
    }
  }

 private:
  std::array<double, D> g_;
  double ramp_;
  std::function<double(double)> rho_of_p_;
};

}  // namespace sphmol
