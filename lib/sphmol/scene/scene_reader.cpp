#include "sphmol/scene/scene_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "sphmol/config/yaml_reader.hpp"
#include "sphmol/core/join.hpp"

#include "sphmol/scene/ghost_planes.hpp"
#include "sphmol/scene/scene_shapes.hpp"

namespace sphmol {

namespace {

const char* const kAxis = "xyz";

std::string face_name(int face) { return std::string(1, kAxis[face / 2]) + (face % 2 == 0 ? "_lo" : "_hi"); }

std::vector<double> point(MapReader& r, const std::string& key, int dim, std::string_view hint) {
  auto v = r.required(r.reals(key), key, hint);
  if (static_cast<int>(v.size()) != dim)
    r.fail(key, "expected " + std::to_string(dim) + " numbers (one per axis), got " + std::to_string(v.size()));
  return v;
}

ShapeSpec read_shape(MapReader& any, int dim, const std::filesystem::path& folder) {
  static const std::vector<std::string> all = {"type", "lo", "hi", "centre", "radius", "start", "end",
                                               "vertices", "file", "point", "normal", "shapes"};
  MapReader r0 = any.with_keys(all);
  ShapeSpec s;
  if (!r0.has("type")) r0.fail_missing("type", "box, sphere, cylinder, polygon, mesh, plane, union, intersection or difference");
  s.type = r0.choice("type", *r0.string("type"),
                     {"box", "sphere", "cylinder", "polygon", "mesh", "plane", "union", "intersection", "difference"});
  s.where = r0.where("type");
  s.where.resize(s.where.size() - 5);  // "FILE:LINE: path.type" -> "FILE:LINE: path"
  const std::string dtext = std::to_string(dim) + "D";
  if (s.type == "cylinder" && dim != 3) r0.fail("type", "a cylinder is three-dimensional; in 2D use a sphere (a circle) or a box");
  if (s.type == "polygon" && dim != 2) r0.fail("type", "a polygon is two-dimensional; in 3D use a mesh");
  if (s.type == "mesh" && dim != 3) r0.fail("type", "a mesh is three-dimensional; in 2D use a polygon");
  const std::map<std::string, std::vector<std::string>> keys = {
      {"box", {"type", "lo", "hi"}},        {"sphere", {"type", "centre", "radius"}},
      {"cylinder", {"type", "start", "end", "radius"}}, {"polygon", {"type", "vertices"}},
      {"mesh", {"type", "file"}},           {"plane", {"type", "point", "normal"}},
      {"union", {"type", "shapes"}},        {"intersection", {"type", "shapes"}},
      {"difference", {"type", "shapes"}}};
  MapReader r = r0.with_keys(keys.at(s.type));
  if (s.type == "box") {
    s.lo = point(r, "lo", dim, "the lower corner");
    s.hi = point(r, "hi", dim, "the upper corner");
    for (int d = 0; d < dim; ++d)
      if (!(s.hi[d] > s.lo[d])) r.fail_element("hi", static_cast<std::size_t>(d), "must exceed lo along every axis");
  } else if (s.type == "sphere" || s.type == "cylinder") {
    if (s.type == "sphere") {
      s.centre = point(r, "centre", dim, "the centre");
    } else {
      s.start = point(r, "start", dim, "the centre of one end cap");
      s.end = point(r, "end", dim, "the centre of the other end cap");
      double len2 = 0.0;
      for (int d = 0; d < dim; ++d) len2 += (s.end[d] - s.start[d]) * (s.end[d] - s.start[d]);
      if (!(len2 > 0.0)) r.fail("end", "must differ from start");
    }
    s.radius = r.required(r.real("radius"), "radius", "[m], > 0");
    if (!(s.radius > 0.0)) r.fail("radius", "must be > 0");
  } else if (s.type == "polygon") {
    s.vertices = r.required(r.real_rows("vertices", 2), "vertices", "the outline [[x, y], ...]");
    if (s.vertices.size() < 3) r.fail("vertices", "a polygon needs at least three vertices");
  } else if (s.type == "mesh") {
    const std::string f = r.required(r.string("file"), "file", "an STL, OFF, PLY or OBJ surface file");
    std::filesystem::path p(f);
    s.file = (p.is_absolute() ? p : folder / p).lexically_normal().string();
    s.where = r.where("file");
  } else if (s.type == "plane") {
    s.point = point(r, "point", dim, "a point on the plane");
    s.normal = point(r, "normal", dim, "the outward normal: the solid is the side it points away from");
    double n2 = 0.0;
    for (double c : s.normal) n2 += c * c;
    if (!(n2 > 0.0)) r.fail("normal", "must not be zero");
  } else {
    auto parts = r.section_list("shapes", {"type", "lo", "hi", "centre", "radius", "start", "end", "vertices", "file",
                                           "point", "normal", "shapes"});
    const std::size_t need = s.type == "difference" ? 2 : 1;
    if (parts.size() < need)
      r.fail(parts.empty() && !r.has("shapes") ? "type" : "shapes",
             s.type + " needs at least " + std::to_string(need) + " shape" + (need > 1 ? "s" : "") + " under 'shapes'");
    for (auto& p : parts) s.shapes.push_back(read_shape(p, dim, folder));
  }
  // What only the kit can check (a self-intersecting outline, an open mesh): now, at this line.
  if (dim == 2) make_shape<2>(s);
  else make_shape<3>(s);
  return s;
}

DomainSpec read_domain(MapReader& scene, int dim) {
  MapReader r = scene.section("domain", {"lo", "hi", "boundaries", "open_faces"});
  DomainSpec d;
  d.lo = point(r, "lo", dim, "the lower corner of the domain box");
  d.hi = point(r, "hi", dim, "the upper corner of the domain box");
  d.where_lo = r.where("lo");
  d.where_hi = r.where("hi");
  for (int a = 0; a < dim; ++a)
    if (!(d.hi[a] > d.lo[a])) r.fail_element("hi", static_cast<std::size_t>(a), "must exceed lo along every axis");
  d.boundary.assign(static_cast<std::size_t>(dim), AxisBoundary::wall);
  d.where_boundaries = r.where("boundaries");
  if (const auto b = r.strings("boundaries")) {
    if (static_cast<int>(b->size()) != dim)
      r.fail("boundaries", "expected " + std::to_string(dim) + " entries (one per axis), got " + std::to_string(b->size()));
    for (std::size_t a = 0; a < b->size(); ++a) {
      const std::string& v = (*b)[a];
      if (v == "periodic") d.boundary[a] = AxisBoundary::periodic;
      else if (v == "wall") d.boundary[a] = AxisBoundary::wall;
      else if (v == "open") d.boundary[a] = AxisBoundary::open;
      else {
        const std::string near = closest_match(v, {"periodic", "wall", "open"});
        r.fail_element("boundaries", a, "unknown value '" + v + "' (" + (near.empty() ? "" : "did you mean '" + near + "'? ") +
                                            "allowed: periodic, wall, open)");
      }
    }
  }
  d.open.assign(static_cast<std::size_t>(2 * dim), false);
  for (int a = 0; a < dim; ++a)
    if (d.boundary[a] == AxisBoundary::open) d.open[2 * a] = d.open[2 * a + 1] = true;
  d.where_open = r.where("open_faces");
  if (const auto f = r.strings("open_faces")) {
    std::vector<std::string> names;
    for (int face = 0; face < 2 * dim; ++face) names.push_back(face_name(face));
    for (std::size_t i = 0; i < f->size(); ++i) {
      const auto it = std::find(names.begin(), names.end(), (*f)[i]);
      if (it == names.end()) {
        const std::string near = closest_match((*f)[i], names);
        r.fail_element("open_faces", i, "unknown face '" + (*f)[i] + "' (" + (near.empty() ? "" : "did you mean '" + near + "'? ") +
                                            "faces: " + join(names) + ")");
      }
      const int face = static_cast<int>(it - names.begin());
      if (d.boundary[face / 2] != AxisBoundary::wall)
        r.fail_element("open_faces", i, "the face " + (*f)[i] + " is on a " +
                                            (d.boundary[face / 2] == AxisBoundary::periodic ? "periodic" : "open") +
                                            " axis; only faces of wall axes can be opened");
      if (d.open[face]) r.fail_element("open_faces", i, "the face " + (*f)[i] + " is listed twice");
      d.open[face] = true;
    }
  }
  return d;
}

std::vector<std::shared_ptr<const Expression>> read_velocity(MapReader& r, int dim) {
  std::vector<std::shared_ptr<const Expression>> out;
  const auto v = r.strings("velocity");
  if (!v) return out;
  if (static_cast<int>(v->size()) != dim)
    r.fail("velocity", "expected " + std::to_string(dim) + " components (numbers or expressions of x" +
                           std::string(dim > 2 ? ", y, z" : ", y") + "), got " + std::to_string(v->size()));
  for (std::size_t i = 0; i < v->size(); ++i) {
    try {
      out.push_back(std::make_shared<const Expression>((*v)[i], dim));
    } catch (const ExpressionError& e) {
      r.fail_element("velocity", i, "'" + (*v)[i] + "': " + e.what());
    }
  }
  return out;
}

WallMotionSpec read_motion(MapReader& wall, int dim) {
  static const std::vector<std::string> all = {"type",      "stationary",      "velocity",  "centre", "axis",
                                               "angular_velocity", "amplitude", "angle_amplitude", "frequency", "phase"};
  MapReader r0 = wall.section("motion", all);
  WallMotionSpec m;
  m.where = wall.where("motion");
  if (!r0.has("type")) r0.fail_missing("type", "translation, rotation, oscillation or pitching");
  m.type = r0.choice("type", *r0.string("type"), {"translation", "rotation", "oscillation", "pitching"});
  const bool turns = m.type == "rotation" || m.type == "pitching";
  if (turns && dim < 2) r0.fail("type", "a one-dimensional wall cannot " + std::string(m.type == "rotation" ? "rotate" : "pitch"));
  const std::map<std::string, std::vector<std::string>> keys = {
      {"translation", {"type", "stationary", "velocity"}},
      {"rotation", {"type", "stationary", "centre", "axis", "angular_velocity"}},
      {"oscillation", {"type", "stationary", "amplitude", "frequency", "phase"}},
      {"pitching", {"type", "stationary", "centre", "axis", "angle_amplitude", "frequency", "phase"}}};
  std::vector<std::string> allowed = keys.at(m.type);
  // In 2D every rotation is about the z axis: an `axis` there would be ignored, so it is an error.
  if (dim != 3) allowed.erase(std::remove(allowed.begin(), allowed.end(), "axis"), allowed.end());
  MapReader r = r0.with_keys(allowed);
  m.stationary = r.boolean("stationary").value_or(false);
  if (m.type == "translation") {
    m.velocity = point(r, "velocity", dim, "[m/s]");
  } else if (m.type == "oscillation") {
    m.amplitude = point(r, "amplitude", dim, "[m], one per axis");
  } else {
    m.centre = point(r, "centre", dim, "a point on the axis of rotation [m]");
    if (dim == 3) {
      m.axis = point(r, "axis", 3, "the direction of the axis of rotation, e.g. [0, 0, 1]");
      double n2 = 0.0;
      for (double a : m.axis) n2 += a * a;
      if (!(n2 > 0.0)) r.fail("axis", "must not be zero");
    }
  }
  if (m.type == "rotation") m.angular_velocity = r.required(r.real("angular_velocity"), "angular_velocity", "[rad/s], counter-clockwise about the axis");
  if (m.type == "pitching") m.angle_amplitude = r.required(r.real("angle_amplitude"), "angle_amplitude", "[rad]");
  if (m.type == "oscillation" || m.type == "pitching") {
    m.frequency = r.required(r.real("frequency"), "frequency", "[Hz], > 0");
    if (!(m.frequency > 0.0)) r.fail("frequency", "must be > 0");
    m.phase = r.real("phase").value_or(0.0);
  }
  return m;
}

// The body's `treatment` and, for a repulsive body, its `repulsive` law; what contradicts it is an
// error at its line. Checks against the discretization are check_wall_bodies' (scene_builder.hpp).
void read_treatment(MapReader& w, WallBodySpec& b) {
  b.where_treatment = w.where("treatment");
  b.where_repulsion = w.where("repulsive");
  if (const auto v = w.string("treatment")) {
    b.treatment = w.choice("treatment", *v, {"rest", "extrapolated", "dynamic", "repulsive", "ghost"});
  }
  if (b.treatment == "ghost") {
    // A mirror plane: no particles, and it must stay where it is (boundary/ghost_particles.hpp).
    if (b.shape.type != "plane")
      w.fail("treatment", "ghost mirrors need a plane body (shape type plane); a '" + b.shape.type +
                              "' takes rest, extrapolated, dynamic or repulsive");
    if (w.has("repulsive")) w.fail("repulsive", "the parameters of the repulsive force need treatment: repulsive");
    check_ghost_body(b);
    return;
  }
  const bool repulsive = b.treatment == "repulsive";
  if (w.has("repulsive") && !repulsive)
    w.fail("repulsive", "the parameters of the repulsive force (Niedoba 2012, eq 2.76) need treatment: repulsive");
  if (!repulsive) return;
  if (w.has("slip"))
    w.fail("slip", "a repulsive body exerts no viscous stress (its particles take no part in the SPH sums): remove slip, or "
                   "use treatment rest, extrapolated or dynamic");
  if (b.layers > 0) w.fail("layers", "a repulsive body is one layer of particles on its surface: remove layers");
  // A surface velocity acts through the viscous term, which a repulsive body does not enter.
  if (b.belt) w.fail("belt", "a repulsive body exerts no shear, so a moving surface on it would act on nothing");
  if (b.motion && b.motion->stationary)
    w.fail("motion", "a repulsive body exerts no shear, so a stationary motion (particles in place carrying a velocity) would "
                     "act on nothing; use stationary: false");
  if (!w.has("repulsive")) return;
  MapReader r = w.section("repulsive", {"strength", "p1", "p2", "r0"});
  auto& law = b.repulsion;
  if (const auto v = r.real("strength")) {
    law.strength = *v;
    if (!(law.strength > 0.0)) r.fail("strength", "must be > 0 m^2/s^2 (omit it for the squared velocity scale of the scene)");
  }
  if (const auto v = r.real("p2")) law.p2 = *v;
  if (!(law.p2 > 0.0)) r.fail("p2", "must be > 0");
  if (const auto v = r.real("p1")) law.p1 = *v;
  if (!(law.p1 > law.p2)) r.fail(r.has("p1") ? "p1" : "p2", "p1 (" + number_text(law.p1) + ") must exceed p2 (" + number_text(law.p2) + ")");
  if (const auto v = r.real("r0")) law.r0 = *v;
  if (!(law.r0 > 0.0)) r.fail("r0", "must be > 0 particle spacings");
}

}  // namespace

SceneSpec read_scene(MapReader& scene, int dimension, const std::string& config_file) {
  SceneSpec s;
  s.dimension = dimension;
  s.where = scene.where("domain");
  const std::filesystem::path folder = std::filesystem::path(config_file).parent_path();
  s.domain = read_domain(scene, dimension);

  auto fluids = scene.section_list("fluid", {"shape", "lattice", "velocity", "pressure", "density", "kinematic_viscosity"});
  if (fluids.empty()) scene.fail(scene.has("fluid") ? "fluid" : "domain", "the scene needs at least one fluid body under 'fluid'");
  for (auto& f : fluids) {
    FluidBodySpec b;
    b.where = f.where("shape");
    if (!f.has("shape")) f.fail_missing("shape", "the region the fluid fills, e.g. {type: box, lo: [...], hi: [...]}");
    MapReader shape = f.section("shape", {"type", "lo", "hi", "centre", "radius", "start", "end", "vertices", "file",
                                          "point", "normal", "shapes"});
    b.shape = read_shape(shape, dimension, folder);
    b.where_lattice = f.where("lattice");
    const std::string lattice = f.choice("lattice", f.string("lattice").value_or("cubic"), {"cubic", "hexagonal"});
    if (lattice == "hexagonal" && dimension != 2) f.fail("lattice", "the hexagonal lattice is two-dimensional only");
    b.lattice = lattice == "hexagonal" ? geometry::LatticeType::hexagonal : geometry::LatticeType::cubic;
    b.velocity = read_velocity(f, dimension);
    b.where_pressure = f.where("pressure");
    if (f.has("pressure")) {
      const auto text = f.string("pressure");
      if (text && *text == kHydrostaticPressure) {
        b.hydrostatic = true;
      } else {
        try {
          b.pressure = *f.real("pressure");
        } catch (const ConfigError&) {
          f.fail("pressure", "expected 'hydrostatic' or a number [Pa], got '" + text.value_or("a list or map") + "'");
        }
      }
    }
    b.where_density = f.where("density");
    if (const auto rho = f.real("density")) {
      b.density = *rho;
      if (!(b.density > 0.0)) f.fail("density", "the body's rest density must be > 0 kg/m^3");
    }
    b.where_viscosity = f.where("kinematic_viscosity");
    if (const auto nu = f.real("kinematic_viscosity")) {
      b.viscosity = *nu;
      if (!(b.viscosity >= 0.0) || !std::isfinite(b.viscosity))
        f.fail("kinematic_viscosity", "the body's kinematic viscosity must be a number >= 0 m^2/s");
    }
    s.fluid.push_back(std::move(b));
  }

  auto walls = scene.section_list("walls", {"name", "shape", "layers", "velocity", "belt", "motion", "slip", "treatment", "repulsive"});
  for (std::size_t k = 0; k < walls.size(); ++k) {
    auto& w = walls[k];
    WallBodySpec b;
    b.where = w.where("shape");
    b.name = w.string("name").value_or("wall" + std::to_string(k));
    for (std::size_t j = 0; j < k; ++j)
      if (s.walls[j].name == b.name) w.fail("name", "the name '" + b.name + "' is used by walls[" + std::to_string(j) + "] too");
    if (!w.has("shape")) w.fail_missing("shape", "the solid body, e.g. {type: sphere, centre: [...], radius: ...}");
    MapReader shape = w.section("shape", {"type", "lo", "hi", "centre", "radius", "start", "end", "vertices", "file",
                                          "point", "normal", "shapes"});
    b.shape = read_shape(shape, dimension, folder);
    const long long layers = w.integer("layers").value_or(0);
    if (layers < 0 || layers > 20) w.fail("layers", "must be 0 (enough to fill the kernel support) or 1 to 20");
    b.layers = static_cast<int>(layers);
    b.where_layers = w.where("layers");
    b.where_velocity = w.where("velocity");
    b.where_motion = w.where("motion");
    if (w.has("motion")) {
      if (w.has("velocity")) w.fail("velocity", "give the body either velocity or motion, not both (motion: {type: translation, velocity: [...]})");
      if (w.has("belt")) w.fail("belt", "a body with motion keeps its place with motion.stationary: true, not belt");
      b.motion = read_motion(w, dimension);
    }
    if (w.has("velocity")) b.velocity = point(w, "velocity", dimension, "[m/s]");
    b.belt = w.boolean("belt").value_or(false);
    if (b.belt && b.velocity.empty()) w.fail("belt", "a belt needs the velocity its surface moves with");
    if (const auto v = w.string("slip")) b.free_slip = w.choice("slip", *v, {"no_slip", "free_slip"}) == "free_slip";
    read_treatment(w, b);
    s.walls.push_back(std::move(b));
  }
  return s;
}

}  // namespace sphmol
