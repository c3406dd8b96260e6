// Measurements at output times read the fields (density, pressure) of the output state itself, not
// of the integrator's last stage (for the leapfrog: the half-step state), and taking them changes
// neither the step sizes nor the reported cost.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/run/run_case.hpp"

using namespace sphmol;

TEST_CASE("output: hydrostatic pressure error is measured on the output state", "[integration][output]") {
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/hydrostatic.yaml",
                               {"discretization.particles_across=20", "fluid.body_force_ramp=0.01", "time.t_end=0.05",
                                "output.times=[0.05]", "output.plots=false"});
  std::vector<double> y;
  RunOptions opt;
  opt.write_files = false;
  opt.final_state = &y;
  const nlohmann::json s = run_case(c, opt);
  REQUIRE(s["status"] == "completed");
  const double reported = s["errors"].back()["p_rms"].get<double>();

  // The same measurement from a fresh system evaluated at exactly (t_end, y).
  auto fresh = make_case<2>(c);
  auto sys = fresh->build(c);
  std::vector<double> ydot(sys->size());
  sys->rhs(0.05, y.data(), ydot.data());
  const double expected = fresh->measure(*sys, y.data(), 0.05, OutputSink{"", false})["p_rms"].get<double>();
  INFO("reported " << reported << ", at the output state " << expected);
  // Equal up to the summation order of a freshly built pair list; the half-step state differs by far more.
  CHECK(std::abs(reported - expected) <= 1e-10 * expected);
}

TEST_CASE("output: output times change neither the steps nor the RHS count", "[integration][output]") {
  const auto run = [](const std::string& times) {
    const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml",
                                 {"discretization.particles_across=20", "time.integrator=leapfrog", "time.t_end=0.02",
                                  "output.times=" + times, "output.plots=false"});
    RunOptions opt;
    opt.write_files = false;
    return run_case(c, opt);
  };
  const auto few = run("[0.02]"), many = run("[0.004, 0.008, 0.012, 0.016, 0.02]");
  CHECK(few["rhs_evals"] == few["steps"].get<long>() + 1);
  CHECK(many["rhs_evals"] == many["steps"].get<long>() + 1);
}
