// A rank's share of a user scene as a system (Case::build_share, SphSystem::set_whole_scene): the
// share's own state is the whole state's rows of its particles, it reports the whole scene's counts
// and layout, and after release_particles() it stands for the whole scene as a released whole
// system does; its starting particles (run/start_piece.hpp) carry their global ids, and the force
// probes' walls gathered from the shares are the whole scene's body walls to the bit.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "sphmol/cases/case_module.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/probes/wall_force.hpp"
#include "sphmol/run/start_piece.hpp"

using namespace sphmol;

namespace {

// Two liquids over a dynamic floor (wall densities in the state) with a moving paddle and a block.
Config scene() {
  return load_config_string(R"yaml(case: scene
dimension: 2
fluid:
  density: 1000.0
  kinematic_viscosity: 1.0e-6
  eos: {type: tait, sound_speed: 20.0, gamma: 7.0}
  body_force: [0.0, -9.81]
scene:
  domain: {lo: [0, 0], hi: [0.6, 0.4], boundaries: [wall, wall]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [0.6, 0.1]}
      pressure: hydrostatic
    - shape: {type: box, lo: [0, 0.1], hi: [0.3, 0.2]}
      density: 800
      kinematic_viscosity: 1.0e-4
      pressure: hydrostatic
      velocity: ["0.1", "0"]
  walls:
    - name: block
      shape: {type: box, lo: [0.4, 0.0], hi: [0.44, 0.06]}
    - name: paddle
      shape: {type: box, lo: [0.5, 0.1], hi: [0.52, 0.2]}
      motion: {type: oscillation, amplitude: [0.01, 0], frequency: 2}
discretization:
  spacing: 0.01
  kernel: wendland_c2
  smoothing_ratio: 1.5
  density: continuity
  wall_pressure: dynamic
time: {t_end: 0.01, integrator: leapfrog}
output: {times: [0.01], plots: false}
)yaml");
}

std::unique_ptr<SphSystem<2>> share_of_scene(const Config& c, std::size_t k, std::size_t count) {
  auto kase = make_case<2>(c);
  REQUIRE(kase->builds_shares());
  return kase->build_share(c, {k, count});
}

}  // namespace

TEST_CASE("a share of a user scene: its state, the whole scene's counts and layout, released as whole", "[scene][shares]") {
  const Config c = scene();
  auto whole = make_case<2>(c)->build(c);
  REQUIRE_FALSE(whole->is_share());
  const std::vector<double> y = whole->initial_state();
  const StateLayout<2> W = whole->layout();
  REQUIRE(W.n_wall_density > 0);
  const std::size_t n = whole->base_particles();
  for (const std::size_t count : {2u, 3u}) {
    for (std::size_t k = 0; k < count; ++k) {
      INFO("share " << k << " of " << count);
      auto s = share_of_scene(c, k, count);
      REQUIRE(s->is_share());
      const auto ws = s->whole_scene();
      CHECK(ws.first == n * k / count);
      CHECK(ws.size == n);
      CHECK(ws.fluid == W.n);
      CHECK(s->base_particles() == n * (k + 1) / count - n * k / count);
      CHECK(s->whole_layout().size() == W.size());
      CHECK(s->whole_layout().n_wall_density == W.n_wall_density);
      // The share's own state is the whole state's rows of its particles.
      CHECK(s->share_of(y) == s->initial_state());
      CHECK_THROWS_AS(s->share_of(s->initial_state()), std::invalid_argument);
      // Its starting particles, with their global ids; the same rows of the whole system.
      const std::vector<double> ys = s->initial_state();
      const OwnedPiece<2> mine = start_piece(*s, ys.data(), {k, count}, one_rank_collectives());
      const OwnedPiece<2> of_whole = start_piece(*whole, y.data(), {k, count}, one_rank_collectives());
      CHECK(mine.fluid_ids == of_whole.fluid_ids);
      CHECK(mine.wall_ids == of_whole.wall_ids);
      CHECK(mine.fluid_rows.size() + mine.wall_rows.size() == s->base_particles());
      CHECK_THROWS_AS(start_piece(*s, ys.data(), {(k + 1) % count, count}, one_rank_collectives()), std::logic_error);
      // A fluid particle taken out before the release keeps its global id afterwards.
      if (s->layout().n > 0) s->retire({0});
      s->release_particles();
      CHECK_FALSE(s->is_share());
      CHECK(s->layout().n == W.n);
      CHECK(s->layout().size() == W.size());
      CHECK(s->base_particles() == n);
      if (!s->retired().empty()) CHECK(s->retired() == std::vector<std::size_t>{ws.first});
    }
  }
}

TEST_CASE("a share of a user scene: set_whole_scene refuses particles that are not a share", "[scene][shares]") {
  const Config c = scene();
  // The share that holds the last fluid particles and the first walls.
  std::unique_ptr<SphSystem<2>> s;
  for (std::size_t k = 0; k < 3 && !s; ++k) {
    auto t = share_of_scene(c, k, 3);
    if (t->layout().n > 0 && t->layout().n < t->base_particles()) s = std::move(t);
  }
  REQUIRE(s);
  const auto ws = s->whole_scene();
  // Shifted by one: its fluid would not end where the scene's does.
  CHECK_THROWS_AS(s->set_whole_scene({ws.first + 1, ws.size + 1, ws.fluid}), std::invalid_argument);
  CHECK_THROWS_AS(s->set_whole_scene({ws.first, ws.size, ws.fluid + 1}), std::invalid_argument);
  // Past the scene's end.
  CHECK_THROWS_AS(s->set_whole_scene({ws.first, ws.first + s->base_particles() - 1, ws.fluid}), std::invalid_argument);
  CHECK_NOTHROW(s->set_whole_scene(ws));
}

TEST_CASE("the force probes' walls gathered from the shares are the whole scene's body walls", "[scene][shares][probes]") {
  const Config c = scene();
  auto whole = make_case<2>(c)->build(c);
  const std::vector<double> y = whole->initial_state();
  for (const int body : {0, 1}) {
    const BodyWalls<2> ref = body_walls<2>(whole->particles(), body);
    REQUIRE(ref.ids.size() > 10);
    const std::size_t count = 3;
    // What each share sends (the gather returning its own bytes), then all of them joined.
    std::vector<std::byte> joined;
    std::vector<std::unique_ptr<SphSystem<2>>> shares;
    std::vector<std::vector<double>> states;
    for (std::size_t k = 0; k < count; ++k) {
      shares.push_back(share_of_scene(c, k, count));
      states.push_back(shares.back()->initial_state());
      PieceCollectives own = one_rank_collectives();
      own.all_gather_bytes = [&](const std::vector<std::byte>& b) {
        joined.insert(joined.end(), b.begin(), b.end());
        return b;
      };
      gather_body_walls<2>(start_piece(*shares.back(), states.back().data(), {k, count}, own), body);
    }
    PieceCollectives all = one_rank_collectives();
    all.all_gather_bytes = [&](const std::vector<std::byte>&) { return joined; };
    const BodyWalls<2> got = gather_body_walls<2>(start_piece(*shares[1], states[1].data(), {1, count}, all), body);
    CHECK(got.body == body);
    CHECK(got.ids == ref.ids);
    CHECK(got.walls.n_fluid == 0);
    for (int d = 0; d < 2; ++d) {
      CHECK(got.walls.x[d] == ref.walls.x[d]);
      CHECK(got.walls.x_ref[d] == ref.walls.x_ref[d]);
      CHECK(got.walls.wall_normal[d] == ref.walls.wall_normal[d]);
    }
    CHECK(got.walls.mass == ref.walls.mass);
    CHECK(got.walls.rho == ref.walls.rho);
    CHECK(got.walls.body == ref.walls.body);
    CHECK(got.walls.motion == ref.walls.motion);
    CHECK(got.walls.motions.size() == ref.walls.motions.size());
    // One rank: the whole scene's walls themselves.
    const BodyWalls<2> one = gather_body_walls<2>(start_piece(*whole, y.data(), {}, one_rank_collectives()), body);
    CHECK(one.ids == ref.ids);
    CHECK(one.walls.x[0] == ref.walls.x[0]);
  }
}
