// Cases are modules: each owns its config sections, shared code never names a case, and the
// registry's records agree with what the modules build.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sphmol/cases/case_module.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/config/yaml_reader.hpp"

using namespace sphmol;
namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every source file under `dir` (relative to the checkout), except those under `except`.
std::vector<fs::path> sources(const std::string& dir, const std::string& except = "") {
  std::vector<fs::path> out;
  const fs::path root = fs::path(SPHMOL_SOURCE_DIR) / dir;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    if (!e.is_regular_file()) continue;
    const auto ext = e.path().extension();
    if (ext != ".cpp" && ext != ".hpp") continue;
    if (!except.empty() && e.path().string().find(except) != std::string::npos) continue;
    out.push_back(e.path());
  }
  return out;
}

}  // namespace

TEST_CASE("case modules: no case name appears in shared code, and only the registry includes a case", "[cases]") {
  auto files = sources("lib/sphmol", "/lib/sphmol/cases/");
  for (const auto& p : sources("apps/sph-mol")) files.push_back(p);
  REQUIRE(files.size() > 50);
  const auto names = case_names();
  REQUIRE(names.size() >= 7);
  for (const auto& p : files) {
    std::string text = read_text(p);
    // `sph-mol kernels --analysis hydrostatic` names a kernel analysis (the lattice of Potapov &
    // Reshetnikova 2021), not the case.
    if (p.filename() == "cmd_kernels.cpp")
      for (std::size_t at; (at = text.find("analysis == \"hydrostatic\"")) != std::string::npos;) text.erase(at, 25);
    // A scene's `pressure: hydrostatic` (scene/scene_spec.hpp) is an initial state, not the case.
    if (p.filename() == "scene_spec.hpp")
      for (std::size_t at; (at = text.find("kHydrostaticPressure = \"hydrostatic\"")) != std::string::npos;) text.erase(at, 36);
    for (const auto& name : names) {
      INFO(p.string() << " names case '" << name << "'");
      CHECK(text.find("\"" + name + "\"") == std::string::npos);
      CHECK(text.find("case '" + name + "'") == std::string::npos);
    }
    INFO(p.string() << " includes a case's own header");
    std::size_t at = 0;
    while ((at = text.find("#include \"sphmol/cases/", at)) != std::string::npos) {
      const std::string line = text.substr(at, text.find('\n', at) - at);
      CHECK(line == "#include \"sphmol/cases/case_module.hpp\"");
      at += line.size();
    }
    // Shared code asks a case what it needs through the module record, never by comparing names.
    CHECK(text.find("case_name == \"") == std::string::npos);
    CHECK(text.find("case_name != \"") == std::string::npos);
  }
}

TEST_CASE("case modules: each record builds the case in exactly its declared dimensions", "[cases]") {
  for (const auto& m : case_modules()) {
    INFO("case " << m.name);
    CHECK(!m.name.empty());
    CHECK(!m.description.empty());
    CHECK(m.read);
    CHECK(static_cast<bool>(m.make1) == m.supports(1));
    CHECK(static_cast<bool>(m.make2) == m.supports(2));
    CHECK(static_cast<bool>(m.make3) == m.supports(3));
    CHECK(find_case_module(m.name) == &m);
  }
  CHECK(find_case_module("no_such_case") == nullptr);
}

TEST_CASE("case modules: a case's sections are its own, another case's keys are config errors", "[cases][config]") {
  const std::string base = std::string(SPHMOL_SOURCE_DIR) + "/verification/";
  // The Taylor-Green case has no water column and no wall speed (they used to be accepted and ignored).
  try {
    (void)load_config(base + "taylor_green.yaml", {"geometry.column=[0.1, 0.1]"});
    FAIL("accepted geometry.column for taylor_green");
  } catch (const ConfigError& e) {
    CHECK_THAT(e.what(), Catch::Contains("geometry.column: unknown key"));
  }
  try {
    (void)load_config(base + "hydrostatic.yaml", {"geometry.wall_velocity=1"});
    FAIL("accepted geometry.wall_velocity for hydrostatic");
  } catch (const ConfigError& e) {
    CHECK_THAT(e.what(), Catch::Contains("geometry.wall_velocity: unknown key"));
  }
  // A top-level section of another case names the sections this case has.
  try {
    (void)load_config(base + "couette.yaml", {"shock_tube.left.density=1"});
    FAIL("accepted a shock_tube section for couette");
  } catch (const ConfigError& e) {
    CHECK_THAT(e.what(), Catch::Contains("shock_tube: is not used by case 'couette' (its own sections: geometry)"));
  }
  // Each module writes its sections back so that the resolved YAML loads to the same settings.
  for (const auto* f : {"couette", "poiseuille", "taylor_green", "hydrostatic", "cavity", "shock_tube", "dam_break", "duct_3d",
                        "beltrami_3d"}) {
    INFO(f);
    const Config c = load_config(base + f + ".yaml");
    const Config r = load_config_string(to_yaml(c));
    REQUIRE(r.case_settings);
    CHECK(r.case_settings->to_yaml() == c.case_settings->to_yaml());
  }
}

TEST_CASE("yaml reader: lists of maps and narrowed key lists locate their errors", "[config]") {
  const YAML::Node root = YAML::Load("items:\n  - {a: 1, b: 2}\n  - {a: 3, c: 4}\nscalar: 5\n");
  const YamlOrigin origin("f.yaml");
  MapReader top(origin, root, "", root.Mark(), {"items", "scalar"});
  const auto items = top.section_list("items", {"a", "b", "c"});
  REQUIRE(items.size() == 2);
  CHECK(items[1].path() == "items[1]");
  auto first = items[0];
  CHECK(first.real("a") == 1.0);
  // Narrowing to {a, b} rejects the second item's c, at its line.
  try {
    (void)items[1].with_keys({"a", "b"});
    FAIL("accepted c");
  } catch (const ConfigError& e) {
    CHECK_THAT(e.what(), Catch::StartsWith("f.yaml:3: items[1].c: unknown key"));
  }
  CHECK(items[0].with_keys({"a", "b"}).keys_present() == std::vector<std::string>{"a", "b"});
  try {
    (void)top.section_list("scalar", {"a"});
    FAIL("accepted a scalar as a list");
  } catch (const ConfigError& e) {
    CHECK_THAT(e.what(), Catch::Contains("scalar: expected a list of maps"));
  }
  CHECK(top.section_list("absent", {"a"}).empty());
}
