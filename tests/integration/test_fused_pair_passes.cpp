// Fused pair passes (rhs/fused_pair_pass.hpp) against the stored active-pair list: for every shipped
// verification case whose terms all run row by row, one RHS evaluation gives the same derivatives in
// both modes, bit for bit (same pairs, same order, same arithmetic), on a state taken after some
// steps so that every term is active. The passes are grouped where the term dependencies require.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <omp.h>
#include <stdexcept>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/time/integrator.hpp"

using namespace sphmol;

namespace {

struct Case {
  const char* file;
  std::vector<std::string> overrides;
  std::size_t passes;  // fused passes
  bool auto_fuses;     // pair_passes: auto picks the fused passes (one pass; the cases are small)
};

std::vector<Case> cases() {
  return {
      {"couette.yaml", {"time.t_end=0.5"}, 2, false},  // summation density | Morris walls, pressure, viscosity, XSPH
      {"poiseuille.yaml", {"time.t_end=1.0"}, 2, false},
      // density | moments | pressure, viscosity, divergences | bulk viscosity, shift | extra stress (the file's
      // normalised summation needs the stored list: plain summation here)
      {"taylor_green.yaml", {"discretization.particles_across=24", "discretization.density=summation"}, 5, false},
      {"cavity.yaml", {"time.t_end=1.0", "discretization.particles_across=20"}, 3, false},
      {"cavity.yaml", {"time.t_end=1.0", "discretization.particles_across=20", "discretization.boundary=ghost",
                       "discretization.wall_model=prescribed"}, 3, false},
      // The bulk viscosity's wall pairs (a wall takes the fluid particle's divergence).
      {"cavity.yaml", {"time.t_end=1.0", "discretization.particles_across=20", "discretization.bulk_viscosity=1"}, 4, false},
      {"shock_tube.yaml", {}, 1, true},  // variable h, ghost walls, energy
      {"dam_break.yaml", {"discretization.spacing=0.04", "time.t_end=0.5"}, 1, true},  // continuity .. AV, wall rows
      {"dam_break.yaml", {"discretization.spacing=0.04", "time.t_end=0.5", "discretization.combine_terms=false"}, 1, true},
  };
}

std::unique_ptr<SphSystem<2>> build(const Config& c) { return make_case<2>(c)->build(c); }

std::vector<double> state_after(const Config& c, int steps) {
  auto sys = build(c);
  std::vector<double> y = sys->initial_state();
  auto integ = make_integrator(c.time);
  integ->initialize(*sys, 0.0, y.data());
  for (int s = 0; s < steps; ++s) integ->step_toward(c.time.t_end);
  return y;
}

}  // namespace

TEST_CASE("fused pair passes give the stored-list derivatives bit for bit", "[integration][fused]") {
  omp_set_num_threads(2);
  for (const auto& k : cases()) {
    auto overrides = k.overrides;
    INFO(k.file << " " << (overrides.size() > 1 ? overrides.back() : std::string()));
    overrides.push_back("discretization.pair_passes=stored");
    const Config stored_cfg = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/" + k.file, overrides);
    overrides.back() = "discretization.pair_passes=fused";
    const Config fused_cfg = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/" + k.file, overrides);
    overrides.back() = "discretization.pair_passes=auto";
    CHECK(build(load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/" + k.file, overrides))->pair_passes().size() ==
          (k.auto_fuses ? k.passes : 0));
    const std::vector<double> y = state_after(stored_cfg, 10);

    auto stored = build(stored_cfg);
    auto fused = build(fused_cfg);
    CHECK(stored->pair_passes().empty());
    CHECK(fused->pair_passes().size() == k.passes);
    CHECK(fused->active_terms() == stored->active_terms());
    std::vector<double> f_stored(y.size()), f_fused(y.size());
    stored->rhs(0.0, y.data(), f_stored.data());
    fused->rhs(0.0, y.data(), f_fused.data());
    std::size_t differ = 0, nonzero = 0;
    for (std::size_t i = 0; i < y.size(); ++i) {
      differ += f_stored[i] != f_fused[i] ? 1 : 0;
      nonzero += f_stored[i] != 0.0 ? 1 : 0;
    }
    CHECK(differ == 0);
    CHECK(nonzero > y.size() / 4);  // the comparison is not vacuous
    // Rows are split in ranges by cost and a thread done early takes chunks of the others' ranges:
    // with 1 and with 3 threads (more than the cores, so a thread is often off its core and the
    // others take its chunks) the derivatives are the same.
    for (const int threads : {1, 3}) {
      omp_set_num_threads(threads);
      std::vector<double> f_threads(y.size());
      fused->rhs(0.0, y.data(), f_threads.data());
      CHECK(f_threads == f_fused);
    }
    omp_set_num_threads(2);
    // The fused system never built the active list, but can still count it.
    CHECK(fused->active_pairs() == stored->active_pairs());
    CHECK(fused->active_pairs() > 0);
  }
  omp_set_num_threads(1);
}

TEST_CASE("fused pair passes: the dam break runs as one pass, and 'fused' is refused where a term needs the stored list",
          "[integration][fused]") {
  const std::string dir = std::string(SPHMOL_SOURCE_DIR) + "/verification/";
  auto dam = build(load_config(dir + "dam_break.yaml", {"discretization.spacing=0.04"}));
  REQUIRE(dam->pair_passes().size() == 1);
  CHECK(dam->pair_passes()[0] ==
        std::vector<std::string>{"continuity_density+density_diffusion_molteni_colagrossi+pressure_gradient_117+"
                                 "artificial_viscosity",
                                 "dynamic_wall_density"});
  // Both terms add nothing for a skin pair (W = F = 0): the rows keep them and skip the compaction.
  // The derivatives equal the stored (compacted) list's bit for bit (first test case).
  CHECK(dam->pair_passes_keep_skin_pairs() == std::vector<bool>{true});
  // Without combining, the four terms run one after the other in the same pass.
  auto apart = build(load_config(dir + "dam_break.yaml", {"discretization.spacing=0.04", "discretization.combine_terms=false"}));
  REQUIRE(apart->pair_passes().size() == 1);
  CHECK(apart->pair_passes()[0] == std::vector<std::string>{"continuity_density", "dynamic_wall_density",
                                                            "density_diffusion_molteni_colagrossi",
                                                            "pressure_gradient_117", "artificial_viscosity"});
  CHECK(apart->pair_passes_keep_skin_pairs() == std::vector<bool>{false});
  // The hydrostatic tank's extrapolated wall pressure sums over the stored list: auto falls back to it,
  // and asking for fused passes is a config error that names the setting.
  auto tank = build(load_config(dir + "hydrostatic.yaml", {}));
  CHECK(tank->pair_passes().empty());
  CHECK(tank->terms_needing_stored_pairs() == std::vector<std::string>{"wall_pressure_extrapolated"});
  CHECK_THROWS_WITH(build(load_config(dir + "hydrostatic.yaml", {"discretization.pair_passes=fused"})),
                    Catch::Contains("wall_pressure: extrapolated") && Catch::Contains("discretization.pair_passes"));
}

TEST_CASE("the combined weakly compressible row equals its four separate terms to round-off", "[integration][fused]") {
  // Dam break with and without delta-SPH: both template variants of physics/weakly_compressible_row.hpp
  // against continuity, diffusion, pressure and AV. The row runs in blocks of 64 pairs; at h = 3 dp a
  // row has about 110 pairs, so a row spans two blocks.
  const std::string dir = std::string(SPHMOL_SOURCE_DIR) + "/verification/";
  // Without artificial viscosity the row runs with Pi = 0 (it ran the separate terms: 1.9x the
  // instructions).
  struct Variant {
    std::vector<std::string> overrides;
    bool diffusion;
    double min_pairs_per_row;
    bool viscosity = true;
  };
  for (const Variant& v :
       {Variant{{"discretization.spacing=0.04", "time.t_end=0.5"}, true, 10.0},
        Variant{{"discretization.spacing=0.04", "time.t_end=0.5", "discretization.density_diffusion=0"}, false, 10.0},
        Variant{{"discretization.spacing=0.04", "time.t_end=0.5", "discretization.smoothing_ratio=3"}, true, 80.0},
        Variant{{"discretization.spacing=0.04", "time.t_end=0.5", "discretization.artificial_viscosity=null"}, true, 10.0, false},
        Variant{{"discretization.spacing=0.04", "time.t_end=0.5", "discretization.artificial_viscosity=null",
                 "discretization.density_diffusion=0"}, false, 10.0, false}}) {
    const auto& base = v.overrides;
    auto on = base, off = base;
    off.push_back("discretization.combine_terms=false");
    const Config c_on = load_config(dir + "dam_break.yaml", on), c_off = load_config(dir + "dam_break.yaml", off);
    const std::vector<double> y = state_after(c_off, 10);
    auto combined = build(c_on);
    auto separate = build(c_off);
    REQUIRE(combined->active_terms().size() + (v.diffusion ? 2 : 1) + (v.viscosity ? 1 : 0) == separate->active_terms().size());
    const auto terms = combined->active_terms();
    const auto row = std::find_if(terms.begin(), terms.end(), [](const std::string& t) { return t.rfind("continuity_density+", 0) == 0; });
    REQUIRE(row != terms.end());
    CHECK((row->find("+artificial_viscosity") != std::string::npos) == v.viscosity);
    std::vector<double> f_on(y.size()), f_off(y.size());
    combined->rhs(0.0, y.data(), f_on.data());
    separate->rhs(0.0, y.data(), f_off.data());
    const double pairs_per_row = static_cast<double>(combined->active_pairs()) / static_cast<double>(combined->layout().n);
    INFO(base.back() << ": " << pairs_per_row << " active pairs per particle");
    CHECK(pairs_per_row > v.min_pairs_per_row);
    // Per field block (positions, velocities, densities, wall densities): largest difference relative
    // to the block's largest magnitude. The AV sits inside the pressure bracket, so sums differ in order.
    const std::size_t n = combined->layout().n;
    double worst = 0.0;
    bool differ = false;
    for (std::size_t first = 0; first < y.size(); first += n) {
      const std::size_t last = std::min(y.size(), first + n);
      double scale = 0.0, diff = 0.0;
      for (std::size_t i = first; i < last; ++i) {
        scale = std::max(scale, std::abs(f_off[i]));
        diff = std::max(diff, std::abs(f_on[i] - f_off[i]));
        differ = differ || f_on[i] != f_off[i];
      }
      if (scale > 0.0) worst = std::max(worst, diff / scale);
    }
    INFO("largest relative difference of a block: " << worst);
    CHECK(worst < 1e-12);
    // Really the other code path (the term names above): with the AV inside the pressure bracket the
    // sums differ in order; without it they are the separate terms' bit for bit.
    CHECK(differ == v.viscosity);
  }
}
