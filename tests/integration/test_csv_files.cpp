// Every CSV file a short run of each case writes is a plain table that pandas.read_csv, numpy and
// gnuplot read with no options: exactly one header row whose column names carry their unit in
// brackets, then only numeric rows with as many cells as the header (a missing value is an empty
// cell, never "nan"), no comment lines. The cases' gnuplot scripts must still draw from them. With python3 on PATH the files are also read
// with Python's csv module (an independent reader); the test does not need it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <unistd.h>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "run_helpers.hpp"
#include "support/process.hpp"

using namespace run_helpers;

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  std::string c;
  while (std::getline(s, c, ',')) cells.push_back(c);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

bool numeric(const std::string& cell) {
  if (cell.empty()) return false;
  char* end = nullptr;
  std::strtod(cell.c_str(), &end);
  return end == cell.c_str() + cell.size();
}

// A data cell: a finite number, or empty for a value that is missing (pandas and numpy read an empty
// cell as NaN). "nan" and "inf" are not: gnuplot and spreadsheets take them as text.
bool data_cell(const std::string& cell) {
  if (cell.empty()) return true;
  char* end = nullptr;
  const double x = std::strtod(cell.c_str(), &end);
  return end == cell.c_str() + cell.size() && std::isfinite(x);
}

// Problems of one file, empty when it is a plain numeric table with a unit in every column name.
std::string csv_problems(const fs::path& file, bool numeric_rows) {
  const std::string text = slurp(file);
  if (text.find('#') != std::string::npos) return "contains '#'";
  if (text.empty() || text.back() != '\n') return "does not end with a newline";
  std::stringstream s(text);
  std::string line;
  std::getline(s, line);
  const auto header = split(line);
  for (const auto& name : header) {
    if (numeric(name)) return "header cell '" + name + "' is a number";
    if (name.size() > 4 && name.compare(name.size() - 4, 4, " [1]") == 0) return "column '" + name + "': a dimensionless unit is [-]";
    const auto open = name.find(" [");
    if (open == std::string::npos || name.back() != ']') {
      // Text columns (labels, status) have no unit; numeric tables have none of them.
      if (numeric_rows) return "column '" + name + "' has no [unit]";
    }
  }
  std::size_t rows = 0;
  while (std::getline(s, line)) {
    ++rows;
    const auto cells = split(line);
    if (cells.size() != header.size())
      return "row " + std::to_string(rows) + " has " + std::to_string(cells.size()) + " cells, the header " +
             std::to_string(header.size());
    if (numeric_rows)
      for (const auto& c : cells)
        if (!data_cell(c)) return "row " + std::to_string(rows) + ": '" + c + "' is neither a finite number nor empty";
  }
  if (rows == 0) return "no data rows";
  return {};
}

std::vector<fs::path> csv_files(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".csv") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// The program's path on PATH, or "".
std::string on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::string d;
  while (std::getline(dirs, d, ':'))
    if (!d.empty() && ::access((d + "/" + program).c_str(), X_OK) == 0) return d + "/" + program;
  return {};
}

// Python's csv module as a second, independent reader (argv, no shell).
void check_with_python(const std::string& python, const std::vector<fs::path>& files, const fs::path& err) {
  const char* script =
      "import csv, math, sys\n"
      "for name in sys.argv[1:]:\n"
      "    with open(name, newline='') as f:\n"
      "        rows = list(csv.reader(f))\n"
      "    header = rows[0]\n"
      "    assert all(c.endswith(']') and ' [' in c for c in header), (name, header)\n"
      "    assert len(rows) > 1, name\n"
      "    for r in rows[1:]:\n"
      "        assert len(r) == len(header), (name, r)\n"
      "        assert all(c == '' or math.isfinite(float(c)) for c in r), (name, r)\n";
  std::vector<std::string> args{"-c", script};
  for (const auto& f : files) args.push_back(f.string());
  const auto r = test_support::run_process(python, args, err.string());
  INFO(r.err);
  CHECK(r.code == 0);
}

}  // namespace

TEST_CASE("csv: every case writes plain CSV tables with units in the header", "[integration][csv][plots]") {
  const fs::path dir = scratch("csv");
  const std::string v = std::string(SPHMOL_SOURCE_DIR) + "/verification/";
  struct Run {
    std::string name, config;
    std::vector<std::string> sets;
    std::vector<std::string> expect;  // files that must be among the CSVs
  };
  const std::vector<Run> runs = {
      {"couette", "couette.yaml", {"discretization.particles_across=20", "time.t_end=0.05", "output.times=[0.025, 0.05]"},
       {"profile_t0.025.csv", "profile_t0.05.csv"}},
      {"poiseuille", "poiseuille.yaml", {"discretization.particles_across=20", "time.t_end=0.02", "output.times=[0.02]"},
       {"profile_t0.02.csv"}},
      {"shock_tube", "shock_tube.yaml",
       {"discretization.spacing=5e-3", "time.integrator=leapfrog", "time.t_end=0.02", "output.times=[0.02]"},
       {"profile_t0.02.csv", "midline_t0.02.csv"}},
      {"shock_tube_1d", "shock_tube_1d.yaml", {"time.integrator=leapfrog", "time.t_end=0.02", "output.times=[0.01, 0.02]"},
       {"profile_t0.01.csv", "midline_t0.02.csv"}},
      {"taylor_green", "taylor_green.yaml", {"discretization.particles_across=20", "time.t_end=0.1", "output.times=[0.05, 0.1]"},
       {"decay.csv"}},
      {"cavity", "cavity.yaml",
       {"discretization.particles_across=20", "time.dt=1.2e-3", "time.t_end=0.1", "output.times=[0.05, 0.1]"},
       {"centreline_u_t0.1.csv", "centreline_v_t0.1.csv"}},
      {"hydrostatic", "hydrostatic.yaml",
       {"discretization.particles_across=10", "time.dt=1e-3", "time.t_end=0.05", "output.times=[0.05]"},
       {"pressure_t0.05.csv"}},
      {"dam_break", "dam_break.yaml", {"discretization.spacing=0.04", "time.t_end=0.2", "output.times=[0.1, 0.2]"},
       {"front.csv", "front_martin_moyce_1952.csv", "front_koshizuka_oka_1996.csv"}},
      // H != 2a: the experiments' columns of front.csv are missing in every row.
      {"dam_break_tall", "dam_break.yaml",
       {"discretization.spacing=0.05", "geometry.column=[1.0, 2.5]", "time.t_end=0.05", "output.times=[0.05]"},
       {"front.csv"}},
      {"duct_3d", "duct_3d.yaml",
       {"discretization.particles_across=8", "geometry.length=1e-3", "time.t_end=0.05", "output.times=[0.025, 0.05]"},
       {"peak.csv", "profile_t0.025.csv", "profile_t0.05.csv"}},
      {"beltrami_3d", "beltrami_3d.yaml", {"discretization.particles_across=8", "time.t_end=0.05", "output.times=[0.025, 0.05]"},
       {"decay.csv"}},
  };
  const bool have_gnuplot = !on_path("gnuplot").empty();
  std::vector<fs::path> all;
  for (const auto& run : runs) {
    INFO(run.name);
    const fs::path out = dir / run.name;
    std::vector<std::string> args{"--config", v + run.config, "-q", "--output", out.string(), "--set", "output.plots=true"};
    for (const auto& s : run.sets) {
      args.push_back("--set");
      args.push_back(s);
    }
    const auto r = test_support::run_process(SPHMOL_BINARY, args, (dir / (run.name + ".err")).string());
    INFO(r.err);
    REQUIRE(r.code == 0);
    const auto files = csv_files(out);
    for (const auto& e : run.expect) CHECK(std::find(files.begin(), files.end(), out / e) != files.end());
    for (const auto& f : files) {
      INFO(f.filename().string());
      CHECK(csv_problems(f, true) == "");
      all.push_back(f);
    }
    // Provenance (what each file compares with) is in the summary, not in the files.
    const auto summary = json_file(out / "summary.json");
    for (const auto& f : files) {
      std::string pattern = f.filename().string();
      const auto t = pattern.rfind("_t");
      if (t != std::string::npos) pattern = pattern.substr(0, t) + "_t<t>.csv";
      CHECK(summary["csv_files"].contains(pattern));
    }
    if (have_gnuplot) {
      CHECK(!summary["plots"].empty());
      CHECK(summary.value("warnings", nlohmann::json::array()).empty());
    }
  }

  // A run that blows up leaves its last good state as a table of the same kind.
  const fs::path out = dir / "blow_up";
  const auto r = test_support::run_process(
      SPHMOL_BINARY,
      {"--config", v + "couette.yaml", "-q", "--output", out.string(), "--set", "discretization.particles_across=20", "--set",
       "time.integrator=leapfrog", "--set", "time.dt=2e-2", "--set", "time.t_end=5", "--set", "output.times=[5]"},
      (dir / "blow_up.err").string());
  REQUIRE(r.code == 3);
  CHECK(csv_problems(out / "last_good_state.csv", true) == "");
  all.push_back(out / "last_good_state.csv");

  if (const std::string python = on_path("python3"); !python.empty())
    check_with_python(python, all, dir / "python.err");
  else
    WARN("python3 not on PATH: the csv-module check is skipped");
}

TEST_CASE("csv: the study and kernel tables have one header row and no comment lines", "[integration][csv]") {
  const fs::path dir = scratch("csv-studies");
  const auto r = test_support::run_process(SPHMOL_BINARY, {"kernels", "--analysis", "hydrostatic", "--output", dir.string()},
                                           (dir / "k.err").string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto files = csv_files(dir);
  REQUIRE(files.size() >= 3);
  CHECK(std::find(files.begin(), files.end(), dir / "hydrostatic_roots.csv") != files.end());
  for (const auto& f : files) {
    INFO(f.filename().string());
    const bool curves = f.filename().string().rfind("hydrostatic_curves_", 0) == 0;
    CHECK(csv_problems(f, curves) == "");
    // One value per cell (the roots were ';'-joined lists, which numpy reads as text), and column
    // names a reader can use as identifiers with their unit (no '=' or '/').
    const std::string text = slurp(f);
    CHECK(text.find(';') == std::string::npos);
    const std::string header = text.substr(0, text.find('\n'));
    CHECK(header.find('=') == std::string::npos);
    CHECK(header.find('/') == std::string::npos);
  }
}

TEST_CASE("csv: output.profiles false writes no per-output-time files in any case", "[integration][csv][output]") {
  // The hydrostatic tank (pressure_t<t>.csv) and the cavity (centreline_[uv]_t<t>.csv) wrote them anyway.
  const fs::path dir = scratch("no-profiles");
  const std::string v = std::string(SPHMOL_SOURCE_DIR) + "/verification/";
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"hydrostatic.yaml", "discretization.particles_across=10"}, {"cavity.yaml", "discretization.particles_across=10"},
      {"couette.yaml", "discretization.particles_across=20"}, {"shock_tube_1d.yaml", "discretization.spacing=0.02"}};
  for (const auto& [config, size] : runs) {
    INFO(config);
    const fs::path out = dir / config;
    const auto r = test_support::run_process(SPHMOL_BINARY,
                                             {"--config", v + config, "-q", "--threads", "1", "--output", out.string(), "--set", size,
                                              "--set", "time.t_end=0.05", "--set", "output.times=[0.05]", "--set", "output.profiles=false"},
                                             (dir / "err").string());
    INFO(r.err);
    REQUIRE(r.code == 0);
    for (const auto& f : csv_files(out)) {
      INFO(f.filename().string());
      CHECK(f.filename().string().find("_t0.05") == std::string::npos);
    }
    const auto summary = json_file(out / "summary.json");
    for (const auto& [pattern, what] : summary["csv_files"].items()) CHECK(pattern.find("_t<t>") == std::string::npos);
  }
}
