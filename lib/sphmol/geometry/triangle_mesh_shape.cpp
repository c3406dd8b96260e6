#include "sphmol/geometry/triangle_mesh_shape.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Container_helper.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sphmol/io/input_file.hpp"

namespace sphmol::geometry {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

struct TriangleMeshShape::Impl {
  Mesh mesh;
  std::unique_ptr<Tree> tree;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, K, CGAL::Default, Tree>> side;
};

namespace {

std::string lower_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  if (!e.empty()) e.erase(0, 1);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// The element counts an OFF or PLY header declares, checked against the bytes there are: every OFF
// vertex takes at least 6 bytes ("0 0 0\n") and every face 8 ("3 0 1 2\n") in ASCII, more in binary;
// every PLY element takes at least one byte. Only the header is parsed; CGAL reads the rest.
void check_declared_counts(const std::string& bytes, const std::string& format, const std::string& name) {
  const auto too_many = [&](const std::string& what) {
    throw std::invalid_argument("mesh " + name + ": the header declares " + what + " than a file of " +
                                std::to_string(bytes.size()) + " bytes can hold");
  };
  std::istringstream in(bytes.substr(0, std::min<std::size_t>(bytes.size(), 1 << 16)));
  if (format == "off") {
    // Binary OFF stores its counts as raw integers, which CGAL 5.5 allocates before checking them
    // against the file (found by fuzzing): refused; ASCII OFF, STL and PLY cover the same surfaces.
    if (bytes.substr(0, std::min<std::size_t>(bytes.size(), 64)).find("BINARY") != std::string::npos)
      throw std::invalid_argument("mesh " + name + ": binary OFF is not read (use ASCII OFF, STL or PLY)");
    // Read the counts as CGAL's scanner does: after the keyword (OFF, COFF, NOFF, 4OFF, ...) and any
    // '#' comment lines, two integers by stream extraction (which stops at the first non-digit, so
    // "1870000100+0000" is 1870000100 and then 0).
    std::string keyword;
    in >> keyword;
    if (keyword.find("OFF") == std::string::npos) in.seekg(0);  // no keyword: the counts come first
    const auto skip_comments = [&] {
      while ((in >> std::ws) && in.peek() == '#') {
        std::string line;
        std::getline(in, line);
      }
    };
    long long nv = 0, nf = 0;
    skip_comments();
    if (!(in >> nv)) return;  // not a header CGAL reads: it reports that
    skip_comments();
    if (!(in >> nf)) return;
    if (nv < 0 || nf < 0 || !(6.0 * static_cast<double>(nv) + 8.0 * static_cast<double>(nf) <= static_cast<double>(bytes.size())))
      too_many(std::to_string(nv) + " vertices and " + std::to_string(nf) + " faces, more");
  } else if (format == "ply") {
    // Also the header's structure, which CGAL 5.5's PLY reader trusts: a property line before any
    // element line makes it read past an empty list.
    const auto malformed = [&](const std::string& why) {
      throw std::invalid_argument("mesh " + name + ": not a PLY header (" + why + ")");
    };
    std::string line;
    double total = 0.0;
    bool element = false, ended = false;
    for (int k = 0; std::getline(in, line); ++k) {
      std::istringstream l(line);
      std::string key;
      l >> key;
      if (k == 0 && key != "ply") malformed("the first line is not 'ply'");
      if (key == "end_header") {
        ended = true;
        break;
      }
      if (key == "property" && !element) malformed("a property before any element");
      // CGAL 5.5 sizes a list by its count before reading the entries: a 32-bit count could ask for
      // 16 GB in a small file. Counts of 8 or 16 bits (every common exporter writes uchar) bound a
      // list to 65535 entries.
      if (std::string kind, count_type; key == "property" && (l >> kind >> count_type) && kind == "list" &&
                                         count_type != "char" && count_type != "uchar" && count_type != "int8" &&
                                         count_type != "uint8" && count_type != "short" && count_type != "ushort" &&
                                         count_type != "int16" && count_type != "uint16")
        throw std::invalid_argument("mesh " + name + ": a list property with '" + count_type +
                                    "' counts is not read (write the face lists with uchar or ushort counts)");
      if (key == "element") {
        std::string what;
        double n = -1.0;
        if (!(l >> what >> n) || !(n >= 0.0)) malformed("an element line without a count");
        element = true;
        total += n;
      }
    }
    if (!ended) malformed("no end_header within the first 64 KiB");
    if (!(total <= static_cast<double>(bytes.size()))) too_many(std::to_string(static_cast<long long>(total)) + " elements, more");
  }
}

// A face as CGAL's ASCII OFF reader fills it. The reader sizes each face by the count at the start of
// its line before it reads the indices (CGAL 5.5, IO/OFF.h), so "1000000000 0 1 2" in a tiny file
// allocated 8 GB (found by fuzzing). Every index takes at least two bytes of the file ("0 "), so
// all faces together hold at most half the file's size in indices: each resize draws on that
// budget, and a face that asks for more is refused before anything is allocated.
class OffFaceTooLarge : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};
thread_local std::size_t off_index_budget = 0;
struct OffFace : std::vector<std::size_t> {
  void resize(std::size_t n) {
    if (n > off_index_budget)
      throw OffFaceTooLarge("a face declares " + std::to_string(n) + " vertices, more than the file holds");
    off_index_budget -= n;
    std::vector<std::size_t>::resize(n);
  }
};
static_assert(CGAL::internal::has_resize<OffFace>::value, "CGAL must size OffFace through its resize");

// A convex face with a nonzero area whose vertices all lie in the plane of its Newell normal
// (Sutherland, Sproull & Schumacker 1974), to 1e-9 of its size.
bool plane_face(const std::vector<K::Point_3>& points, const std::vector<std::size_t>& face) {
  double n[3] = {0, 0, 0}, c[3] = {0, 0, 0}, size = 0.0;
  for (std::size_t a = 0; a < face.size(); ++a) {
    const auto& p = points[face[a]];
    const auto& q = points[face[(a + 1) % face.size()]];
    n[0] += (p.y() - q.y()) * (p.z() + q.z());
    n[1] += (p.z() - q.z()) * (p.x() + q.x());
    n[2] += (p.x() - q.x()) * (p.y() + q.y());
    c[0] += p.x() / face.size();
    c[1] += p.y() / face.size();
    c[2] += p.z() / face.size();
  }
  for (const std::size_t v : face) {
    const auto& p = points[v];
    size = std::max({size, std::abs(p.x() - c[0]), std::abs(p.y() - c[1]), std::abs(p.z() - c[2])});
  }
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(len > 1e-12 * size * size) || !std::isfinite(len)) return false;
  for (const std::size_t v : face) {
    const auto& p = points[v];
    const double off = ((p.x() - c[0]) * n[0] + (p.y() - c[1]) * n[1] + (p.z() - c[2]) * n[2]) / len;
    if (!(std::abs(off) <= 1e-9 * size)) return false;
  }
  // Strictly convex: every corner turns the same way about n, so the fan from the first vertex
  // covers the face with proper triangles.
  const std::size_t k = face.size();
  for (std::size_t a = 0; a < k; ++a) {
    const auto& p = points[face[a]];
    const auto& q = points[face[(a + 1) % k]];
    const auto& r = points[face[(a + 2) % k]];
    const double e[3] = {q.x() - p.x(), q.y() - p.y(), q.z() - p.z()};
    const double f[3] = {r.x() - q.x(), r.y() - q.y(), r.z() - q.z()};
    const double turn = (e[1] * f[2] - e[2] * f[1]) * n[0] + (e[2] * f[0] - e[0] * f[2]) * n[1] + (e[0] * f[1] - e[1] * f[0]) * n[2];
    if (!(turn > 0.0)) return false;
  }
  return true;
}

}  // namespace

TriangleMeshShape::TriangleMeshShape(const std::string& path) : impl_(std::make_unique<Impl>()) {
  if (!std::filesystem::is_regular_file(path)) throw std::invalid_argument("mesh " + path + ": no such file");
  std::string bytes;
  try {
    bytes = read_input_file(path, kMaxMeshBytes, "mesh file");
  } catch (const InputFileError& e) {
    throw std::invalid_argument(std::string("mesh ") + e.what());
  }
  build(bytes, lower_extension(path), path);
}

TriangleMeshShape::TriangleMeshShape(const std::string& bytes, const std::string& format, const std::string& name)
    : impl_(std::make_unique<Impl>()) {
  build(bytes, format, name);
}

void TriangleMeshShape::build(const std::string& bytes, const std::string& format, const std::string& name) {
  try {
    build_unchecked(bytes, format, name);
  } catch (const CGAL::Failure_exception& e) {
    // A CGAL check (these are on only in debug builds) that the input broke.
    throw std::invalid_argument("mesh " + name + ": cannot be turned into a surface (" + e.expression() + ")");
  }
}

void TriangleMeshShape::build_unchecked(const std::string& bytes, const std::string& format, const std::string& name) {
  if (bytes.size() > kMaxMeshBytes)
    throw std::invalid_argument("mesh " + name + ": larger than " + format_bytes(kMaxMeshBytes));
  if (format != "stl" && format != "off" && format != "ply" && format != "obj")
    throw std::invalid_argument("mesh " + name + ": unknown format '" + format + "' (the file name must end in .stl, .off, .ply or .obj)");
  check_declared_counts(bytes, format, name);
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  // As CGAL::IO::read_polygon_soup and read_polygon_mesh do for a file name, from memory.
  const auto read = [&](bool binary) {
    points.clear();
    polygons.clear();
    std::istringstream is(bytes, binary ? std::ios::in | std::ios::binary : std::ios::in);
    CGAL::IO::set_mode(is, binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
    if (format == "stl") return CGAL::IO::read_STL(is, points, polygons, CGAL::parameters::use_binary_mode(binary));
    if (format == "off") {
      std::vector<OffFace> faces;
      off_index_budget = bytes.size() / 2;
      const bool read_ok = CGAL::IO::read_OFF(is, points, faces);
      for (auto& f : faces) polygons.push_back(std::move(static_cast<std::vector<std::size_t>&>(f)));
      return read_ok;
    }
    if (format == "ply") return CGAL::IO::read_PLY(is, points, polygons);
    return CGAL::IO::read_OBJ(is, points, polygons);
  };
  bool ok = false;
  try {
    ok = read(format == "stl" || format == "ply") || (format == "stl" && read(false));
  } catch (const OffFaceTooLarge& e) {
    throw std::invalid_argument("mesh " + name + ": " + e.what());
  } catch (const std::exception&) {
    ok = false;
  }
  for (std::size_t k = 0; k < polygons.size(); ++k)
    for (const std::size_t v : polygons[k])
      if (v >= points.size())
        throw std::invalid_argument("mesh " + name + ": face " + std::to_string(k) + " refers to a vertex the file does not have (it has " +
                                    std::to_string(points.size()) + ")");
  // Coordinates whose squares overflow: the distance queries construct points from squared
  // distances, and CGAL's exact fallback aborts on the infinities that result (found by fuzzing).
  constexpr double kMaxCoordinate = 1e100;  // [m]
  const auto fits = [](double x) { return std::abs(x) <= kMaxCoordinate; };  // false for NaN too
  for (const auto& p : points)
    if (ok && !(fits(p.x()) && fits(p.y()) && fits(p.z())))
      throw std::invalid_argument("mesh " + name + ": a vertex coordinate is not a number of magnitude up to 1e100");
  Mesh& m = impl_->mesh;
  if (ok && !polygons.empty()) {
    namespace PMP = CGAL::Polygon_mesh_processing;
    // Faces that repeat a vertex once equal points are merged have no area (a common defect of STL
    // exports); they are dropped before the repair, whose canonical ordering of CGAL 5.5 assumes
    // distinct vertices (a precondition violation otherwise).
    PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
    std::erase_if(polygons, [](std::vector<std::size_t> f) {
      std::sort(f.begin(), f.end());
      return f.size() < 3 || std::adjacent_find(f.begin(), f.end()) != f.end();
    });
    PMP::repair_polygon_soup(points, polygons);
    // Triangles with no area (three points on a line): the inside test casts rays against every
    // triangle and needs each to be proper. Dropping them changes no area; if a gap remains, the
    // surface is refused below as not closed.
    std::erase_if(polygons, [&](const std::vector<std::size_t>& f) {
      return f.size() == 3 && CGAL::collinear(points[f[0]], points[f[1]], points[f[2]]);
    });
    // Larger faces must be plane and convex, and are split into the fan of their first vertex. CGAL's
    // triangulate_faces (a constrained triangulation of the face's projection) failed or did not end
    // on bent or sliver faces (found by fuzzing); non-convex faces must come as triangles.
    std::vector<std::vector<std::size_t>> triangles;
    triangles.reserve(polygons.size());
    for (std::size_t k = 0; k < polygons.size(); ++k) {
      const auto& f = polygons[k];
      if (f.size() == 3) {
        triangles.push_back(f);
        continue;
      }
      if (!plane_face(points, f))
        throw std::invalid_argument("mesh " + name + ": face " + std::to_string(k) + " has " + std::to_string(f.size()) +
                                    " vertices that do not lie in one plane or do not make a convex face; give it as triangles");
      for (std::size_t a = 1; a + 1 < f.size(); ++a) triangles.push_back({f[0], f[a], f[a + 1]});
    }
    polygons = std::move(triangles);
    if (polygons.empty())
      throw std::invalid_argument("mesh " + name + ": no face has an area (all its vertices coincide or lie on a line)");
    PMP::orient_polygon_soup(points, polygons);
    ok = PMP::is_polygon_soup_a_polygon_mesh(polygons);
    if (ok) PMP::polygon_soup_to_polygon_mesh(points, polygons, m);
  }
  if (!ok || m.number_of_faces() == 0)
    throw std::invalid_argument("mesh " + name + ": cannot be read as a polygon mesh (STL, OFF, PLY or OBJ)");
  if (!CGAL::is_closed(m)) throw std::invalid_argument("mesh " + name + ": the surface is not closed, so it has no inside");
  // The inside test counts ray crossings, which is the inside only of a surface that does not cross
  // itself: two overlapping closed parts would leave their overlap outside.
  if (CGAL::Polygon_mesh_processing::does_self_intersect(m))
    throw std::invalid_argument("mesh " + name + ": the surface intersects itself (join overlapping parts into one surface, or "
                                "give them as separate bodies)");
  impl_->tree = std::make_unique<Tree>(faces(m).first, faces(m).second, m);
  impl_->tree->accelerate_distance_queries();
  impl_->side = std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, K, CGAL::Default, Tree>>(*impl_->tree);
  const auto box = impl_->tree->bbox();
  bounds_.lo = {box.xmin(), box.ymin(), box.zmin()};
  bounds_.hi = {box.xmax(), box.ymax(), box.zmax()};
}

TriangleMeshShape::~TriangleMeshShape() = default;

std::size_t TriangleMeshShape::triangles() const { return impl_->mesh.number_of_faces(); }

double TriangleMeshShape::signed_distance(const Vec<3>& p) const {
  const K::Point_3 q(p[0], p[1], p[2]);
  const double d = std::sqrt(CGAL::to_double(impl_->tree->squared_distance(q)));
  switch ((*impl_->side)(q)) {
    case CGAL::ON_BOUNDED_SIDE: return signed_by_side(d, true);
    case CGAL::ON_BOUNDARY: return 0.0;
    default: return signed_by_side(d, false);
  }
}

}  // namespace sphmol::geometry
