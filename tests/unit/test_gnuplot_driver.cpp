// The gnuplot driver (io/gnuplot.hpp): what may enter a script, and what a failing, truncating or
// interrupted gnuplot leaves behind (a stand-in program plays gnuplot, so these tests need none).
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "sphmol/io/gnuplot.hpp"
#include "sphmol/run/gnuplot_preamble.hpp"
#include "sphmol/studies/gnuplot_chart.hpp"

#include "support/files.hpp"

namespace fs = std::filesystem;
using namespace sphmol;

namespace {

// A stand-in for gnuplot: a /bin/sh script (the test's own text) made executable.
std::string fake_gnuplot(const fs::path& dir, const std::string& body) {
  const fs::path p = dir / "fake-gnuplot";
  std::ofstream(p) << "#!/bin/sh\n" << body << '\n';
  fs::permissions(p, fs::perms::owner_all);
  return p.string();
}

// Names in `dir` other than the ones listed: temporaries that were left behind.
std::vector<std::string> hidden_files(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().front() == '.') out.push_back(e.path().filename().string());
  return out;
}

const std::string kScript = "set terminal pngcairo\n" + gnuplot_output_line("x.png") + "plot sin(x)\n";

// The output file a script was run with: the argument gnuplot got, read back in the working directory.
const std::string kPng = "printf '\\211PNG\\r\\n\\032\\n' > \"$out\"; printf '\\0\\0\\0\\0IEND\\256\\102\\140\\202' >> \"$out\"";
const std::string kFindOutput = "out=$(sed -n \"s/^set output '\\(.*\\)'$/\\1/p\" \"$1\")";

}  // namespace

TEST_CASE("gnuplot text: quotes, newlines, backquotes and shell characters never reach a script", "[gnuplot]") {
  CHECK(gnuplot_text("error vs wall time: couette") == "'error vs wall time: couette'");
  const std::string t = gnuplot_text("a'b\n!touch pwned `id` $(id) |x <y \"z\" \\");
  CHECK(t.front() == '\'');
  CHECK(t.back() == '\'');
  const std::string inner = t.substr(1, t.size() - 2);
  for (char c : std::string("'\n\r`$|<>\"\\!&@"))
    CHECK(inner.find(c) == std::string::npos);
  CHECK(plain_file_name("comparison.png"));
  CHECK(plain_file_name("profile_t0.5.csv"));
  CHECK(plain_file_name("profile_t1e-05.csv"));
  for (const char* bad : {"", "|touch pwned", "<x", ".hidden", "-e", "a/b", "a b", "a'b", "x\ny", "..", "a..b", "$(x)"})
    CHECK_FALSE(plain_file_name(bad));
  CHECK_THROWS_AS(gnuplot_file("|touch pwned"), std::logic_error);
  CHECK_THROWS_AS(gnuplot_output_line("a'b.png"), std::logic_error);
}

TEST_CASE("gnuplot scripts of the studies and the cases hold only relative, generated names", "[gnuplot]") {
  Chart c{"title with 'quote'\nand newline", "x", "y", true, true, {}};
  c.series.push_back({"arkode_erk:'; !touch pwned", {1, 2}, {1, 2}, "forest-green"});
  c.series.push_back({"s", {1, 2}, {1, 2}, "red'; system('touch pwned"});
  const std::string s = chart_script(c, "comparison");
  CHECK(s.find("set output 'comparison.png'\n") != std::string::npos);
  CHECK(s.find("'comparison.dat' index 0") != std::string::npos);
  CHECK(s.find("lc rgb 'forest-green'") != std::string::npos);
  CHECK(s.find("system") == std::string::npos);  // the unsafe colour is dropped
  CHECK(s.find('!') == std::string::npos);
  CHECK(s.find('/') == std::string::npos);  // no directory anywhere
  CHECK(s.find("set title 'title with _quote__and newline'\n") != std::string::npos);  // one line, one string
  CHECK(s.find("title 'arkode_erk:_; _touch pwned'") != std::string::npos);
  CHECK_THROWS_AS(chart_script(c, "../x"), std::logic_error);
  const std::string p = gnuplot_csv_preamble("comment\n!touch pwned \\", 800, 600, 11, "front.png");
  CHECK(p.find("\n!") == std::string::npos);
  CHECK(p.find("set output 'front.png'\n") != std::string::npos);
}

TEST_CASE("gnuplot driver: the PNG appears under its final name only when gnuplot succeeded", "[gnuplot]") {
  const fs::path dir = test_support::fresh_dir("gnuplot-ok");
  const std::string ok = fake_gnuplot(dir, kFindOutput + "\n" + kPng + "\necho drawn >&2");
  const GnuplotOutcome r = run_gnuplot(ok, dir.string(), "plot_x.gp", kScript, "x.png");
  INFO(r.problem);
  CHECK(r.ok);
  CHECK(test_support::slurp(dir / "x.png").substr(1, 3) == "PNG");
  CHECK(test_support::slurp(dir / "plot_x.gp") == kScript);  // kept, naming the final PNG
  CHECK(test_support::slurp(dir / "plot_x.gnuplot.log") == "drawn\n");
  CHECK(hidden_files(dir).empty());

  // gnuplot fails: no PNG (the earlier one is removed: it would show other data), no temporaries.
  const std::string fails = fake_gnuplot(dir, kFindOutput + "\n" + kPng + "\necho broken >&2\nexit 1");
  const GnuplotOutcome f = run_gnuplot(fails, dir.string(), "plot_x.gp", kScript, "x.png");
  CHECK_FALSE(f.ok);
  CHECK(f.problem.find("exit status 1") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "x.png"));
  CHECK(test_support::slurp(dir / "plot_x.gnuplot.log") == "broken\n");
  CHECK(hidden_files(dir).empty());

  // gnuplot exits 0 but the PNG is truncated (a full disk): not renamed to x.png.
  const std::string truncates = fake_gnuplot(dir, kFindOutput + "\nprintf '\\211PNG\\r\\n\\032\\n1234' > \"$out\"");
  const GnuplotOutcome t = run_gnuplot(truncates, dir.string(), "plot_x.gp", kScript, "x.png");
  CHECK_FALSE(t.ok);
  CHECK(t.problem.find("no complete x.png") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "x.png"));
  CHECK(hidden_files(dir).empty());

  CHECK_THROWS_AS(run_gnuplot(ok, dir.string(), "plot_x.gp", "plot sin(x)\n", "x.png"), std::logic_error);  // no set output
}

TEST_CASE("gnuplot driver: gnuplot runs in the output directory and is stopped when interrupted", "[gnuplot]") {
  const fs::path dir = test_support::fresh_dir("gnuplot-cwd dir;'x'");
  // The working directory is the output directory, and the script is named relative to it.
  const std::string where = fake_gnuplot(dir, "pwd > where.txt; printf '%s' \"$1\" > arg.txt; exit 1");
  run_gnuplot(where, dir.string(), "plot_x.gp", kScript, "x.png");
  CHECK(fs::equivalent(test_support::slurp(dir / "where.txt").substr(0, test_support::slurp(dir / "where.txt").size() - 1), dir));
  CHECK(test_support::slurp(dir / "arg.txt").find('/') == std::string::npos);

  const std::string slow = fake_gnuplot(dir, "exec sleep 20");
  const auto t0 = std::chrono::steady_clock::now();
  int polls = 0;
  const GnuplotOutcome r = run_gnuplot(slow, dir.string(), "plot_x.gp", kScript, "x.png", [&] { return ++polls > 5; });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CHECK(r.interrupted);
  CHECK_FALSE(r.ok);
  CHECK(seconds < 5.0);
  CHECK_FALSE(fs::exists(dir / "x.png"));
  CHECK(hidden_files(dir).empty());
}

TEST_CASE("gnuplot is looked up on absolute PATH entries only", "[gnuplot]") {
  const fs::path dir = test_support::fresh_dir("gnuplot-path");
  fake_gnuplot(dir, "exit 0");
  fs::rename(dir / "fake-gnuplot", dir / "gnuplot");
  const std::string old = std::getenv("PATH") ? std::getenv("PATH") : "";
  const fs::path cwd = fs::current_path();
  fs::current_path(dir);
  ::setenv("PATH", ":.:/nonexistent", 1);
  const std::string relative = find_gnuplot();
  ::setenv("PATH", (dir.string() + ":/nonexistent").c_str(), 1);
  const std::string absolute = find_gnuplot();
  ::setenv("PATH", old.c_str(), 1);
  fs::current_path(cwd);
  CHECK(relative.empty());  // "" and "." would run ./gnuplot from wherever sph-mol is started
  CHECK(absolute == (dir / "gnuplot").string());
}
