// SphSystem::release_particles: what a rank other than 0 keeps of the whole scene in a run over
// MPI ranks (the counts, the layout, the domain, the terms), and that reading the released
// particles or evaluating the system is an error rather than a read of freed data.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>
#include <vector>

#include "sphmol/analysis/drift_monitor.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/config/config.hpp"

using namespace sphmol;

TEST_CASE("release_particles keeps the scene's counts, layout and terms and refuses its particles", "[sph_system][release]") {
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml", {"discretization.spacing=0.05"});
  auto sys = make_case<2>(c)->build(c);
  const std::size_t n_fluid = sys->particles().n_fluid, n_wall = sys->particles().n_wall();
  const auto layout = sys->layout();
  const auto terms = sys->active_terms();
  const double h = sys->smoothing_length(), radius = sys->pair_list().list_radius();
  std::vector<double> y = sys->initial_state();

  sys->release_particles();
  CHECK(sys->particles_released());
  CHECK_THROWS_AS(sys->particles(), std::logic_error);
  CHECK_THROWS_AS(sys->is_retired(0), std::logic_error);
  CHECK(sys->layout().n == n_fluid);
  CHECK(sys->base_particles() - sys->layout().n == n_wall);
  CHECK(sys->layout().size() == layout.size());
  CHECK(sys->active_terms() == terms);
  CHECK(sys->smoothing_length() == h);
  CHECK(sys->pair_list().list_radius() == radius);
  CHECK(sys->domain().periodic == make_case<2>(c)->build(c)->domain().periodic);
  // An evaluation would read the freed arrays: refused.
  std::vector<double> f(y.size());
  CHECK_THROWS_AS(sys->rhs(0.0, y.data(), f.data()), std::logic_error);
  // retire() records the indices (the outflow's count), and refuses a non-fluid index as before.
  sys->retire({3, 7});
  CHECK(sys->retired() == std::vector<std::size_t>{3, 7});
  CHECK_THROWS_AS(sys->retire({n_fluid}), std::invalid_argument);
}

TEST_CASE("release_particles is refused on an evaluated system", "[sph_system][release]") {
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml", {"discretization.spacing=0.05"});
  auto sys = make_case<2>(c)->build(c);
  std::vector<double> y = sys->initial_state(), f(y.size());
  sys->rhs(0.0, y.data(), f.data());
  CHECK_THROWS_AS(sys->release_particles(), std::logic_error);
}

TEST_CASE("release_particles drops the monitors' per-particle data of the whole scene", "[sph_system][release][monitors]") {
  // The hydrostatic case's drift monitor keeps every fluid particle's start for the scene's own
  // system; a rank that drops the scene drops those too (its local systems' rows carry theirs).
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/hydrostatic.yaml", {"discretization.particles_across=10"});
  auto sys = make_case<2>(c)->build(c);
  REQUIRE(sys->monitors().size() == 1);
  const auto* drift = dynamic_cast<const DriftMonitor<2>*>(sys->monitors()[0].get());
  REQUIRE(drift != nullptr);
  CHECK(drift->starts_held() == 2 * sys->layout().n);
  sys->release_particles();
  CHECK(drift->starts_held() == 0);
}
