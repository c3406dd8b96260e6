// The IMEX integrators on the channel flows: leapfrog_imex and arkode_imex at steps well above the
// explicit viscous limit 0.125 h^2/nu reach the explicit leapfrog's e_rms (within 10 %), and the run
// summary reports their Krylov iterations.
#include <catch2/catch.hpp>

#include <cmath>
#include <nlohmann/json.hpp>

#include "sphmol/config/config.hpp"
#include "sphmol/run/run_case.hpp"

using namespace sphmol;

namespace {
std::string verification(const std::string& name) { return std::string(SPHMOL_SOURCE_DIR) + "/verification/" + name; }

nlohmann::json run(const std::string& file, std::vector<std::string> overrides) {
  overrides.push_back("time.t_end=0.2");
  overrides.push_back("output.times=[0.2]");
  overrides.push_back("output.plots=false");
  const Config c = load_config(verification(file), overrides);
  RunOptions o;
  o.write_files = false;
  return run_case(c, o);
}

// 0.125 h^2 / nu of the shipped channels (40 across, h = 1.3 dx, nu = 1e-6).
double viscous_limit() {
  const double h = 1.3 * 1e-3 / 40.0;
  return 0.125 * h * h / 1e-6;
}
}  // namespace

TEST_CASE("IMEX integrators reach the explicit e_rms on Poiseuille and Couette", "[integration][imex]") {
  const std::string file = GENERATE(std::string("poiseuille.yaml"), std::string("couette.yaml"));
  INFO(file);
  const auto lf = run(file, {"time.integrator=leapfrog_kdk"});
  const double e_ref = lf["final_errors"]["e_rms"];
  // leapfrog_imex at the acoustic CFL step 0.25 h / c (no viscous limit), 12x the viscous limit;
  // couette.yaml ships 0.125 for its final e_max, poiseuille.yaml 0.5.
  const auto li = run(file, {"time.integrator=leapfrog_imex", "time.cfl.acoustic=0.25"});
  CHECK(li["status"] == "completed");
  CHECK(li["final_errors"]["e_rms"].get<double>() == Approx(e_ref).epsilon(0.1));
  const double li_step = 0.2 / li["steps"].get<double>();  // the mean CFL step
  CHECK(li_step > 8.0 * viscous_limit());
  CHECK(li["integrator"]["krylov_iterations"].get<long>() > 0);
  CHECK(li["rhs_evals"].get<long>() < lf["rhs_evals"].get<long>() / 5);
  // arkode_imex, fixed step 10x the viscous limit.
  const double dt = 10.0 * viscous_limit();
  const auto ai = run(file, {"time.integrator=arkode_imex", "time.table=ARKODE_ARK324L2SA_ERK_4_2_3", "time.dt=" + std::to_string(dt)});
  CHECK(ai["status"] == "completed");
  CHECK(ai["final_errors"]["e_rms"].get<double>() == Approx(e_ref).epsilon(0.1));
  CHECK(ai["integrator"]["krylov_iterations"].get<long>() > 0);
}
