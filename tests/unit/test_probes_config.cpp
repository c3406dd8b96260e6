// The `probes` section and output.every: what each probe type reads, the errors (FILE:LINE: key:
// message) for bad types, missing or misplaced keys, names unfit for file names, duplicates, planes
// in 2D, force probes on bodies the scene does not have; to_yaml writes back what was read.
#include <catch2/catch.hpp>

#include <string>

#include "config_test_base.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/config/yaml_reader.hpp"
#include "sphmol/probes/probe_config.hpp"

using namespace sphmol;
using config_test::base;
using config_test::error_of;

namespace {

// `base` (t_end 0.5; its last line is line 17) with `probes:` on line 18, the first probe on line 19.
std::string with_probes(const std::string& probes) { return base + "probes:\n" + probes; }

}  // namespace

TEST_CASE("probes config: each type reads its keys", "[probes][config]") {
  const Config c = load_config_string(with_probes(R"(  - {name: p_front, type: point, at: [2.0e-4, 5.0e-4], fields: [velocity, p]}
  - {name: u_line, type: line, from: [0, 1.0e-4], to: [5.0e-4, 1.0e-4], points: 11, every: 0.01}
  - {name: gauge-1, type: height_gauge, at: [2.5e-4], range: [0, 1.0e-3]}
)"), {}, "case.yaml");
  REQUIRE(c.probes.size() == 3);
  CHECK(c.probes[0].type == "point");
  CHECK(c.probes[0].at == std::vector<double>{2.0e-4, 5.0e-4});
  CHECK(c.probes[0].fields == std::vector<std::string>{"p", "velocity"});  // the columns' fixed order
  CHECK(!c.probes[0].every);
  CHECK(c.probes[0].where == "case.yaml:19: probes[0].at");
  CHECK(c.probes[1].points == std::vector<int>{11});
  CHECK(*c.probes[1].every == 0.01);
  CHECK(c.probes[1].fields == std::vector<std::string>{"p", "rho", "velocity"});  // default: all
  CHECK(c.probes[1].sample_points().size() == 11);
  CHECK(c.probes[1].sample_points()[10][0] == Approx(5.0e-4));
  CHECK(c.probes[2].range == std::vector<double>{0, 1.0e-3});
  // Written back and read again: the same probes.
  const Config again = load_config_string(to_yaml(c), {}, "case.yaml");
  CHECK(to_yaml(again) == to_yaml(c));
  REQUIRE(again.probes.size() == 3);
  CHECK(again.probes[0].fields == c.probes[0].fields);
  CHECK(again.probes[2].name == "gauge-1");
}

TEST_CASE("probes config: errors name the key and its line", "[probes][config]") {
  CHECK(error_of(with_probes("  - {name: a, type: pointt, at: [0, 0]}\n")) ==
        "case.yaml:19: probes[0].type: unknown value 'pointt' (did you mean 'point'? allowed: point, line, plane, "
        "height_gauge, force)");
  CHECK(error_of(with_probes("  - {name: a, type: point}\n")).rfind("case.yaml:19: probes[0].at: required value missing", 0) == 0);
  CHECK(error_of(with_probes("  - {type: point, at: [0, 0]}\n")).rfind("case.yaml:19: probes[0].name: required value missing", 0) == 0);
  CHECK(error_of(with_probes("  - {name: a, type: point, at: [0, 0, 0]}\n")) ==
        "case.yaml:19: probes[0].at: expected 2 coordinates (the point's position in 2D), got 3");
  CHECK(error_of(with_probes("  - {name: a, type: point, at: [0, 0], points: 3}\n")).rfind("case.yaml:19: probes[0].points: unknown key", 0) == 0);
  CHECK(error_of(with_probes("  - {name: ../a, type: point, at: [0, 0]}\n")) ==
        "case.yaml:19: probes[0].name: '../a' may hold only letters, digits, '_' and '-' (it names the file probe_<name>.csv)");
  CHECK(error_of(with_probes("  - {name: " + std::string(101, 'n') + ", type: point, at: [0, 0]}\n")) ==
        "case.yaml:19: probes[0].name: is 101 characters long, more than 100 (it names the file probe_<name>.csv)");
  CHECK(error_of(with_probes("  - {name: a, type: point, at: [0, 0]}\n  - {name: a, type: point, at: [0, 1.0e-4]}\n")) ==
        "case.yaml:20: probes[1].name: 'a' is used by an earlier probe (names must be unique)");
  CHECK(error_of(with_probes("  - {name: a, type: plane, origin: [0, 0], edge_1: [1, 0], edge_2: [0, 1], points: [2, 2]}\n")) ==
        "case.yaml:19: probes[0].type: a plane probe needs dimension 3 (this run is 2D; use a line probe)");
  CHECK(error_of(with_probes("  - {name: f, type: force, body: obstacle}\n")) ==
        "case.yaml:19: probes[0].body: the scene has no wall body named 'obstacle' (this scene has no named wall bodies)");
  CHECK(error_of(with_probes("  - {name: a, type: point, at: [0, 0], every: 0}\n")) ==
        "case.yaml:19: probes[0].every: 0 is out of range (allowed: > 0 s)");
  // Past t_end (a file shortened with --set time.t_end): accepted, with a notice.
  const Config late = load_config_string(with_probes("  - {name: a, type: point, at: [0, 0], every: 0.6}\n"), {}, "case.yaml");
  REQUIRE(late.probes.size() == 1);
  bool said = false;
  for (const auto& n : late.notices) said = said || n == "case.yaml:19: probes[0].every: 0.6 s is past time.t_end = 0.5 s: the probe samples t = 0 and t_end only";
  CHECK(said);
  CHECK(error_of(with_probes("  - {name: a, type: line, from: [0, 0], to: [0, 1.0e-4], points: 1}\n"))
            .rfind("case.yaml:19: probes[0].points: 1 is out of range", 0) == 0);
  CHECK(error_of(with_probes("  - {name: a, type: point, at: [0, 0], fields: [p, vel]}\n"))
            .rfind("case.yaml:19: probes[0].fields: unknown value 'vel'", 0) == 0);
  CHECK(error_of(with_probes("  name: a\n")).rfind("case.yaml:18: probes: ", 0) == 0);  // not a list
}

TEST_CASE("probes config: a list given with --set is named in its errors", "[probes][config]") {
  // The element paths (probes[0].at) belong to the override of the whole list.
  CHECK(error_of(base, {"probes=[{name: a, type: point, at: [1]}]"}) ==
        "--set probes=[{name: a, type: point, at: [1]}]: probes[0].at: expected 2 coordinates (the point's position in 2D), got 1");
}

TEST_CASE("output.every: evenly spaced output times instead of a list", "[probes][config]") {
  const std::string every = config_test::with("  times: [0.1, 0.2]\n", "  every: 0.1\n");
  const Config c = load_config_string(every);
  REQUIRE(c.output.times.size() == 5);
  CHECK(c.output.times[2] == Approx(0.3));
  CHECK(c.output.times.back() == 0.5);  // 5 x 0.1 rounds to t_end, not past it
  CHECK(*c.output.every == 0.1);
  const Config again = load_config_string(to_yaml(c));
  CHECK(again.output.times == c.output.times);
  CHECK(error_of(config_test::with("  times: [0.1, 0.2]\n", "  times: [0.1, 0.2]\n  every: 0.1\n")) ==
        "case.yaml:18: output.every: give either output.times or output.every, not both");
  CHECK(error_of(config_test::with("  times: [0.1, 0.2]\n", "  every: 0\n")).rfind("case.yaml:17: output.every: 0 is out of range", 0) == 0);
  // A file's list switched off from the command line gives way to every.
  const Config switched = load_config_string(config_test::with("  times: [0.1, 0.2]\n", "  times: [0.1, 0.2]\n"),
                                             {"output.times=[]", "output.every=0.25"});
  CHECK(switched.output.times == std::vector<double>{0.25, 0.5});
}

TEST_CASE("probes config: a plane in 3D, its grid and its checks", "[probes][config]") {
  const auto read = [](const std::string& yaml) {
    const YAML::Node root = YAML::Load(yaml);
    const YamlOrigin origin("case.yaml");
    MapReader top(origin, root, "", root.Mark(), {"probes"});
    Config c;
    c.dimension = 3;
    c.time.t_end = 1.0;
    return read_probes(top, c, {});
  };
  const auto p = read("probes:\n  - {name: mid, type: plane, origin: [0, 0, 0.5], edge_1: [1, 0, 0], edge_2: [0, 2, 0], points: [3, 2]}\n");
  REQUIRE(p.size() == 1);
  const auto pts = p[0].sample_points();
  REQUIRE(pts.size() == 6);
  CHECK(pts[1] == std::vector<double>{0.5, 0, 0.5});  // edge_1 varies fastest
  CHECK(pts[3] == std::vector<double>{0, 2, 0.5});
  CHECK(pts[5] == std::vector<double>{1, 2, 0.5});
  try {
    (void)read("probes:\n  - {name: mid, type: plane, origin: [0, 0, 0], edge_1: [1, 0, 0], edge_2: [2, 0, 0], points: [3, 2]}\n");
    FAIL("no error");
  } catch (const ConfigError& e) {
    CHECK(std::string(e.what()) == "case.yaml:2: probes[0].edge_2: is parallel to edge_1 (or one of them is zero): they must span a plane");
  }
  try {
    (void)read("probes:\n  - {name: g, type: height_gauge, at: [0.1]}\n");
    FAIL("no error");
  } catch (const ConfigError& e) {
    CHECK(std::string(e.what()) == "case.yaml:2: probes[0].at: expected 2 coordinates (x and y of the vertical line), got 1");
  }
}
