// Integrators on ODEs with known solutions: the leapfrog is second order, ARKODE tables are loaded by
// name, fixed steps are honoured, and the state vector is advanced in place (no copy).
#include <catch2/catch.hpp>

#include <cmath>

#include "sphmol/time/arkode_erk.hpp"
#include "sphmol/time/leapfrog.hpp"

using namespace sphmol;

namespace {
// Damped oscillator x'' = -w^2 x - c x' as y = [x, v]: velocity-dependent force like viscosity.
struct Oscillator final : OdeSystem {
  double w2 = 4.0, c = 0.3, dt_stable = 0.05;
  long evals = 0;
  std::size_t size() const override { return 2; }
  void rhs(double, const double* y, double* f) override {
    ++evals;
    f[0] = y[1];
    f[1] = -w2 * y[0] - c * y[1];
  }
  double stable_step() const override { return dt_stable; }
  std::size_t velocities_begin() const override { return 1; }
  std::size_t velocities_end() const override { return 2; }
  long rhs_evaluations() const override { return evals; }
  double exact_x(double t) const {  // x(0) = 1, v(0) = 0
    const double wd = std::sqrt(w2 - c * c / 4.0);
    return std::exp(-c * t / 2.0) * (std::cos(wd * t) + c / (2.0 * wd) * std::sin(wd * t));
  }
};

double leapfrog_error(double dt) {
  Oscillator sys;
  std::vector<double> y{1.0, 0.0};
  Leapfrog lf({dt, 1'000'000});
  lf.initialize(sys, 0.0, y.data());
  lf.advance(2.0);
  return std::abs(y[0] - sys.exact_x(2.0));
}
}  // namespace

TEST_CASE("leapfrog is second order with a velocity-dependent force", "[time]") {
  const double e1 = leapfrog_error(0.01), e2 = leapfrog_error(0.005);
  CHECK(std::log2(e1 / e2) == Approx(2.0).margin(0.1));
}

TEST_CASE("leapfrog lands on output times and uses one RHS per step", "[time]") {
  Oscillator sys;
  std::vector<double> y{1.0, 0.0};
  Leapfrog lf({0.03, 1'000'000});
  lf.initialize(sys, 0.0, y.data());
  lf.advance(0.1);
  CHECK(lf.stats().steps == 4);  // 3 full steps and a shortened one
  lf.advance(1.0);
  CHECK(sys.evals == lf.stats().steps + 1);
  CHECK(y[0] == Approx(sys.exact_x(1.0)).margin(2e-3));
}

TEST_CASE("ARKODE ERK: tables by name, tolerances, fixed step, state advanced in place", "[time]") {
  for (const char* table : {"ARKODE_DORMAND_PRINCE_7_4_5", "ARKODE_BOGACKI_SHAMPINE_4_2_3", "ARKODE_VERNER_8_5_6"}) {
    Oscillator sys;
    std::vector<double> y{1.0, 0.0};
    const double* storage = y.data();
    ArkodeErk erk({table, 1e-9, 1e-12, std::nullopt, 100000});
    erk.initialize(sys, 0.0, y.data());
    erk.advance(2.0);
    CHECK(y.data() == storage);
    CHECK(y[0] == Approx(sys.exact_x(2.0)).margin(1e-6));
    CHECK(erk.describe()["table"] == table);
  }
  Oscillator sys;
  std::vector<double> y{1.0, 0.0};
  ArkodeErk fixed({"ARKODE_DORMAND_PRINCE_7_4_5", 1e-6, 1e-12, 0.01, 100000});
  fixed.initialize(sys, 0.0, y.data());
  fixed.advance(1.0);
  CHECK(fixed.stats().steps == 100);
  CHECK(fixed.stats().last_step == Approx(0.01));
}

TEST_CASE("ARKODE honours the CFL limit of the stability callback", "[time]") {
  Oscillator sys;
  sys.dt_stable = 1e-3;  // far below what the error control would choose
  std::vector<double> y{1.0, 0.0};
  ArkodeErk erk({"ARKODE_DORMAND_PRINCE_7_4_5", 1e-3, 1e-6, std::nullopt, 100000});
  erk.initialize(sys, 0.0, y.data());
  erk.advance(0.5);
  CHECK(erk.stats().steps >= 500);
  CHECK(erk.stats().last_step <= 1e-3 * (1 + 1e-12));
}

TEST_CASE("an unknown Butcher table is an error", "[time]") {
  Oscillator sys;
  std::vector<double> y{1.0, 0.0};
  ArkodeErk erk({"ARKODE_NO_SUCH_TABLE", 1e-6, 1e-12, std::nullopt, 100});
  CHECK_THROWS_WITH(erk.initialize(sys, 0.0, y.data()), Catch::Contains("ARKODE_NO_SUCH_TABLE"));
}
