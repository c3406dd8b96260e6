// Checkpoint files: pruning keeps the last two checkpoints the run wrote (never one it did not write,
// whatever its time), the list survives a restart, and the reader refuses what a restart cannot
// continue from (non-finite or negative time, negative counters, non-finite state, deep nesting).
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "sphmol/io/double_codec.hpp"
#include "sphmol/run/case_state.hpp"
#include "sphmol/run/checkpoint.hpp"

#include "support/files.hpp"

using namespace sphmol;
namespace fs = std::filesystem;

namespace {

Checkpoint sample(double t) {
  Checkpoint cp;
  cp.case_name = "couette";
  cp.dimension = 2;
  cp.t = t;
  cp.y = {1.0, 2.0, 3.0, 4.0};
  cp.integrator = "leapfrog";
  cp.integrator_state = nlohmann::json::object();
  return cp;
}

nlohmann::json json_of(const fs::path& checkpoint_dir) {
  std::ifstream in(checkpoint_dir / "checkpoint.json");
  return nlohmann::json::parse(in);
}

void write_json(const fs::path& checkpoint_dir, const nlohmann::json& j) {
  std::ofstream(checkpoint_dir / "checkpoint.json") << j.dump();
}

std::string error_of(const fs::path& checkpoint_dir) {
  try {
    read_checkpoint(checkpoint_dir.string());
  } catch (const CheckpointError& e) {
    return e.what();
  }
  return "<no error>";
}

}  // namespace

TEST_CASE("checkpoint pruning keeps the last two this run wrote, not the two latest times", "[checkpoint]") {
  const fs::path dir = test_support::fresh_dir("prune");
  // An earlier run left checkpoints at later times.
  std::vector<std::string> other;
  write_checkpoint(dir.string(), sample(0.075), "case: couette\n", other);
  write_checkpoint(dir.string(), sample(0.1), "case: couette\n", other);
  // This run (a rerun to an earlier t_end, or a restart from an older checkpoint) writes 0.025, 0.05.
  std::vector<std::string> written;
  write_checkpoint(dir.string(), sample(0.025), "case: couette\n", written);
  const std::string newest = write_checkpoint(dir.string(), sample(0.05), "case: couette\n", written);
  CHECK(newest == (dir / "checkpoint-0.05").string());
  CHECK(fs::exists(dir / "checkpoint-0.025"));
  CHECK(fs::exists(dir / "checkpoint-0.05"));
  CHECK(fs::exists(dir / "checkpoint-0.075"));  // not written by this run: kept
  CHECK(fs::exists(dir / "checkpoint-0.1"));
  CHECK(written == std::vector<std::string>{(dir / "checkpoint-0.025").string(), (dir / "checkpoint-0.05").string()});

  // The third checkpoint of this run removes its first one, and only that.
  write_checkpoint(dir.string(), sample(0.0625), "case: couette\n", written);
  CHECK_FALSE(fs::exists(dir / "checkpoint-0.025"));
  CHECK(fs::exists(dir / "checkpoint-0.05"));
  CHECK(fs::exists(dir / "checkpoint-0.0625"));
  CHECK(fs::exists(dir / "checkpoint-0.075"));
  CHECK(fs::exists(dir / "checkpoint-0.1"));
  // No staging directories left behind.
  for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().filename().string().rfind("checkpoint-", 0) == 0);
}

TEST_CASE("checkpoint pruning continues over a restart into the same directory only", "[checkpoint]") {
  const fs::path dir = test_support::fresh_dir("prune-restart");
  std::vector<std::string> written;
  write_checkpoint(dir.string(), sample(0.025), "case: couette\n", written);
  write_checkpoint(dir.string(), sample(0.05), "case: couette\n", written);
  // The restarted run takes the list from the checkpoint it continues.
  const Checkpoint back = read_checkpoint((dir / "checkpoint-0.05").string());
  CHECK(back.written == written);
  CHECK(back.config_yaml == "case: couette\n");
  std::vector<std::string> continued = back.written;
  write_checkpoint(dir.string(), sample(0.075), "case: couette\n", continued);
  CHECK_FALSE(fs::exists(dir / "checkpoint-0.025"));  // the predecessor's, pruned as if one run
  CHECK(fs::exists(dir / "checkpoint-0.05"));
  CHECK(fs::exists(dir / "checkpoint-0.075"));

  // Into another directory: the first directory is never touched.
  const fs::path dir2 = test_support::fresh_dir("prune-restart-2");
  std::vector<std::string> elsewhere = read_checkpoint((dir / "checkpoint-0.075").string()).written;
  for (double t : {0.1, 0.125, 0.15}) write_checkpoint(dir2.string(), sample(t), "case: couette\n", elsewhere);
  CHECK(fs::exists(dir / "checkpoint-0.05"));
  CHECK(fs::exists(dir / "checkpoint-0.075"));
  CHECK_FALSE(fs::exists(dir2 / "checkpoint-0.1"));
  CHECK(fs::exists(dir2 / "checkpoint-0.125"));
  CHECK(fs::exists(dir2 / "checkpoint-0.15"));
}

TEST_CASE("checkpoint written again at the same time replaces the old one and counts once", "[checkpoint]") {
  const fs::path dir = test_support::fresh_dir("same-time");
  std::vector<std::string> written;
  write_checkpoint(dir.string(), sample(0.025), "a\n", written);
  write_checkpoint(dir.string(), sample(0.05), "a\n", written);
  write_checkpoint(dir.string(), sample(0.05), "b\n", written);
  CHECK(fs::exists(dir / "checkpoint-0.025"));
  CHECK(read_checkpoint((dir / "checkpoint-0.05").string()).config_yaml == "b\n");
  CHECK(written.size() == 2);
}

TEST_CASE("read_checkpoint refuses values a restart cannot continue from, naming file and field", "[checkpoint]") {
  const fs::path dir = test_support::fresh_dir("read-bad");
  std::vector<std::string> written;
  const fs::path cp = write_checkpoint(dir.string(), sample(0.05), "case: couette\n", written);
  const nlohmann::json good = json_of(cp);
  REQUIRE(error_of(cp) == "<no error>");
  const std::string file = (cp / "checkpoint.json").string();
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();

  struct Bad {
    std::string key;
    nlohmann::json value;
    std::string message;
  };
  const std::vector<Bad> cases = {
      {"t_bits", encode_doubles({nan}), "t_bits: time nan is not a finite time >= 0"},
      {"t_bits", encode_doubles({inf}), "t_bits: time inf is not a finite time >= 0"},
      {"t_bits", encode_doubles({-0.5}), "t_bits: time -0.500000 is not a finite time >= 0"},
      {"state", encode_doubles({1.0, nan, 3.0, 4.0}), "state: value 1 is nan, not finite"},
      {"rhs_evals", -3, "rhs_evals: -3 < 0"},
      {"wall_seconds", -1.0, "wall_seconds: -1.000000 is not a finite time >= 0"},
      {"dimension", 7, "dimension: 7 is not 1, 2 or 3"},
      {"errors", 5, "errors: not an array"},
      {"case_state", "rows", "case_state: not an object"},
  };
  {
    nlohmann::json j = good;
    j["integrator_state"] = {{"steps", -4}, {"rejected_steps", 1}};
    write_json(cp, j);
    CHECK(error_of(cp) == file + ": integrator_state.steps: -4 is not a count >= 0");
    j["integrator_state"] = {{"steps", 4}, {"rejected_steps", 1.5}};
    write_json(cp, j);
    CHECK(error_of(cp) == file + ": integrator_state.rejected_steps: 1.5 is not a count >= 0");
  }
  for (const auto& c : cases) {
    nlohmann::json j = good;
    j[c.key] = c.value;
    write_json(cp, j);
    INFO(c.key << " = " << c.value.dump());
    CHECK(error_of(cp) == file + ": " + c.message);
  }
}

TEST_CASE("read_checkpoint refuses deeply nested JSON without exhausting the stack", "[checkpoint]") {
  const fs::path dir = test_support::fresh_dir("read-deep");
  std::vector<std::string> written;
  const fs::path cp = write_checkpoint(dir.string(), sample(0.05), "case: couette\n", written);
  std::string text = json_of(cp).dump();
  // A million nested arrays in a field that the reader copies (errors).
  const std::string deep = std::string(1'000'000, '[') + std::string(1'000'000, ']');
  const auto at = text.find("\"errors\":[");
  REQUIRE(at != std::string::npos);
  text.insert(at + 10, deep + ",");
  std::ofstream(cp / "checkpoint.json") << text;
  CHECK_THAT(error_of(cp), Catch::Matchers::Contains("nested deeper than 64 levels"));
}

TEST_CASE("read_checkpoint refuses a checkpoint.json that is not a regular file", "[checkpoint]") {
  const fs::path dir = test_support::fresh_dir("read-fifo");
  fs::create_directories(dir / "checkpoint-1");
  fs::create_symlink("/dev/zero", dir / "checkpoint-1" / "checkpoint.json");
  CHECK_THAT(error_of(dir / "checkpoint-1"), Catch::Matchers::Contains("not a regular file"));
}

TEST_CASE("checkpoint carries the case's state and one written without it reads back as none", "[checkpoint]") {
  const fs::path dir = test_support::fresh_dir("case-state");
  std::vector<std::string> written;
  Checkpoint cp = sample(0.05);
  const std::vector<double> series = {0.1, 1.0 / 3.0, std::numeric_limits<double>::quiet_NaN(), -0.0};
  cp.case_state = {{"t", encode_doubles(series)}, {"rows", "a,b\n1,2\n"}};
  const fs::path path = write_checkpoint(dir.string(), cp, "case: couette\n", written);
  const Checkpoint back = read_checkpoint(path.string());
  CHECK(back.case_state == cp.case_state);
  const std::vector<double> t = state_doubles(back.case_state, "t");
  REQUIRE(t.size() == series.size());
  CHECK(encode_doubles(t) == encode_doubles(series));  // to the bit, NaN and -0 included
  // As an earlier sph-mol wrote it: no state (the run warns, run/run_case.cpp).
  nlohmann::json j = json_of(path);
  j.erase("case_state");
  write_json(path, j);
  CHECK(read_checkpoint(path.string()).case_state.is_null());
}

TEST_CASE("case_state helpers name the key of a malformed entry and restore columns of one length only", "[checkpoint]") {
  const nlohmann::json state = {{"t", encode_doubles({0.1, 0.2})}, {"a", encode_doubles({1.0, 2.0})},
                                {"short", encode_doubles({1.0})}, {"odd", "abc"}, {"number", 3}};
  std::vector<double> t, a;
  restore_columns(state, {{"t", &t}, {"a", &a}});
  CHECK(t == std::vector<double>{0.1, 0.2});
  CHECK(a == std::vector<double>{1.0, 2.0});
  std::vector<double> kept = {7.0};
  CHECK_THROWS_WITH(restore_columns(state, {{"t", &t}, {"short", &kept}}), "short: 1 values, expected 2 (t)");
  CHECK(kept == std::vector<double>{7.0});  // nothing restored
  CHECK_THROWS_WITH(state_doubles(state, "missing"), "missing: missing or not a string of hex digits");
  CHECK_THROWS_WITH(state_doubles(state, "number"), "number: missing or not a string of hex digits");
  CHECK_THROWS_WITH(state_doubles(state, "odd"), Catch::Matchers::StartsWith("odd: "));
  CHECK_THROWS_WITH(state_double(state, "t"), "t: 2 values, expected 1");
  CHECK(state_double(state, "short") == 1.0);
}

TEST_CASE("checkpoints are neither written into nor read from a folder that is a symbolic link", "[checkpoint]") {
  const fs::path dir = test_support::fresh_dir("checkpoint-links");
  fs::create_directories(dir / "victim");
  fs::create_symlink("victim", dir / "link");
  std::vector<std::string> written;
  for (const std::string name : {"link", "link/", "link/."})
    CHECK_THROWS_WITH(write_checkpoint((dir / name).string(), sample(0.5), "case: couette\n", written),
                      Catch::Matchers::Contains((dir / name).string() + " is a symbolic link to " + (dir / "victim").string()));
  CHECK(fs::is_empty(dir / "victim"));

  // A checkpoint folder reached through a link of that name is refused; one below a linked folder
  // (a link higher up the path) is read.
  write_checkpoint((dir / "victim").string(), sample(0.5), "case: couette\n", written);
  fs::create_symlink("victim/checkpoint-0.5", dir / "checkpoint-link");
  CHECK_THAT(error_of(dir / "checkpoint-link"), Catch::Matchers::Contains("checkpoint-link is a symbolic link to " +
                                                                           (dir / "victim" / "checkpoint-0.5").string()));
  CHECK(error_of(dir / "link" / "checkpoint-0.5") == "<no error>");
}
