// Hardened input (exit 2, message with file:line, key and hint, no output directory) and the
// output files: VTK collection, gnuplot plots, and a missing gnuplot being a warning only.
#include <catch2/catch.hpp>

#include "../unit/mini_xml.hpp"
#include "../unit/vtk_appended.hpp"
#include "run_helpers.hpp"

using namespace run_helpers;
using Catch::Matchers::Contains;

TEST_CASE("input: config errors exit 2 with location and hint, and write nothing", "[input][integration]") {
  const fs::path dir = scratch("input");
  const fs::path out = dir / "out";
  const std::string o = " --output '" + out.string() + "'";
  std::ofstream(dir / "bad.yaml") << slurp(std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml") << "extra_key: 1\n";
  auto r = sph_mol("--config '" + (dir / "bad.yaml").string() + "'" + o, dir / "e");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("bad.yaml:") && Contains("extra_key: unknown key"));
  r = sph_mol(couette("--set time.rtl=1e-8" + o), dir / "e");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("--set time.rtl=1e-8: time.rtl: unknown key (did you mean 'rtol'?"));
  r = sph_mol(couette("--set output.checkpoint_every=-1" + o), dir / "e");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("output.checkpoint_every: -1 is out of range (allowed: >= 0 s"));
  r = sph_mol("--config '" + (dir / "missing.yaml").string() + "'" + o, dir / "e");
  CHECK(r.code == 2);
  r = sph_mol("--no-such-option" + o, dir / "e");
  CHECK(r.code == 2);
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("output: VTK collection and gnuplot profile plot", "[vtk][plots][integration]") {
  const fs::path dir = scratch("files");
  auto r = sph_mol(couette("--set time.t_end=0.05 --set output.vtk=true --set output.vtk_walls=false "
                           "--set output.plots=true --output '" + (dir / "a").string() + "'"),
                   dir / "e");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto pvd = mini_xml::parse(slurp(dir / "a" / "particles.pvd"));
  const auto sets = pvd->child("Collection")->all("DataSet");
  REQUIRE(sets.size() == 4);  // the initial state, 0.0225, 0.045, 0.05: fluid only
  CHECK(std::stod(sets[0]->attr.at("timestep")) == 0.0);
  CHECK(std::stod(sets[3]->attr.at("timestep")) == 0.05);
  for (const auto* s : sets) {
    CHECK(s->attr.at("part") == "0");
    CHECK(s->attr.at("name") == "fluid");
    const std::string text = slurp(dir / "a" / s->attr.at("file"));
    const auto vtp = vtk_appended::read(text);
    const auto* poly = vtp.root->child("PolyData");
    CHECK(poly->child("Piece")->attr.at("NumberOfPoints") == "200");
    CHECK(vtp.of(vtk_appended::array_named(*poly->child("FieldData"), "TimeValue"))[0] == std::stod(s->attr.at("timestep")));
  }
  CHECK(fs::exists(dir / "a" / "fluid_0003.vtp"));
  CHECK_FALSE(fs::exists(dir / "a" / "walls_0000.vtp"));
  const auto summary = json_file(dir / "a" / "summary.json");
  const bool have_gnuplot = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  if (have_gnuplot) {
    CHECK(summary["plots"] == nlohmann::json::array({"profiles.png"}));
    const std::string png = slurp(dir / "a" / "profiles.png");
    CHECK(png.substr(1, 3) == "PNG");
  } else {
    WARN("gnuplot not installed: the PNG part of this test is skipped");
  }

  // Without gnuplot on PATH: a warning, exit 0, results written.
  r = sph_mol(couette("--set time.t_end=0.02 --set output.plots=true --output '" + (dir / "b").string() + "'"),
              dir / "e2", "PATH=/nonexistent");
  CHECK(r.code == 0);
  CHECK_THAT(r.err, Contains("gnuplot not found"));
  const auto s2 = json_file(dir / "b" / "summary.json");
  CHECK(s2["plots"].empty());
  CHECK_THAT(s2["warnings"][0].get<std::string>(), Contains("gnuplot not found"));
}

TEST_CASE("output: Taylor-Green decay and cavity centre-line plots", "[plots][integration][taylor_green][cavity]") {
  const fs::path dir = scratch("box-plots");
  const std::string v = std::string(SPHMOL_SOURCE_DIR) + "/verification/";
  auto r = sph_mol("--config '" + v + "taylor_green.yaml' -q --set discretization.particles_across=20 --set time.t_end=0.1 "
                   "--set 'output.times=[0.05, 0.1]' --set output.plots=true --output '" + (dir / "tg").string() + "'",
                   dir / "e1");
  INFO(r.err);
  REQUIRE(r.code == 0);
  // The decay CSV holds every output time; the plot reads it.
  const std::string decay = slurp(dir / "tg" / "decay.csv");
  CHECK_THAT(decay, Contains("t [s],maxv_sph [m/s],mode_amplitude_sph [m/s],amplitude_exact [m/s]\n") && Contains("\n0.05,") && Contains("\n0.1,"));
  r = sph_mol("--config '" + v + "cavity.yaml' -q --set discretization.particles_across=20 --set time.dt=1.2e-3 "
              "--set time.t_end=0.1 --set 'output.times=[0.1]' --set output.plots=true --output '" +
                  (dir / "cav").string() + "'",
              dir / "e2");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(fs::exists(dir / "cav" / "centreline_u_t0.1.csv"));
  CHECK(fs::exists(dir / "cav" / "centreline_v_t0.1.csv"));
  const bool have_gnuplot = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  if (!have_gnuplot) {
    WARN("gnuplot not installed: the PNG part of this test is skipped");
    return;
  }
  CHECK(json_file(dir / "tg" / "summary.json")["plots"] == nlohmann::json::array({"decay.png"}));
  CHECK(slurp(dir / "tg" / "decay.png").substr(1, 3) == "PNG");
  CHECK(json_file(dir / "cav" / "summary.json")["plots"] == nlohmann::json::array({"centrelines.png"}));
  CHECK(slurp(dir / "cav" / "centrelines.png").substr(1, 3) == "PNG");
  CHECK(fs::exists(dir / "cav" / "plot_centrelines.gp"));
}
