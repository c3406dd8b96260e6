// The per-particle fields an evaluation leaves for output (density, pressure of every particle,
// walls included) are a function of the evaluated (t, y) alone: the VTK files, probes and profiles
// read them, and a run over ranks writes each rank's walls from its own local system, whose
// evaluation history differs from the serial run's. A wall particle whose extrapolated pressure
// (Adami et al. 2012) has no fluid to extrapolate from must read the same value whatever the
// system evaluated before.
#include <catch2/catch.hpp>

#include <omp.h>
#include <string>
#include <vector>

#include "sphmol/cases/case_module.hpp"
#include "sphmol/config/config.hpp"

using namespace sphmol;

namespace {

struct Fields {
  std::vector<double> rho, p;
};

Fields fields_at(SphSystem<2>& sys, const std::vector<double>& y) {
  std::vector<double> f(y.size());
  sys.rhs(0.0, y.data(), f.data());
  return {sys.density(), sys.pressure()};
}

}  // namespace

TEST_CASE("extrapolated wall pressures: walls without fluid read the same fields whatever was evaluated before",
          "[integration][wall_output_fields]") {
  omp_set_num_threads(1);
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/hydrostatic.yaml",
                               {"discretization.particles_across=10", "fluid.body_force_ramp=0"});
  REQUIRE(c.discretization.wall_pressure == "extrapolated");
  auto fresh = make_case<2>(c)->build(c);
  auto used = make_case<2>(c)->build(c);
  const std::vector<double> y0 = fresh->initial_state();
  const auto& layout = fresh->layout();
  const std::size_t nf = layout.n;
  // The same column lifted by 0.3 m: the bottom walls' supports (2 h = 0.2 m) hold no fluid.
  std::vector<double> lifted = y0;
  for (std::size_t i = 0; i < nf; ++i) lifted[layout.position(1) + i] += 0.3;

  // `used` extrapolated every wall from the column at rest before; `fresh` never did.
  const Fields before = fields_at(*used, y0);
  const Fields a = fields_at(*fresh, lifted);
  const Fields b = fields_at(*used, lifted);
  REQUIRE(a.p.size() == b.p.size());
  std::size_t walls_without_fluid_changed = 0, differ = 0;
  const auto& kind = fresh->particles().kind;
  for (std::size_t i = nf; i < fresh->base_particles(); ++i) {
    if (kind[i] != Kind::Wall) continue;
    if (a.p[i] != b.p[i] || a.rho[i] != b.rho[i]) ++differ;
    // A bottom wall had the column's weight on it before and has nothing to extrapolate from now.
    if (before.p[i] > 0.0 && fresh->particles().x[1][i] < 0.0) ++walls_without_fluid_changed;
  }
  INFO(differ << " wall particles differ; " << walls_without_fluid_changed << " bottom walls carried the column's pressure before");
  REQUIRE(walls_without_fluid_changed > 0);
  CHECK(differ == 0);
  for (std::size_t i = 0; i < nf; ++i) CHECK(a.p[i] == b.p[i]);
}
