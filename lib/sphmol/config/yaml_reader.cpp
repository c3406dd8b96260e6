#include "sphmol/config/yaml_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <iterator>
#include <limits>

#include "sphmol/core/join.hpp"

namespace sphmol {

namespace {

std::string normalise(std::string_view s) {
  std::string out;
  for (char c : s) out += c == '-' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

// Quoted scalars carry the non-specific tag "!": "1.5" in quotes is a string, not a number.
bool is_quoted(const YAML::Node& node) { return node.Tag() == "!"; }

std::optional<double> parse_real(const YAML::Node& node) {
  if (!node.IsScalar() || is_quoted(node)) return std::nullopt;
  std::string_view s = node.Scalar();
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  // YAML spellings of infinity and NaN, so that they are reported as "not finite".
  const std::string n = normalise(s);
  if (n == ".inf" || n == "-.inf") return n[0] == '-' ? -HUGE_VAL : HUGE_VAL;
  if (n == ".nan") return std::numeric_limits<double>::quiet_NaN();
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc{} || end != s.data() + s.size() || s.empty()) return std::nullopt;
  return v;
}

}  // namespace

std::string closest_match(std::string_view word, const std::vector<std::string>& candidates) {
  const std::string w = normalise(word);
  std::string best;
  std::size_t best_d = std::numeric_limits<std::size_t>::max();
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(w, normalise(c));
    if (d < best_d) best_d = d, best = c;
  }
  // A third of the word (at least 2 edits) separates typos from different words.
  const std::size_t limit = std::max<std::size_t>(2, w.size() / 3);
  return best_d <= limit ? best : std::string{};
}

std::string number_text(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string yaml_list(const std::vector<double>& v) {
  std::string out = "[";
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + number_text(v[i]);
  return out + "]";
}

std::string yaml_quoted(const std::string& s) {
  YAML::Emitter e;
  e << YAML::DoubleQuoted << s;
  return e.c_str();
}

std::string yaml_comment_text(const std::string& s) {
  static constexpr char hex[] = "0123456789abcdef";
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    const auto next = i + 1 < s.size() ? static_cast<unsigned char>(s[i + 1]) : 0u;
    const auto next2 = i + 2 < s.size() ? static_cast<unsigned char>(s[i + 2]) : 0u;
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    } else if (c == 0xc2 && next >= 0x80 && next <= 0x9f) {  // U+0080..U+009F (NEL is U+0085)
      out += std::string("\\u00") + hex[next >> 4] + hex[next & 15];
      ++i;
    } else if (c == 0xe2 && next == 0x80 && (next2 == 0xa8 || next2 == 0xa9)) {  // U+2028, U+2029
      out += next2 == 0xa8 ? "\\u2028" : "\\u2029";
      i += 2;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

YAML::Node parse_yaml(const std::string& text, const std::string& name) {
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw ConfigError(name + ":" + std::to_string(e.mark.line + 1) + ": YAML syntax error: " + e.msg);
  }
}

void YamlOrigin::add_override(const std::string& path, const std::string& text) {
  for (auto it = overrides_.begin(); it != overrides_.end();) {
    const std::string& p = it->first;
    const bool under = p.size() > path.size() && p.compare(0, path.size(), path) == 0 && (p[path.size()] == '.' || p[path.size()] == '[');
    it = under ? overrides_.erase(it) : std::next(it);
  }
  overrides_[path] = text;
}

std::string YamlOrigin::locate(const std::string& path, const YAML::Mark& mark) const {
  // The longest overridden prefix of `path` owns the value.
  const std::string* best = nullptr;
  std::size_t best_len = 0;
  for (const auto& [p, text] : overrides_) {
    // "probes" owns "probes.x" and the list elements "probes[0].at".
    const bool covers = path == p || (path.size() > p.size() && path.compare(0, p.size(), p) == 0 &&
                                      (path[p.size()] == '.' || path[p.size()] == '['));
    if (covers && p.size() >= best_len) best = &text, best_len = p.size();
  }
  if (best) return "--set " + *best;
  if (mark.line >= 0) return file_ + ":" + std::to_string(mark.line + 1);
  // A section that exists only because an override created it.
  for (const auto& [p, text] : overrides_)
    if (p.size() > path.size() && p.compare(0, path.size(), path) == 0 && p[path.size()] == '.')
      return "--set " + text;
  return file_;
}

MapReader::MapReader(const YamlOrigin& origin, const YAML::Node& node, std::string path,
                     YAML::Mark mark, std::vector<std::string> keys)
    : origin_(&origin), path_(std::move(path)), mark_(mark), keys_(std::move(keys)) {
  const std::string here = path_.empty() ? "the config" : path_;
  if (node.IsDefined() && !node.IsNull() && !node.IsMap()) {
    throw ConfigError(origin_->locate(path_, mark_) + ": " + here + ": expected a map of keys (" +
                      join(keys_) + "), got " + describe(node));
  }
  if (!node.IsMap()) return;
  for (const auto& kv : node) {
    // Copies: the iterator's pair is a proxy value, references into it would dangle.
    const YAML::Node k = kv.first;
    const YAML::Node v = kv.second;
    const YAML::Mark km = k.Mark();
    if (!k.IsScalar()) {
      throw ConfigError(origin_->locate(path_, km) + ": " + here + ": keys must be plain names");
    }
    const std::string name = k.Scalar();
    const std::string full = key_path(name);
    if (std::find(keys_.begin(), keys_.end(), name) == keys_.end()) {
      const std::string near = closest_match(name, keys_);
      throw ConfigError(origin_->locate(full, km) + ": " + full + ": unknown key (" +
                        (near.empty() ? "" : "did you mean '" + near + "'? ") + "allowed in " +
                        here + ": " + join(keys_) + ")");
    }
    if (const auto prev = entries_.find(name); prev != entries_.end()) {
      throw ConfigError(origin_->locate(full, km) + ": " + full + ": given twice (first on line " +
                        std::to_string(prev->second.mark.line + 1) + ")");
    }
    entries_.emplace(name, Entry{v, km});
  }
}

std::string MapReader::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

bool MapReader::has(const std::string& key) const { return find(key) != nullptr; }

const MapReader::Entry* MapReader::find(const std::string& key) const {
  const auto it = entries_.find(key);
  return it == entries_.end() ? nullptr : &it->second;
}

std::string MapReader::describe(const YAML::Node& node) const {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsMap()) return "a map";
  if (node.IsSequence()) return "a list";
  return (is_quoted(node) ? "the string \"" : "'") + node.Scalar() + (is_quoted(node) ? "\"" : "'");
}

std::string MapReader::where(const std::string& key) const {
  const Entry* e = find(key);
  return origin_->locate(key_path(key), e ? e->mark : mark_) + ": " + key_path(key);
}

void MapReader::fail(const std::string& key, std::string_view what) const {
  throw ConfigError(where(key) + ": " + std::string(what));
}

void MapReader::fail_element(const std::string& key, std::size_t index, std::string_view what) const {
  const Entry* e = find(key);
  YAML::Mark m = e ? e->mark : mark_;
  if (e && e->value.IsSequence() && index < e->value.size() && e->value[index].Mark().line >= 0)
    m = e->value[index].Mark();
  throw ConfigError(origin_->locate(key_path(key), m) + ": " + key_path(key) + "[" +
                    std::to_string(index) + "]: " + std::string(what));
}

void MapReader::fail_missing(const std::string& key, std::string_view hint) const {
  const std::string section = path_.empty() ? "" : " in section '" + path_ + "'";
  throw ConfigError(origin_->locate(path_, mark_) + ": " + key_path(key) +
                    ": required value missing" + section + " (" + std::string(hint) + ")");
}

void MapReader::wrong_type(const std::string& key, const YAML::Node& node,
                           std::string_view expected) const {
  fail(key, "expected " + std::string(expected) + ", got " + describe(node));
}

std::optional<double> MapReader::real(const std::string& key) {
  const Entry* e = find(key);
  if (!e) return std::nullopt;
  const auto v = parse_real(e->value);
  if (!v) wrong_type(key, e->value, "a number");
  if (!std::isfinite(*v)) fail(key, "expected a finite number, got " + describe(e->value));
  return v;
}

std::optional<long long> MapReader::integer(const std::string& key) {
  const Entry* e = find(key);
  if (!e) return std::nullopt;
  const auto v = parse_real(e->value);
  if (!v) wrong_type(key, e->value, "an integer");
  // Accepts 1e7 (integral-valued), rejects 2.5.
  if (!std::isfinite(*v) || *v != std::floor(*v) || std::fabs(*v) > 9.0e15)
    fail(key, "expected an integer, got " + describe(e->value));
  return static_cast<long long>(*v);
}

std::optional<bool> MapReader::boolean(const std::string& key) {
  const Entry* e = find(key);
  if (!e) return std::nullopt;
  if (e->value.IsScalar() && !is_quoted(e->value)) {
    const std::string s = normalise(e->value.Scalar());
    if (s == "true" || s == "yes" || s == "on") return true;
    if (s == "false" || s == "no" || s == "off") return false;
  }
  wrong_type(key, e->value, "true or false");
}

std::optional<std::string> MapReader::string(const std::string& key) {
  const Entry* e = find(key);
  if (!e) return std::nullopt;
  if (!e->value.IsScalar()) wrong_type(key, e->value, "a string");
  return e->value.Scalar();
}

std::optional<std::vector<double>> MapReader::reals(const std::string& key) {
  const Entry* e = find(key);
  if (!e) return std::nullopt;
  if (!e->value.IsSequence()) wrong_type(key, e->value, "a list of numbers such as [0.1, 0.2]");
  std::vector<double> out;
  for (std::size_t i = 0; i < e->value.size(); ++i) {
    const auto v = parse_real(e->value[i]);
    if (!v || !std::isfinite(*v))
      fail_element(key, i, "expected a finite number, got " + describe(e->value[i]));
    out.push_back(*v);
  }
  return out;
}

std::optional<std::vector<std::string>> MapReader::strings(const std::string& key) {
  const Entry* e = find(key);
  if (!e) return std::nullopt;
  if (!e->value.IsSequence()) wrong_type(key, e->value, "a list such as [a, b]");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < e->value.size(); ++i) {
    if (!e->value[i].IsScalar()) fail_element(key, i, "expected a single value, got " + describe(e->value[i]));
    out.push_back(e->value[i].Scalar());
  }
  return out;
}

std::optional<std::vector<std::vector<double>>> MapReader::real_rows(const std::string& key, std::size_t width) {
  const Entry* e = find(key);
  if (!e) return std::nullopt;
  const std::string shape = "a list of " + std::to_string(width) + "-number lists such as [[0, 0], [1, 0]]";
  if (!e->value.IsSequence()) wrong_type(key, e->value, shape);
  std::vector<std::vector<double>> out;
  for (std::size_t i = 0; i < e->value.size(); ++i) {
    const YAML::Node row = e->value[i];
    if (!row.IsSequence() || row.size() != width)
      fail_element(key, i, "expected a list of " + std::to_string(width) + " numbers, got " + describe(row));
    std::vector<double> r;
    for (std::size_t j = 0; j < width; ++j) {
      const auto v = parse_real(row[j]);
      if (!v || !std::isfinite(*v)) fail_element(key, i, "expected finite numbers, got " + describe(row[j]));
      r.push_back(*v);
    }
    out.push_back(std::move(r));
  }
  return out;
}

MapReader MapReader::section(const std::string& key, std::vector<std::string> keys) {
  const Entry* e = find(key);
  // An absent section keeps this section's mark: "missing" errors point at the nearest parent.
  if (!e) return MapReader(*origin_, YAML::Node(), key_path(key), mark_, std::move(keys));
  return MapReader(*origin_, e->value, key_path(key), e->mark, std::move(keys));
}

std::vector<MapReader> MapReader::section_list(const std::string& key, std::vector<std::string> keys) {
  const Entry* e = find(key);
  std::vector<MapReader> out;
  if (!e) return out;
  if (!e->value.IsSequence()) wrong_type(key, e->value, "a list of maps (one '- ' entry per item)");
  for (std::size_t i = 0; i < e->value.size(); ++i) {
    const YAML::Node item = e->value[i];
    const YAML::Mark m = item.Mark().line >= 0 ? item.Mark() : e->mark;
    if (!item.IsMap()) fail_element(key, i, "expected a map of keys (" + join(keys) + "), got " + describe(item));
    out.emplace_back(*origin_, item, key_path(key) + "[" + std::to_string(i) + "]", m, keys);
  }
  return out;
}

MapReader MapReader::with_keys(std::vector<std::string> keys) const {
  MapReader r(*origin_, YAML::Node(), path_, mark_, std::move(keys));
  for (const auto& [name, entry] : entries_) {
    if (std::find(r.keys_.begin(), r.keys_.end(), name) == r.keys_.end()) {
      const std::string near = closest_match(name, r.keys_);
      throw ConfigError(origin_->locate(key_path(name), entry.mark) + ": " + key_path(name) + ": unknown key (" +
                        (near.empty() ? "" : "did you mean '" + near + "'? ") + "allowed here: " + join(r.keys_) + ")");
    }
    r.entries_.emplace(name, entry);
  }
  return r;
}

std::vector<std::string> MapReader::keys_present() const {
  std::vector<std::string> out;
  for (const auto& [name, entry] : entries_) out.push_back(name);
  return out;
}

std::string MapReader::choice(const std::string& key, const std::string& value,
                              const std::vector<std::string>& allowed) const {
  if (std::find(allowed.begin(), allowed.end(), value) != allowed.end()) return value;
  const std::string near = closest_match(value, allowed);
  fail(key, "unknown value '" + value + "' (" + (near.empty() ? "" : "did you mean '" + near + "'? ") +
                "allowed: " + join(allowed) + ")");
}

}  // namespace sphmol
