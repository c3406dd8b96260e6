#pragma once
// A minimal XML reader for the tests (elements, attributes, text; no DTD, CDATA or entities
// beyond what our writers never emit): enough to check the structure of the VTK files
// independently of the writer. Throws std::runtime_error on malformed input, including
// mismatched closing tags.
#include <cctype>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace mini_xml {

struct Element {
  std::string name;
  std::map<std::string, std::string> attr;
  std::vector<std::unique_ptr<Element>> children;
  std::string text;
  const Element* child(const std::string& n) const {
    for (const auto& c : children)
      if (c->name == n) return c.get();
    return nullptr;
  }
  std::vector<const Element*> all(const std::string& n) const {
    std::vector<const Element*> out;
    for (const auto& c : children)
      if (c->name == n) out.push_back(c.get());
    return out;
  }
};

class Parser {
 public:
  explicit Parser(const std::string& s) : s_(s) {}
  std::unique_ptr<Element> parse() {
    skip_ws();
    if (s_.compare(i_, 5, "<?xml") == 0) {
      i_ = s_.find("?>", i_);
      if (i_ == std::string::npos) fail("unterminated XML declaration");
      i_ += 2;
    }
    skip_ws();
    auto root = element();
    skip_ws();
    if (i_ != s_.size()) fail("content after the root element");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("XML: " + what + " at offset " + std::to_string(i_));
  }
  void skip_ws() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  std::string name() {
    const auto b = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_' || s_[i_] == ':' || s_[i_] == '-')) ++i_;
    if (b == i_) fail("expected a name");
    return s_.substr(b, i_ - b);
  }
  std::unique_ptr<Element> element() {
    if (s_[i_] != '<') fail("expected '<'");
    ++i_;
    auto e = std::make_unique<Element>();
    e->name = name();
    for (;;) {
      skip_ws();
      if (i_ >= s_.size()) fail("unterminated tag");
      if (s_.compare(i_, 2, "/>") == 0) {
        i_ += 2;
        return e;
      }
      if (s_[i_] == '>') {
        ++i_;
        break;
      }
      const std::string key = name();
      skip_ws();
      if (s_[i_] != '=') fail("expected '='");
      ++i_;
      skip_ws();
      if (s_[i_] != '"') fail("expected '\"'");
      const auto end = s_.find('"', i_ + 1);
      if (end == std::string::npos) fail("unterminated attribute");
      if (!e->attr.emplace(key, s_.substr(i_ + 1, end - i_ - 1)).second) fail("duplicate attribute " + key);
      i_ = end + 1;
    }
    for (;;) {
      const auto lt = s_.find('<', i_);
      if (lt == std::string::npos) fail("unterminated element " + e->name);
      e->text += s_.substr(i_, lt - i_);
      i_ = lt;
      if (s_.compare(i_, 2, "</") == 0) {
        i_ += 2;
        if (name() != e->name) fail("mismatched closing tag for " + e->name);
        skip_ws();
        if (s_[i_] != '>') fail("expected '>'");
        ++i_;
        return e;
      }
      e->children.push_back(element());
    }
  }
  const std::string& s_;
  std::size_t i_ = 0;
};

inline std::unique_ptr<Element> parse(const std::string& text) { return Parser(text).parse(); }

// Whitespace-separated numbers of an element's text, parsed with strtod (exact for %.17g).
inline std::vector<double> numbers(const Element& e) {
  std::vector<double> out;
  const char* p = e.text.c_str();
  for (;;) {
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if (end == p) break;
    out.push_back(v);
    p = end;
  }
  return out;
}

}  // namespace mini_xml
