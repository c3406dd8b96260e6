// Ghia, Ghia & Shin (1982) loader: column selection by Re, wall/lid values, malformed files.
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "sphmol/reference/ghia_table.hpp"

using sphmol::load_ghia;

namespace {
const std::string dir = std::string(SPHMOL_SOURCE_DIR) + "/verification/";
const std::string path_u = dir + "ghia1982_u_vertical_centreline.csv";
const std::string path_v = dir + "ghia1982_v_horizontal_centreline.csv";

std::string write_temp(const std::string& name, const std::string& text) {
  const auto p = std::filesystem::temp_directory_path() / ("sphmol_test_ghia_" + name);
  std::ofstream(p) << text;
  return p.string();
}

std::string load_error(const std::string& pu, const std::string& pv) {
  try {
    load_ghia(pu, pv, 100.0);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("Ghia 1982: Re 100 centre lines with no-slip and lid values", "[reference][ghia]") {
  const auto t = load_ghia(path_u, path_v, 100.0);
  REQUIRE(t.has_value());
  REQUIRE(t->y.size() == 17);  // Table I: 17 points incl. both walls
  REQUIRE(t->x.size() == 17);  // Table II
  REQUIRE(t->u.size() == t->y.size());
  REQUIRE(t->v.size() == t->x.size());
  CHECK(t->y.front() == 0.0);
  CHECK(t->u.front() == 0.0);  // no slip on the bottom wall
  CHECK(t->y.back() == 1.0);
  CHECK(t->u.back() == 1.0);   // lid speed
  CHECK(t->v.front() == 0.0);  // side walls
  CHECK(t->v.back() == 0.0);
  CHECK(t->u[8] == -0.20581);  // y = 0.5
  CHECK(t->y[8] == 0.5);
}

TEST_CASE("Ghia 1982: other Reynolds numbers and missing columns", "[reference][ghia]") {
  const auto t400 = load_ghia(path_u, path_v, 400.0);
  REQUIRE(t400);
  CHECK(t400->v[11] == -0.23827);  // x = 0.9063, kept as printed (see verification/README.md)
  const auto t1000 = load_ghia(path_u, path_v, 1000.0 * (1.0 + 5e-10));
  REQUIRE(t1000);
  CHECK(t1000->u[1] == -0.18109);
  CHECK_FALSE(load_ghia(path_u, path_v, 100.0 * (1.0 + 1e-6)).has_value());
  CHECK_FALSE(load_ghia(path_u, path_v, 3200.0).has_value());
}

TEST_CASE("Ghia 1982: malformed files are rejected with a clear message", "[reference][ghia]") {
  const std::string good_v = write_temp("v.csv", "# c\nx,v_Re100\n0,0\n0.5,0.05\n1,0\n");
  const std::string bad_num = write_temp("num.csv", "# c\ny,u_Re100\n0,0\n0.5,abc\n1,1\n");
  CHECK_THAT(load_error(bad_num, good_v), Catch::Contains(bad_num + ":4") && Catch::Contains("not a number"));
  const std::string bad_cols = write_temp("cols.csv", "y,u_Re100,u_Re400\n0,0,0\n0.5,0.1\n");
  CHECK_THAT(load_error(bad_cols, good_v), Catch::Contains(":3") && Catch::Contains("expected 3 columns"));
  const std::string bad_header = write_temp("hdr.csv", "0,0\n1,1\n");
  CHECK_THAT(load_error(bad_header, good_v), Catch::Contains("header"));
  const std::string bad_order = write_temp("order.csv", "y,u_Re100\n0,0\n0.6,0.1\n0.5,0.2\n");
  CHECK_THAT(load_error(bad_order, good_v), Catch::Contains("strictly increasing"));
  const std::string bad_name = write_temp("name.csv", "y,u_Reynolds\n0,0\n");
  CHECK_THAT(load_error(bad_name, good_v), Catch::Contains("not a number"));
  CHECK_THAT(load_error(dir + "does_not_exist.csv", good_v), Catch::Contains("cannot open"));
  // Re present in the u file but not in the v file: inconsistent pair.
  const std::string good_u = write_temp("u.csv", "y,u_Re100\n0,0\n1,1\n");
  const std::string v400 = write_temp("v400.csv", "x,v_Re400\n0,0\n1,0\n");
  CHECK_THAT(load_error(good_u, v400), Catch::Contains("only one"));
  REQUIRE(load_ghia(good_u, good_v, 100.0));  // the well-formed pair loads
  for (const auto& p : {good_v, bad_num, bad_cols, bad_header, bad_order, bad_name, good_u, v400}) std::remove(p.c_str());
}

TEST_CASE("Ghia 1982: plain CSV with units in the header, as shipped", "[reference][ghia]") {
  // The shipped tables are plain CSV (pandas.read_csv reads them as they are): no comment lines.
  for (const auto& p : {path_u, path_v}) {
    std::ifstream in(p);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(text.find('#') == std::string::npos);
    CHECK(text.substr(0, text.find('\n')).find(" [-]") != std::string::npos);
  }
  const std::string u = write_temp("u_units.csv", "y [-],u_Re100 [-]\n0,0\n0.5,-0.2\n1,1\n");
  const std::string v = write_temp("v_units.csv", "x [-],v_Re100 [-]\n0,0\n0.5,0.05\n1,0\n");
  const auto t = load_ghia(u, v, 100.0);
  REQUIRE(t);
  CHECK(t->u == std::vector<double>{0.0, -0.2, 1.0});
  CHECK(t->x == std::vector<double>{0.0, 0.5, 1.0});
  const std::string metres = write_temp("u_metres.csv", "y [m],u_Re100 [-]\n0,0\n1,1\n");
  CHECK_THAT(load_error(metres, v), Catch::Contains(metres + ":1") && Catch::Contains("the unit must be [-]"));
  for (const auto& p : {u, v, metres}) std::remove(p.c_str());
}
