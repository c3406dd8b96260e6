// libFuzzer target for the config loader: any byte string must either load or be rejected with a
// ConfigError — no other exception, crash, hang or sanitizer report. A config that loads must also
// survive the to_yaml round trip unchanged (what `sph-mol --restart` relies on).
#include <cstdint>
#include <cstdlib>
#include <string>

#include "sphmol/config/config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  sphmol::Config c;
  try {
    c = sphmol::load_config_string(text, {}, "fuzz.yaml");
  } catch (const sphmol::ConfigError&) {
    return 0;
  }
  const std::string yaml = sphmol::to_yaml(c);
  try {
    if (sphmol::to_yaml(sphmol::load_config_string(yaml, {}, "fuzz.yaml")) != yaml) std::abort();
  } catch (const sphmol::ConfigError&) {
    std::abort();  // to_yaml wrote something the loader rejects
  }
  return 0;
}
