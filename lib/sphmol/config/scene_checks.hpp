#pragma once
// What the scene builders (scenes/*.cpp) and the assembly (rhs/assemble.cpp) would reject, checked
// while loading so that every input error names its key and line: lengths that are not whole
// numbers of the spacing, periodic lengths shorter than two neighbour radii, case/term combinations
// that cannot be built, a run too large for the machine's memory, and step or checkpoint counts
// beyond time.max_steps. Called by the loader once every section has been read.
#include "sphmol/config/config.hpp"
#include "sphmol/config/yaml_reader.hpp"

namespace sphmol {

struct SectionReaders {
  MapReader& top;
  MapReader& fluid;
  MapReader& geometry;
  MapReader& discretization;
  MapReader& time;
  MapReader& output;
};

// Particle counts of the scene (wall particles: the layers the builders add; generated ghosts are
// not counted) and the memory they need, estimated before anything is allocated.
struct SceneSize {
  double spacing = 0.0;
  double fluid = 0.0, wall = 0.0;  // doubles: an absurd config must not overflow the count
  double bytes_per_particle = 0.0;
  double bytes() const { return (fluid + wall) * bytes_per_particle; }
};

// Throws ConfigError through the readers; returns the scene's size.
SceneSize check_scene(const Config& c, SectionReaders& r);

// Physical memory of this machine in bytes (sysconf), the limit for SceneSize::bytes().
double physical_memory_bytes();

}  // namespace sphmol
