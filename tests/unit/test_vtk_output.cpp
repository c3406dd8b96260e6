// The .vtp writer: VTK XML PolyData with raw appended binary data (decoded here by an independent
// reader, tests/unit/vtk_appended.hpp), one file per particle group, every field present with one
// tuple per particle and equal to the state bit for bit, wall particles where the solver puts them.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <fstream>
#include <sstream>

#include "mini_xml.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/run/vtk_observer.hpp"
#include "sphmol/cases/cavity/cavity_case.hpp"
#include "sphmol/cases/channel/channel_case.hpp"
#include "sphmol/cases/hydrostatic/hydrostatic_case.hpp"
#include "sphmol/cases/shock_tube/shock_tube_case.hpp"
#include "vtk_appended.hpp"

using namespace sphmol;
using vtk_appended::array_named;

namespace {
const std::string kConfig = R"(case: couette
fluid: {density: 1000, kinematic_viscosity: 1.0e-6, eos: {sound_speed: 0.005}}
geometry: {channel_height: 1.0e-3, channel_length: 5.0e-4, wall_velocity: 2.5e-5}
discretization: {particles_across: 12}
time: {t_end: 0.1}
)";

std::string slurp_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Decoded {
  vtk_appended::File file;
  const mini_xml::Element* piece = nullptr;
  const mini_xml::Element* pd = nullptr;
  double time = 0.0;
  std::size_t n = 0;
  std::vector<double> xyz;
  const std::vector<double>& point(const std::string& name) const { return file.of(array_named(*pd, name)); }
};

Decoded decode(const std::string& text) {
  Decoded d;
  d.file = vtk_appended::read(text);
  REQUIRE(d.file.root->name == "VTKFile");
  REQUIRE(d.file.root->attr.at("type") == "PolyData");
  const auto* poly = d.file.root->child("PolyData");
  REQUIRE(poly);
  const auto* fd = poly->child("FieldData");
  REQUIRE(fd);
  const auto& tv = d.file.of(array_named(*fd, "TimeValue"));  // the name ParaView reads
  REQUIRE(tv.size() == 1);
  d.time = tv[0];
  d.piece = poly->child("Piece");
  REQUIRE(d.piece);
  d.n = std::stoul(d.piece->attr.at("NumberOfPoints"));
  REQUIRE(d.piece->attr.at("NumberOfVerts") == std::to_string(d.n));
  d.pd = d.piece->child("PointData");
  REQUIRE(d.pd);
  d.xyz = d.file.of(array_named(*d.piece->child("Points"), "Points"));
  REQUIRE(d.xyz.size() == 3 * d.n);
  for (const char* name : {"id", "mass", "density", "pressure", "kind"}) REQUIRE(d.point(name).size() == d.n);
  REQUIRE(d.point("velocity").size() == 3 * d.n);
  const auto* verts = d.piece->child("Verts");
  REQUIRE(verts);
  const auto& conn = d.file.of(array_named(*verts, "connectivity"));
  const auto& offsets = d.file.of(array_named(*verts, "offsets"));
  REQUIRE(conn.size() == d.n);
  REQUIRE(offsets.size() == d.n);
  for (std::size_t k = 0; k < d.n; ++k) {
    REQUIRE(conn[k] == static_cast<double>(k));
    REQUIRE(offsets[k] == static_cast<double>(k + 1));
  }
  return d;
}
}  // namespace

TEST_CASE("vtk: binary .vtp files decode to the state, fluid and walls apart", "[vtk][output]") {
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

  const Decoded fl = decode(vtp_file<2>(*sys, y.data(), t, VtkPart::fluid));
  const Decoded wa = decode(vtp_file<2>(*sys, y.data(), t, VtkPart::walls));
  CHECK(fl.time == t);
  CHECK(wa.time == t);
  REQUIRE(fl.n == nf);
  REQUIRE(wa.n == n - nf);
  REQUIRE(vtk_part_size<2>(*sys, VtkPart::ghosts) == 0);
  for (const Decoded* d : {&fl, &wa}) {
    const std::size_t first = d == &fl ? 0 : nf;
    for (std::size_t k = 0; k < d->n; ++k) {
      const std::size_t i = first + k;
      REQUIRE(d->point("id")[k] == static_cast<double>(i));  // index in the initial particle set
      for (int dim = 0; dim < 2; ++dim) {
        const double x = i < nf ? y[L.position(dim) + i] : P.x_ref[dim][i] + P.v[dim][i] * t;
        REQUIRE(d->xyz[3 * k + dim] == sys->domain().wrap(dim, x));  // exact: binary doubles
        REQUIRE(d->point("velocity")[3 * k + dim] == (i < nf ? y[L.velocity(dim) + i] : P.v[dim][i]));
      }
      REQUIRE(d->xyz[3 * k + 2] == 0.0);
      REQUIRE(d->point("velocity")[3 * k + 2] == 0.0);
      REQUIRE(d->point("mass")[k] == P.mass[i]);
      REQUIRE(d->point("density")[k] == sys->density()[i]);
      REQUIRE(d->point("pressure")[k] == sys->pressure()[i]);
      REQUIRE(d->point("kind")[k] == (i < nf ? 0.0 : 1.0));
    }
  }
  CHECK(fl.xyz[0] < 5.0e-4);  // wrapped back into the box
}

TEST_CASE("vtk: the cavity lid is written where the solver keeps it", "[vtk][output][cavity]") {
  CavityCase c;
  auto sys = c.build(load_config_string(R"(case: cavity
fluid: {density: 1.0, kinematic_viscosity: 0.01, eos: {type: linear_relative, sound_speed: 10.0}}
geometry: {box: [1.0, 1.0], wall_velocity: 1.0}
discretization: {particles_across: 10, kernel: wendland_c2, smoothing_ratio: 2.0, viscosity: morris, boundary: wall_particles, wall_model: morris}
time: {t_end: 2.0, integrator: leapfrog, dt: 1.0e-3}
)"));
  std::vector<double> y = sys->initial_state(), ydot(y.size());
  const double t = 2.0;  // the lid has carried U t = 2 m of fluid along by now; its particles stay put
  sys->rhs(t, y.data(), ydot.data());
  const auto& P = sys->particles();
  const std::size_t nf = P.n_fluid, nb = sys->base_particles();
  const Decoded wa = decode(vtp_file<2>(*sys, y.data(), t, VtkPart::walls));
  REQUIRE(wa.n == nb - nf);
  const auto& order = sys->workspace_order();
  std::size_t lid = 0;
  for (std::size_t k = nf; k < nb; ++k) {  // workspace index k -> particle i
    const std::size_t i = order.empty() ? k : order[k];
    for (int d = 0; d < 2; ++d) REQUIRE(wa.xyz[3 * (i - nf) + d] == sys->positions()[d][k]);
    if (P.v[0][i] != 0.0) {
      ++lid;
      REQUIRE(wa.point("velocity")[3 * (i - nf)] == 1.0);  // the belt moves, its particles do not
      REQUIRE(wa.xyz[3 * (i - nf)] <= 1.0 + 0.5);         // inside the box (plus the corner layers)
    }
  }
  CHECK(lid > 10);
}

TEST_CASE("vtk: the test's XML reader rejects malformed text", "[vtk][output]") {
  CHECK_THROWS(mini_xml::parse("<a><b></a></b>"));
  CHECK_THROWS(mini_xml::parse("<a x=\"1\" x=\"2\"/>"));
  CHECK_THROWS(mini_xml::parse("<a>"));
  CHECK(mini_xml::parse("<?xml version=\"1.0\"?>\n<a><b c=\"d\"/>1 2</a>\n")->child("b")->attr.at("c") == "d");
}

TEST_CASE("vtk: the test's appended-data reader rejects truncated or shifted data", "[vtk][output]") {
  ChannelCase c;
  auto sys = c.build(load_config_string(kConfig));
  std::vector<double> y = sys->initial_state(), ydot(y.size());
  sys->rhs(0.0, y.data(), ydot.data());
  const std::string good = vtp_file<2>(*sys, y.data(), 0.0, VtkPart::fluid);
  CHECK_NOTHROW(vtk_appended::read(good));
  const auto data = good.find("</AppendedData>");
  CHECK_THROWS(vtk_appended::read(good.substr(0, data - 9) + good.substr(data - 1)));  // 8 bytes short
  std::string extra = good;
  extra.insert(data - 1, "12345678");
  CHECK_THROWS(vtk_appended::read(extra));
  std::string shifted = good;
  const auto second = shifted.find("offset=\"16\"");  // TimeValue takes 8 + 8 bytes: the next array
  REQUIRE(second != std::string::npos);
  shifted.replace(second, 11, "offset=\"24\"");
  CHECK_THROWS(vtk_appended::read(shifted));
}

TEST_CASE("vtk: ghost particles are written in their own file with kind 2 and their generated state", "[vtk][ghost]") {
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
  HydrostaticCase<2> c;
  auto sys = c.build(load_config_string(yaml));
  std::vector<double> y = sys->initial_state(), ydot(y.size());
  sys->rhs(0.5, y.data(), ydot.data());
  const std::size_t nf = sys->particles().n_fluid, nb = sys->base_particles(), ng = sys->generated_particles();
  REQUIRE(nb == nf);  // ghost walls: no scene wall particles
  REQUIRE(ng > 0);
  CHECK(vtk_part_size<2>(*sys, VtkPart::walls) == 0);
  const Decoded g = decode(vtp_file<2>(*sys, y.data(), 0.5, VtkPart::ghosts));
  REQUIRE(g.n == ng);
  for (std::size_t k = 0; k < ng; ++k) {
    REQUIRE(g.point("kind")[k] == 2.0);
    REQUIRE(g.point("id")[k] == -1.0);
    REQUIRE(g.point("pressure")[k] == sys->pressure()[nb + k]);
    REQUIRE(g.point("mass")[k] == sys->particles().mass[nb + k]);
    REQUIRE(g.xyz[3 * k] == sys->positions()[0][nb + k]);
    REQUIRE(g.xyz[3 * k + 1] == sys->positions()[1][nb + k]);
    REQUIRE(g.xyz[3 * k + 1] < 0.9);  // images lie behind a wall: below y = 0 or beside the tank
    REQUIRE((g.xyz[3 * k] < 0.0 || g.xyz[3 * k] > 1.0 || g.xyz[3 * k + 1] < 0.0));
  }
  CHECK(decode(vtp_file<2>(*sys, y.data(), 0.5, VtkPart::fluid)).n == nf);
}

TEST_CASE("vtk: the observer writes one file per group and a .pvd that a restart continues", "[vtk][output]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("sphmol-vtk-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const OutputSink out{dir.string(), true};
  ChannelCase c;
  auto sys = c.build(load_config_string(kConfig));
  std::vector<double> y = sys->initial_state(), ydot(y.size());
  sys->rhs(0.0, y.data(), ydot.data());
  VtkObserver<2> first(true);
  first.at_output(*sys, y.data(), 0.0, out);
  first.at_output(*sys, y.data(), 0.25, out);
  VtkObserver<2> restarted(true);
  restarted.restore_state(first.save_state(), out);
  restarted.at_output(*sys, y.data(), 0.5, out);
  const auto pvd = mini_xml::parse(slurp_file((dir / "particles.pvd").string()));
  const auto sets = pvd->child("Collection")->all("DataSet");
  REQUIRE(sets.size() == 6);
  const char* files[] = {"fluid_0000.vtp", "walls_0000.vtp", "fluid_0001.vtp", "walls_0001.vtp", "fluid_0002.vtp", "walls_0002.vtp"};
  const double times[] = {0.0, 0.0, 0.25, 0.25, 0.5, 0.5};
  for (std::size_t k = 0; k < 6; ++k) {
    CHECK(sets[k]->attr.at("file") == files[k]);
    CHECK(sets[k]->attr.at("part") == (k % 2 == 0 ? "0" : "1"));
    CHECK(std::stod(sets[k]->attr.at("timestep")) == times[k]);
    CHECK(decode(slurp_file((dir / files[k]).string())).time == times[k]);
  }
  // A restart into another directory starts a new collection.
  const fs::path other = dir / "other";
  fs::create_directories(other);
  VtkObserver<2> elsewhere(false);
  elsewhere.restore_state(first.save_state(), OutputSink{other.string(), true});
  elsewhere.at_output(*sys, y.data(), 0.5, OutputSink{other.string(), true});
  CHECK(mini_xml::parse(slurp_file((other / "particles.pvd").string()))->child("Collection")->all("DataSet").size() == 1);
  CHECK(fs::exists(other / "fluid_0000.vtp"));
  CHECK_FALSE(fs::exists(other / "walls_0000.vtp"));
  // State saved without the group and the output count (one file per output time): continued too.
  const fs::path single = dir / "single";
  fs::create_directories(single);
  { std::ofstream(single / "particles_0000.vtp") << "x"; }
  VtkObserver<2> old(false);
  old.restore_state(nlohmann::json::parse(R"({"files": [{"t": 0.5, "file": "particles_0000.vtp"}]})"),
                    OutputSink{single.string(), true});
  old.at_output(*sys, y.data(), 1.0, OutputSink{single.string(), true});
  const auto kept_pvd = mini_xml::parse(slurp_file((single / "particles.pvd").string()));
  const auto kept = kept_pvd->child("Collection")->all("DataSet");
  REQUIRE(kept.size() == 2);
  CHECK(kept[0]->attr.at("file") == "particles_0000.vtp");
  CHECK(kept[1]->attr.at("file") == "fluid_0001.vtp");
  fs::remove_all(dir);
}

TEST_CASE("vtk: 1D shock tube: padded coordinates and the further state blocks under their names", "[vtk][output]") {
  ShockTubeCase<1> c;
  auto sys = c.build(load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/shock_tube_1d.yaml"));
  std::vector<double> y = sys->initial_state(), ydot(y.size());
  sys->rhs(0.0, y.data(), ydot.data());
  const auto& L = sys->layout();
  const std::size_t nf = sys->particles().n_fluid;
  const Decoded d = decode(vtp_file<1>(*sys, y.data(), 0.0, VtkPart::fluid));
  REQUIRE(d.n == nf);
  const auto names = L.field_names();
  REQUIRE(L.has_density);  // continuity density: a state block named "density" like the point array
  REQUIRE(L.extra_blocks() >= 2);
  std::set<std::string> seen;
  for (const auto* a : d.pd->all("DataArray")) CHECK(seen.insert(a->attr.at("Name")).second);  // names unique
  for (std::size_t b = 0; b < L.extra_blocks(); ++b) {
    INFO(names[2 + b]);
    const auto& v = d.point(names[2 + b]);
    REQUIRE(v.size() == nf);
    for (std::size_t i = 0; i < nf; ++i) REQUIRE(v[i] == y[L.velocities_end() + b * nf + i]);
  }
  for (std::size_t i = 0; i < nf; ++i) {
    REQUIRE(d.xyz[3 * i] == sys->domain().wrap(0, y[L.position(0) + i]));
    REQUIRE(d.xyz[3 * i + 1] == 0.0);
    REQUIRE(d.xyz[3 * i + 2] == 0.0);
  }
}
