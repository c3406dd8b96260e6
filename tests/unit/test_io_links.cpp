// io/links.hpp and read_input_file's InputLinks::refuse: a symbolic link as the last component of a
// path is named with its target; links higher up the path are layout and pass.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "sphmol/io/input_file.hpp"
#include "sphmol/io/links.hpp"

#include "support/files.hpp"

using namespace sphmol;
namespace fs = std::filesystem;
using Catch::Matchers::Contains;

TEST_CASE("final_link_message names a link at the end of a path and its target", "[io][links]") {
  const fs::path dir = test_support::fresh_dir("io-links");
  fs::create_directories(dir / "real" / "sub");
  fs::create_symlink("real", dir / "relative");
  fs::create_symlink(dir / "real", dir / "absolute");
  fs::create_symlink(dir / "missing", dir / "dangling");

  CHECK_FALSE(final_link_message((dir / "real").string()));
  CHECK_FALSE(final_link_message((dir / "not-there" / "x").string()));
  CHECK_FALSE(final_link_message(""));
  CHECK_FALSE(final_link_message("."));
  // A link higher up the path is not judged.
  CHECK_FALSE(final_link_message((dir / "relative" / "sub").string()));

  for (const std::string name : {"relative", "relative/", "relative/.", "absolute", "absolute//"}) {
    const auto m = final_link_message((dir / name).string());
    REQUIRE(m);
    CHECK_THAT(*m, Contains((dir / name).string() + " is a symbolic link to " + (dir / "real").string()));
    CHECK_THAT(*m, Contains("give " + (dir / "real").string() + " itself"));
  }
  const auto m = final_link_message((dir / "dangling").string());
  REQUIRE(m);
  CHECK_THAT(*m, Contains("is a symbolic link to " + (dir / "missing").string()));
}

TEST_CASE("read_input_file refuses a link when asked and FIFOs and sizes as before", "[io][links]") {
  const fs::path dir = test_support::fresh_dir("io-input-links");
  std::ofstream(dir / "plain.json") << "{}";
  fs::create_symlink(dir / "plain.json", dir / "link.json");
  fs::create_symlink("/dev/zero", dir / "zero.json");
  ::mkfifo((dir / "fifo.json").c_str(), 0644);

  CHECK(read_input_file((dir / "link.json").string(), 100, "run summary") == "{}");  // followed by default
  CHECK_THROWS_WITH(read_input_file((dir / "link.json").string(), 100, "run summary", InputLinks::refuse),
                    Contains("link.json: a symbolic link; a run summary is never read through a link"));
  CHECK_THROWS_WITH(read_input_file((dir / "zero.json").string(), 100, "run summary", InputLinks::refuse),
                    Contains("zero.json: a symbolic link"));
  CHECK_THROWS_WITH(read_input_file((dir / "fifo.json").string(), 100, "run summary", InputLinks::refuse),
                    Contains("fifo.json: not a regular file"));
  CHECK_THROWS_WITH(read_input_file((dir / "plain.json").string(), 1, "run summary", InputLinks::refuse),
                    Contains("run summary is larger than the limit of 1 bytes"));
  CHECK(read_input_file((dir / "plain.json").string(), 100, "run summary", InputLinks::refuse) == "{}");
}
