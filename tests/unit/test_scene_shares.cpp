// The scene builder's shares (SceneShare): each build goes through the whole scene and keeps the
// particles of its share of the global indices. Built in 1, 2, 3 and 7 shares, the shares laid end
// to end are the whole build's particles, every column to the bit, and every build reports the
// whole scene's counts, velocity scale, fluid mass and kinetic energy, as the whole build does;
// the whole build's summaries equal sums and extremes taken over its particles afterwards.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "scene_test_support.hpp"
#include "sphmol/scene/scene_velocity_scale.hpp"

using namespace sphmol;
using scene_test::config;
using scene_test::read;

namespace {

template <int D>
void append(Particles<D>& to, const Particles<D>& from) {
  for (int d = 0; d < D; ++d) {
    to.x[d].insert(to.x[d].end(), from.x[d].begin(), from.x[d].end());
    to.v[d].insert(to.v[d].end(), from.v[d].begin(), from.v[d].end());
    to.x_ref[d].insert(to.x_ref[d].end(), from.x_ref[d].begin(), from.x_ref[d].end());
    to.wall_normal[d].insert(to.wall_normal[d].end(), from.wall_normal[d].begin(), from.wall_normal[d].end());
  }
  to.mass.insert(to.mass.end(), from.mass.begin(), from.mass.end());
  to.rho.insert(to.rho.end(), from.rho.begin(), from.rho.end());
  to.kind.insert(to.kind.end(), from.kind.begin(), from.kind.end());
  to.wall_depth.insert(to.wall_depth.end(), from.wall_depth.begin(), from.wall_depth.end());
  to.stationary.insert(to.stationary.end(), from.stationary.begin(), from.stationary.end());
  to.body.insert(to.body.end(), from.body.begin(), from.body.end());
  to.motion.insert(to.motion.end(), from.motion.begin(), from.motion.end());
  to.rest_density.insert(to.rest_density.end(), from.rest_density.begin(), from.rest_density.end());
  to.viscosity.insert(to.viscosity.end(), from.viscosity.begin(), from.viscosity.end());
  to.n_fluid += from.n_fluid;
}

template <int D>
void check_shares(const std::string& yaml, const Config& c) {
  const SceneSpec spec = read(yaml, D);
  const BuiltScene<D> whole = build_scene<D>(spec, c);
  const Particles<D>& W = whole.particles;
  REQUIRE(whole.first == 0);
  REQUIRE(whole.whole_size == W.size());
  REQUIRE(whole.whole_fluid == W.n_fluid);
  REQUIRE(W.size() > 100);
  // The whole build's summaries against its particles.
  CHECK(whole.velocity_scale == scene_velocity_scale<D>(W, c.fluid.body_force, whole.spacing));
  double mass = 0.0, ke = 0.0;
  for (std::size_t i = 0; i < W.n_fluid; ++i) {
    double v2 = 0.0;
    for (int d = 0; d < D; ++d) v2 += W.v[d][i] * W.v[d][i];
    ke += 0.5 * W.mass[i] * v2;
    mass += W.mass[i];
  }
  CHECK(whole.fluid_mass == mass);
  CHECK(whole.fluid_kinetic_energy == ke);
  for (const std::size_t count : {1u, 2u, 3u, 7u}) {
    INFO("shares: " << count);
    Particles<D> joined;
    for (std::size_t k = 0; k < count; ++k) {
      const BuiltScene<D> s = build_scene<D>(spec, c, {k, count});
      CHECK(s.first == joined.size());
      CHECK(s.first == W.size() * k / count);
      CHECK(s.whole_size == whole.whole_size);
      CHECK(s.whole_fluid == whole.whole_fluid);
      CHECK(s.fluid_counts == whole.fluid_counts);
      CHECK(s.velocity_scale == whole.velocity_scale);
      CHECK(s.fluid_mass == whole.fluid_mass);
      CHECK(s.fluid_kinetic_energy == whole.fluid_kinetic_energy);
      CHECK(s.fills_domain == whole.fills_domain);
      CHECK(s.body_names == whole.body_names);
      CHECK(s.particles.body_treatment == W.body_treatment);
      CHECK(s.particles.free_slip_body == W.free_slip_body);
      CHECK(s.particles.motions.size() == W.motions.size());
      for (std::size_t b = 0; b < W.body_repulsion.size(); ++b) CHECK(s.particles.body_repulsion[b].strength == W.body_repulsion[b].strength);
      for (int d = 0; d < D; ++d) CHECK(s.domain.lo[d] == whole.domain.lo[d]);
      append(joined, s.particles);
    }
    REQUIRE(joined.size() == W.size());
    CHECK(joined.n_fluid == W.n_fluid);
    for (int d = 0; d < D; ++d) {
      CHECK(joined.x[d] == W.x[d]);
      CHECK(joined.v[d] == W.v[d]);
      CHECK(joined.x_ref[d] == W.x_ref[d]);
      CHECK(joined.wall_normal[d] == W.wall_normal[d]);
    }
    CHECK(joined.mass == W.mass);
    CHECK(joined.rho == W.rho);
    CHECK(joined.kind == W.kind);
    CHECK(joined.wall_depth == W.wall_depth);
    CHECK(joined.stationary == W.stationary);
    CHECK(joined.body == W.body);
    CHECK(joined.motion == W.motion);
    CHECK(joined.rest_density == W.rest_density);
    CHECK(joined.viscosity == W.viscosity);
  }
}

}  // namespace

TEST_CASE("scene shares: two liquids, a hexagonal body, seeded displacement, a rotating and a repulsive body (2D)", "[scene][shares]") {
  Config c = config(2, 0.05);
  c.fluid.body_force = {0.0, -9.81};
  c.fluid.eos.type = "tait";
  c.fluid.eos.gamma = 7.0;
  c.discretization.density = "continuity";
  c.discretization.viscosity = "morris";
  c.discretization.position_noise = 0.05;
  check_shares<2>(R"yaml(scene:
  domain: {lo: [0, 0], hi: [2, 1.5], open_faces: [y_hi]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [2, 0.6]}
      pressure: hydrostatic
    - shape: {type: box, lo: [0, 0.6], hi: [1.2, 1.0]}
      lattice: hexagonal
      density: 800
      kinematic_viscosity: 0.001
      pressure: hydrostatic
      velocity: ["0.1 * y", "0"]
  walls:
    - name: stirrer
      shape: {type: sphere, centre: [1.5, 0.3], radius: 0.15}
      motion: {type: rotation, centre: [1.5, 0.3], angular_velocity: 2}
    - name: post
      shape: {type: box, lo: [0.4, 0.0], hi: [0.6, 0.3]}
      treatment: repulsive
)yaml",
                  c);
}

TEST_CASE("scene shares: a 3D tank with an oscillating box and periodic y", "[scene][shares][3d]") {
  Config c = config(3, 0.05);
  c.fluid.body_force = {0.0, 0.0, -9.81};
  check_shares<3>(R"yaml(scene:
  domain: {lo: [0, 0, 0], hi: [1, 0.5, 0.6], boundaries: [wall, periodic, wall]}
  fluid:
    - shape: {type: box, lo: [0, 0, 0], hi: [1, 0.5, 0.4]}
      pressure: hydrostatic
  walls:
    - name: paddle
      shape: {type: box, lo: [0.7, 0.1, 0.1], hi: [0.8, 0.4, 0.5]}
      motion: {type: oscillation, amplitude: [0.02, 0, 0], frequency: 1.5}
)yaml",
                  c);
}

TEST_CASE("scene shares: a share index past the count is refused", "[scene][shares]") {
  const Config c = config(2, 0.1);
  const SceneSpec spec = read(R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 1]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [1, 0.5]}
)yaml",
                              2);
  CHECK_THROWS_AS(build_scene<2>(spec, c, {2, 2}), std::invalid_argument);
  CHECK_THROWS_AS(build_scene<2>(spec, c, {0, 0}), std::invalid_argument);
}
