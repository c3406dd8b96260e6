// The assembly of a fluid without viscosity (rhs/assemble.cpp): `viscosity: morris` (the default) or
// `strain_rate` with kinematic_viscosity 0 builds no viscous term and no wall velocities for it, since
// they would add zeros (a full pair pass: 1.21x the instructions of the inviscid hydrostatic tank), and
// ghost walls make no no-slip image velocities. The right-hand side is that of `viscosity: none`.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "sphmol/cases/case_module.hpp"
#include "sphmol/config/config.hpp"

using namespace sphmol;

namespace {

std::vector<double> rhs_at_start(const Config& c, std::vector<std::string>* terms = nullptr) {
  auto sys = make_case<2>(c)->build(c);
  if (terms) *terms = sys->active_terms();
  std::vector<double> y = sys->initial_state(), f(y.size());
  sys->rhs(0.0, y.data(), f.data());
  return f;
}

bool names(const std::vector<std::string>& terms, const std::string& part) {
  return std::any_of(terms.begin(), terms.end(), [&](const std::string& t) { return t.find(part) != std::string::npos; });
}

}  // namespace

TEST_CASE("assembly: a viscous term of an inviscid fluid is not built, the RHS is that of viscosity none", "[rhs][assembly]") {
  const std::string file = std::string(SPHMOL_SOURCE_DIR) + "/verification/hydrostatic.yaml";
  const std::vector<std::string> inviscid = {"fluid.kinematic_viscosity=0", "discretization.particles_across=20"};
  std::vector<std::string> none_terms;
  auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.begin(), inviscid.begin(), inviscid.end());
    return load_config(file, extra);
  };
  const auto reference = rhs_at_start(with({"discretization.viscosity=none", "discretization.wall_model=prescribed"}), &none_terms);
  REQUIRE_FALSE(names(none_terms, "viscosity"));
  for (const std::vector<std::string>& variant :
       {std::vector<std::string>{"discretization.viscosity=morris", "discretization.wall_model=morris"},
        std::vector<std::string>{"discretization.viscosity=morris", "discretization.wall_model=prescribed"},
        std::vector<std::string>{"discretization.viscosity=strain_rate", "discretization.wall_model=morris"},
        std::vector<std::string>{"discretization.viscosity=morris", "discretization.wall_model=adami"}}) {
    CAPTURE(variant);
    std::vector<std::string> terms;
    const auto f = rhs_at_start(with(variant), &terms);
    CHECK(terms == none_terms);
    CHECK(f == reference);
  }
  // A viscous fluid keeps its term and its wall model.
  std::vector<std::string> viscous_terms;
  rhs_at_start(load_config(file, {"discretization.particles_across=20", "discretization.wall_model=morris"}), &viscous_terms);
  CHECK(names(viscous_terms, "morris_viscosity"));
  CHECK(names(viscous_terms, "morris_wall_velocity"));
}
