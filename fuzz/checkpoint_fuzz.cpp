// libFuzzer target for the checkpoint reader: any checkpoint.json must either be read or be refused
// with a CheckpointError (no other exception, crash, stack overflow or sanitizer report). A checkpoint
// that is read is written again and must read back identically (state and time bit for bit), and is
// checked against its own config as a restart does.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "sphmol/run/checkpoint.hpp"
#include "sphmol/run/restart_check.hpp"

namespace {
const std::filesystem::path& scratch() {
  static const std::filesystem::path dir = [] {
    std::string templ = (std::filesystem::temp_directory_path() / "sphmol-checkpoint-fuzz.XXXXXX").string();
    if (!::mkdtemp(templ.data())) std::abort();
    std::filesystem::create_directories(std::filesystem::path(templ) / "in");
    std::filesystem::create_directories(std::filesystem::path(templ) / "out");
    return std::filesystem::path(templ);
  }();
  return dir;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto in = scratch() / "in";
  std::ofstream(in / "checkpoint.json", std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));  // no fsync: fast
  sphmol::Checkpoint cp;
  try {
    cp = sphmol::read_checkpoint(in.string());
  } catch (const sphmol::CheckpointError&) {
    return 0;
  }
  // Written again (with an empty list of this run's checkpoints: nothing outside out/ is touched).
  std::vector<std::string> written;
  const std::string again = sphmol::write_checkpoint((scratch() / "out").string(), cp, cp.config_yaml, written);
  const sphmol::Checkpoint back = sphmol::read_checkpoint(again);
  if (!same_bits(back.t, cp.t) || back.y.size() != cp.y.size() || back.case_name != cp.case_name ||
      back.integrator_state != cp.integrator_state || back.errors != cp.errors || back.case_state != cp.case_state ||
      back.config_yaml != cp.config_yaml)
    std::abort();
  for (std::size_t k = 0; k < cp.y.size(); ++k)
    if (!same_bits(back.y[k], cp.y[k])) std::abort();
  std::filesystem::remove_all(again);
  try {
    sphmol::Config config = sphmol::load_config_string(cp.config_yaml, {}, "checkpoint config");
    sphmol::check_restart(cp, config, in.string(), false);
  } catch (const sphmol::ConfigError&) {
  } catch (const sphmol::CheckpointError&) {
  }
  return 0;
}
