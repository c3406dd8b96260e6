#pragma once
// Wall-particle pressure extrapolated from the fluid (Adami, Hu & Adams 2012, J. Comput. Phys.
// 231:7057, eq. 27):
//   p_w = (sum_f p_f W_wf + (g - a_w) . sum_f rho_f (x_w - x_f) W_wf) / sum_f W_wf
// and the wall density from the inverse EOS (their eq. 28). a_w is the acceleration of the wall's
// material at the particle (zero for walls at rest, translating, or a belt such as a cavity lid;
// wall_acceleration below), needed for oscillating and rotating walls. Time derivatives are central
// differences over +-1e-6 s: error ~1e-12 omega^2 relative, far below the pressure's round-off.
// A wall held at rest density has p = 0 (Tait, gauge EOS),
// which under a hydrostatic column is a pressure jump at the wall: the symmetric gradient (Vukčević
// 2012, eq 117) turns it into a force drawing the first fluid rows into the wall (the walls' p = 0
// pushes less than the fluid they stand for would; tests/unit/test_boundaries_3d.cpp). Wall rows list only fluid
// neighbours. Wall particles without fluid neighbours keep their pressure of the EOS pass, from the
// density they were made with (reset at every evaluation, rhs/sph_system.cpp). A scene
// whose wall bodies differ in treatment passes a per-body mask (Particles::treatment_mask): only the
// walls it marks are extrapolated, the others keep the pressure of their own treatment.
#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "sphmol/physics/body_force.hpp"
#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class WallPressureExtrapolated final : public Term<D> {
 public:
  // mask: mask[body + 1] = 1 for the walls to extrapolate (Particles::treatment_mask); empty: all walls.
  WallPressureExtrapolated(const std::array<double, D>& g, double ramp, std::function<double(double)> density_of_pressure,
                           std::vector<std::uint8_t> mask = {})
      : g_(g), ramp_(ramp), rho_of_p_(std::move(density_of_pressure)), mask_(std::move(mask)) {}
  std::string_view name() const override { return "wall_pressure_extrapolated"; }
  bool reads_stored_pairs() const override { return true; }
  void apply(Workspace<D>& w) const override {
    const auto& P = w.pairs;
    const double f = body_force_ramp_factor(w.t, ramp_);
    for (std::size_t i = w.n_fluid; i < w.n; ++i) {
      if (w.particles->kind[i] != Kind::Wall || P.offset[i] == P.offset[i + 1]) continue;
      if (!mask_.empty() && !mask_[static_cast<std::size_t>(w.particles->body[i] + 1)]) continue;
      double ge[D];  // g - a_w
      for (int d = 0; d < D; ++d) ge[d] = f * g_[d];
      if (const auto a = wall_acceleration(*w.particles, i, w.t)) for (int d = 0; d < D; ++d) ge[d] -= (*a)[d];
      double sw = 0.0, sp = 0.0;
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
        const std::uint32_t j = P.j[k];
        double gr = 0.0;  // dx = x_w - x_f
        for (int d = 0; d < D; ++d) gr += ge[d] * w.dx[d][k];
        sw += w.W[k];
        sp += (w.p[j] + w.rho[j] * gr) * w.W[k];
      }
      if (sw <= 0.0) continue;
      w.p[i] = sp / sw;
      w.rho[i] = rho_of_p_(w.p[i]);
    }
  }

  // The acceleration of the wall's material at wall particle i at time t (core/wall_motion.hpp,
  // WallMotion::acceleration); none for a wall that does not accelerate (no motion, a translation).
  static std::optional<std::array<double, D>> wall_acceleration(const Particles<D>& pt, std::size_t i, double t) {
    if (i >= pt.motion.size() || pt.motion[i] < 0) return std::nullopt;
    const auto& m = pt.motions[pt.motion[i]];
    if (m.kind == WallMotionKind::translation) return std::nullopt;  // constant velocity
    const auto now = pt.wall_state(i, t);
    return m.acceleration(m.frame(t), now.x, now.n, pt.wall_depth[i], now.v);
  }

 private:
  std::array<double, D> g_;
  double ramp_;
  std::function<double(double)> rho_of_p_;
  std::vector<std::uint8_t> mask_;
};

}  // namespace sphmol
