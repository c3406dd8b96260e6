#pragma once
// A reader of VTK XML files with raw appended data, written independently of the writer from the
// VTK file-format description: the XML header is parsed with mini_xml, and each DataArray with
// format="appended" is decoded from the bytes after the '_' that opens <AppendedData>, at its
// offset: a UInt64 byte count (header_type="UInt64"), then the values, little-endian. Checks that
// the blocks tile the appended section exactly and that the file closes properly after it.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "mini_xml.hpp"

namespace vtk_appended {

struct File {
  std::unique_ptr<mini_xml::Element> root;     // the XML without the binary section
  std::map<const mini_xml::Element*, std::vector<double>> values;  // every appended DataArray, decoded
  const std::vector<double>& of(const mini_xml::Element& a) const { return values.at(&a); }
};

inline std::uint64_t u64_le(const unsigned char* b) {
  std::uint64_t v = 0;
  for (int k = 7; k >= 0; --k) v = (v << 8) | b[k];
  return v;
}

inline double decode(const std::string& type, const unsigned char* b) {
  if (type == "Float64") {
    const std::uint64_t bits = u64_le(b);
    double v;
    std::memcpy(&v, &bits, 8);
    return v;
  }
  if (type == "Int64") return static_cast<double>(static_cast<std::int64_t>(u64_le(b)));
  if (type == "UInt8") return b[0];
  throw std::runtime_error("vtk_appended: unexpected type " + type);
}

inline std::size_t type_size(const std::string& type) { return type == "UInt8" ? 1 : 8; }

inline void collect(const mini_xml::Element& e, std::vector<const mini_xml::Element*>& out) {
  if (e.name == "DataArray") out.push_back(&e);
  for (const auto& c : e.children) collect(*c, out);
}

inline File read(const std::string& text) {
  const std::string open = "<AppendedData encoding=\"raw\">";
  const auto a = text.find(open);
  if (a == std::string::npos) throw std::runtime_error("vtk_appended: no raw AppendedData");
  const auto underscore = text.find('_', a + open.size());
  if (underscore == std::string::npos) throw std::runtime_error("vtk_appended: no '_' before the data");
  for (auto k = a + open.size(); k < underscore; ++k)
    if (!std::isspace(static_cast<unsigned char>(text[k]))) throw std::runtime_error("vtk_appended: text before '_'");
  File f;
  f.root = mini_xml::parse(text.substr(0, a) + "</VTKFile>");
  if (f.root->attr.at("header_type") != "UInt64" || f.root->attr.at("byte_order") != "LittleEndian")
    throw std::runtime_error("vtk_appended: expected header_type UInt64, little-endian");
  const auto* data = reinterpret_cast<const unsigned char*>(text.data()) + underscore + 1;
  const std::size_t available = text.size() - underscore - 1;
  std::vector<const mini_xml::Element*> arrays;
  collect(*f.root, arrays);
  std::uint64_t end = 0;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> blocks;
  for (const auto* arr : arrays) {
    if (arr->attr.at("format") != "appended") throw std::runtime_error("vtk_appended: array not appended");
    const std::uint64_t off = std::stoull(arr->attr.at("offset"));
    if (off + 8 > available) throw std::runtime_error("vtk_appended: offset past the end");
    const std::uint64_t bytes = u64_le(data + off);
    if (off + 8 + bytes > available) throw std::runtime_error("vtk_appended: block past the end");
    const std::string& type = arr->attr.at("type");
    if (bytes % type_size(type) != 0) throw std::runtime_error("vtk_appended: partial value");
    std::vector<double> v;
    for (std::uint64_t k = 0; k < bytes; k += type_size(type)) v.push_back(decode(type, data + off + 8 + k));
    f.values[arr] = std::move(v);
    blocks.emplace_back(off, off + 8 + bytes);
  }
  std::sort(blocks.begin(), blocks.end());
  for (const auto& [b, e] : blocks) {
    if (b != end) throw std::runtime_error("vtk_appended: blocks do not tile the appended data");
    end = e;
  }
  const std::string tail(text.begin() + static_cast<std::ptrdiff_t>(underscore + 1 + end), text.end());
  const auto close = tail.find("</AppendedData>");
  if (close == std::string::npos || tail.find_first_not_of(" \n", 0) != close ||
      tail.substr(close) .find("</VTKFile>") == std::string::npos)
    throw std::runtime_error("vtk_appended: bytes after the last block");
  return f;
}

// The DataArray called `name` among the children of `parent`.
inline const mini_xml::Element& array_named(const mini_xml::Element& parent, const std::string& name) {
  for (const auto* a : parent.all("DataArray"))
    if (a->attr.count("Name") && a->attr.at("Name") == name) return *a;
  throw std::runtime_error("no DataArray " + name);
}

}  // namespace vtk_appended
