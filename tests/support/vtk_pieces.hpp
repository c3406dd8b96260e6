#pragma once
// The particles of a VTK PolyData file (.vtp) or of a parallel one (.pvtp and its pieces), read
// with the tests' own reader (unit/vtk_appended.hpp), keyed by the `id` array, so that a run's
// per-rank pieces can be compared with a serial file: the same arrays (names, types, components,
// in order) and, for every particle, the same values to the bit. Ghost images (id -1) have no key:
// their rows are compared as a multiset (the pieces split the serial order by owner).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "../unit/vtk_appended.hpp"
#include "files.hpp"

namespace vtk_pieces {

struct Declaration {
  std::string type, name, components;
  bool operator==(const Declaration&) const = default;
};

struct Particles {
  std::vector<Declaration> arrays;                     // point data, then the points
  std::map<std::int64_t, std::vector<double>> values;  // by id: every array's components in order
  // Particles with id -1 (ghost images, made anew at every evaluation): compared as a multiset.
  std::vector<std::vector<double>> unkeyed;
  std::vector<double> time;                            // each file's TimeValue
  std::size_t pieces = 0;
};

inline Declaration declaration(const mini_xml::Element& a) {
  return {a.attr.at("type"), a.attr.at("Name"), a.attr.at("NumberOfComponents")};
}

// One .vtp file's particles (ids must be unique within it and across `into`).
inline void read_vtp(const std::filesystem::path& file, Particles& into) {
  const std::string text = test_support::slurp(file);
  if (text.empty()) throw std::runtime_error(file.string() + ": missing or empty");
  const vtk_appended::File f = vtk_appended::read(text);
  if (f.root->attr.at("type") != "PolyData") throw std::runtime_error(file.string() + ": not PolyData");
  const auto* poly = f.root->child("PolyData");
  const auto* piece = poly->child("Piece");
  const std::size_t n = std::stoull(piece->attr.at("NumberOfPoints"));
  std::vector<const mini_xml::Element*> arrays = piece->child("PointData")->all("DataArray");
  arrays.push_back(&vtk_appended::array_named(*piece->child("Points"), "Points"));
  std::vector<Declaration> decl;
  for (const auto* a : arrays) decl.push_back(declaration(*a));
  if (into.pieces == 0) into.arrays = decl;
  else if (decl != into.arrays) throw std::runtime_error(file.string() + ": other arrays than the first piece");
  ++into.pieces;
  into.time.push_back(f.of(vtk_appended::array_named(*poly->child("FieldData"), "TimeValue")).at(0));
  const std::vector<double>& id = f.of(vtk_appended::array_named(*piece->child("PointData"), "id"));
  if (id.size() != n) throw std::runtime_error(file.string() + ": not one id per point");
  for (std::size_t k = 0; k < n; ++k) {
    std::vector<double> row;
    for (const auto* a : arrays) {
      const std::vector<double>& v = f.of(*a);
      const std::size_t c = std::stoull(a->attr.at("NumberOfComponents"));
      if (v.size() != n * c) throw std::runtime_error(file.string() + ": array " + a->attr.at("Name") + " has the wrong length");
      row.insert(row.end(), v.begin() + static_cast<long>(k * c), v.begin() + static_cast<long>((k + 1) * c));
    }
    if (id[k] == -1) into.unkeyed.push_back(std::move(row));
    else if (!into.values.emplace(static_cast<std::int64_t>(id[k]), std::move(row)).second)
      throw std::runtime_error(file.string() + ": particle " + std::to_string(static_cast<long long>(id[k])) + " written twice");
  }
}

inline Particles read_vtp(const std::filesystem::path& file) {
  Particles p;
  read_vtp(file, p);
  return p;
}

// A .pvtp and its pieces (Source paths relative to the .pvtp): the union of the pieces' particles.
// The .pvtp must declare the pieces' arrays, with GhostLevel 0.
inline Particles read_pvtp(const std::filesystem::path& file) {
  const auto root = mini_xml::parse(test_support::slurp(file));
  if (root->name != "VTKFile" || root->attr.at("type") != "PPolyData") throw std::runtime_error(file.string() + ": not PPolyData");
  const auto* pp = root->child("PPolyData");
  if (!pp || pp->attr.at("GhostLevel") != "0") throw std::runtime_error(file.string() + ": no PPolyData with GhostLevel 0");
  std::vector<Declaration> declared;
  for (const auto* a : pp->child("PPointData")->all("PDataArray")) declared.push_back(declaration(*a));
  for (const auto* a : pp->child("PPoints")->all("PDataArray")) declared.push_back(declaration(*a));
  Particles p;
  for (const auto* piece : pp->all("Piece")) {
    const std::string source = piece->attr.at("Source");
    if (std::filesystem::path(source).is_absolute()) throw std::runtime_error(file.string() + ": absolute piece path " + source);
    read_vtp(file.parent_path() / source, p);
  }
  if (p.pieces == 0) throw std::runtime_error(file.string() + ": no pieces");
  if (declared != p.arrays) throw std::runtime_error(file.string() + ": declares other arrays than its pieces hold");
  return p;
}

// The rows sorted by their values' bits (a total order, so equal multisets sort alike).
inline std::vector<std::vector<double>> sorted_bits(std::vector<std::vector<double>> rows) {
  const auto bits = [](const std::vector<double>& r) {
    std::vector<std::uint64_t> b(r.size());
    std::memcpy(b.data(), r.data(), r.size() * sizeof(double));
    return b;
  };
  std::sort(rows.begin(), rows.end(), [&](const auto& x, const auto& y) { return bits(x) < bits(y); });
  return rows;
}

// "" when a and b hold the same arrays and the same particles with the same values (bits), else
// what differs first.
inline std::string difference(const Particles& a, const Particles& b) {
  if (a.arrays != b.arrays) return "other arrays";
  if (a.values.size() != b.values.size())
    return std::to_string(a.values.size()) + " particles against " + std::to_string(b.values.size());
  if (a.unkeyed.size() != b.unkeyed.size())
    return std::to_string(a.unkeyed.size()) + " particles with id -1 against " + std::to_string(b.unkeyed.size());
  const auto ua = sorted_bits(a.unkeyed), ub = sorted_bits(b.unkeyed);
  std::size_t unkeyed_differing = 0;
  for (std::size_t k = 0; k < ua.size(); ++k)
    unkeyed_differing += ua[k].size() != ub[k].size() ||
                         std::memcmp(ua[k].data(), ub[k].data(), ua[k].size() * sizeof(double)) != 0;
  if (unkeyed_differing > 0)
    return std::to_string(unkeyed_differing) + " of the particles with id -1 differ (as sorted multisets)";
  std::size_t differing = 0;
  std::string first;
  for (auto ia = a.values.begin(), ib = b.values.begin(); ia != a.values.end(); ++ia, ++ib) {
    const bool same = ia->first == ib->first && ia->second.size() == ib->second.size() &&
                      std::memcmp(ia->second.data(), ib->second.data(), ia->second.size() * sizeof(double)) == 0;
    if (!same && differing++ == 0) first = "particle id " + std::to_string(ia->first);
  }
  if (differing > 0) return std::to_string(differing) + " particles differ, the first " + first;
  for (const auto* times : {&a.time, &b.time})
    for (const double t : *times)
      if (t != a.time.front()) return "another TimeValue";
  return "";
}

}  // namespace vtk_pieces
