// gnuplot runs a file name that starts with '|' or '<' as a shell command and ends a command at a
// newline: output folder names with quotes, spaces, $(...), ';', backquotes, '|', '<' and newlines,
// given to compare, converge, stability and a plain run with plots, must run no command and keep
// every file inside the folder. The runs are tiny (Couette, 10 particles across, t_end 2 ms).
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/files.hpp"
#include "support/process.hpp"

namespace fs = std::filesystem;

namespace {

// Every path under `root` whose name starts with "pwned": the marker a command injection would create.
std::vector<std::string> markers(const fs::path& root) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.path().filename().string().rfind("pwned", 0) == 0) found.push_back(e.path().string());
  return found;
}

std::set<std::string> top_level(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

const std::vector<std::string> kHostileNames = {
    "|touch pwned;x",       "<touch pwned",     "q'uote'; system('touch pwned'); '", "with space",
    "$(touch pwned)",       "`touch pwned`",    "semi;touch pwned;x",                "dq\"x\"",
    "nl\n!touch pwned\n",   "nl2\nset output '|touch pwned'\nplot 1\n",               "sub/|touch pwned"};

const std::vector<std::string> kTiny = {"--set", "discretization.particles_across=10", "--set", "geometry.channel_length=1.0e-3", "--set", "time.t_end=0.002",
                                        "--set", "output.times=[0.002]"};

struct Command {
  std::string name;
  std::vector<std::string> args;  // before --output and the tiny sizes
  std::vector<std::string> files;  // expected in the output folder
};

std::vector<Command> commands() {
  const std::string couette = std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml";
  return {
      {"compare", {"compare", "--config", couette, "--integrators", "leapfrog", "--step-factors", "1"},
       {"comparison.json", "comparison.csv", "comparison.gp", "comparison.dat"}},
      {"converge", {"converge", "--config", couette, "--refine", "time", "--levels", "2", "--integrators", "leapfrog", "--dt0", "1e-4"},
       {"convergence.json", "convergence.csv", "convergence.gp"}},
      {"stability", {"stability", "--config", couette, "--sound-speed-factors", "1", "--step-factors", "1", "--samples", "3"},
       {"stability.json", "stability.csv", "stability.gp"}},
      {"run", {"--config", couette, "-q", "--set", "output.plots=true"}, {"summary.json", "plot_profiles.gp"}},
  };
}

const std::map<std::string, std::string> kPng = {
    {"compare", "comparison.png"}, {"converge", "convergence.png"}, {"stability", "stability.png"}, {"run", "profiles.png"}};

bool have_gnuplot() {
  return fs::exists("/usr/bin/gnuplot") || fs::exists("/usr/local/bin/gnuplot") || fs::exists("/bin/gnuplot");
}

}  // namespace

TEST_CASE("gnuplot: hostile --output names run no command and keep the files inside the folder", "[security][gnuplot]") {
  const fs::path base = test_support::fresh_dir("gnuplot-injection");
  for (const auto& cmd : commands()) {
    for (std::size_t k = 0; k < kHostileNames.size(); ++k) {
      const std::string& name = kHostileNames[k];
      DYNAMIC_SECTION(cmd.name << " --output name " << k) {
        const fs::path cwd = base / (cmd.name + "-" + std::to_string(k));
        fs::create_directories(cwd);
        std::vector<std::string> args = cmd.args;
        args.push_back("--output");
        args.push_back(name);
        args.insert(args.end(), kTiny.begin(), kTiny.end());
        const auto r = test_support::run_process(SPHMOL_BINARY, args, (base / (cmd.name + "-" + std::to_string(k) + ".err")).string(),
                                                 cwd.string());
        INFO(r.err);
        CHECK(r.code == 0);
        CHECK(markers(base).empty());
        // Everything lands in the folder named, and nothing beside it.
        const fs::path out = cwd / name;
        CHECK(top_level(cwd) == std::set<std::string>{fs::path(name).begin()->string()});
        for (const auto& f : cmd.files) CHECK(fs::exists(out / f));
        if (have_gnuplot()) {
          CHECK(fs::exists(out / kPng.at(cmd.name)));
          for (const auto& e : fs::directory_iterator(out))  // no temporary left behind (the run's lock file stays)
            if (e.path().filename() != ".sph-mol.lock") CHECK(e.path().filename().string().front() != '.');
        }
      }
    }
  }
}

TEST_CASE("gnuplot: a file planted in the output folder under a profile name never enters a plot script", "[security][gnuplot]") {
  const fs::path base = test_support::fresh_dir("gnuplot-planted");
  const fs::path out = base / "out";
  fs::create_directories(out);
  // Matches the profile_t*.csv pattern the Couette plot reads, with a pipe that a quoted name would open.
  const std::string planted = "profile_t9' using 2:1, '<touch pwned; echo 1,2,3' using 2:1, 'x.csv";
  std::ofstream(out / planted) << "y,u_sph,u_exact\n0,0,0\n";
  std::vector<std::string> args = {"--config", std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml", "-q",
                                   "--set", "output.plots=true", "--output", "out"};
  args.insert(args.end(), kTiny.begin(), kTiny.end());
  const auto r = test_support::run_process(SPHMOL_BINARY, args, (base / "err").string(), base.string());
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(markers(base).empty());
  std::ifstream gp(out / "plot_profiles.gp");
  REQUIRE(gp.good());
  std::ostringstream s;
  s << gp.rdbuf();
  CHECK(s.str().find("pwned") == std::string::npos);
  CHECK(s.str().find("profile_t0.002.csv") != std::string::npos);
}
