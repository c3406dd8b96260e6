// The `scene:` reader: what it reads from each key, its defaults, the expression parser of initial
// velocities, and every input error with its line (the text of the error a user sees).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "scene_test_support.hpp"
#include "sphmol/scene/expression.hpp"
#include "sphmol/scene/scene_yaml.hpp"

using namespace sphmol;
using scene_test::read;

namespace {

std::string read_error(const std::string& yaml, int dim, const std::string& config_file = "scene.yaml") {
  try {
    (void)read(yaml, dim, config_file);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "<no error>";
}

const std::string tank = R"yaml(scene:
  domain:
    lo: [0, 0]
    hi: [1, 0.6]
    boundaries: [wall, wall]
    open_faces: [y_hi]
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [1, 0.4]}
      velocity: ["sin(2*pi*y)", 0]
      pressure: hydrostatic
  walls:
    - name: obstacle
      shape: {type: sphere, centre: [0.5, 0.2], radius: 0.1}
      velocity: [0.5, 0]
      belt: true
)yaml";

}  // namespace

TEST_CASE("scene reader: expressions follow the usual precedence and name their column", "[scene][expression]") {
  const std::array<double, 3> p{0.25, 0.5, 2.0};
  CHECK(Expression("1 + 2*3", 2)(p) == 7.0);
  CHECK(Expression("-2^2", 2)(p) == -4.0);  // ^ binds tighter than the unary minus
  CHECK(Expression("2^3^2", 2)(p) == 512.0);  // right-associative
  CHECK(Expression("(1 + 2) * 3 / 4", 2)(p) == Approx(2.25));
  CHECK(Expression("sin(2*pi*x)", 2)(p) == Approx(1.0));
  CHECK(Expression("cos(pi*y) + sqrt(abs(-16)) + exp(0) + tan(0)", 2)(p) == Approx(5.0));
  CHECK(Expression("x*y*z", 3)(p) == Approx(0.25));
  CHECK(Expression("1.5e-1", 2)(p) == Approx(0.15));
  CHECK(Expression("3", 2).constant());
  CHECK_FALSE(Expression("y", 2).constant());
  const auto column = [](const std::string& text, int dim) -> std::size_t {
    try {
      (void)Expression(text, dim);
    } catch (const ExpressionError& e) {
      return e.column;
    }
    return 0;
  };
  CHECK(column("sin(2*pi*q)", 2) == 10);  // unknown name
  CHECK(column("x + z", 2) == 5);         // z is not a coordinate in 2D
  CHECK(column("(x + 1", 2) == 7);        // missing ')'
  CHECK(column("2x", 2) == 1);            // implicit product
  CHECK(column("x +* y", 2) == 4);
  CHECK(column("", 2) == 1);
  CHECK(column("sin x", 2) == 5);
  CHECK(column("x y", 2) == 3);
  CHECK(column("system(x)", 2) == 1);     // no functions beyond the listed ones
}

TEST_CASE("scene reader: a tank with an obstacle is read key by key", "[scene]") {
  const SceneSpec s = read(tank, 2);
  CHECK(s.dimension == 2);
  CHECK(s.domain.hi == std::vector<double>{1.0, 0.6});
  CHECK(s.domain.boundary == std::vector<AxisBoundary>{AxisBoundary::wall, AxisBoundary::wall});
  CHECK(s.domain.open == std::vector<bool>{false, false, false, true});
  REQUIRE(s.fluid.size() == 1);
  CHECK(s.fluid[0].shape.type == "box");
  CHECK(s.fluid[0].shape.where == "scene.yaml:8: scene.fluid[0].shape");
  CHECK(s.fluid[0].hydrostatic);
  CHECK(s.fluid[0].lattice == geometry::LatticeType::cubic);
  REQUIRE(s.fluid[0].velocity.size() == 2);
  CHECK((*s.fluid[0].velocity[0])({0.0, 0.25, 0.0}) == Approx(1.0));
  REQUIRE(s.walls.size() == 1);
  CHECK(s.walls[0].name == "obstacle");
  CHECK(s.walls[0].shape.radius == 0.1);
  CHECK(s.walls[0].velocity == std::vector<double>{0.5, 0.0});
  CHECK(s.walls[0].belt);
  CHECK(s.walls[0].layers == 0);
}

TEST_CASE("scene reader: defaults are a closed box at rest, and numeric pressures are read", "[scene]") {
  const SceneSpec s = read(R"yaml(scene:
  domain: {lo: [0, 0, 0], hi: [1, 1, 1]}
  fluid:
    - shape: {type: box, lo: [0, 0, 0], hi: [1, 1, 0.5]}
      pressure: 250
  walls:
    - shape: {type: cylinder, start: [0.5, 0.5, 0], end: [0.5, 0.5, 1], radius: 0.1}
)yaml",
                           3);
  CHECK(s.domain.boundary == std::vector<AxisBoundary>(3, AxisBoundary::wall));
  CHECK(s.domain.open == std::vector<bool>(6, false));
  CHECK_FALSE(s.fluid[0].hydrostatic);
  CHECK(s.fluid[0].pressure == 250.0);
  CHECK(s.fluid[0].velocity.empty());
  CHECK(s.walls[0].name == "wall0");
  CHECK(s.walls[0].velocity.empty());
}

TEST_CASE("scene reader: boolean shapes nest, and a mesh is found next to the config file", "[scene][cgal]") {
  const auto dir = std::filesystem::temp_directory_path() / ("sphmol-scene-reader-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir / "meshes");
  {
    std::ofstream f(dir / "meshes" / "cube.off");
    f << "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
      << "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n";
  }
  const SceneSpec s = read(R"yaml(scene:
  domain: {lo: [0, 0, 0], hi: [2, 2, 2]}
  fluid:
    - shape:
        type: difference
        shapes:
          - {type: box, lo: [0, 0, 0], hi: [2, 2, 1]}
          - type: union
            shapes:
              - {type: mesh, file: meshes/cube.off}
              - {type: plane, point: [0, 0, 0.2], normal: [0, 0, -1]}
)yaml",
                           3, (dir / "case.yaml").string());
  const auto& d = s.fluid[0].shape;
  CHECK(d.type == "difference");
  REQUIRE(d.shapes.size() == 2);
  CHECK(d.shapes[1].shapes[0].file == (dir / "meshes" / "cube.off").string());
  CHECK(d.shapes[1].shapes[1].normal == std::vector<double>{0, 0, -1});
  // An open surface has no inside: an error at the mesh's file key.
  {
    std::ofstream f(dir / "open.off");
    f << "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
  }
  const std::string open = R"yaml(scene:
  domain: {lo: [0, 0, 0], hi: [2, 2, 2]}
  fluid:
    - shape: {type: mesh, file: open.off}
)yaml";
  const std::string e = read_error(open, 3, (dir / "case.yaml").string());
  CHECK_THAT(e, Catch::StartsWith("scene.yaml:4: scene.fluid[0].shape.file: mesh "));
  CHECK_THAT(e, Catch::Contains("not closed"));
  CHECK_THAT(read_error(R"yaml(scene:
  domain: {lo: [0, 0, 0], hi: [2, 2, 2]}
  fluid:
    - shape: {type: mesh, file: none.stl}
)yaml",
                        3, (dir / "case.yaml").string()),
             Catch::StartsWith("scene.yaml:4: scene.fluid[0].shape.file: mesh ") && Catch::Contains("no such file"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("scene reader: every malformed scene is an error at its key and line", "[scene]") {
  const std::string d2 = "scene:\n  domain: {lo: [0, 0], hi: [1, 1]}\n";
  const auto fluid = [&](const std::string& body) { return d2 + "  fluid:\n    - {" + body + "}\n"; };
  const auto fluid3 = [&](const std::string& body) {
    return "scene:\n  domain: {lo: [0, 0, 0], hi: [1, 1, 1]}\n  fluid:\n    - {" + body + "}\n";
  };
  const std::string box = "shape: {type: box, lo: [0, 0], hi: [1, 0.5]}";
  struct Case {
    std::string yaml;
    int dim;
    std::string error;
  };
  const std::vector<Case> cases = {
      {d2, 2, "scene.yaml:2: scene.domain: the scene needs at least one fluid body under 'fluid'"},
      {"scene:\n  fluid: []\n", 2, "scene.yaml:1: scene.domain.lo: required value missing in section 'scene.domain' (the lower corner of the domain box)"},
      {"scene:\n  domain: {lo: [0, 0, 0], hi: [1, 1]}\n", 2, "scene.yaml:2: scene.domain.lo: expected 2 numbers (one per axis), got 3"},
      {"scene:\n  domain: {lo: [0, 0], hi: [1, 0]}\n", 2, "scene.yaml:2: scene.domain.hi[1]: must exceed lo along every axis"},
      {"scene:\n  domain: {lo: [0, 0], hi: [1, 1], boundaries: [wall, periodc]}\n", 2,
       "scene.yaml:2: scene.domain.boundaries[1]: unknown value 'periodc' (did you mean 'periodic'? allowed: periodic, wall, open)"},
      {"scene:\n  domain: {lo: [0, 0], hi: [1, 1], boundaries: [wall]}\n", 2,
       "scene.yaml:2: scene.domain.boundaries: expected 2 entries (one per axis), got 1"},
      {"scene:\n  domain: {lo: [0, 0], hi: [1, 1], boundaries: [periodic, wall], open_faces: [x_hi]}\n", 2,
       "scene.yaml:2: scene.domain.open_faces[0]: the face x_hi is on a periodic axis; only faces of wall axes can be opened"},
      {"scene:\n  domain: {lo: [0, 0], hi: [1, 1], open_faces: [z_hi]}\n", 2,
       "scene.yaml:2: scene.domain.open_faces[0]: unknown face 'z_hi' (did you mean 'x_hi'? faces: x_lo, x_hi, y_lo, y_hi)"},
      {fluid("shape: {type: bx, lo: [0, 0], hi: [1, 1]}"), 2,
       "scene.yaml:4: scene.fluid[0].shape.type: unknown value 'bx' (did you mean 'box'? allowed: box, sphere, cylinder, polygon, mesh, plane, union, intersection, difference)"},
      {fluid("shape: {type: box, lo: [0, 0], hi: [1, 1], radius: 2}"), 2,
       "scene.yaml:4: scene.fluid[0].shape.radius: unknown key (allowed here: type, lo, hi)"},
      {fluid("shape: {type: cylinder, start: [0, 0], end: [0, 1], radius: 1}"), 2,
       "scene.yaml:4: scene.fluid[0].shape.type: a cylinder is three-dimensional; in 2D use a sphere (a circle) or a box"},
      {fluid3("shape: {type: polygon, vertices: [[0, 0, 0], [1, 0, 0], [1, 1, 0]]}"), 3,
       "scene.yaml:4: scene.fluid[0].shape.type: a polygon is two-dimensional; in 3D use a mesh"},
      {fluid("shape: {type: mesh, file: a.stl}"), 2, "scene.yaml:4: scene.fluid[0].shape.type: a mesh is three-dimensional; in 2D use a polygon"},
      {fluid("shape: {type: sphere, centre: [0.5, 0.5], radius: 0}"), 2, "scene.yaml:4: scene.fluid[0].shape.radius: must be > 0"},
      {fluid("shape: {type: polygon, vertices: [[0, 0], [1, 1], [1, 0], [0, 1]]}"), 2,
       "scene.yaml:4: scene.fluid[0].shape: polygon: the outline intersects itself (or repeats a vertex)"},
      {fluid("shape: {type: polygon, vertices: [[0, 0], [1]]}"), 2,
       "scene.yaml:4: scene.fluid[0].shape.vertices[1]: expected a list of 2 numbers, got a list"},
      {fluid("shape: {type: plane, point: [0, 0], normal: [0, 0]}"), 2, "scene.yaml:4: scene.fluid[0].shape.normal: must not be zero"},
      {fluid("shape: {type: difference, shapes: [{type: box, lo: [0, 0], hi: [1, 1]}]}"), 2,
       "scene.yaml:4: scene.fluid[0].shape.shapes: difference needs at least 2 shapes under 'shapes'"},
      {fluid("shape: {type: union}"), 2, "scene.yaml:4: scene.fluid[0].shape.type: union needs at least 1 shape under 'shapes'"},
      {fluid("lattice: cubic"), 2, "scene.yaml:4: scene.fluid[0].shape: required value missing in section 'scene.fluid[0]' (the region the fluid fills, e.g. "
       "{type: box, lo: [...], hi: [...]})"},
      {fluid3("shape: {type: box, lo: [0, 0, 0], hi: [1, 1, 1]}, lattice: hexagonal"), 3, "scene.yaml:4: scene.fluid[0].lattice: the hexagonal lattice is two-dimensional only"},
      {fluid(box + ", lattice: square"), 2,
       "scene.yaml:4: scene.fluid[0].lattice: unknown value 'square' (allowed: cubic, hexagonal)"},
      {fluid(box + ", velocity: [1]"), 2,
       "scene.yaml:4: scene.fluid[0].velocity: expected 2 components (numbers or expressions of x, y), got 1"},
      {d2 + "  fluid:\n    - " + box + "\n      velocity:\n        - 0\n        - sin(2*pi*q)\n", 2,
       "scene.yaml:7: scene.fluid[0].velocity[1]: 'sin(2*pi*q)': column 10: unknown name 'q' (known: x y pi sin cos tan exp sqrt abs)"},
      {fluid(box + ", pressure: hydrostatik"), 2,
       "scene.yaml:4: scene.fluid[0].pressure: expected 'hydrostatic' or a number [Pa], got 'hydrostatik'"},
      {fluid(box) + "  walls:\n    - {name: a, shape: {type: sphere, centre: [0.5, 0.8], radius: 0.1}}\n"
                    "    - {name: a, shape: {type: sphere, centre: [0.2, 0.8], radius: 0.1}}\n",
       2, "scene.yaml:7: scene.walls[1].name: the name 'a' is used by walls[0] too"},
      {fluid(box) + "  walls:\n    - {shape: {type: sphere, centre: [0.5, 0.8], radius: 0.1}, layers: -1}\n", 2,
       "scene.yaml:6: scene.walls[0].layers: must be 0 (enough to fill the kernel support) or 1 to 20"},
      {fluid(box) + "  walls:\n    - {shape: {type: sphere, centre: [0.5, 0.8], radius: 0.1}, belt: true}\n", 2,
       "scene.yaml:6: scene.walls[0].belt: a belt needs the velocity its surface moves with"},
      {fluid(box) + "  walls:\n    - {shape: {type: sphere, centre: [0.5, 0.8], radius: 0.1}, slip: free}\n", 2,
       "scene.yaml:6: scene.walls[0].slip: unknown value 'free' (allowed: no_slip, free_slip)"},
      {fluid(box) + "  walls:\n    - {shape: {type: sphere, centre: [0.5, 0.8], radius: 0.1}, slipp: free_slip}\n", 2,
       "scene.yaml:6: scene.walls[0].slipp: unknown key (did you mean 'slip'? allowed in scene.walls[0]: name, shape, layers, velocity, belt, motion, slip, treatment, repulsive)"},
  };
  for (const auto& c : cases) {
    INFO(c.yaml);
    CHECK(read_error(c.yaml, c.dim) == c.error);
  }
}

TEST_CASE("scene reader: the resolved scene YAML reads back to itself, defaults filled in", "[scene]") {
  const std::string text = R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 0.6], boundaries: [periodic, wall], open_faces: [y_hi]}
  fluid:
    - shape:
        type: difference
        shapes:
          - {type: box, lo: [0, 0], hi: [1, 0.4]}
          - {type: polygon, vertices: [[0.1, 0.1], [0.3, 0.1], [0.2, 0.3]]}
      velocity: ["0.1*sin(2*pi*x)", 0]
    - shape: {type: plane, point: [0, 0.45], normal: [0, 1]}
      lattice: hexagonal
      pressure: 12.5
  walls:
    - shape: {type: sphere, centre: [0.5, 0.2], radius: 0.1}
      velocity: [0.25, 0]
      layers: 3
)yaml";
  const std::string once = scene_to_yaml(read(text, 2));
  CHECK(scene_to_yaml(read(once, 2)) == once);
  CHECK_THAT(once, Catch::Contains("boundaries: [periodic, wall]\n    open_faces: [y_hi]"));
  CHECK_THAT(once, Catch::Contains("velocity: [\"0.1*sin(2*pi*x)\", 0]"));
  CHECK_THAT(once, Catch::Contains("lattice: hexagonal\n      velocity: [0, 0]\n      pressure: 12.5"));
  CHECK_THAT(once, Catch::Contains("- name: \"wall0\"\n      shape: {type: sphere, centre: [0.5, 0.2], radius: 0.1}\n      layers: 3\n"
                                   "      velocity: [0.25, 0]\n      belt: false"));
}

namespace {

// A 2D (or 3D) scene with one wall body whose map ends in `wall`.
std::string moving(const std::string& wall, int dim = 2) {
  if (dim == 3)
    return "scene:\n  domain: {lo: [0, 0, 0], hi: [1, 1, 1]}\n  fluid:\n    - shape: {type: box, lo: [0, 0, 0], hi: [1, 1, 0.5]}\n"
           "  walls:\n    - shape: {type: cylinder, start: [0.5, 0.5, 0], end: [0.5, 0.5, 1], radius: 0.1}\n      " + wall + "\n";
  return "scene:\n  domain: {lo: [0, 0], hi: [1, 1]}\n  fluid:\n    - shape: {type: box, lo: [0, 0], hi: [1, 0.5]}\n"
         "  walls:\n    - shape: {type: sphere, centre: [0.5, 0.5], radius: 0.1}\n      " + wall + "\n";
}

}  // namespace

TEST_CASE("scene reader: a wall body's motion is read key by key", "[scene][motion]") {
  SceneSpec s = read(moving("motion: {type: rotation, centre: [0.5, 0.5], angular_velocity: 2, stationary: true}"), 2);
  REQUIRE(s.walls[0].motion);
  CHECK(s.walls[0].motion->type == "rotation");
  CHECK(s.walls[0].motion->centre == std::vector<double>{0.5, 0.5});
  CHECK(s.walls[0].motion->angular_velocity == 2.0);
  CHECK(s.walls[0].motion->stationary);
  CHECK(s.walls[0].motion->axis.empty());
  CHECK(s.walls[0].motion->where == "scene.yaml:7: scene.walls[0].motion");
  CHECK(s.walls[0].velocity.empty());

  s = read(moving("motion: {type: oscillation, amplitude: [0.01, 0], frequency: 3}"), 2);
  CHECK(s.walls[0].motion->amplitude == std::vector<double>{0.01, 0.0});
  CHECK(s.walls[0].motion->frequency == 3.0);
  CHECK(s.walls[0].motion->phase == 0.0);
  CHECK_FALSE(s.walls[0].motion->stationary);

  s = read(moving("motion: {type: pitching, centre: [0.5, 0.5, 0.5], axis: [0, 2, 0], angle_amplitude: 0.1, frequency: 0.5, phase: 1}", 3), 3);
  CHECK(s.walls[0].motion->axis == std::vector<double>{0.0, 2.0, 0.0});
  CHECK(s.walls[0].motion->angle_amplitude == 0.1);
  CHECK(s.walls[0].motion->phase == 1.0);

  s = read(moving("motion: {type: translation, velocity: [0.1, 0]}"), 2);
  CHECK(s.walls[0].motion->velocity == std::vector<double>{0.1, 0.0});
}

TEST_CASE("scene reader: wall motions read back to themselves", "[scene][motion]") {
  for (const auto& [wall, dim] : std::vector<std::pair<std::string, int>>{
           {"motion: {type: rotation, centre: [0.5, 0.5], angular_velocity: -1.5}", 2},
           {"motion: {type: rotation, centre: [0.5, 0.5, 0], axis: [0, 0, 1], angular_velocity: 4, stationary: true}", 3},
           {"motion: {type: oscillation, amplitude: [0.01, 0.02], frequency: 2.5, phase: 0.25}", 2},
           {"motion: {type: pitching, centre: [0.5, 0.5], angle_amplitude: 0.2, frequency: 1}", 2},
           {"motion: {type: translation, velocity: [0, 0.1, 0], stationary: true}", 3}}) {
    INFO(wall);
    const SceneSpec first = read(moving(wall, dim), dim);
    const std::string once = scene_to_yaml(first);
    CHECK_THAT(once, Catch::Contains("motion: {type: " + first.walls[0].motion->type));
    CHECK_THAT(once, !Catch::Contains("belt:"));
    const SceneSpec again = read(once, dim);
    REQUIRE(again.walls[0].motion);
    const auto& a = *first.walls[0].motion;
    const auto& b = *again.walls[0].motion;
    CHECK(a.type == b.type);
    CHECK(a.stationary == b.stationary);
    CHECK(a.velocity == b.velocity);
    CHECK(a.centre == b.centre);
    CHECK(a.axis == b.axis);
    CHECK(a.angular_velocity == b.angular_velocity);
    CHECK(a.amplitude == b.amplitude);
    CHECK(a.angle_amplitude == b.angle_amplitude);
    CHECK(a.frequency == b.frequency);
    CHECK(a.phase == b.phase);
    CHECK(scene_to_yaml(again) == once);
  }
}

TEST_CASE("scene reader: every wall motion error names its key and line", "[scene][motion]") {
  struct Case {
    std::string yaml;
    int dim;
    std::string error;
  };
  const std::string at = "scene.yaml:7: scene.walls[0].";
  const std::vector<Case> cases = {
      {moving("motion: {type: spin, centre: [0.5, 0.5], angular_velocity: 1}"), 2,
       at + "motion.type: unknown value 'spin' (allowed: translation, rotation, oscillation, pitching)"},
      {moving("motion: {centre: [0.5, 0.5], angular_velocity: 1}"), 2,
       at + "motion.type: required value missing in section 'scene.walls[0].motion' (translation, rotation, oscillation or pitching)"},
      {moving("motion: {type: rotation, centre: [0.5, 0.5, 0], angular_velocity: 1}"), 2,
       at + "motion.centre: expected 2 numbers (one per axis), got 3"},
      {moving("motion: {type: rotation, centre: [0.5, 0.5]}"), 2,
       at + "motion.angular_velocity: required value missing in section 'scene.walls[0].motion' ([rad/s], counter-clockwise about the axis)"},
      {moving("motion: {type: rotation, centre: [0.5, 0.5], axis: [0, 0, 1], angular_velocity: 1}"), 2,
       at + "motion.axis: unknown key (allowed here: type, stationary, centre, angular_velocity)"},
      {moving("motion: {type: rotation, centre: [0.5, 0.5, 0], angular_velocity: 1}", 3), 3,
       at + "motion.axis: required value missing in section 'scene.walls[0].motion' (the direction of the axis of rotation, e.g. [0, 0, 1])"},
      {moving("motion: {type: rotation, centre: [0.5, 0.5, 0], axis: [0, 0], angular_velocity: 1}", 3), 3,
       at + "motion.axis: expected 3 numbers (one per axis), got 2"},
      {moving("motion: {type: pitching, centre: [0.5, 0.5, 0], axis: [0, 0, 0], angle_amplitude: 0.1, frequency: 1}", 3), 3,
       at + "motion.axis: must not be zero"},
      {moving("motion: {type: oscillation, amplitude: [0.1, 0], frequency: 0}"), 2, at + "motion.frequency: must be > 0"},
      {moving("motion: {type: pitching, centre: [0.5, 0.5], angle_amplitude: 0.1, frequency: -2}"), 2, at + "motion.frequency: must be > 0"},
      {moving("motion: {type: oscillation, amplitude: [0.1, 0]}"), 2,
       at + "motion.frequency: required value missing in section 'scene.walls[0].motion' ([Hz], > 0)"},
      {moving("motion: {type: oscillation, amplitude: [0.1], frequency: 1}"), 2, at + "motion.amplitude: expected 2 numbers (one per axis), got 1"},
      {moving("motion: {type: oscillation, amplitude: [0.1, 0], frequency: 1, angular_velocity: 2}"), 2,
       at + "motion.angular_velocity: unknown key (allowed here: type, stationary, amplitude, frequency, phase)"},
      {moving("motion: {type: translation, velocity: [1, 0, 0]}"), 2, at + "motion.velocity: expected 2 numbers (one per axis), got 3"},
      {moving("motion: {type: rotation, centre: [0.5, 0.5], angular_velocity: 1}\n      velocity: [1, 0]"), 2,
       "scene.yaml:8: scene.walls[0].velocity: give the body either velocity or motion, not both (motion: {type: translation, velocity: [...]})"},
      {moving("motion: {type: rotation, centre: [0.5, 0.5], angular_velocity: 1}\n      belt: true"), 2,
       "scene.yaml:8: scene.walls[0].belt: a body with motion keeps its place with motion.stationary: true, not belt"},
      {moving("motion: {type: rotation, centre: [0.5, 0.5], angular_velocity: 1, stationary: 3}"), 2,
       at + "motion.stationary: "},
  };
  for (const auto& c : cases) {
    INFO(c.yaml);
    const std::string e = read_error(c.yaml, c.dim);
    if (c.error.back() == ' ') CHECK_THAT(e, Catch::StartsWith(c.error));  // the type error's wording is the reader's
    else CHECK(e == c.error);
  }
}
