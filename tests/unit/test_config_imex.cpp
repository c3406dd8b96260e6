// Config keys of the IMEX integrators: the names, the ARK pair named by either table, the Krylov
// options with their defaults, and clear errors for combinations that make no sense.
#include <catch2/catch.hpp>

#include "config_test_base.hpp"
#include "sphmol/config/config.hpp"

using namespace sphmol;
using config_test::base;
using config_test::error_of;
using config_test::with;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {
std::string time_lines(const std::string& lines) { return with("  t_end: 0.5", "  t_end: 0.5\n" + lines); }
}  // namespace

TEST_CASE("config imex: integrator names, default pair and Krylov defaults", "[config][imex]") {
  const Config a = load_config_string(time_lines("  integrator: arkode_imex"), {}, "case.yaml");
  CHECK(a.time.integrator == "arkode_imex");
  CHECK(a.time.table == "ARKODE_ARK324L2SA_ERK_4_2_3");
  CHECK(a.time.krylov.solver == "pcg");
  CHECK(a.time.krylov.max_iterations == 100);
  const Config b = load_config_string(time_lines("  integrator: arkode_imex\n  table: ARKODE_ARK548L2SA_DIRK_8_4_5"), {}, "case.yaml");
  CHECK(b.time.table == "ARKODE_ARK548L2SA_DIRK_8_4_5");
  const Config c = load_config_string(
      time_lines("  integrator: leapfrog_imex\n  krylov:\n    solver: spgmr\n    tolerance: 1.0e-6\n    max_iterations: 50"), {},
      "case.yaml");
  CHECK(c.time.integrator == "leapfrog_imex");
  CHECK(c.time.krylov.solver == "spgmr");
  CHECK(c.time.krylov.tolerance == 1e-6);
  CHECK(c.time.krylov.max_iterations == 50);
  // The resolved config reloads to the same settings.
  const Config d = load_config_string(to_yaml(c), {}, "resolved.yaml");
  CHECK(d.time.krylov.solver == "spgmr");
  CHECK(d.time.krylov.tolerance == 1e-6);
  // GMRES by default where the Laplacian correction scales rows apart (not symmetric).
  const Config g = load_config_string(time_lines("  integrator: leapfrog_imex"), {"discretization.laplacian_correction=moment"}, "case.yaml");
  CHECK(g.time.krylov.solver == "spgmr");
  // Conjugate gradients stay the default, and allowed, with the pair-symmetric correction (symmetric L).
  const Config s = load_config_string(time_lines("  integrator: leapfrog_imex"), {"discretization.laplacian_correction=moment_symmetric"}, "case.yaml");
  CHECK(s.time.krylov.solver == "pcg");
  const Config sp = load_config_string(time_lines("  integrator: arkode_imex\n  krylov:\n    solver: pcg"),
                                       {"discretization.laplacian_correction=moment_symmetric"}, "case.yaml");
  CHECK(sp.time.krylov.solver == "pcg");
  const Config e = load_config_string(to_yaml(b), {}, "resolved.yaml");
  CHECK(e.time.table == "ARKODE_ARK548L2SA_DIRK_8_4_5");
}

TEST_CASE("config imex: errors name the file, line and key", "[config][imex]") {
  // An explicit-only table for the ARK pair.
  CHECK_THAT(error_of(time_lines("  integrator: arkode_imex\n  table: ARKODE_DORMAND_PRINCE_7_4_5")),
             StartsWith("case.yaml:17: time.table: 'ARKODE_DORMAND_PRINCE_7_4_5' is not one table of a SUNDIALS ARK ImEx pair"));
  CHECK_THAT(error_of(time_lines("  integrator: arkode_imex\n  table: ARKODE_ARK324L2SA_ERK_4_2")),
             Contains("did you mean 'ARKODE_ARK324L2SA_ERK_4_2_3'?"));
  // Nothing to treat implicitly.
  CHECK_THAT(error_of(time_lines("  integrator: arkode_imex"), {"discretization.viscosity=none", "fluid.kinematic_viscosity=0"}),
             StartsWith("case.yaml:16: time.integrator: 'arkode_imex' treats the viscous term implicitly, and "
                        "discretization.viscosity is 'none'"));
  CHECK_THAT(error_of(time_lines("  integrator: leapfrog_imex"), {"discretization.viscosity=strain_rate"}),
             StartsWith("case.yaml:16: time.integrator: 'leapfrog_imex' needs discretization.viscosity: morris"));
  CHECK_THAT(error_of(time_lines("  integrator: leapfrog_imex"), {"discretization.wall_model=adami", "discretization.wall_pressure=extrapolated"}),
             StartsWith("case.yaml:16: time.integrator: 'leapfrog_imex' needs discretization.wall_model: prescribed or morris"));
  // Krylov options with an explicit integrator would be ignored.
  CHECK_THAT(error_of(time_lines("  integrator: leapfrog_kdk\n  krylov:\n    solver: pcg")),
             StartsWith("case.yaml:17: time.krylov: applies to time.integrator: leapfrog_imex or arkode_imex (got 'leapfrog_kdk')"));
  CHECK_THAT(error_of(time_lines("  integrator: arkode_imex\n  krylov:\n    tolerance: 1.0e-6")),
             StartsWith("case.yaml:18: time.krylov.tolerance: is for leapfrog_imex"));
  CHECK_THAT(error_of(time_lines("  integrator: leapfrog_imex\n  krylov:\n    solver: cg")),
             StartsWith("case.yaml:18: time.krylov.solver: unknown value 'cg'"));
  CHECK_THAT(error_of(time_lines("  integrator: leapfrog_imex\n  krylov:\n    tolerance: 2")),
             StartsWith("case.yaml:18: time.krylov.tolerance: 2 is out of range"));
  CHECK_THAT(error_of(time_lines("  integrator: leapfrog_imex\n  krylov:\n    max_iterations: 0")),
             StartsWith("case.yaml:18: time.krylov.max_iterations: 0 is out of range"));
  // PCG needs a symmetric operator.
  CHECK_THAT(error_of(time_lines("  integrator: leapfrog_imex\n  krylov:\n    solver: pcg"), {"discretization.laplacian_correction=moment"}),
             StartsWith("case.yaml:18: time.krylov.solver: 'pcg' needs a symmetric operator"));
}

TEST_CASE("config imex: the step-count check uses the CFL step without the viscous limit", "[config][imex]") {
  // Base: 20 across a 1 mm channel, h = 1.3 * 5e-5 m, c = 0.01 m/s, nu = 1e-6: the viscous limit
  // 5.3e-4 s needs 943 steps to t_end = 0.5 s, the acoustic limit 1.6e-3 s needs 308.
  const std::vector<std::string> limit{"time.max_steps=500"};
  CHECK_THAT(error_of(time_lines("  integrator: leapfrog_kdk"), limit),
             Contains("time.max_steps: 500 steps cannot reach time.t_end = 0.5 s"));
  CHECK(error_of(time_lines("  integrator: leapfrog_imex"), limit) == "<no error>");
  CHECK(error_of(time_lines("  integrator: arkode_imex"), limit) == "<no error>");
}
