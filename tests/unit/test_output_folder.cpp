// The output folder's claim (run/output_folder.hpp): folders it made are removed again when a
// failure unwinds it before anything but the lock file was written; anything else stays.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

#include "sphmol/run/output_folder.hpp"

namespace fs = std::filesystem;
using sphmol::OutputFolder;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("sphmol-unit-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

// Claims `dir` as a study does, optionally writes one file, then fails.
void claim_and_fail(const fs::path& dir, bool write_a_file) {
  try {
    const OutputFolder folder(dir.string(), OutputFolder::Options{.lock_only = true});
    if (write_a_file) std::ofstream(dir / "convergence.csv") << "x\n";
    throw std::runtime_error("the study failed");
  } catch (const std::runtime_error&) {
  }
}

}  // namespace

TEST_CASE("output folder: folders made for a claim that fails before writing are removed", "[output-folder]") {
  const fs::path base = scratch("folder-fail");
  claim_and_fail(base / "new" / "deeper", false);
  CHECK(!fs::exists(base / "new"));
  CHECK(fs::exists(base));  // it was there before

  // Written as "dir/": the same folder.
  claim_and_fail((base / "slash").string() + "/", false);
  CHECK(!fs::exists(base / "slash"));
}

TEST_CASE("output folder: a failed claim keeps folders that were there or hold files", "[output-folder]") {
  const fs::path base = scratch("folder-keep");
  // The folder existed: it stays, with its lock file.
  fs::create_directories(base / "old");
  claim_and_fail(base / "old", false);
  CHECK(fs::exists(base / "old" / sphmol::kOutputLockFile));
  // Something was written before the failure: the folder and the file stay.
  claim_and_fail(base / "written" / "run", true);
  CHECK(fs::exists(base / "written" / "run" / "convergence.csv"));
  // No failure: the folder stays even when empty.
  { const OutputFolder folder((base / "ok").string(), OutputFolder::Options{.lock_only = true}); }
  CHECK(fs::exists(base / "ok" / sphmol::kOutputLockFile));
  fs::remove_all(base);
}

TEST_CASE("output folder: a study refuses a run's folder and keeps its own earlier results", "[output-folder]") {
  // A study into a run's folder wrote its files beside the run's, where the run's --overwrite (which
  // deletes the files its summary lists) would leave them.
  const fs::path base = scratch("folder-study");
  fs::create_directories(base / "run");
  std::ofstream(base / "run" / "summary.json") << R"({"files": ["summary.json"]})";
  CHECK_THROWS_WITH(OutputFolder((base / "run").string(), OutputFolder::Options{.lock_only = true}),
                    Catch::Contains("holds the results of a run (summary.json); a study does not write into a run's folder"));
  // A study's own folder is claimed again (its fixed file names are rewritten).
  fs::create_directories(base / "study");
  std::ofstream(base / "study" / "comparison.json") << "{}";
  { const OutputFolder folder((base / "study").string(), OutputFolder::Options{.lock_only = true}); }
  CHECK(fs::exists(base / "study" / "comparison.json"));
  fs::remove_all(base);
}
