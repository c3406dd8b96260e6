// The `scene` case module: a user scene from shapes (the `scene:` section, scene/scene_reader.hpp),
// checked against the shared settings and built once while loading, so every error has its line.
#include <algorithm>
#include <memory>

#include "sphmol/cases/case_module.hpp"
#include "sphmol/cases/scene/scene_case.hpp"
#include "sphmol/cases/scene/scene_settings.hpp"
#include "sphmol/scene/ghost_planes.hpp"
#include "sphmol/scene/scene_builder.hpp"
#include "sphmol/scene/scene_reader.hpp"

namespace sphmol {

namespace {

// Past this many particles the scene is not counted while loading (built_size: no memory, but the
// time of going through every particle): the shared memory check gets the bound
// (scene_particle_bound, the lattice of the whole domain box) and refuses what the machine cannot hold.
constexpr double kCountWhileLoading = 1.0e8;

// The scene's counts from a build that goes through every particle (and so refuses what the run's
// build would) but keeps none: a share too small to hold one (scene/scene_builder.hpp), so that the
// loader needs no memory for the scene (over MPI ranks every rank loads the config).
template <int D>
SceneSize built_size(CaseReaders& r, const SceneSpec& spec, const Config& c) {
  constexpr std::size_t kNoParticle = std::size_t{1} << 62;  // N / kNoParticle = 0 for any scene
  const BuiltScene<D> s = build_scene<D>(spec, c, SceneShare{0, kNoParticle});
  if (c.discretization.transport_velocity.enabled && (s.open_faces || !s.fills_domain))
    r.discretization.fail("transport_velocity", "needs a confined liquid; this scene has a free surface (an open face, or "
                                                "fluid that does not fill the domain)");
  return {s.spacing, static_cast<double>(s.whole_fluid), static_cast<double>(s.whole_size - s.whole_fluid)};
}

CaseRead read_scene_case(CaseReaders& r, const Config& c) {
  auto settings = std::make_shared<SceneSettings>();
  MapReader scene = r.top.section("scene", kSceneKeys);
  if (!r.top.has("scene")) r.top.fail_missing("scene", "the domain, fluid bodies and wall bodies of the scene (config/README.md)");
  settings->spec = read_scene(scene, c.dimension, c.source);
  const SceneSpec& spec = settings->spec;
  const auto& d = c.discretization;
  if (d.boundary == "virtual_repulsive")
    r.discretization.fail("boundary", "a scene's walls are wall particles or ghost mirrors (wall_particles or ghost)");
  check_ghost_bodies(spec, c, r.discretization.where("boundary"));
  check_scene_bodies(spec, c);  // also for a scene too large to build while loading
  SceneSize size;
  const double bound = scene_particle_bound(spec, c);
  if (bound > kCountWhileLoading) {
    size.spacing = scene_spacing(spec, c);
    size.fluid = bound;
  } else {
    size = c.dimension == 2 ? built_size<2>(r, spec, c) : built_size<3>(r, spec, c);
  }
  for (const auto& f : spec.fluid) size.kinematic_viscosity = std::max(size.kinematic_viscosity, f.viscosity);
  for (int a = 0; a < c.dimension; ++a)
    if (spec.domain.boundary[a] == AxisBoundary::periodic)
      size.periodic.push_back({spec.domain.where_hi, spec.domain.hi[a] - spec.domain.lo[a]});
  CaseRead out{settings, size};
  out.wall_count_known = bound <= kCountWhileLoading;
  out.open_to_outflow = spec.domain.has_open_face();
  // Only the continuity density is set from the start pressure; the summed densities come from the
  // particles' positions, whatever pressure the body was given.
  if (d.density != "continuity")
    for (const auto& f : spec.fluid)
      if (f.hydrostatic || f.pressure != 0.0)
        out.notices.push_back(f.where_pressure + ": has no effect with discretization.density: " + d.density +
                              " (the densities, and so the pressures, come from the particles' positions); "
                              "density: continuity starts from it");
  return out;
}

}  // namespace

CaseModule scene_module() {
  CaseModule m;
  m.name = "scene";
  m.description = "a user scene of shapes (scene: section): no reference, conservation and spurious speeds reported";
  m.dimensions = {2, 3};
  m.sections = {"scene"};
  m.position_noise = true;
  m.lattice_mass = true;
  m.read = read_scene_case;
  m.make2 = [] { return std::make_unique<SceneCase<2>>(); };
  m.make3 = [] { return std::make_unique<SceneCase<3>>(); };
  return m;
}

}  // namespace sphmol
