#pragma once
// Dam break: a water column of width a and height H collapses into an open tank of width Lx
// (scenes/dam_break_scene.hpp). Measured at output times, over fluid particles:
//   x_front     surge-front position: the largest x of any fluid particle plus dx/2 (the edge of its
//               lattice cell, so x_front(0) = a);
//   x_ritter    a + 2 sqrt(g H) t, Ritter's shallow-water front, an upper bound before the impact;
//   x_mm, x_ko  Martin & Moyce 1952 (n^2 = 2) and Koshizuka & Oka 1996 fronts scaled to a, where their
//               data cover t (reference/dam_break_front.hpp); both experiments have H = 2a, so for
//               another column they are not compared (null, empty cells in front.csv);
//   mass_change relative change of the total fluid mass, sum_i m_i (constant particle masses and no
//               particle ever removed: exactly 0 unless a particle is lost);
//   wall_penetrations  fluid particles that ever passed a wall (every RHS evaluation; analysis/
//               wall_penetration_monitor.hpp), min_wall_gap the closest approach to a wall surface [dx].
// A front at the right wall (x_front >= Lx - dx) is "impacted": later times are not compared with the
// free-surge references. Writes front.csv (all output times so far) and the reference points.
#include <cmath>
#include <memory>

#include "sphmol/analysis/wall_penetration_monitor.hpp"
#include "sphmol/run/case.hpp"

namespace sphmol {

class DamBreakCase final : public Case<2> {
 public:
  std::unique_ptr<SphSystem<2>> build(const Config& config) override;
  std::string reference() const override {
    return "surge front vs Ritter 2 sqrt(gH) t (upper bound), Martin & Moyce 1952, Koshizuka & Oka 1996";
  }
  // The free-fall speed sqrt(2 g H) of the column.
  double velocity_scale(const Config&) const override { return std::sqrt(2.0 * g_ * H_); }
  bool free_surface() const override { return true; }
  // From pieces (run/piece_reduction.hpp): over ranks without gathering the whole state.
  bool measures_pieces() const override { return true; }
  nlohmann::json measure_pieces(const SphSystem<2>& whole, const OwnedPiece<2>& piece, double t, const OutputSink& out) override;
  nlohmann::json final_errors(const nlohmann::json& errors) const override;
  // Without the experiments (a column other than H = 2a) the studies compare the final front
  // position with a reference run.
  std::string primary_error() const override { return experiments_ ? "front_rms_martin_moyce" : "x_front"; }
  bool has_exact_reference() const override { return experiments_; }
  void annotate(nlohmann::json& summary) const override;
  std::vector<PlotScript> plots(const OutputSink& out) const override;
  // front.csv's rows so far and the wall penetrations of the whole run (run/case_state.hpp).
  nlohmann::json save_state() const override;
  void restore_state(const nlohmann::json& state) override;

 private:
  double a_ = 0.0, H_ = 0.0, Lx_ = 0.0, t_end_ = 0.0, g_ = 0.0, dx_ = 0.0, mass0_ = 0.0;
  std::size_t n_fluid0_ = 0, n_wall_ = 0;
  int wall_layers_ = 0;
  bool experiments_ = true;  // H = 2a: the experiments' fronts apply
  std::string csv_;  // front.csv rows so far
  std::shared_ptr<WallPenetration> penetration_ = std::make_shared<WallPenetration>();
};

}  // namespace sphmol
