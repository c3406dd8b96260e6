// The documents match the code: config/defaults.yaml names exactly the keys the loader accepts, the
// README's case table gives each shipped verification config's integrator, and the files a user
// reads cite no internal documents.
#include <catch2/catch.hpp>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

using namespace sphmol;
namespace fs = std::filesystem;

namespace {

const fs::path source_dir{SPHMOL_SOURCE_DIR};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  REQUIRE(in.good());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

std::string join_path(const std::string& section, const std::string& key) {
  return section.empty() ? key : section + "." + key;
}

// Every key path in defaults.yaml, the commented-out alternatives included ("  # gamma: 1.4" under
// eos is fluid.eos.gamma): a commented key sits where it would sit with "# " removed, so its depth
// is its column minus 2. Flow maps ("{alpha: 1.0, ...}") contribute their keys too.
std::set<std::string> defaults_keys(const std::string& text) {
  static const std::regex plain(R"(^( *)([a-z_][a-z0-9_]*):(?: +(.*))?$)");
  static const std::regex commented(R"(^ *# +([a-z_][a-z0-9_]*):(?: +(.*))?$)");
  std::set<std::string> keys;
  std::vector<std::pair<std::size_t, std::string>> stack;  // (indent, key) of the open sections
  for (const auto& line : lines_of(text)) {
    std::smatch m;
    std::size_t indent = 0;
    std::string key, value;
    if (std::regex_match(line, m, plain)) {
      indent = m[1].length();
      key = m[2];
      value = m[3];
    } else if (std::regex_match(line, m, commented)) {
      indent = static_cast<std::size_t>(m.position(1)) - 2;
      key = m[1];
      value = m[2];
    } else {
      continue;
    }
    while (!stack.empty() && stack.back().first >= indent) stack.pop_back();
    const std::string path = join_path(stack.empty() ? "" : stack.back().second, key);
    keys.insert(path);
    if (const auto hash = value.find(" #"); hash != std::string::npos) value.erase(hash);
    value.erase(0, value.find_first_not_of(' '));
    if (value.empty() || value[0] == '#') {
      stack.emplace_back(indent, path);
    } else if (value[0] == '{') {
      for (const auto& kv : YAML::Load(value)) keys.insert(path + "." + kv.first.as<std::string>());
    }
  }
  return keys;
}

// The keys the loader accepts in `section` for the config `base`, read from the "unknown key
// (... allowed in SECTION: a, b, c)" error it gives for a key that cannot exist; nullopt when the
// loader does not read `section` as a section for this config.
std::optional<std::vector<std::string>> accepted_keys(const fs::path& base, const std::string& section) {
  const std::string probe = join_path(section, "zz_not_a_key");
  try {
    (void)load_config(base.string(), {probe + "=1"});
  } catch (const ConfigError& e) {
    const std::string msg = e.what();
    if (msg.find(": " + probe + ": unknown key (") == std::string::npos) return std::nullopt;
    const auto allowed = msg.find("allowed in ");
    const auto list = msg.find(": ", allowed);
    if (allowed == std::string::npos || list == std::string::npos || msg.back() != ')') return std::nullopt;
    std::vector<std::string> keys;
    std::istringstream in(msg.substr(list + 2, msg.size() - list - 3));
    for (std::string k; std::getline(in, k, ',');) keys.push_back(k.substr(k.find_first_not_of(' ')));
    return keys;
  } catch (const std::exception&) {
    return std::nullopt;
  }
  return std::nullopt;
}

std::vector<fs::path> shipped_configs() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(source_dir / "verification"))
    if (e.path().extension() == ".yaml") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// Every key path the loader accepts, over every shipped config (each case reads its own sections):
// a section's keys, and recursively the keys of those that are sections themselves.
std::set<std::string> loader_keys() {
  std::vector<fs::path> bases = shipped_configs();
  bases.push_back(source_dir / "config" / "defaults.yaml");
  std::set<std::string> keys;
  for (const auto& base : bases) {
    std::vector<std::string> todo{""};
    std::set<std::string> seen;
    while (!todo.empty()) {
      const std::string section = todo.back();
      todo.pop_back();
      if (!seen.insert(section).second) continue;
      const auto accepted = accepted_keys(base, section);
      if (!accepted) continue;
      for (const auto& k : *accepted) {
        keys.insert(join_path(section, k));
        todo.push_back(join_path(section, k));
      }
    }
  }
  return keys;
}

std::string listing(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += "\n  " + s;
  return out;
}

}  // namespace

TEST_CASE("docs: config/defaults.yaml names exactly the keys the loader accepts", "[docs]") {
  const auto documented = defaults_keys(slurp(source_dir / "config" / "defaults.yaml"));
  const auto accepted = loader_keys();
  REQUIRE(accepted.count("time.integrator") == 1);   // the probe reads the loader's lists
  REQUIRE(accepted.count("fluid.eos.type") == 1);    // nested sections are reached
  REQUIRE(documented.count("fluid.eos.gamma") == 1);  // commented keys are read at their depth
  std::vector<std::string> undocumented, unknown;
  std::set_difference(accepted.begin(), accepted.end(), documented.begin(), documented.end(),
                      std::back_inserter(undocumented));
  std::set_difference(documented.begin(), documented.end(), accepted.begin(), accepted.end(),
                      std::back_inserter(unknown));
  INFO("keys the loader accepts that config/defaults.yaml lacks:" << listing(undocumented));
  INFO("keys in config/defaults.yaml the loader rejects:" << listing(unknown));
  CHECK(undocumented.empty());
  CHECK(unknown.empty());
}

TEST_CASE("docs: config/README.md documents every key the loader accepts", "[docs]") {
  const std::string readme = slurp(source_dir / "config" / "README.md");
  std::vector<std::string> missing;
  for (const auto& key : loader_keys()) {
    // Named in backticks ("`fluid.eos.type`", also "`fluid.eos.type: tait`"), or a key of a section
    // whose row is named ("`discretization.artificial_viscosity`" describes alpha, beta and eta).
    const auto dot = key.rfind('.');
    const bool named = readme.find("`" + key) != std::string::npos;
    const bool in_section_row = dot != std::string::npos &&
                                readme.find("`" + key.substr(0, dot) + "`") != std::string::npos &&
                                readme.find(key.substr(dot + 1)) != std::string::npos;
    if (!named && !in_section_row) missing.push_back(key);
  }
  INFO("keys missing from config/README.md:" << listing(missing));
  CHECK(missing.empty());
}

TEST_CASE("docs: the README case table gives each shipped config's integrator", "[docs]") {
  const auto readme = lines_of(slurp(source_dir / "README.md"));
  const auto start = std::find(readme.begin(), readme.end(), "## Verification cases");
  REQUIRE(start != readme.end());
  static const std::regex row(R"(^\| `([a-z0-9_]+\.yaml)` \| `([a-z_]+)`.*)");
  std::map<std::string, std::string> table;  // config file -> integrator named in the table
  for (auto it = start + 1; it != readme.end() && it->rfind("## ", 0) != 0; ++it) {
    std::smatch m;
    if (std::regex_match(*it, m, row)) table[m[1]] = m[2];
  }
  for (const auto& path : shipped_configs()) {
    const std::string name = path.filename().string();
    INFO(name);
    REQUIRE(table.count(name) == 1);
    CHECK(load_config(path.string()).time.integrator == table[name]);
  }
  CHECK(table.size() == shipped_configs().size());
}

TEST_CASE("docs: user documents cite papers, not internal documents", "[docs]") {
  std::vector<fs::path> files{source_dir / "README.md", source_dir / "config" / "README.md",
                              source_dir / "config" / "defaults.yaml", source_dir / "verification" / "README.md"};
  for (const auto& e : fs::directory_iterator(source_dir / "docs"))
    if (e.path().extension() == ".md") files.push_back(e.path());
  for (const auto& p : shipped_configs()) files.push_back(p);
  // Case-insensitive phrases, and "SPEC" as a word in capitals.
  static const std::regex banned(R"(seed 0|issue #|issue \d|session |the anchor)", std::regex::icase);
  static const std::regex spec(R"(\bSPEC\b)");
  std::vector<std::string> hits;
  for (const auto& f : files) {
    const auto lines = lines_of(slurp(f));
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (std::regex_search(lines[i], banned) || std::regex_search(lines[i], spec))
        hits.push_back(fs::relative(f, source_dir).string() + ":" + std::to_string(i + 1) + ": " + lines[i]);
  }
  INFO("lines citing internal documents:" << listing(hits));
  CHECK(hits.empty());
}
