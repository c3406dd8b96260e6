#pragma once
// The shock tube of Niedoba 2012, §3 against the exact Riemann solution (Toro): L1 errors of rho, u, p, e
// over all fluid particles and over the mid-line particles (|y - W/2| < dx; with y periodic every row is
// a mid-line, with walls the rows next to them differ), wave positions detected on the x-binned SPH profile, and a CSV of the binned profile with the exact
// solution at each output time.
#include <array>
#include <memory>
#include <optional>

#include "sphmol/reference/exact_riemann.hpp"
#include "sphmol/run/case.hpp"

namespace sphmol {

// One x-bin of the SPH profile (bin width = the particle spacing), averaged over its particles.
struct ShockTubeBin {
  double x, rho, u, p, e;
};

// The waves of the exact solution (Toro 2009, §4.2): on each side a shock (p* above that side's
// pressure), a rarefaction (below) or none (equal), and the contact between them. detect_waves reads
// each wave the exact solution has off a binned profile by a threshold crossing (linear interpolation
// between bin centres), the outermost crossing on its side; u_s, rho_s are the side's initial state
// and u*, rho*_s the star state on that side:
//   rarefaction head: where u passes u_s + 5 % of (u* - u_s); tail: u_s + 95 % of (u* - u_s);
//   shock:            where rho passes (rho*_s + rho_s)/2, the middle of the density jump (like the contact);
//   shock_velocity:   where u passes (u* + u_s)/2, reported beside it. A shock smeared over a width w
//                     reads ahead by a fraction of w here: across a steady shock of speed S the mass flux
//                     gives u - u_s = S (1 - rho_s / rho) (Rankine-Hugoniot), so u passes halfway where rho
//                     has risen only (rho - rho_s) / (rho*_s - rho_s) = 0.32 of the jump in Sod's tube, not
//                     half of it. The density crossing has no such bias;
//   contact:          between the two waves' inner edges, where rho passes (rho*_L + rho*_R)/2, the
//                     crossing nearest the lighter side.
// The right wave is read as the left one on the mirrored profile (x -> -x, u -> -u), so a mirrored
// problem gives mirrored positions. The summary reports each with its offset from the exact profile's
// crossing, in spacings of the denser side and in local particle spacings (the x spacing of the gas at
// the wave, see local_spacing). NaN when a crossing is not found or the wave does not exist.
enum class ShockTubeWaveKind { none, shock, rarefaction };
struct ShockTubeSideWave {
  ShockTubeWaveKind kind = ShockTubeWaveKind::none;
  double head, tail;      // rarefaction: outer and inner edge; shock: both the density crossing
  double shock_velocity;  // shock: the velocity crossing
};
struct ShockTubeWaves {
  ShockTubeSideWave left, right;
  double contact;
};
// The kind of the left (side 0) or right (side 1) wave of the exact solution.
ShockTubeWaveKind shock_tube_wave_kind(const ExactRiemannSolver& exact, int side);
ShockTubeWaves detect_waves(const std::vector<ShockTubeBin>& bins, const ExactRiemannSolver& exact);

template <int D>
class ShockTubeCase final : public Case<D> {
 public:
  std::unique_ptr<SphSystem<D>> build(const Config& config) override;
  std::string reference() const override { return "exact Riemann solution (Toro ch. 4)"; }
  // From pieces (run/piece_reduction.hpp): over ranks without gathering the whole state; the mid-line
  // file's rows are gathered on rank 0 when the run writes files.
  bool measures_pieces() const override { return true; }
  nlohmann::json measure_pieces(const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t, const OutputSink& out) override;
  void annotate(nlohmann::json& summary) const override;
  std::vector<PlotScript> plots(const OutputSink& out) const override;
  // Studies compare integrators on the density error: rho carries every wave (shock, contact, fan).
  std::string primary_error() const override { return "L1_rho"; }

 private:
  std::optional<ExactRiemannSolver> exact_;
  double gamma_ = 1.4, spacing_ = 0.0, length_ = 0.0, width_ = 0.0;
  std::string boundary_, setup_;
  double smoothing_ = 0.0, mass_left_ = 0.0, mass_right_ = 0.0;  // masses: of the particles next to the tube ends
  std::size_t fluid_left_ = 0, fluid_right_ = 0;
  std::array<int, 2> side_rows_{1, 1};
  // The x distance between neighbouring particles of one side at density rho: they keep their mass
  // and (the flow being planar) their row spacing, so it is m / (rho dy), in 1D m / rho.
  double local_spacing(int side, double rho) const;
  int wall_layers_ = 0;
  bool profiles_ = true;
};

}  // namespace sphmol
