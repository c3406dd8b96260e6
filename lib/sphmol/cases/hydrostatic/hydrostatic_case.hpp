#pragma once
// Water column at rest in a tank (Potapov & Reshetnikova 2021, §5), in 2D or 3D: fluid [0, width] x
// [0, depth] (3D: [0, width] x [0, breadth] x [0, depth]) starting at uniform density, walls on every
// side and below (the side walls reach 1.2 x depth), open top, gravity along the last axis ramped in
// (fluid.body_force_ramp). Reference p = rho0 g (depth - z), z the last coordinate. At output times
// t >= settle time (2 x body_force_ramp), over fluid particles:
//   p_rms, p_max = RMS / max of (p_i - rho0 g (depth - z_i)) / (rho0 g depth);
// max_drift = largest displacement of any fluid particle from its start, over every RHS evaluation of
// the whole run (analysis/drift_monitor.hpp), in particle spacings.
// p_i is the pressure of the RHS evaluation that ended the last step (within one step of t).
#include <cmath>
#include <memory>

#include "sphmol/run/case.hpp"

namespace sphmol {

template <int D>
class HydrostaticCase final : public Case<D> {
 public:
  std::unique_ptr<SphSystem<D>> build(const Config& config) override;
  std::string reference() const override {
    return D == 3 ? "hydrostatic p = rho0 g (depth - z)" : "hydrostatic p = rho0 g (depth - y)";
  }
  // The free-fall speed sqrt(2 g H) of the column.
  double velocity_scale(const Config&) const override { return std::sqrt(2.0 * g_ * depth_); }
  bool free_surface() const override { return true; }
  // From pieces (run/piece_reduction.hpp): over ranks without gathering the whole state; the pressure
  // file's rows (one per fluid particle) are gathered on rank 0 when the run writes files.
  bool measures_pieces() const override { return true; }
  nlohmann::json measure_pieces(const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t, const OutputSink& out) override;
  nlohmann::json final_errors(const nlohmann::json& errors) const override;
  std::string primary_error() const override { return "p_rms"; }
  void annotate(nlohmann::json& summary) const override;
  std::vector<PlotScript> plots(const OutputSink& out) const override;
  // max_drift is over the whole run: carried through checkpoints (run/case_state.hpp).
  nlohmann::json save_state() const override;
  void restore_state(const nlohmann::json& state) override;

 private:
  double rho0_ = 0.0, g_ = 0.0, depth_ = 0.0, spacing_ = 0.0, settle_ = 0.0;
  bool profiles_ = true;  // output.profiles: pressure_t<t>.csv
  std::shared_ptr<double> drift_ = std::make_shared<double>(0.0);
};

}  // namespace sphmol
