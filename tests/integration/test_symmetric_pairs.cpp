// Symmetric fused passes (rhs/fused_pair_pass.hpp, neighbors/pair_twins.hpp): evaluating each fluid
// pair of the weakly compressible row once, in the row of its smaller index, gives the state of the
// full rows bit for bit after many steps (neighbour-list rebuilds included), for 1, 2 and 3 threads,
// in 2D and 3D and across a periodic face; and it is what the dam break runs by default.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <omp.h>
#include <string>
#include <vector>

#include "sphmol/cases/case_module.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/time/integrator.hpp"
#include "support/files.hpp"
#include "support/stepped_run.hpp"

using namespace sphmol;

namespace {

using test_support::differing;
using Run = test_support::SteppedRun;

template <int D>
Run run(const Config& c, int steps, bool symmetric, int threads) {
  return test_support::run_steps<D>(c, steps, threads, [&](auto& sys) { sys.set_symmetric_pairs(symmetric); });
}

template <int D>
void check_same(const Config& c, int steps, long min_rebuilds) {
  const Run full = run<D>(c, steps, false, 2);
  CHECK(full.symmetric == 0);
  CHECK(full.rebuilds >= min_rebuilds);  // the list is rebuilt during the run, so the twin tables are remade
  for (int threads : {1, 2, 3}) {
    INFO("threads " << threads);
    const Run sym = run<D>(c, steps, true, threads);
    CHECK(sym.symmetric == sym.evaluations);
    REQUIRE(sym.y.size() == full.y.size());
    CHECK(differing(sym.y, full.y) == 0);
  }
}

}  // namespace

TEST_CASE("symmetric pairs: the dam break's state equals the full rows' bit for bit", "[integration][fused]") {
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml",
                               {"discretization.spacing=0.04", "time.t_end=1.0"});
  check_same<2>(c, 300, 3);
}

TEST_CASE("symmetric pairs: the same with the smooth viscosity switch", "[integration][fused]") {
  // The records evaluate the switch four pairs at a time (core/polynomial_step.hpp), the full rows one
  // pair at a time. The default band and a wide one that holds most pairs (so most groups of four
  // evaluate P, some only in part of their lanes).
  for (const char* band : {"discretization.artificial_viscosity.switch_width=1e-4",
                           "discretization.artificial_viscosity.switch_width=0.3"}) {
    INFO(band);
    const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml",
                                 {"discretization.spacing=0.04", "time.t_end=1.0", "discretization.artificial_viscosity.switch=smooth",
                                  band, "discretization.artificial_viscosity.switch_offset=0.3"});
    check_same<2>(c, 300, 3);
  }
}

TEST_CASE("symmetric pairs: the same with rows of more than 64 upper pairs", "[integration][fused]") {
  // h = 3.5 spacings: about 150 neighbours a row, so a row's upper part spans more than one block of
  // 64 pairs in the records (physics/weakly_compressible_row.hpp).
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml",
                               {"discretization.spacing=0.05", "discretization.smoothing_ratio=3.5", "time.t_end=1.0"});
  check_same<2>(c, 60, 1);
}

namespace {

// A layer over a floor, periodic in x, with a travelling wave in its initial velocity: pairs across
// the periodic face use the minimum image, and the x-momentum keeps the particles crossing it.
Config periodic_layer(double density_diffusion) {
  const auto dir = test_support::fresh_dir("symmetric_pairs");
  const auto file = dir / "layer.yaml";
  std::ofstream(file) << R"yaml(case: scene
dimension: 2
fluid:
  density: 1000.0
  kinematic_viscosity: 0.0
  eos: {type: tait, sound_speed: 20.0, gamma: 7.0}
  body_force: [0.0, -9.81]
scene:
  domain: {lo: [0, 0], hi: [0.4, 0.3], boundaries: [periodic, wall], open_faces: [y_hi]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [0.4, 0.12]}
      pressure: hydrostatic
      velocity: ["0.6 + 0.3*sin(2*pi*x/0.4)", "0.05*cos(2*pi*x/0.4)"]
discretization:
  spacing: 0.01
  kernel: wendland_c2
  smoothing_ratio: 1.414
  density: continuity
  viscosity: none
  artificial_viscosity: {alpha: 0.05, beta: 0.0, eta: 0.1}
  wall_pressure: dynamic
  wall_model: prescribed
  skin: 0.3
time:
  t_end: 1.0
  integrator: leapfrog
output:
  plots: false
)yaml";
  const Config c = load_config(file.string(), {"discretization.density_diffusion=" + std::to_string(density_diffusion)});
  std::filesystem::remove_all(dir);
  return c;
}

}  // namespace

TEST_CASE("symmetric pairs: the same across a periodic face, with density diffusion off", "[integration][fused]") {
  check_same<2>(periodic_layer(0.0), 300, 3);
}

TEST_CASE("symmetric pairs: the same across a periodic face, with density diffusion on", "[integration][fused]") {
  // The row with diffusion has its own vectorised records in 2D, the minimum image among them.
  check_same<2>(periodic_layer(0.1), 300, 3);
}

TEST_CASE("symmetric pairs: the 3D dam break's state equals the full rows' bit for bit", "[integration][fused][3d]") {
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/examples/dam_break_3d.yaml", {});
  check_same<3>(c, 40, 1);
}

TEST_CASE("symmetric pairs are the default for the 2D dam break, not for the 3D one", "[integration][fused]") {
  omp_set_num_threads(1);
  const Config c2 = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml",
                                {"discretization.spacing=0.04"});
  auto s2 = make_case<2>(c2)->build(c2);
  std::vector<double> y2 = s2->initial_state(), f2(y2.size());
  s2->rhs(0.0, y2.data(), f2.data());
  CHECK(s2->symmetric_evaluations() == 1);
  const Config c3 = load_config(std::string(SPHMOL_SOURCE_DIR) + "/examples/dam_break_3d.yaml", {});
  auto s3 = make_case<3>(c3)->build(c3);
  std::vector<double> y3 = s3->initial_state(), f3(y3.size());
  s3->rhs(0.0, y3.data(), f3.data());
  CHECK(s3->symmetric_evaluations() == 0);
}
