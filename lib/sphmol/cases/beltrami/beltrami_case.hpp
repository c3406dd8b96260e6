#pragma once
// The decaying Arnold-Beltrami-Childress flow in the periodic cube [0, L]^3 (reference/abc_flow.hpp).
// Particles fill the cubic lattice; velocities start from the exact field and the pressure
// p = -rho0 |u|^2 / 2 (p0 = 0) is put in through the densities the EOS returns it from: the particle
// masses are scaled by rho(p)/rho0 (summation density then gives rho(p)) and the initial densities are
// rho(p) (continuity density starts from them).
// Errors at each output time, relative to U(t) = sqrt(A^2 + B^2 + C^2) e^{-nu k^2 t} (the exact rms speed):
//   L1_velocity = mean_i |v_i - v_exact(x_i, t)| / U(t),
//   mode_amplitude_rel_error of the ABC mode's amplitude a(t) (the mass-weighted least-squares projection
//   of the particle velocities on the mode shape at the particles' positions, 1 at t = 0).
// final_errors adds decay_rate = -(least-squares slope of ln a(t) over the output times) against
// decay_rate_exact = nu k^2, and decay_rate_rel_error.
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/reference/abc_flow.hpp"
#include "sphmol/run/case.hpp"

namespace sphmol {

class BeltramiCase final : public Case<3> {
 public:
  std::unique_ptr<SphSystem<3>> build(const Config& config) override;
  std::string reference() const override { return "abc_flow (decaying Arnold-Beltrami-Childress flow, exact)"; }
  // sqrt(A^2 + B^2 + C^2) from the config's amplitudes (also before the scene is built).
  double velocity_scale(const Config& config) const override;
  // From pieces (run/piece_reduction.hpp): over ranks without gathering the whole state.
  bool measures_pieces() const override { return true; }
  nlohmann::json measure_pieces(const SphSystem<3>& whole, const OwnedPiece<3>& piece, double t, const OutputSink& out) override;
  nlohmann::json final_errors(const nlohmann::json& errors) const override;
  std::string primary_error() const override { return "L1_velocity"; }
  void annotate(nlohmann::json& summary) const override;
  std::vector<PlotScript> plots(const OutputSink& out) const override;
  // The series so far (run/case_state.hpp), so that a restart writes all of its rows and fits over them.
  nlohmann::json save_state() const override;
  void restore_state(const nlohmann::json& state) override;

 private:
  double scale() const { return std::sqrt(ref_.A * ref_.A + ref_.B * ref_.B + ref_.C * ref_.C); }
  AbcFlow ref_;
  double spacing_ = 0.0;
  std::vector<double> t_, mode_;
};

}  // namespace sphmol
