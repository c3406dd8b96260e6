#pragma once
// The `scene` case: a user scene (config `scene:` section) with no reference solution. It reports
// what the flow must conserve: at every output time the fluid mass, momentum, kinetic energy and
// largest speed; its primary error is the change of the kinetic energy since t = 0 relative to
// M U^2 / 2 (M the fluid mass, U the scene's velocity scale), which for a fluid at rest measures the
// spurious currents.
#include <memory>
#include <string>
#include <vector>

#include "sphmol/run/case.hpp"
#include "sphmol/scene/scene_spec.hpp"
#include "sphmol/scene/scene_velocity_scale.hpp"

namespace sphmol {

template <int D>
class SceneCase final : public Case<D> {
 public:
  std::unique_ptr<SphSystem<D>> build(const Config& config) override;
  bool builds_shares() const override { return true; }
  std::unique_ptr<SphSystem<D>> build_share(const Config& config, SceneShare share) override;
  std::string reference() const override { return "none (conservation of mass, momentum and kinetic energy)"; }
  // From pieces (run/piece_reduction.hpp): over ranks without gathering the whole state.
  bool measures_pieces() const override { return true; }
  nlohmann::json measure_pieces(const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t, const OutputSink& out) override;
  nlohmann::json final_errors(const nlohmann::json& errors) const override;
  std::string primary_error() const override { return "kinetic_energy_change"; }
  // A user scene has no exact solution: the studies compare its kinetic-energy change with a
  // finer run (Case::has_exact_reference).
  bool has_exact_reference() const override { return false; }
  double velocity_scale(const Config& config) const override { return velocity_scale_; }
  bool free_surface() const override { return free_surface_; }
  void annotate(nlohmann::json& summary) const override;

 private:
  double velocity_scale_ = 0.0;
  bool free_surface_ = false;
  double spacing_ = 0.0;
  double ke0_ = 0.0, mass0_ = 0.0;  // fluid kinetic energy and mass at t = 0
  std::vector<std::string> body_names_;
  std::vector<std::string> body_treatments_;  // per wall body, as resolved by the builder
  std::vector<std::size_t> fluid_counts_;
  std::size_t n_wall_ = 0;
};

}  // namespace sphmol
