#pragma once
// The ghost mirror planes of a scene: its plane wall bodies with treatment ghost (the treatment of
// every plane body under discretization.boundary: ghost unless it names another, which is refused).
// Mirrors and wall particles do not mix: a mirror reflects fluid only, so wall particles beside it
// would have no images and the fluid would see a gap; hence boundary: ghost makes every wall a mirror
// (the domain's faces and the plane bodies), and a ghost body needs it.
// What the images of a plane need, each a ConfigError at the body's line:
//   - it stays in place (the fluid bodies keep to its fluid side, as to every wall body's outside);
//   - along a periodic axis it is parallel to that axis (a plane across it would not be periodic);
//   - a plane along an axis lies a whole number of spacings from the domain's lower face, as the
//     domain's faces do, so the first fluid row is half a spacing from it;
//   - two mirrors that are neither parallel nor at right angles must not both come within the kernel
//     support of a point of the domain: their images do not close (a particle there would get the
//     images of each mirror but no consistent corner image; Niedoba 2012, Fig 3.4 shows the right
//     angle).
#include <vector>

#include "sphmol/boundary/ghost_particles.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/scene/scene_spec.hpp"

namespace sphmol {

// The wall bodies' ghost treatment against discretization.boundary (no building): a body that is not
// a mirror under boundary: ghost, or a ghost body under wall_particles. `boundary_where` locates the
// discretization.boundary key for the first case (empty: the error is at the body).
void check_ghost_bodies(const SceneSpec& spec, const Config& config, const std::string& boundary_where);

// What a mirror plane cannot have, each a ConfigError at its key: layers, a motion, a velocity with a
// component normal to the plane (it stays in place). For a body with treatment: ghost (the scene
// reader) and for a plane body that is a mirror through discretization.boundary: ghost alone
// (check_ghost_bodies).
void check_ghost_body(const WallBodySpec& body);

// Whether wall body k is a mirror plane in this configuration.
bool is_ghost_body(const WallBodySpec& body, const Config& config);

// The mirror planes of the ghost bodies, in the order of spec.walls, checked as above against the
// domain's box faces `faces` (the present ones are mirrors too), the spacing dx and the kernel
// support (in metres). A plane on a closed face of the domain replaces that face's mirror (it is
// marked not present in `faces`): that is how a domain face moves along itself (a lid) or slips.
// Two mirrors facing the same way so close that the images of the one behind reach the fluid in front
// of the other are an error (that fluid would be mirrored twice).
template <int D>
std::vector<GhostPlane<D>> ghost_planes(const SceneSpec& spec, const Config& config, BoxWalls<D>& faces, double dx,
                                        double support);

}  // namespace sphmol
