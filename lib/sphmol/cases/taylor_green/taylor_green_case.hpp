#pragma once
// Decaying Taylor-Green vortex on a periodic square (reference/taylor_green.hpp). Velocities start from
// the exact field; the initial pressure is put in through the particle masses: m_i = m_lattice (1 + p_i /
// (c^2 rho0)), so that summation density gives rho ~ rho0 + p/c^2 and the gauge EOS p = c^2 (rho - rho0)
// returns the exact pressure (up to kernel smoothing). Errors, normalised by the exact amplitude U e^{bt}:
//   L1_velocity = mean_i |v_i - v_exact(x_i, t)| / (U e^{bt}),  maxv_rel_error = |max_i |v_i| - U e^{bt}| / (U e^{bt}),
// mode_amplitude_rel_error of the vortex mode's amplitude (the mass-weighted projection of the velocities on
// the mode shape), and decay_rate = least-squares slope of ln(mode amplitude) over the output times, against
// b = -8 pi^2 nu / L^2 (decay_rate_maxv: the same fit of ln max_i |v_i|), both over the output times at
// which U e^{bt} >= kFitFloor U (decay_fit_until: the last of them). L1_velocity_per_U is L1_velocity
// normalised by U instead of U e^{bt}: the measure that stays meaningful once the vortex has decayed
// below the particle noise (at Re 10, U e^{bt} is 7e-18 U at t = 5 s).
#include "sphmol/cases/taylor_green/taylor_green_settings.hpp"
#include <vector>

#include "sphmol/reference/taylor_green.hpp"
#include "sphmol/run/case.hpp"

namespace sphmol {

class TaylorGreenCase final : public Case<2> {
 public:
  static constexpr double kFitFloor = 0.01;  // decay fits use the times with U e^{bt} >= 1 % of U
  std::unique_ptr<SphSystem<2>> build(const Config& config) override;
  std::string reference() const override { return "taylor_green_vortex (exact)"; }
  double velocity_scale(const Config& config) const override { return config.settings<TaylorGreenSettings>().velocity_amplitude; }
  // From pieces (run/piece_reduction.hpp): over ranks without gathering the whole state.
  bool measures_pieces() const override { return true; }
  nlohmann::json measure_pieces(const SphSystem<2>& whole, const OwnedPiece<2>& piece, double t, const OutputSink& out) override;
  nlohmann::json final_errors(const nlohmann::json& errors) const override;
  std::string primary_error() const override { return "L1_velocity"; }
  void annotate(nlohmann::json& summary) const override;
  // decay.png: max|v| of the particles at the output times against U e^{bt} (log scale).
  std::vector<PlotScript> plots(const OutputSink& out) const override;
  // The series so far (run/case_state.hpp), so that a restart writes all of its rows and fits over them.
  nlohmann::json save_state() const override;
  void restore_state(const nlohmann::json& state) override;

 private:
  TaylorGreenVortex ref_;
  double L_ = 1.0, spacing_ = 0.0;
  std::vector<double> t_, vmax_, mode_;
};

}  // namespace sphmol
