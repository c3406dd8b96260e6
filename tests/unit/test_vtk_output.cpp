// The .vtp writer: well-formed XML with the VTK PolyData structure, every field present with one
// tuple per particle, and positions/velocities/density round-tripping exactly (%.17g).
#include <catch2/catch.hpp>

#include <cmath>

#include "mini_xml.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/run/vtk_observer.hpp"
#include "sphmol/scenes/channel_case.hpp"
#include "sphmol/scenes/hydrostatic_case.hpp"

using namespace sphmol;

namespace {
const std::string kConfig = R"(case: couette
fluid: {density: 1000, kinematic_viscosity: 1.0e-6, eos: {sound_speed: 0.005}}
geometry: {channel_height: 1.0e-3, channel_length: 5.0e-4, wall_velocity: 2.5e-5}
discretization: {particles_across: 12}
time: {t_end: 0.1}
)";

const mini_xml::Element& array_named(const mini_xml::Element& parent, const std::string& name) {
  for (const auto* a : parent.all("DataArray"))
    if (a->attr.count("Name") && a->attr.at("Name") == name) return *a;
  FAIL("no DataArray " << name);
  throw;
}
}  // namespace

TEST_CASE("vtk: .vtp parses and round-trips the particle fields", "[vtk][output]") {
  ChannelCase c;
  auto sys = c.build(load_config_string(kConfig));
  std::vector<double> y = sys->initial_state();
  const auto& L = sys->layout();
  const auto& P = sys->particles();
  const std::size_t nf = P.n_fluid, n = P.size();
  // Perturb so that nothing is accidentally symmetric, and move a particle out of the periodic box.
  for (std::size_t i = 0; i < nf; ++i) y[L.velocity(0) + i] = 1e-5 * std::sin(0.37 * static_cast<double>(i));
  y[L.position(0)] += 5.0e-4;  // one periodic length
  std::vector<double> ydot(y.size());
  const double t = 0.0125;
  sys->rhs(t, y.data(), ydot.data());

  for (const bool walls : {true, false}) {
    const std::size_t np = walls ? n : nf;
    const auto root = mini_xml::parse(vtp_text<2>(*sys, y.data(), t, walls));
    REQUIRE(root->name == "VTKFile");
    CHECK(root->attr.at("type") == "PolyData");
    const auto* poly = root->child("PolyData");
    REQUIRE(poly);
    const auto* time = poly->child("FieldData");
    REQUIRE(time);
    CHECK(mini_xml::numbers(array_named(*time, "TIME")) == std::vector<double>{t});
    const auto* piece = poly->child("Piece");
    REQUIRE(piece);
    CHECK(piece->attr.at("NumberOfPoints") == std::to_string(np));
    CHECK(piece->attr.at("NumberOfVerts") == std::to_string(np));

    const auto* points = piece->child("Points");
    REQUIRE(points);
    const auto xyz = mini_xml::numbers(*points->child("DataArray"));
    REQUIRE(xyz.size() == 3 * np);
    for (std::size_t i = 0; i < np; ++i) {
      for (int d = 0; d < 2; ++d) {
        const double expect = sys->domain().wrap(d, i < nf ? y[L.position(d) + i] : P.x_ref[d][i] + P.v[d][i] * t);
        REQUIRE(xyz[3 * i + d] == expect);  // exact: %.17g round-trips
      }
      REQUIRE(xyz[3 * i + 2] == 0.0);
    }
    const auto* pd = piece->child("PointData");
    REQUIRE(pd);
    const auto vel = mini_xml::numbers(array_named(*pd, "velocity"));
    const auto rho = mini_xml::numbers(array_named(*pd, "density"));
    const auto p = mini_xml::numbers(array_named(*pd, "pressure"));
    const auto kind = mini_xml::numbers(array_named(*pd, "kind"));
    REQUIRE(vel.size() == 3 * np);
    REQUIRE(rho.size() == np);
    REQUIRE(p.size() == np);
    REQUIRE(kind.size() == np);
    for (std::size_t i = 0; i < np; ++i) {
      REQUIRE(vel[3 * i] == (i < nf ? y[L.velocity(0) + i] : P.v[0][i]));
      REQUIRE(rho[i] == sys->density()[i]);
      REQUIRE(p[i] == sys->pressure()[i]);
      REQUIRE(kind[i] == (i < nf ? 0.0 : 1.0));
    }
    const auto* verts = piece->child("Verts");
    REQUIRE(verts);
    const auto offsets = mini_xml::numbers(array_named(*verts, "offsets"));
    REQUIRE(offsets.size() == np);
    CHECK(offsets.back() == static_cast<double>(np));
  }
}

TEST_CASE("vtk: the test's XML reader rejects malformed text", "[vtk][output]") {
  CHECK_THROWS(mini_xml::parse("<a><b></a></b>"));
  CHECK_THROWS(mini_xml::parse("<a x=\"1\" x=\"2\"/>"));
  CHECK_THROWS(mini_xml::parse("<a>"));
  CHECK(mini_xml::parse("<?xml version=\"1.0\"?>\n<a><b c=\"d\"/>1 2</a>\n")->child("b")->attr.at("c") == "d");
}

TEST_CASE("vtk: ghost particles are written after the fluid with kind 2 and their generated state", "[vtk][ghost]") {
  const std::string yaml = R"(case: hydrostatic
fluid:
  density: 1000.0
  kinematic_viscosity: 0.01
  eos: {type: tait, sound_speed: 29.7, gamma: 7.0, clamp_negative: true}
  body_force: [0.0, -9.81]
  body_force_ramp: 1.0
geometry: {box: [1.0, 0.9]}
discretization: {particles_across: 10, boundary: ghost}
time: {t_end: 0.01, integrator: leapfrog, dt: 1.0e-3}
)";
  HydrostaticCase c;
  auto sys = c.build(load_config_string(yaml));
  std::vector<double> y = sys->initial_state(), ydot(y.size());
  sys->rhs(0.5, y.data(), ydot.data());
  const std::size_t nf = sys->particles().n_fluid, nb = sys->base_particles(), ng = sys->generated_particles();
  REQUIRE(nb == nf);  // ghost walls: no scene wall particles
  REQUIRE(ng > 0);
  for (const bool walls : {true, false}) {
    const auto root = mini_xml::parse(vtp_text<2>(*sys, y.data(), 0.5, walls, true));
    const auto* piece = root->child("PolyData")->child("Piece");
    REQUIRE(piece->attr.at("NumberOfPoints") == std::to_string(nf + ng));
    const auto* pd = piece->child("PointData");
    const auto kind = mini_xml::numbers(array_named(*pd, "kind"));
    const auto p = mini_xml::numbers(array_named(*pd, "pressure"));
    const auto xyz = mini_xml::numbers(*piece->child("Points")->child("DataArray"));
    for (std::size_t k = 0; k < nf + ng; ++k) {
      REQUIRE(kind[k] == (k < nf ? 0.0 : 2.0));
      REQUIRE(p[k] == sys->pressure()[k]);
      if (k >= nf) {
        REQUIRE(xyz[3 * k] == sys->positions()[0][k]);
        REQUIRE(xyz[3 * k + 1] == sys->positions()[1][k]);
        REQUIRE(xyz[3 * k + 1] < 0.9);  // images lie behind a wall: below y = 0 or beside the tank
        REQUIRE((xyz[3 * k] < 0.0 || xyz[3 * k] > 1.0 || xyz[3 * k + 1] < 0.0));
      }
    }
  }
  // Without ghosts: the fluid only (and no read past the scene's particles).
  const auto root = mini_xml::parse(vtp_text<2>(*sys, y.data(), 0.5, true, false));
  CHECK(root->child("PolyData")->child("Piece")->attr.at("NumberOfPoints") == std::to_string(nf));
}
