#pragma once
// A small schema reader over yaml-cpp: walks one YAML map, knows which keys the section may
// hold, converts values with strict type checks, and turns every problem into a one-line
// ConfigError "LOCATION: key.path: what is wrong (hint)". LOCATION is "FILE:LINE", or the
// "--set ..." text when the value came from a command-line override. Reusable for any
// YAML-configured section; the config loader is its only user today.
#include <yaml-cpp/yaml.h>

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sphmol/config/config.hpp"

namespace sphmol {

// Closest candidate to `word` for a "did you mean" hint (case and '-'/'_' insensitive edit
// distance, at most about a third of the word), or "" when nothing is close.
std::string closest_match(std::string_view word, const std::vector<std::string>& candidates);

// The shortest text that reads back as the same double (for messages and the resolved YAML).
std::string number_text(double v);
// "[a, b, c]" of number_text, and free text double-quoted with YAML escapes: the pieces of a
// resolved YAML file (config/to_yaml.cpp and the case modules' sections).
std::string yaml_list(const std::vector<double>& v);
std::string yaml_quoted(const std::string& s);
// Free text for a YAML comment (a path in the resolved file's first line): control characters, and
// the C1 controls and Unicode line separators a YAML reader may take for a line break, written as
// escapes (\n, \t, \xHH, \uHHHH), so the comment stays one line and the file loads back.
std::string yaml_comment_text(const std::string& s);

// YAML::Load of `text`; a syntax error is a ConfigError "NAME:LINE: YAML syntax error: ...".
YAML::Node parse_yaml(const std::string& text, const std::string& name);

// Where the YAML tree came from: the file name, and which key paths were replaced by overrides.
class YamlOrigin {
 public:
  explicit YamlOrigin(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }
  // Records that `path` (and everything under it) now comes from override text `text`, which
  // replaces or removes (key=null) what earlier overrides set under it.
  void add_override(const std::string& path, const std::string& text);
  // "FILE:LINE" for a node at `mark`, or "--set path=value" if `path` was overridden.
  std::string locate(const std::string& path, const YAML::Mark& mark) const;

 private:
  std::string file_;
  std::map<std::string, std::string> overrides_;
};

class MapReader {
 public:
  // `node` must be a map or null/undefined (an absent section reads as empty); `mark` is where
  // the section starts (or the nearest existing ancestor, for errors about missing keys).
  // `keys` lists every key the section may hold; any other key is an error right away, so
  // that a misspelt key is reported before the "missing value" it causes.
  MapReader(const YamlOrigin& origin, const YAML::Node& node, std::string path, YAML::Mark mark,
            std::vector<std::string> keys);

  const std::string& path() const { return path_; }
  std::string key_path(std::string_view key) const;
  bool has(const std::string& key) const;

  // Typed getters: nullopt if the key is absent; ConfigError on a wrong type.
  std::optional<double> real(const std::string& key);  // finite number
  std::optional<long long> integer(const std::string& key);
  std::optional<bool> boolean(const std::string& key);
  std::optional<std::string> string(const std::string& key);
  std::optional<std::vector<double>> reals(const std::string& key);  // list of finite numbers
  // A list of scalars as their text (numbers too: [1, "sin(x)"] reads as {"1", "sin(x)"}).
  std::optional<std::vector<std::string>> strings(const std::string& key);
  // A list of lists of finite numbers, each of length `width` (points such as [[0, 0], [1, 0]]).
  std::optional<std::vector<std::vector<double>>> real_rows(const std::string& key, std::size_t width);
  MapReader section(const std::string& key, std::vector<std::string> keys);
  // A list of maps under `key` (e.g. the bodies of a scene), each read with `keys`; element i has the
  // path "key[i]". Absent: empty. Not a list of maps: an error at the key.
  std::vector<MapReader> section_list(const std::string& key, std::vector<std::string> keys);
  // This same map read again with a narrower key list, for maps whose keys depend on one of their
  // values (read `type` with the union of every type's keys, then narrow to that type's keys).
  MapReader with_keys(std::vector<std::string> keys) const;
  // The keys this map holds, in name order.
  std::vector<std::string> keys_present() const;

  // The value, or a "required value missing" error located at this section.
  template <class T>
  T required(std::optional<T> value, const std::string& key, std::string_view hint) const {
    if (!value) fail_missing(key, hint);
    return *std::move(value);
  }

  // Errors located at the key (its line, or its override), or at this section.
  [[noreturn]] void fail(const std::string& key, std::string_view what) const;
  [[noreturn]] void fail_element(const std::string& key, std::size_t index,
                                 std::string_view what) const;
  [[noreturn]] void fail_missing(const std::string& key, std::string_view hint) const;
  // Range check: "KEY: VALUE is out of range (allowed: ALLOWED)" unless `ok`.
  void check(const std::string& key, bool ok, double value, std::string_view allowed) const {
    if (!ok) fail(key, number_text(value) + " is out of range (allowed: " + std::string(allowed) + ")");
  }
  // "LOCATION: key.path" for notices.
  std::string where(const std::string& key) const;

  // Checks the value against `allowed`; error lists them, with a "did you mean" if one is close.
  std::string choice(const std::string& key, const std::string& value,
                     const std::vector<std::string>& allowed) const;

 private:
  struct Entry {
    YAML::Node value;
    YAML::Mark mark;  // of the key (the line a user looks for)
  };
  const Entry* find(const std::string& key) const;
  std::string describe(const YAML::Node& node) const;
  [[noreturn]] void wrong_type(const std::string& key, const YAML::Node& node,
                               std::string_view expected) const;

  const YamlOrigin* origin_;
  std::string path_;
  YAML::Mark mark_;
  std::vector<std::string> keys_;
  std::map<std::string, Entry> entries_;
};

}  // namespace sphmol
