#pragma once
// Body-force-driven laminar flow in a rectangular duct |y| < a, |z| < b, periodic in x, started from
// rest (reference/duct_series.hpp). The fluid fills the cubic lattice of the box [0, Lx] x [-a, a] x
// [-b, b]; wall particles continue the lattice beyond the four side faces (the x faces are open: the
// duct is periodic there), enough layers to fill the kernel support. fluid.body_force = [g, 0, 0]
// drives the flow (g < 0: along -x). Errors at each output time, over the fluid particles, against the
// start-up series at the particles' positions and relative to the steady centre speed |u_max|:
//   e_rms = sqrt(mean_i (u_i - u_exact)^2) / |u_max|,  e_max = max_i |u_i - u_exact| / |u_max|,
//   e_cross = max_i sqrt(v_i^2 + w_i^2) / |u_max| (the exact flow has none).
// peak.csv: u_x of the fastest particle along the flow and of the exact speed's fastest value over the
// particles, per output.
// profile_t<t>.csv (output.profiles): u across the duct, y from wall to wall, over the fluid particles
// of the two lattice rows beside the mid-plane z = 0, with the series at the same points.
// Plots: peak.png (peak speeds against time) and profiles.png (the profiles at the output times).
#include <memory>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/reference/duct_series.hpp"
#include "sphmol/run/case.hpp"

namespace sphmol {

class DuctCase final : public Case<3> {
 public:
  std::unique_ptr<SphSystem<3>> build(const Config& config) override;
  std::string reference() const override {
    return std::string("duct_series (rectangular-duct start-up, Fourier series)") +
           (ramp_ > 0.0 ? " of the body force ramped in over fluid.body_force_ramp (Duhamel's principle)" : "");
  }
  // |u_max|, the steady centre speed of the series, from the config alone (also before the scene is built).
  double velocity_scale(const Config& config) const override;
  // From pieces (run/piece_reduction.hpp): over ranks without gathering the whole state.
  bool measures_pieces() const override { return true; }
  nlohmann::json measure_pieces(const SphSystem<3>& whole, const OwnedPiece<3>& piece, double t, const OutputSink& out) override;
  void annotate(nlohmann::json& summary) const override;
  std::vector<PlotScript> plots(const OutputSink& out) const override;
  // The peak series so far (run/case_state.hpp), so that a restart writes all of its rows.
  nlohmann::json save_state() const override;
  void restore_state(const nlohmann::json& state) override;

 private:
  DuctSeries ref_{1.0, 1.0, 1.0, 0.0};
  double ramp_ = 0.0;  // fluid.body_force_ramp [s]
  // The start-up series at (y, z, t), with the force ramped in over ramp_ (reference/ramped_start.hpp).
  double exact(double y, double z, double t) const;
  double length_ = 0.0, spacing_ = 0.0;
  bool profiles_ = true;
  std::vector<double> t_, peak_sph_, peak_exact_;
};

}  // namespace sphmol
