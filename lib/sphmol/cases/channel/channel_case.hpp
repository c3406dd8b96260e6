#pragma once
// Couette and Poiseuille start-up flows (Vukčević et al. 2012, §4): the channel scene, the series reference and
// the e_rms / e_max error of u / |v0| over fluid particles, with a profile CSV per output time.
#include "sphmol/run/case.hpp"
#include "sphmol/cases/channel/channel_reference.hpp"

namespace sphmol {

class ChannelCase final : public Case<2> {
 public:
  std::unique_ptr<SphSystem<2>> build(const Config& config) override;
  std::string reference() const override { return ref_.name; }
  // Couette: the plate speed; Poiseuille: the centre-line speed F l^2 / (8 nu) of the steady profile.
  double velocity_scale(const Config& config) const override;
  // From pieces (run/piece_reduction.hpp): over ranks without gathering the whole state; the profile
  // file's rows (one per fluid particle) are gathered on rank 0 when the run writes files.
  bool measures_pieces() const override { return true; }
  nlohmann::json measure_pieces(const SphSystem<2>& whole, const OwnedPiece<2>& piece, double t, const OutputSink& out) override;
  void annotate(nlohmann::json& summary) const override;
  // profiles.png: SPH velocity (points) and the exact series (lines) across the channel at every
  // output time, from the profile CSVs in the output directory (also those of an earlier run that a
  // restart continued).
  std::vector<PlotScript> plots(const OutputSink& out) const override;

 private:
  ChannelReference ref_;
  bool profiles_ = true;
  int wall_layers_ = 0;
  double spacing_ = 0.0;
  double height_ = 0.0;  // channel height l: fluid particles outside [0, l] are inside a wall
};

}  // namespace sphmol
