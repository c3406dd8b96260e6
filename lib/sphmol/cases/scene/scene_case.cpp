#include "sphmol/cases/scene/scene_case.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "sphmol/cases/scene/scene_settings.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "sphmol/run/conservation.hpp"
#include "sphmol/scene/scene_builder.hpp"

namespace sphmol {

template <int D>
std::unique_ptr<SphSystem<D>> SceneCase<D>::build(const Config& config) {
  return build_share(config, SceneShare{});
}

template <int D>
std::unique_ptr<SphSystem<D>> SceneCase<D>::build_share(const Config& config, SceneShare share) {
  BuiltScene<D> s = build_scene<D>(config.settings<SceneSettings>().spec, config, share);
  spacing_ = s.spacing;
  velocity_scale_ = s.velocity_scale;
  // A mirror plane moving along itself drives the fluid as a moving wall body does.
  for (const auto& p : s.ghost_planes) velocity_scale_ = std::max(velocity_scale_, p.speed());
  free_surface_ = s.open_faces || !s.fills_domain;
  body_names_ = s.body_names;
  fluid_counts_ = s.fluid_counts;
  n_wall_ = s.whole_size - s.whole_fluid;
  body_treatments_.clear();
  for (const WallTreatment t : s.particles.body_treatment)
    body_treatments_.push_back(t == WallTreatment::rest           ? "rest"
                               : t == WallTreatment::extrapolated ? "extrapolated"
                               : t == WallTreatment::dynamic      ? "dynamic"
                               : t == WallTreatment::ghost        ? "ghost"
                                                                  : "repulsive");
  // KE(0) and M from the built state (also on a restart, which rebuilds the scene): the first
  // measurement is at the first output time, not at t = 0.
  ke0_ = s.fluid_kinetic_energy;
  mass0_ = s.fluid_mass;
  auto sys = assemble_system<D>(config, std::move(s.particles), s.domain, s.spacing, s.ghost ? &s.walls : nullptr, {},
                                s.ghost_planes);
  if (share.count > 1) sys->set_whole_scene({s.first, s.whole_size, s.whole_fluid});
  return sys;
}

template <int D>
nlohmann::json SceneCase<D>::measure_pieces(const SphSystem<D>&, const OwnedPiece<D>& piece, double t, const OutputSink&) {
  const FluidTotals<D> f = fluid_totals(piece);  // exact sums over the ranks (run/conservation.hpp)
  const auto& p = f.momentum;
  const double ke = f.kinetic, mass = f.mass, vmax = f.max_speed;
  // Relative to M U^2 / 2; with no velocity scale (at rest, no body force), to the initial energy
  // or, if that is zero too, absolute [J].
  const double scale = velocity_scale_ > 0.0 ? 0.5 * mass0_ * velocity_scale_ * velocity_scale_ : (ke0_ > 0.0 ? ke0_ : 1.0);
  return {{"t", t},
          {"kinetic_energy", ke},
          {"kinetic_energy_change", std::abs(ke - ke0_) / scale},
          {"momentum", std::vector<double>(p.begin(), p.end())},
          {"max_speed", vmax},
          {"max_speed_ratio", velocity_scale_ > 0.0 ? vmax / velocity_scale_ : vmax},
          {"fluid_mass", mass}};
}

// Worst over the output times: a scene must stay conservative throughout, not only at the end.
template <int D>
nlohmann::json SceneCase<D>::final_errors(const nlohmann::json& errors) const {
  if (errors.empty()) return nlohmann::json::object();
  nlohmann::json f = errors.back();
  f.erase("t");
  double worst = 0.0, speed = 0.0;
  for (const auto& e : errors) {
    worst = std::max(worst, e["kinetic_energy_change"].get<double>());
    speed = std::max(speed, e["max_speed_ratio"].get<double>());
  }
  f["kinetic_energy_change"] = worst;
  f["max_speed_ratio"] = speed;
  return f;
}

template <int D>
void SceneCase<D>::annotate(nlohmann::json& summary) const {
  summary["final_errors_note"] =
      "kinetic_energy_change: worst over the output times of |KE(t) - KE(0)| / (M U^2 / 2), U = velocity_scale "
      "(with U = 0: relative to KE(0), or in J if that is 0 too); max_speed_ratio: worst largest fluid speed / U";
  summary["scene"]["velocity_scale"] = velocity_scale_;
  summary["scene"]["free_surface"] = free_surface_;
  summary["scene"]["fluid_particles"] = fluid_counts_;
  summary["scene"]["wall_particles"] = n_wall_;
  summary["scene"]["wall_bodies"] = body_names_;
  summary["scene"]["wall_treatments"] = body_treatments_;  // resolved: the body's own, or wall_pressure
  summary["discretization"]["spacing"] = spacing_;
}

template class SceneCase<2>;
template class SceneCase<3>;

}  // namespace sphmol
