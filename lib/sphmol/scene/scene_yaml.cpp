#include "sphmol/scene/scene_yaml.hpp"

#include "sphmol/config/yaml_reader.hpp"

#include <yaml-cpp/yaml.h>

#include <charconv>
#include <sstream>

namespace sphmol {

namespace {

std::string num(double v) { return number_text(v); }
std::string list(const std::vector<double>& v) { return yaml_list(v); }
std::string quoted(const std::string& s) { return yaml_quoted(s); }

// A plain number as it is, any other expression quoted (so it reads back as the same text).
std::string scalar(const std::string& text) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  return ec == std::errc{} && end == text.data() + text.size() && !text.empty() ? text : quoted(text);
}

std::string shape(const ShapeSpec& s) {
  std::string out = "{type: " + s.type;
  if (s.type == "box") out += ", lo: " + list(s.lo) + ", hi: " + list(s.hi);
  else if (s.type == "sphere") out += ", centre: " + list(s.centre) + ", radius: " + num(s.radius);
  else if (s.type == "cylinder") out += ", start: " + list(s.start) + ", end: " + list(s.end) + ", radius: " + num(s.radius);
  else if (s.type == "polygon") {
    out += ", vertices: [";
    for (std::size_t i = 0; i < s.vertices.size(); ++i) out += (i ? ", " : "") + list(s.vertices[i]);
    out += "]";
  } else if (s.type == "mesh") out += ", file: " + quoted(s.file);
  else if (s.type == "plane") out += ", point: " + list(s.point) + ", normal: " + list(s.normal);
  else {
    out += ", shapes: [";
    for (std::size_t i = 0; i < s.shapes.size(); ++i) out += (i ? ", " : "") + shape(s.shapes[i]);
    out += "]";
  }
  return out + "}";
}

std::string motion(const WallMotionSpec& m) {
  std::string out = "{type: " + m.type + ", stationary: " + (m.stationary ? "true" : "false");
  if (m.type == "translation") out += ", velocity: " + list(m.velocity);
  if (m.type == "oscillation") out += ", amplitude: " + list(m.amplitude);
  if (m.type == "rotation" || m.type == "pitching") {
    out += ", centre: " + list(m.centre);
    if (!m.axis.empty()) out += ", axis: " + list(m.axis);
  }
  if (m.type == "rotation") out += ", angular_velocity: " + num(m.angular_velocity);
  if (m.type == "pitching") out += ", angle_amplitude: " + num(m.angle_amplitude);
  if (m.type == "oscillation" || m.type == "pitching") out += ", frequency: " + num(m.frequency) + ", phase: " + num(m.phase);
  return out + "}";
}

}  // namespace

std::string scene_to_yaml(const SceneSpec& spec) {
  std::ostringstream y;
  const auto& d = spec.domain;
  const int dim = spec.dimension;
  y << "scene:\n  domain:\n    lo: " << list(d.lo) << "\n    hi: " << list(d.hi) << "\n    boundaries: [";
  for (int a = 0; a < dim; ++a)
    y << (a ? ", " : "")
      << (d.boundary[a] == AxisBoundary::periodic ? "periodic" : d.boundary[a] == AxisBoundary::wall ? "wall" : "open");
  y << "]\n    open_faces: [";
  bool first = true;
  for (int f = 0; f < 2 * dim; ++f)
    if (d.open[f] && d.boundary[f / 2] == AxisBoundary::wall) {
      y << (first ? "" : ", ") << "xyz"[f / 2] << (f % 2 == 0 ? "_lo" : "_hi");
      first = false;
    }
  y << "]\n  fluid:\n";
  for (const auto& b : spec.fluid) {
    y << "    - shape: " << shape(b.shape) << "\n      lattice: "
      << (b.lattice == geometry::LatticeType::hexagonal ? "hexagonal" : "cubic") << "\n      velocity: [";
    for (int a = 0; a < dim; ++a)
      y << (a ? ", " : "") << (b.velocity.empty() ? std::string("0") : scalar(b.velocity[static_cast<std::size_t>(a)]->text()));
    y << "]\n      pressure: " << (b.hydrostatic ? std::string(kHydrostaticPressure) : num(b.pressure)) << "\n";
    if (b.density > 0.0) y << "      density: " << num(b.density) << "\n";
    if (b.viscosity >= 0.0) y << "      kinematic_viscosity: " << num(b.viscosity) << "\n";
  }
  if (spec.walls.empty()) {
    y << "  walls: []\n";
  } else {
    y << "  walls:\n";
    for (const auto& w : spec.walls) {
      std::vector<double> v = w.velocity;
      v.resize(static_cast<std::size_t>(dim), 0.0);
      y << "    - name: " << quoted(w.name) << "\n      shape: " << shape(w.shape) << "\n      layers: " << w.layers << "\n";
      if (w.motion) y << "      motion: " << motion(*w.motion) << "\n";
      else y << "      velocity: " << list(v) << "\n      belt: " << (w.belt ? "true" : "false") << "\n";
      if (w.treatment == "repulsive") {
        const auto& r = w.repulsion;
        y << "      treatment: repulsive\n      repulsive: {";
        if (r.strength > 0.0) y << "strength: " << num(r.strength) << ", ";
        y << "p1: " << num(r.p1) << ", p2: " << num(r.p2) << ", r0: " << num(r.r0) << "}\n";
        continue;
      }
      if (!w.treatment.empty()) y << "      treatment: " << w.treatment << "\n";
      y << "      slip: " << (w.free_slip ? "free_slip" : "no_slip") << "\n";
    }
  }
  return y.str();
}

}  // namespace sphmol
