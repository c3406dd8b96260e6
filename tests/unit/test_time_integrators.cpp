// The built-in and SUNDIALS integrators on small ODEs with known solutions: order of the leapfrogs,
// CVODE Adams accuracy, the step hook, and the integrator config rules.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "config_test_base.hpp"
#include "sphmol/config/erk_tables.hpp"
#include "sphmol/time/arkode_erk.hpp"
#include <arkode/arkode_butcher_erk.h>
#include "sphmol/time/blow_up.hpp"
#include "sphmol/time/cvode_adams.hpp"
#include "sphmol/time/leapfrog.hpp"
#include "sphmol/time/leapfrog_kdk.hpp"

using namespace sphmol;

namespace {
// Damped oscillator x'' = -w^2 x - g x' as y = [x | v]: velocity-dependent force, like SPH viscosity.
struct Oscillator final : OdeSystem {
  double w = 2.0, g = 0.3;
  long evals = 0;
  double cfl = 0.05;
  std::size_t size() const override { return 2; }
  void rhs(double, const double* y, double* f) override {
    ++evals;
    f[0] = y[1];
    f[1] = -w * w * y[0] - g * y[1];
  }
  double stable_step() const override { return cfl; }
  std::size_t velocities_begin() const override { return 1; }
  std::size_t velocities_end() const override { return 2; }
  long rhs_evaluations() const override { return evals; }
  // Exact solution for x(0) = 1, v(0) = 0.
  double exact_x(double t) const {
    const double wd = std::sqrt(w * w - g * g / 4);
    return std::exp(-g * t / 2) * (std::cos(wd * t) + g / (2 * wd) * std::sin(wd * t));
  }
};

double final_error(Integrator& I, double t_end) {
  Oscillator sys;
  std::vector<double> y{1.0, 0.0};
  I.initialize(sys, 0.0, y.data());
  I.advance(t_end);
  return std::abs(y[0] - sys.exact_x(t_end));
}
}  // namespace

TEST_CASE("leapfrog (DKD) and leapfrog_kdk are second order with a velocity-dependent force", "[time]") {
  for (int kdk = 0; kdk < 2; ++kdk) {
    std::vector<double> e;
    for (double dt : {0.02, 0.01, 0.005}) {
      if (kdk) {
        LeapfrogKdk I({dt, 1'000'000});
        e.push_back(final_error(I, 2.0));
      } else {
        Leapfrog I({dt, 1'000'000});
        e.push_back(final_error(I, 2.0));
      }
    }
    INFO("kdk = " << kdk << ", errors " << e[0] << " " << e[1] << " " << e[2]);
    CHECK(std::log2(e[0] / e[1]) > 1.8);
    CHECK(std::log2(e[1] / e[2]) > 1.8);
    CHECK(e[2] < 1e-4);
  }
}

TEST_CASE("leapfrog_kdk counts one RHS evaluation per step and lands on output times", "[time]") {
  Oscillator sys;
  std::vector<double> y{1.0, 0.0};
  LeapfrogKdk I({0.03, 1'000'000});
  I.initialize(sys, 0.0, y.data());
  long hooked = 0;
  double last_t = 0.0;
  I.set_step_hook([&](double t, const double*, double) { ++hooked, last_t = t; });
  I.advance(1.0);
  CHECK(last_t == 1.0);
  CHECK(I.stats().steps == 34);  // 33 full steps of 0.03 and one of 0.01
  CHECK(hooked == 34);
  CHECK(sys.evals == 1 + 34);
}

TEST_CASE("cvode_adams meets its tolerance and bounds the step by the CFL limit", "[time]") {
  for (double rtol : {1e-6, 1e-9}) {
    Oscillator sys;
    sys.cfl = 0.01;
    std::vector<double> y{1.0, 0.0};
    CvodeAdams I({rtol, rtol * 1e-3, 1'000'000});
    I.initialize(sys, 0.0, y.data());
    double hmax = 0.0;
    I.set_step_hook([&](double, const double*, double h) { hmax = std::max(hmax, h); });
    I.advance(3.0);
    INFO("rtol " << rtol << ": error " << std::abs(y[0] - sys.exact_x(3.0)));
    CHECK(std::abs(y[0] - sys.exact_x(3.0)) < 100 * rtol);
    CHECK(hmax <= 0.01 * (1 + 1e-12));
    CHECK(I.stats().steps >= 300);
  }
}

TEST_CASE("the step hook can end an ARKODE run with BlowUp", "[time]") {
  Oscillator sys;
  std::vector<double> y{1.0, 0.0};
  ArkodeErk I({"ARKODE_HEUN_EULER_2_1_2", 1e-6, 1e-12, 0.01, 1'000'000});
  I.initialize(sys, 0.0, y.data());
  I.set_step_hook([](double t, const double*, double) {
    if (t > 0.5) throw BlowUp(t, 7, "test");
  });
  try {
    I.advance(1.0);
    FAIL("no BlowUp");
  } catch (const BlowUp& b) {
    CHECK(b.t > 0.5);
    CHECK(b.t < 0.52);
    CHECK(b.particle == 7);
  }
}

TEST_CASE("config: the new integrators are accepted, cvode_adams rejects a fixed step", "[config]") {
  using config_test::base;
  using config_test::error_of;
  CHECK(load_config_string(base, {"time.integrator=leapfrog_kdk"}).time.integrator == "leapfrog_kdk");
  CHECK(load_config_string(base, {"time.integrator=cvode_adams"}).time.integrator == "cvode_adams");
  CHECK_THAT(error_of(base, {"time.integrator=cvode_adams", "time.dt=1e-4"}), Catch::Matchers::Contains("cvode_adams is adaptive only"));
}

TEST_CASE("cvode_adams steps one internal step at a time toward the stop time, with the steps of advance", "[time][cvode]") {
  // The run loop checks for SIGINT/SIGTERM between calls of step_toward: one call must be one step.
  Oscillator sa, sb;
  sa.cfl = sb.cfl = 0.01;
  std::vector<double> ya{1.0, 0.0}, yb{1.0, 0.0};
  CvodeAdams A({1e-8, 1e-11, 1'000'000}), B({1e-8, 1e-11, 1'000'000});
  A.initialize(sa, 0.0, ya.data());
  B.initialize(sb, 0.0, yb.data());
  for (double tout : {1.5, 3.0}) {
    A.advance(tout);
    long calls = 0;
    double t = 0.0;
    do {
      const long before = B.stats().steps;
      t = B.step_toward(tout);
      CHECK(B.stats().steps == before + 1);
      CHECK(t <= tout);
      ++calls;
    } while (t < tout);
    CHECK(t == tout);
    CHECK(calls > 100);
  }
  CHECK(A.stats().steps == B.stats().steps);
  CHECK(ya[0] == yb[0]);  // bit for bit
  CHECK(ya[1] == yb[1]);
  CHECK(B.step_toward(3.0) == 3.0);  // already there: no step
}

namespace {
// y' = lambda y: a Runge-Kutta step multiplies y by the stability function R(h lambda) = 1 + z b^T (I - z A)^-1 1.
struct Decay final : OdeSystem {
  double lambda = -1.0;
  std::size_t size() const override { return 1; }
  void rhs(double, const double* y, double* f) override { f[0] = lambda * y[0]; }
  double stable_step() const override { return 1.0; }
  std::size_t velocities_begin() const override { return 0; }
  std::size_t velocities_end() const override { return 1; }
  long rhs_evaluations() const override { return 0; }
};

double stability_function(const std::string& table, double z) {
  ARKodeButcherTable B = ARKodeButcherTable_LoadERKByName(table.c_str());
  const int s = B->stages;
  std::vector<double> k(s);  // explicit: stage i from stages < i
  double r = 1.0;
  for (int i = 0; i < s; ++i) {
    double yi = 1.0;
    for (int j = 0; j < i; ++j) yi += z * B->A[i][j] * k[j];
    k[i] = yi;  // f = lambda y, scaled by 1/lambda (z = h lambda)
    r += z * B->b[i] * k[i];
  }
  ARKodeButcherTable_Free(B);
  return r;
}
}  // namespace

TEST_CASE("ARKODE ERK: every table's fixed steps on y' = -y multiply y by the table's stability function", "[time][erk_tables]") {
  // ERKStep reuses the last stage of a step as the next step's first whenever c_s = 1; for tables that
  // are not first-same-as-last (Verner 8(5)6, Heun-Euler, the ARK explicit tables) that stage is f at a
  // wrong state, which made Verner 8(5)6 grow by 1.27 per step at h = 0.5.
  for (const std::string& table : erk_table_names()) {
    for (double h : {0.1, 0.5, 1.0}) {
      Decay sys;
      std::vector<double> y{1.0};
      ArkodeErk I({table, 1e-6, 1e-12, h, 1'000'000});
      I.initialize(sys, 0.0, y.data());
      I.advance(4 * h);
      const double expected = std::pow(stability_function(table, -h), 4);
      INFO(table << " h = " << h << ": y = " << y[0] << ", R(-h)^4 = " << expected);
      CHECK(y[0] == Approx(expected).epsilon(1e-12));
    }
  }
}

TEST_CASE("ARKODE ERK: Verner 8(5)6 is sixth order at fixed steps on the damped oscillator", "[time][erk_tables]") {
  std::vector<double> e;
  for (double dt : {0.1, 0.05}) {
    ArkodeErk I({"ARKODE_VERNER_8_5_6", 1e-6, 1e-12, dt, 1'000'000});
    e.push_back(final_error(I, 2.0));
  }
  INFO("errors " << e[0] << " " << e[1]);
  CHECK(std::log2(e[0] / e[1]) > 5.5);
}
