#pragma once
// A user scene as read from the config's `scene:` section (scene_reader.hpp), before the spacing is
// applied: the domain box and what bounds it, the fluid bodies and the solid wall bodies, each with
// its shape. Dimension-free: coordinates are lists of `dimension` numbers; build_scene<D>
// (scene_builder.hpp) turns it into particles. Every element keeps `where` ("FILE:LINE: key.path"),
// so that what the builder finds wrong (an empty fill, a body outside the domain) is a config error
// at the user's line.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sphmol/geometry/lattice.hpp"
#include "sphmol/scene/expression.hpp"

namespace sphmol {

struct ShapeSpec {
  // box | sphere | cylinder | polygon | mesh | plane | union | intersection | difference
  std::string type;
  std::string where;
  std::vector<double> lo, hi;                 // box: the two opposite corners
  std::vector<double> centre;                 // sphere (a circle in 2D)
  double radius = 0.0;                        // sphere, cylinder
  std::vector<double> start, end;             // cylinder (3D): the centres of its two end caps
  std::vector<std::vector<double>> vertices;  // polygon (2D): the outline, in either orientation
  std::string file;                           // mesh (3D): the surface file, resolved to a path
  std::vector<double> point, normal;          // plane: the solid is the side `normal` points away from
  std::vector<ShapeSpec> shapes;              // union, intersection (all of them), difference (first minus the rest)
};

enum class AxisBoundary { periodic, wall, open };

struct DomainSpec {
  std::vector<double> lo, hi;
  std::vector<AxisBoundary> boundary;  // per axis
  // open[2 d + side]: face left open (side 0 the lo face, 1 the hi face). Periodic axes: false.
  std::vector<bool> open;
  std::string where_lo, where_hi, where_boundaries, where_open;
  // Whether fluid can leave through some face (open, on an axis that is not periodic).
  bool has_open_face() const {
    for (std::size_t f = 0; f < open.size(); ++f)
      if (open[f] && boundary[f / 2] != AxisBoundary::periodic) return true;
    return false;
  }
};

// The value of a fluid body's `pressure` key for the hydrostatic initial state.
inline constexpr const char* kHydrostaticPressure = "hydrostatic";

struct FluidBodySpec {
  ShapeSpec shape;
  geometry::LatticeType lattice = geometry::LatticeType::cubic;
  // One expression per axis of x (x, y, z); empty = at rest.
  std::vector<std::shared_ptr<const Expression>> velocity;
  bool hydrostatic = false;  // pressure from the depth below the body's free surface under the body force
  double pressure = 0.0;     // [Pa] above the rest state when not hydrostatic
  double density = 0.0;      // rest density rho0 of the body [kg/m^3]; 0 = fluid.density
  double viscosity = -1.0;   // kinematic viscosity nu of the body [m^2/s]; < 0 = fluid.kinematic_viscosity
  std::string where, where_lattice, where_pressure, where_density, where_viscosity;
};

// A wall body's prescribed rigid motion (`motion:`), as read; build_scene<D> turns it into a
// WallMotion<D> (core/wall_motion.hpp), which defines each type's rule.
struct WallMotionSpec {
  std::string type;                // translation | rotation | oscillation | pitching
  bool stationary = false;         // the particles stay in place and only carry the velocity
  std::vector<double> velocity;    // translation [m/s]
  std::vector<double> centre;      // rotation, pitching: a point on the axis [m]
  std::vector<double> axis;        // rotation, pitching in 3D (as given; empty in 2D: the z axis)
  double angular_velocity = 0.0;   // rotation [rad/s], counter-clockwise about the axis
  std::vector<double> amplitude;   // oscillation [m]
  double angle_amplitude = 0.0;    // pitching [rad]
  double frequency = 0.0;          // oscillation, pitching [Hz]
  double phase = 0.0;              // oscillation, pitching [rad]
  std::string where;               // the motion key
};

// A repulsive wall body's law (Niedoba 2012, eq 2.76), as read.
struct RepulsionSpec {
  double strength = 0.0;  // D [m^2/s^2]; 0 = from the scene (the squared velocity scale)
  double p1 = 12.0, p2 = 4.0;
  double r0 = 1.0;        // cut-off [particle spacings]
};

struct WallBodySpec {
  std::string name;
  ShapeSpec shape;
  int layers = 0;                // 0: discretization.wall_layers, or enough to fill the kernel support
  std::vector<double> velocity;  // [m/s], constant; empty = at rest
  bool belt = false;             // the particles stay in place and carry `velocity` (a moving surface)
  bool free_slip = false;        // `slip: free_slip`: no viscous stress from the body
  std::optional<WallMotionSpec> motion;  // instead of velocity and belt
  // rest | extrapolated | dynamic (wall particles, as discretization.wall_pressure) | repulsive
  // (one layer of massless particles that repel, Monaghan 1994); empty: discretization.wall_pressure.
  std::string treatment;
  RepulsionSpec repulsion;  // treatment: repulsive
  std::string where, where_treatment, where_repulsion;
  std::string where_layers, where_velocity, where_motion;  // for the checks of a ghost body (scene/ghost_planes.hpp)
};

struct SceneSpec {
  int dimension = 2;
  DomainSpec domain;
  std::vector<FluidBodySpec> fluid;
  std::vector<WallBodySpec> walls;
  std::string where;  // the scene section
};

}  // namespace sphmol
