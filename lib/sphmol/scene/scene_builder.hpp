#pragma once
// Particles of a user scene (SceneSpec, read by scene_reader.hpp). All bodies share one lattice of
// spacing dx whose cell centres sit half a spacing inside the domain's lower faces, so fluid, domain
// walls and wall bodies continue each other:
//   fluid bodies: the lattice points inside the shape (hexagonal if asked, 2D), minus those already
//     placed by an earlier fluid body and those inside a wall body or within dx/2 of its surface;
//     mass from the lattice (scenes/lattice_mass.hpp, as the box cases), initial velocity from the
//     body's expressions, initial density from the body's pressure through the EOS;
//   domain walls (boundary axes `wall`, minus the open faces): wall_particles -> the lattice continued
//     outside the box (geometry::box_container_walls); ghost -> planar mirror walls (BoxWalls), no
//     particles;
//   ghost wall bodies (plane bodies under boundary: ghost): mirror planes (scene/ghost_planes.hpp), no
//     particles; they keep the fluid out as the other bodies do;
//   wall bodies: the lattice points inside the solid within `layers` spacings of its surface
//     (geometry::wall_layer), with the surface normal and depth the Morris et al. (1997) wall model
//     reads, and Particles::body = the body's index. Particles::body_treatment holds each body's
//     treatment (its own, or discretization.wall_pressure); a repulsive body is the one layer within a
//     spacing of its surface, massless (it takes no part in the SPH sums), with its law in
//     Particles::body_repulsion (strength by default the squared velocity scale U^2 of the scene,
//     scene/scene_velocity_scale.hpp: Niedoba 2012, §3.3, takes D of the order of the largest squared speed).
//   fluid bodies with their own `density`: that rest density in Particles::rest_density (walls keep
//     fluid.density), mass scaled with it; a hydrostatic body below another hydrostatic body (the
//     lattice point one step above its highest particle lies in that body) carries its weight.
// What makes no sense (an empty fill, a body outside the domain, a length that is not a whole number
// of spacings, ghost walls with wall bodies other than planes, ...) is a ConfigError at the element's line.
#include <string>
#include <vector>

#include "sphmol/boundary/ghost_particles.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"
#include "sphmol/core/scene_share.hpp"
#include "sphmol/scene/scene_spec.hpp"

namespace sphmol {

template <int D>
struct BuiltScene {
  Particles<D> particles;
  Domain<D> domain;
  BoxWalls<D> walls{};  // the domain's planar walls, for boundary: ghost
  bool ghost = false;   // `walls` (and `ghost_planes`) are to be handed to assemble_system
  std::vector<GhostPlane<D>> ghost_planes;  // the mirror planes of the ghost wall bodies
  double spacing = 0.0;
  int wall_layers = 0;                     // layers of the domain walls
  std::vector<std::string> body_names;     // wall bodies, by Particles::body index
  std::vector<std::size_t> fluid_counts;   // particles of each fluid body
  // The fluid occupies the whole domain outside the wall bodies (to 1 % by volume): no free surface
  // unless a face is open.
  bool fills_domain = false;
  bool open_faces = false;                 // some face of the domain is open
  // The whole scene, whatever share `particles` holds: `particles` are its particles of global index
  // [first, first + particles.size()) (fluid first: global index = index in the whole scene), of
  // whole_size particles, whole_fluid of them fluid.
  std::size_t first = 0, whole_size = 0, whole_fluid = 0;
  // Of the whole scene: its velocity scale (scene/scene_velocity_scale.hpp), and the fluid's mass and
  // kinetic energy, summed over its particles in their order (the same bits whatever the share).
  double velocity_scale = 0.0, fluid_mass = 0.0, fluid_kinetic_energy = 0.0;
};


// The particle spacing of the scene: discretization.spacing, or the domain's x length over
// discretization.particles_across. Throws ConfigError when a periodic or wall axis is not a whole
// number of spacings long.
double scene_spacing(const SceneSpec& spec, const Config& config);

// An upper bound on the particle count without building: the lattice points of the domain box with
// the domain walls' layers around it (wall bodies lie inside it). For refusing a scene too large for
// memory before anything is allocated. Throws as scene_spacing.
double scene_particle_bound(const SceneSpec& spec, const Config& config);

// The checks of the wall bodies' treatments and the fluid bodies' densities against the
// discretization and the EOS (what the scene alone cannot know): throws ConfigError at the body's key.
void check_scene_bodies(const SceneSpec& spec, const Config& config);

// Throws ConfigError (located) for every inconsistency; `spec.dimension` must be D. Every build goes
// through the whole scene (and refuses what it would refuse), keeping the particles of `share` only:
// its memory is the share's and the walls' point lists (the surfaces' size), not the whole scene's.
template <int D>
BuiltScene<D> build_scene(const SceneSpec& spec, const Config& config, SceneShare share = {});

// The density at which the EOS of `config` gives `pressure` [Pa] above its value at the rest density
// (linear: rho0 + p / c^2; Tait: rho0 (1 + p / B)^(1/gamma), Niedoba 2012, eq 2.75). Throws
// std::invalid_argument for an EOS without a rest state (ideal gas) or an unreachable pressure.
// rest_density > 0: that of a fluid body with its own density instead of fluid.density.
double density_at_pressure(const Config& config, double pressure, double rest_density = 0.0);

}  // namespace sphmol
