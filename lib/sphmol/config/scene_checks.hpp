#pragma once
// What the assembly (rhs/assemble.cpp) would reject, checked while loading so that every input
// error names its key and line: periodic lengths shorter than two neighbour radii, term
// combinations that cannot be built, a run too large for the machine's memory, and step or
// checkpoint counts beyond time.max_steps. Called by the loader after the case module has read its
// own keys (cases/case_module.hpp), which checks what its scene builder needs.
#include "sphmol/config/config.hpp"
#include <string>
#include <vector>

#include "sphmol/config/yaml_reader.hpp"

namespace sphmol {

// The shared sections, already read: a case module reads its own keys from `top` and reports a
// conflict with a shared key at that key's line.
struct CaseReaders {
  MapReader& top;
  MapReader& fluid;
  MapReader& discretization;
  MapReader& time;
  MapReader& output;
};

// Particle counts of the scene (wall particles: the layers the builders add; generated ghosts are
// not counted) and the memory they need, estimated before anything is allocated.
struct SceneSize {
  SceneSize() = default;
  SceneSize(double spacing_, double fluid_, double wall_) : spacing(spacing_), fluid(fluid_), wall(wall_) {}
  double spacing = 0.0;
  double fluid = 0.0, wall = 0.0;  // doubles: an absurd config must not overflow the count
  double bytes_per_particle = 0.0;
  double kinematic_viscosity = 0.0;  // the largest of the scene's fluids, if above fluid.kinematic_viscosity [m^2/s]
  double bytes() const { return (fluid + wall) * bytes_per_particle; }
  // Periodic lengths of the scene, each with where it came from ("FILE:LINE: key.path", from
  // MapReader::where) for the message.
  struct Periodic {
    std::string where;
    double length;
  };
  std::vector<Periodic> periodic;
  // Ghost mirrors that face each other across the fluid (boundary: ghost): the distance between
  // them, with where it came from. The generator mirrors through one mirror at a time (and through
  // mirrors at right angles together), not through both of a facing pair in turn.
  struct MirrorGap {
    std::string where;
    double gap;
  };
  std::vector<MirrorGap> mirror_gaps;
};

// The checks every scene shares, once the case module has read its keys and measured its scene
// (`size`): term combinations the assembly cannot build, periodic lengths against the neighbour
// radius, facing ghost mirrors against the kernel support, memory, step and checkpoint counts.
// Throws ConfigError through the readers; fills in size.bytes_per_particle.
void check_scene(const Config& c, CaseReaders& r, SceneSize& size);

// Physical memory of this machine in bytes (sysconf), the limit for SceneSize::bytes().
double physical_memory_bytes();

// A run split over MPI ranks (docs/parallel.md): `ranks` in all, `here` of them on this machine.
// Each rank holds about 1/ranks of the scene, so the memory check asks this machine for the share
// of its ranks, not for the whole scene. Process-wide, set by the program before it loads a config;
// one rank (the default) is a serial run.
struct RanksOnMachine {
  int ranks = 1, here = 1;
};
void set_ranks_on_machine(RanksOnMachine r);
RanksOnMachine ranks_on_machine();

}  // namespace sphmol
