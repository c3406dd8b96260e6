#include "sphmol/probes/probe_config.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include "sphmol/config/config.hpp"
#include "sphmol/config/yaml_reader.hpp"
#include "sphmol/core/join.hpp"

namespace sphmol {

namespace {

// Bounds the memory of one probe's sample points and CSV rows (a hostile `points: 1e12`).
constexpr double kMaxSamplePoints = 1e6;

std::string shown(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

bool plain_name(const std::string& s) {
  if (s.empty()) return false;
  return std::all_of(s.begin(), s.end(), [](char ch) {
    return (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_' || ch == '-';
  });
}

// A coordinate list of exactly n values.
std::vector<double> coordinates(MapReader& r, const std::string& key, std::size_t n, const std::string& what) {
  auto v = r.required(r.reals(key), key, what);
  if (v.size() != n)
    r.fail(key, "expected " + std::to_string(n) + " coordinate" + (n == 1 ? "" : "s") + " (" + what + "), got " +
                    std::to_string(v.size()));
  return v;
}

int count(MapReader& r, const std::string& key, double value, std::size_t index, bool element) {
  if (value != std::floor(value) || value < 2 || value > kMaxSamplePoints) {
    const std::string msg = shown(value) + " is out of range (allowed: a whole number of sample points, 2 to " +
                            shown(kMaxSamplePoints) + ")";
    if (element) r.fail_element(key, index, msg);
    r.fail(key, msg);
  }
  return static_cast<int>(value);
}

std::string list(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + shown(v[i]);
  return s + "]";
}

}  // namespace

std::vector<std::vector<double>> ProbeConfig::sample_points() const {
  std::vector<std::vector<double>> pts;
  if (type == "point") {
    pts.push_back(at);
  } else if (type == "line") {
    const int n = points.at(0);
    for (int k = 0; k < n; ++k) {
      const double s = static_cast<double>(k) / (n - 1);
      std::vector<double> p(from.size());
      for (std::size_t d = 0; d < p.size(); ++d) p[d] = from[d] + s * (to[d] - from[d]);
      pts.push_back(std::move(p));
    }
  } else if (type == "plane") {
    const int n1 = points.at(0), n2 = points.at(1);
    for (int b = 0; b < n2; ++b)
      for (int a = 0; a < n1; ++a) {
        const double s1 = static_cast<double>(a) / (n1 - 1), s2 = static_cast<double>(b) / (n2 - 1);
        std::vector<double> p(origin.size());
        for (std::size_t d = 0; d < p.size(); ++d) p[d] = origin[d] + s1 * edge_1[d] + s2 * edge_2[d];
        pts.push_back(std::move(p));
      }
  }
  return pts;
}

std::vector<ProbeConfig> read_probes(MapReader& top, const Config& config, const std::vector<std::string>& bodies,
                                     std::vector<std::string>* notices) {
  const int dimension = config.dimension;
  const double t_end = config.time.t_end;
  const std::vector<std::string> types{"point", "line", "plane", "height_gauge", "force"};
  const std::vector<std::string> common{"name", "type", "every"};
  const auto keys_of = [&](const std::string& type) {
    std::vector<std::string> k = common;
    if (type == "point") k.insert(k.end(), {"at", "fields"});
    if (type == "line") k.insert(k.end(), {"from", "to", "points", "fields"});
    if (type == "plane") k.insert(k.end(), {"origin", "edge_1", "edge_2", "points", "fields"});
    if (type == "height_gauge") k.insert(k.end(), {"at", "range"});
    if (type == "force") k.insert(k.end(), {"body"});
    return k;
  };
  std::vector<std::string> all = common;
  for (const auto& t : types)
    for (const auto& k : keys_of(t))
      if (std::find(all.begin(), all.end(), k) == all.end()) all.push_back(k);

  const std::size_t D = static_cast<std::size_t>(dimension);
  std::vector<ProbeConfig> out;
  for (MapReader& any : top.section_list("probes", all)) {
    ProbeConfig p;
    p.name = any.required(any.string("name"), "name", "the probe's name, [A-Za-z0-9_-]+ (its file is probe_<name>.csv)");
    if (!plain_name(p.name))
      any.fail("name", "'" + p.name + "' may hold only letters, digits, '_' and '-' (it names the file probe_<name>.csv)");
    // File names have at most 255 bytes; the atomic write's temporary adds to probe_<name>.csv.
    constexpr std::size_t kMaxName = 100;
    if (p.name.size() > kMaxName)
      any.fail("name", "is " + std::to_string(p.name.size()) + " characters long, more than " + std::to_string(kMaxName) +
                           " (it names the file probe_<name>.csv)");
    for (const auto& q : out)
      if (q.name == p.name) any.fail("name", "'" + p.name + "' is used by an earlier probe (names must be unique)");
    p.type = any.choice("type", any.required(any.string("type"), "type", join(types)), types);
    MapReader r = any.with_keys(keys_of(p.type));
    if (const auto v = r.real("every")) {
      if (!(*v > 0)) r.fail("every", shown(*v) + " is out of range (allowed: > 0 s)");
      // As output.every: a file shortened with --set time.t_end still loads.
      if (*v > t_end && notices)
        notices->push_back(r.where("every") + ": " + shown(*v) + " s is past time.t_end = " + shown(t_end) +
                           " s: the probe samples t = 0 and t_end only");
      p.every = *v;
    }
    const std::string dims = std::to_string(dimension) + "D";
    if (p.type == "point") {
      p.at = coordinates(r, "at", D, "the point's position in " + dims);
      p.where = r.where("at");
    } else if (p.type == "line") {
      p.from = coordinates(r, "from", D, "the line's first point in " + dims);
      p.to = coordinates(r, "to", D, "the line's last point in " + dims);
      if (p.from == p.to) r.fail("to", "equals `from`: a line needs two distinct end points");
      p.points = {count(r, "points", static_cast<double>(r.required(r.integer("points"), "points", "sample points along the line, >= 2")), 0, false)};
      p.where = r.where("from");
    } else if (p.type == "plane") {
      if (dimension != 3)
        any.fail("type", "a plane probe needs dimension 3 (this run is " + dims + "; use a line probe)");
      p.origin = coordinates(r, "origin", D, "a corner of the plane in 3D");
      p.edge_1 = coordinates(r, "edge_1", D, "the first edge vector from the corner in 3D");
      p.edge_2 = coordinates(r, "edge_2", D, "the second edge vector from the corner in 3D");
      const double cross[3] = {p.edge_1[1] * p.edge_2[2] - p.edge_1[2] * p.edge_2[1],
                               p.edge_1[2] * p.edge_2[0] - p.edge_1[0] * p.edge_2[2],
                               p.edge_1[0] * p.edge_2[1] - p.edge_1[1] * p.edge_2[0]};
      if (std::hypot(cross[0], cross[1], cross[2]) == 0.0)
        r.fail("edge_2", "is parallel to edge_1 (or one of them is zero): they must span a plane");
      const auto n = r.required(r.reals("points"), "points", "[n1, n2] sample points along edge_1 and edge_2, each >= 2");
      if (n.size() != 2) r.fail("points", "expected [n1, n2] (sample points along edge_1 and edge_2), got " + std::to_string(n.size()) + " values");
      p.points = {count(r, "points", n[0], 0, true), count(r, "points", n[1], 1, true)};
      if (static_cast<double>(p.points[0]) * p.points[1] > kMaxSamplePoints)
        r.fail("points", "n1 x n2 = " + shown(static_cast<double>(p.points[0]) * p.points[1]) +
                             " sample points is more than " + shown(kMaxSamplePoints));
      p.where = r.where("origin");
    } else if (p.type == "height_gauge") {
      if (dimension < 2) any.fail("type", "a height gauge needs dimension 2 or 3 (the vertical is the last axis)");
      p.at = coordinates(r, "at", D - 1, dimension == 2 ? "x of the vertical line" : "x and y of the vertical line");
      if (const auto v = r.reals("range")) {
        if (v->size() != 2 || !((*v)[0] < (*v)[1]))
          r.fail("range", list(*v) + " is not [bottom, top] with bottom < top");
        p.range = *v;
      }
      p.where = r.where("at");
    } else {  // force
      p.body = r.required(r.string("body"), "body", "the name of a wall body of the scene");
      const auto it = std::find(bodies.begin(), bodies.end(), p.body);
      if (it == bodies.end())
        r.fail("body", "the scene has no wall body named '" + p.body + "' (" +
                           (bodies.empty() ? std::string("this scene has no named wall bodies") : "its bodies: " + join(bodies)) + ")");
      p.body_index = static_cast<int>(it - bodies.begin());
      // The pair forces wall_force.hpp sums are those of wall particles with these terms only.
      const auto& d = config.discretization;
      std::string why;
      if (d.boundary != "wall_particles") why = "discretization.boundary: wall_particles (not " + d.boundary + ")";
      else if (d.viscosity == "strain_rate") why = "discretization.viscosity: morris or none (not strain_rate)";
      else if (d.transport_velocity.enabled) why = "no discretization.transport_velocity";
      else if (d.smoothing_length != "constant") why = "discretization.smoothing_length: constant";
      else if (d.wall_model == "adami") why = "discretization.wall_model: morris or prescribed (not adami)";
      else if (d.laplacian_correction != "none") why = "discretization.laplacian_correction: none (not " + d.laplacian_correction + ")";
      if (!why.empty()) r.fail("body", "a force probe needs " + why + ": it sums the pair forces of wall particles");
      p.where = r.where("body");
    }
    if (p.type == "point" || p.type == "line" || p.type == "plane") {
      const std::vector<std::string> allowed{"p", "rho", "velocity"};
      if (const auto f = r.strings("fields")) {
        if (f->empty()) r.fail("fields", "is empty (allowed: any of p, rho, velocity; absent: all three)");
        for (std::size_t i = 0; i < f->size(); ++i) {
          r.choice("fields", (*f)[i], allowed);
          if (std::count(f->begin(), f->end(), (*f)[i]) > 1) r.fail_element("fields", i, "'" + (*f)[i] + "' is listed twice");
        }
        for (const auto& a : allowed)  // column order is fixed, whatever order they were listed in
          if (std::find(f->begin(), f->end(), a) != f->end()) p.fields.push_back(a);
      } else {
        p.fields = allowed;
      }
    }
    out.push_back(std::move(p));
  }
  return out;
}

std::string probes_to_yaml(const std::vector<ProbeConfig>& probes) {
  if (probes.empty()) return "";
  std::ostringstream y;
  y << "probes:\n";
  for (const auto& p : probes) {
    y << "  - name: " << p.name << "\n    type: " << p.type << "\n";
    if (p.every) y << "    every: " << shown(*p.every) << "\n";
    if (p.type == "point" || p.type == "height_gauge") y << "    at: " << list(p.at) << "\n";
    if (p.type == "line")
      y << "    from: " << list(p.from) << "\n    to: " << list(p.to) << "\n    points: " << p.points[0] << "\n";
    if (p.type == "plane")
      y << "    origin: " << list(p.origin) << "\n    edge_1: " << list(p.edge_1) << "\n    edge_2: " << list(p.edge_2)
        << "\n    points: [" << p.points[0] << ", " << p.points[1] << "]\n";
    if (!p.range.empty()) y << "    range: " << list(p.range) << "\n";
    if (p.type == "force") y << "    body: " << p.body << "\n";
    if (!p.fields.empty()) y << "    fields: [" << join(p.fields) << "]\n";
  }
  return y.str();
}

}  // namespace sphmol
