// The IMEX integrators on the channel flows: leapfrog_imex and arkode_imex at steps well above the
// explicit viscous limit 0.125 h^2/nu reach the explicit leapfrog's e_rms (within 10 %), and the run
// summary reports their Krylov iterations.
#include <catch2/catch.hpp>

#include <cmath>
#include <nlohmann/json.hpp>

#include "sphmol/config/config.hpp"
#include "sphmol/run/run_case.hpp"
#include "in_process_run.hpp"

using namespace sphmol;

namespace {

nlohmann::json run(const std::string& file, std::vector<std::string> overrides) {
  overrides.push_back("time.t_end=0.2");
  overrides.push_back("output.times=[0.2]");
  overrides.push_back("output.plots=false");
  return in_process::run_verification(file, overrides);
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

TEST_CASE("arkode_imex: a stage solve cut off by max_iterations is not taken as solved", "[integration][imex]") {
  // Poiseuille 20 across: one Krylov iteration per solve is far from the solves' tolerance at the
  // steps the error control would take. ARKStep must shrink the step until the solves converge
  // (same e_rms as unlimited iterations), not accept the unconverged stages (e_rms 40 % off).
  const std::vector<std::string> small{"discretization.particles_across=20", "time.integrator=arkode_imex"};
  auto capped = small;
  capped.push_back("time.krylov.max_iterations=1");
  const auto full = run("poiseuille.yaml", small);
  const auto one = run("poiseuille.yaml", capped);
  CHECK(one["status"] == "completed");
  CHECK(one["final_errors"]["e_rms"].get<double>() == Approx(full["final_errors"]["e_rms"].get<double>()).epsilon(0.01));
  CHECK(one["steps"].get<long>() > 2 * full["steps"].get<long>());
  // At a fixed step it cannot shrink: the run stops and says why.
  capped.push_back("time.dt=0.005");
  try {
    run("poiseuille.yaml", capped);
    FAIL("expected the run to stop");
  } catch (const std::runtime_error& e) {
    CHECK_THAT(e.what(), Catch::Matchers::Contains("did not reach their tolerance in time.krylov.max_iterations = 1"));
  }
}

TEST_CASE("time.max_steps stops the SUNDIALS integrators too", "[integration][max_steps]") {
  // Adaptive steps at a tight tolerance: more than the load-time bound (t_end over the CFL step at
  // rest), which therefore lets a limit just below the run's own count pass.
  const std::string integrator = GENERATE(std::string("arkode_erk"), std::string("cvode_adams"), std::string("arkode_imex"));
  INFO(integrator);
  std::vector<std::string> o{"discretization.particles_across=20", "time.integrator=" + integrator, "time.rtol=1e-10"};
  const long steps = run("poiseuille.yaml", o)["steps"].get<long>();
  const long limit = steps - 5;
  o.push_back("time.max_steps=" + std::to_string(limit));
  try {
    run("poiseuille.yaml", o);
    FAIL("expected the run to stop at time.max_steps");
  } catch (const std::runtime_error& e) {
    CHECK_THAT(e.what(), Catch::Matchers::Contains("time.max_steps = " + std::to_string(limit) + " reached"));
  }
}
