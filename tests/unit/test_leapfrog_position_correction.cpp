// The built-in leapfrogs with a position correction dx/dt = v + c(x) (XSPH, the transport velocity):
// second order in time, as without one, and a checkpoint carries c so that a restarted run continues
// bit for bit. Each scheme evaluates at predicted velocities and once used c lagged by half a step or
// a step: leapfrog, leapfrog_kdk and leapfrog_imex were first order whenever c changed in time (a
// Taylor-Green vortex with the transport velocity: time error 1.52e-3, 7.5e-4, 3.8e-4 at 1, 1/2 and
// 1/4 of its CFL step).
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "sphmol/time/imex_system.hpp"
#include "sphmol/time/leapfrog.hpp"
#include "sphmol/time/leapfrog_imex.hpp"
#include "sphmol/time/leapfrog_kdk.hpp"
#include "unit/state_distance.hpp"

using namespace sphmol;

namespace {

// n particles on springs, x' = v + c(x) with c = -kappa sin(x + phase), v' = -w^2 x - gamma v. The
// damping is the implicit part for leapfrog_imex (a diagonal operator, b = 0).
struct Corrected final : OdeSystem, ImexSystem {
  std::size_t n = 6;
  double w2 = 4.0, kappa = 0.8, gamma = 0.5;
  long evals = 0;
  std::vector<std::uint32_t> capacity = std::vector<std::uint32_t>(7, 0);
  std::size_t size() const override { return 2 * n; }
  void explicit_part(const double* y, double* f) const {
    for (std::size_t i = 0; i < n; ++i) {
      f[i] = y[n + i] - kappa * std::sin(y[i] + 0.4 * static_cast<double>(i));
      f[n + i] = -w2 * y[i];
    }
  }
  void rhs(double, const double* y, double* f) override {
    ++evals;
    explicit_part(y, f);
    for (std::size_t i = 0; i < n; ++i) f[n + i] -= gamma * y[n + i];
  }
  void rhs_explicit(double, const double* y, double* fe, ViscousOperator& op) override {
    ++evals;
    explicit_part(y, fe);
    op.begin(n, 1, capacity.data(), nullptr);
    const double b = 0.0;
    for (std::size_t i = 0; i < n; ++i) op.finish_row(i, 0, -gamma, &b);
    op.end();
  }
  std::vector<std::string> implicit_terms() const override { return {"damping"}; }
  double stable_step() const override { return 0.05; }
  std::size_t velocities_begin() const override { return n; }
  std::size_t velocities_end() const override { return 2 * n; }
  std::size_t block_length() const override { return n; }
  long rhs_evaluations() const override { return evals; }
};

std::unique_ptr<LeapfrogBase> make(const std::string& scheme, double dt) {
  const LeapfrogBase::Options o{dt, 10'000'000};
  if (scheme == "leapfrog") return std::make_unique<Leapfrog>(o);
  if (scheme == "leapfrog_kdk") return std::make_unique<LeapfrogKdk>(o);
  return std::make_unique<LeapfrogImex>(o, KrylovOptions{"pcg", 1e-14, 50});
}

std::vector<double> start(const Corrected& s) {
  std::vector<double> y(s.size());
  for (std::size_t i = 0; i < s.n; ++i) {
    y[i] = 0.3 + 0.2 * static_cast<double>(i);
    y[s.n + i] = std::cos(static_cast<double>(i));
  }
  return y;
}

std::vector<double> run(const std::string& scheme, double dt, double t_end) {
  Corrected s;
  auto y = start(s);
  auto lf = make(scheme, dt);
  lf->initialize(s, 0.0, y.data());
  lf->advance(t_end);
  return y;
}

}  // namespace

TEST_CASE("leapfrogs are second order with a position correction", "[time]") {
  for (const std::string scheme : {"leapfrog", "leapfrog_kdk", "leapfrog_imex"}) {
    const double dt = 0.04, t_end = 2.0;
    const auto ref = run(scheme, dt / 256, t_end);
    const double e1 = rms_distance(run(scheme, dt, t_end), ref), e2 = rms_distance(run(scheme, dt / 2, t_end), ref),
                 e3 = rms_distance(run(scheme, dt / 4, t_end), ref);
    INFO(scheme << ": errors " << e1 << " " << e2 << " " << e3);
    CHECK(std::log2(e1 / e2) > 1.9);
    CHECK(std::log2(e2 / e3) > 1.9);
  }
}

TEST_CASE("leapfrogs: a checkpoint carries the position correction (restart bit for bit)", "[time]") {
  for (const std::string scheme : {"leapfrog", "leapfrog_kdk", "leapfrog_imex"}) {
    INFO(scheme);
    const double dt = 0.03;
    const auto whole = run(scheme, dt, 0.6);
    Corrected s;
    auto y = start(s);
    auto first = make(scheme, dt);
    first->initialize(s, 0.0, y.data());
    first->advance(0.3);
    const nlohmann::json state = first->save_state();
    CHECK(state.contains("c"));
    Corrected s2;
    auto second = make(scheme, dt);
    second->initialize(s2, 0.3, y.data());
    second->restore_state(state);
    second->advance(0.6);
    CHECK(y == whole);
  }
}
