#pragma once
// Constant background pressure added after the EOS: p <- p + p_b. With the gauge EOS p = c^2 (rho - rho0)
// the pressure is negative in half of a Taylor-Green vortex, and the symmetric gradient (Vukčević
// 2012, eq 117) is then attractive between particles (tensile instability): they clump and the
// vortex decays far too fast (measured: decay rate -2.6 instead of -0.79 1/s by t = 0.3 s at 50 x
// 50). A background pressure a few times the dynamic pressure rho U^2 keeps p > 0 everywhere; p =
// c^2 rho (p_b = c^2 rho0, ~400 rho U^2 at Mach 0.1) is far too much: its spurious force on
// disordered particles dominates.
#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class BackgroundPressure final : public Term<D> {
 public:
  explicit BackgroundPressure(double p_b) : pb_(p_b) {}
  std::string_view name() const override { return "background_pressure"; }
  void apply(Workspace<D>& w) const override {
    for (std::size_t i = 0; i < w.n; ++i) w.p[i] += pb_;
  }

 private:
  double pb_;
};

}  // namespace sphmol
