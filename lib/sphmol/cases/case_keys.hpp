#pragma once
// Helpers the case modules share when they read and check their keys: whole numbers of spacings,
// box lengths, and the shared settings a case depends on (viscosity, gravity, wall treatment).
// Errors go through the readers, so each names its key and line.
#include <string>
#include <string_view>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/config/scene_checks.hpp"
#include "sphmol/config/yaml_reader.hpp"

namespace sphmol::case_keys {

// n = round(length / dx) when |n dx - length| <= 1e-6 length (the builders' tolerance), else an
// error at `key` naming `what`.
double whole_spacings(const MapReader& r, const std::string& key, double length, double dx, const std::string& what);
// A list of `dimension` lengths > 0 m under `key`; required.
std::vector<double> read_lengths(MapReader& r, const std::string& key, int dimension, std::string_view hint);
// The spacing: discretization.spacing, or `across` / particles_across.
double spacing(const Config& c, double across);
// Wall layers as the builders add them: discretization.wall_layers, or enough to fill the kernel
// support plus `extra`.
double wall_layers(const Config& c, double extra = 0.0);
// nu > 0, else an error at fluid.kinematic_viscosity explaining `why`.
void require_viscous(CaseReaders& r, const Config& c, std::string_view why);
// Gravity along the last axis only, pointing down: [0, -g] or [0, 0, -g] with g > 0.
void require_gravity(CaseReaders& r, const Config& c);
// fluid.body_force zero, else an error giving `why` (a reference without one).
void require_no_body_force(CaseReaders& r, const Config& c, std::string_view why);
// discretization.boundary among `allowed`, else an error giving `why`.
void require_boundary(CaseReaders& r, const Config& c, const std::vector<std::string>& allowed, std::string_view why);
// "[a, b, c]" with the shortest round-trip text of each number, for to_yaml.
std::string yaml_list(const std::vector<double>& v);

}  // namespace sphmol::case_keys

namespace sphmol::case_keys {

// The size of a scene made by build_box_scene (scenes/box_scene.hpp): fluid [0, Lx] x [0, depth] in a
// box of height Ly, wall particles (or repulsive rows) on the closed faces, `top` closed or open.
// `geo` locates the box key for errors. No walls: a periodic box.
SceneSize box_scene_size(CaseReaders& r, MapReader& geo, const Config& c, double Lx, double depth, double Ly, bool walls,
                         bool top);

}  // namespace sphmol::case_keys
