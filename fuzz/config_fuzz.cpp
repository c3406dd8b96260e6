// libFuzzer target for the config loader: any byte string must either load or be rejected with a
// ConfigError — no other exception, crash, hang or sanitizer report. A config that loads must also
// survive the to_yaml round trip unchanged (what `sph-mol --restart` relies on).
// Input layout: YAML text, optionally followed by '\0' and '\n'-separated --set overrides, so the
// override parser is fuzzed too (the seed inputs are plain YAML files).
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const auto nul = input.find('\0');
  const std::string text = input.substr(0, nul);
  std::vector<std::string> overrides;
  if (nul != std::string::npos) {
    std::size_t start = nul + 1;
    while (start <= input.size() && overrides.size() < 16) {
      const auto nl = input.find('\n', start);
      overrides.push_back(input.substr(start, nl == std::string::npos ? std::string::npos : nl - start));
      if (nl == std::string::npos) break;
      start = nl + 1;
    }
  }
  sphmol::Config c;
  try {
    c = sphmol::load_config_string(text, overrides, "fuzz.yaml");
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
