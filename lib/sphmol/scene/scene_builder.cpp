#include "sphmol/scene/scene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "sphmol/core/wall_motion.hpp"
#include "sphmol/geometry/lattice.hpp"
#include "sphmol/geometry/wall_layers.hpp"
#include "sphmol/kernels/registry.hpp"
#include "sphmol/scene/ghost_planes.hpp"
#include "sphmol/scene/scene_messages.hpp"
#include "sphmol/scene/scene_shapes.hpp"
#include "sphmol/scene/scene_velocity_scale.hpp"
#include "sphmol/scenes/lattice_mass.hpp"
#include "sphmol/scenes/position_noise.hpp"

namespace sphmol {

namespace {

using scene_messages::fail;
using scene_messages::kAxisName;
using scene_messages::num;

template <int D>
std::array<double, 3> padded(const geometry::Vec<D>& p) {
  std::array<double, 3> x{};
  for (int d = 0; d < D; ++d) x[static_cast<std::size_t>(d)] = p[d];
  return x;
}

}  // namespace

double density_at_pressure(const Config& config, double pressure, double rest_density) {
  const auto& eos = config.fluid.eos;
  const double rho0 = rest_density > 0.0 ? rest_density : config.fluid.density, c2 = eos.sound_speed * eos.sound_speed;
  if (eos.type == "linear" || eos.type == "linear_relative") {
    const double rho = rho0 + pressure / c2;
    if (!(rho > 0.0)) throw std::invalid_argument("the pressure " + num(pressure) + " Pa needs a negative density under the linear EOS");
    return rho;
  }
  if (eos.type == "tait") {
    const double B = c2 * rho0 / eos.gamma;
    if (!(1.0 + pressure / B > 0.0))
      throw std::invalid_argument("the pressure " + num(pressure) + " Pa is below -B = " + num(-B) + " Pa, which the Tait EOS cannot reach");
    return rho0 * std::pow(1.0 + pressure / B, 1.0 / eos.gamma);
  }
  throw std::invalid_argument("an initial pressure needs an EOS with a rest density (linear, linear_relative or tait), not " + eos.type);
}

double scene_spacing(const SceneSpec& spec, const Config& config) {
  const auto& disc = config.discretization;
  const auto& dom = spec.domain;
  const double L0 = dom.hi[0] - dom.lo[0];
  const double dx = disc.particles_across > 0 ? L0 / disc.particles_across : disc.spacing;
  if (!(dx > 0.0)) throw ConfigError(spec.where + ": the scene needs discretization.spacing or discretization.particles_across");
  for (int d = 0; d < spec.dimension; ++d) {
    if (dom.boundary[d] == AxisBoundary::open) continue;
    const double L = dom.hi[d] - dom.lo[d];
    const double n = std::round(L / dx);
    if (n < 1.0 || std::abs(n * dx - L) > 1e-6 * L)
      fail(dom.where_hi, "the domain length along " + std::string(kAxisName[d]) + " (" + num(L) +
                             " m) is not a whole number of the spacing " + num(dx) + " m (" +
                             (dom.boundary[d] == AxisBoundary::periodic ? "a periodic" : "a wall") +
                             " axis needs one, so the lattice meets the faces half a spacing inside)");
  }
  return dx;
}

double scene_particle_bound(const SceneSpec& spec, const Config& config) {
  const double dx = scene_spacing(spec, config);
  const auto& disc = config.discretization;
  const double support = (spec.dimension == 2 ? kernel_info<2>(disc.kernel).support : kernel_info<3>(disc.kernel).support) *
                         disc.smoothing_ratio;
  const int layers = disc.wall_layers > 0 ? disc.wall_layers : static_cast<int>(std::ceil(support));
  // Hexagonal rows are 2/sqrt(3) denser than the cubic lattice.
  double n = 2.0 / std::sqrt(3.0);
  for (int d = 0; d < spec.dimension; ++d)
    n *= std::ceil((spec.domain.hi[d] - spec.domain.lo[d]) / dx) + 1.0 +
         (spec.domain.boundary[d] == AxisBoundary::periodic ? 0.0 : 2.0 * layers);
  return n;
}

void check_scene_bodies(const SceneSpec& spec, const Config& config) {
  const auto& d = config.discretization;
  const bool barotropic = config.fluid.eos.type != "ideal_gas";
  const double support = (spec.dimension == 2 ? kernel_info<2>(d.kernel).support : kernel_info<3>(d.kernel).support) *
                         d.smoothing_ratio;  // in spacings
  check_ghost_bodies(spec, config, "");
  for (const auto& w : spec.walls) {
    const std::string& t = w.treatment;
    if (t.empty() || t == "ghost") continue;  // discretization.wall_pressure, which the loader checked; mirrors
    const std::string& at = w.where_treatment;
    if (d.wall_model == "adami" && t != "extrapolated")
      fail(at, "'" + t + "' with discretization.wall_model: adami, which extrapolates every wall's pressure (Adami et al. 2012); "
                         "use treatment: extrapolated or wall_model: morris or prescribed");
    if (t == "dynamic" && d.density != "continuity")
      fail(at, "'dynamic' evolves the body's wall densities by continuity; needs discretization.density: continuity (got '" +
                   d.density + "')");
    if (t == "dynamic" && (!barotropic || d.smoothing_length != "constant"))
      fail(at, "'dynamic' needs a barotropic EOS and discretization.smoothing_length: constant");
    if (t == "extrapolated" && !barotropic)
      fail(at, "'extrapolated' inverts the EOS for the wall density; fluid.eos.type 'ideal_gas' is not barotropic");
    if (d.pair_passes == "fused" && (t == "extrapolated" || t == "repulsive"))
      fail(at, "'" + t + "' needs the stored pair list, and discretization.pair_passes is 'fused' (use auto or stored)");
    if (t == "repulsive" && d.density != "continuity")
      fail(at, "'repulsive' particles take no part in the density sum, so a summed density falls short beside the body and "
               "its negative pressure draws the fluid in; needs discretization.density: continuity (got '" + d.density + "')");
    if (t == "repulsive" && !(w.repulsion.r0 < support))
      fail(w.where_repulsion, "r0 = " + num(w.repulsion.r0) + " spacings must lie inside the kernel support (" + num(support) +
                                  " spacings)");
  }
  for (const auto& f : spec.fluid) {
    const double nu = f.viscosity;
    if (nu >= 0.0 && nu != config.fluid.kinematic_viscosity) {
      const std::string& at = f.where_viscosity;
      if (d.viscosity == "none" && nu > 0.0)
        fail(at, "a viscous body needs discretization.viscosity: morris (it is 'none')");
      if (d.viscosity == "strain_rate")
        fail(at, "fluids of several viscosities need discretization.viscosity: morris (each particle's own mu in Morris et al. "
                 "1997, eq 8); 'strain_rate' takes one mu");
      if (d.energy && nu > 0.0) fail(at, "the energy equation has no viscous heating: the body's kinematic_viscosity must be 0");
    }
  }
  for (const auto& f : spec.fluid) {
    if (!(f.density > 0.0) || f.density == config.fluid.density) continue;
    const std::string& at = f.where_density;
    const auto& eos = config.fluid.eos.type;
    if (eos != "tait" && eos != "linear_relative")
      fail(at, "fluids of several rest densities need fluid.eos.type tait or linear_relative (each phase at p = 0 at its own rest "
               "density); got '" + eos + "'");
    if (d.density != "continuity")
      fail(at, "fluids of several rest densities need discretization.density: continuity (a density summation smears the "
               "density jump at the interface over the kernel support; got '" + d.density + "')");
    if (d.density_diffusion > 0.0)
      fail(at, "discretization.density_diffusion would diffuse the density across the interface of fluids of different rest "
               "density; set it to 0");
    if (d.boundary == "ghost")
      fail(at, "ghost images carry fluid.density; fluids of several rest densities need discretization.boundary: wall_particles");
  }
}

namespace {
// The scene's motion spec as the particles' WallMotion (validated by attach_motion).
template <int D>
WallMotion<D> wall_motion(const WallMotionSpec& spec) {
  WallMotion<D> m;
  const auto copy = [](const std::vector<double>& from, auto& to) {
    for (std::size_t d = 0; d < from.size() && d < to.size(); ++d) to[d] = from[d];
  };
  if (spec.type == "translation") m.kind = WallMotionKind::translation;
  else if (spec.type == "rotation") m.kind = WallMotionKind::rotation;
  else if (spec.type == "oscillation") m.kind = WallMotionKind::oscillation;
  else if (spec.type == "pitching") m.kind = WallMotionKind::pitching;
  else throw std::logic_error("wall_motion: unknown type " + spec.type);
  m.stationary = spec.stationary;
  copy(spec.velocity, m.velocity);
  copy(spec.centre, m.centre);
  if (!spec.axis.empty()) copy(spec.axis, m.axis);
  copy(spec.amplitude, m.amplitude);
  m.omega = spec.angular_velocity;
  m.angle_amplitude = spec.angle_amplitude;
  m.frequency = spec.frequency;
  m.phase = spec.phase;
  return m;
}
}  // namespace

template <int D>
BuiltScene<D> build_scene(const SceneSpec& spec, const Config& config, SceneShare share) {
  using namespace geometry;
  if (spec.dimension != D) throw std::logic_error("build_scene: the spec is for another dimension");
  const auto& disc = config.discretization;
  const auto& dom = spec.domain;
  BuiltScene<D> out;
  check_scene_bodies(spec, config);
  const double dx = scene_spacing(spec, config);
  out.spacing = dx;
  const double h = disc.smoothing_ratio * dx;
  const double support = kernel_info<D>(disc.kernel).support * h;
  const int default_layers = disc.wall_layers > 0 ? disc.wall_layers : static_cast<int>(std::ceil(support / dx));
  out.wall_layers = default_layers;
  const double rho0 = config.fluid.density;
  const double m_cubic = lattice_mass<D>(disc.particle_mass, disc.kernel, rho0, dx, h);
  const bool ghost = disc.boundary == "ghost";
  if (disc.boundary != "wall_particles" && !ghost)
    fail(spec.where, "the scene builds its walls from wall particles or ghost mirrors; discretization.boundary: " +
                         disc.boundary + " is not available for it");

  Bounds<D> box;
  for (int d = 0; d < D; ++d) box.lo[d] = dom.lo[d], box.hi[d] = dom.hi[d];
  Lattice<D> cubic;
  cubic.spacing = dx;
  cubic.origin = box.lo;

  // Wall bodies first: fluid is removed where they are.
  std::vector<ShapePtr<D>> solids;
  std::vector<double> thickness;
  double max_thickness = default_layers * dx;
  for (const auto& w : spec.walls) {
    ShapePtr<D> s = make_shape<D>(w.shape);
    const Bounds<D> b = s->bounds();
    // A mirror plane (scene/ghost_planes.hpp checks its place): it only keeps the fluid out.
    if (is_ghost_body(w, config)) {
      solids.push_back(s);
      thickness.push_back(0.0);
      continue;
    }
    for (int d = 0; d < D; ++d) {
      if (dom.boundary[d] == AxisBoundary::periodic && !(b.lo[d] > box.lo[d] && b.hi[d] < box.hi[d]))
        fail(w.where, std::string("the wall body reaches across the periodic axis ") + kAxisName[d] +
                          " (its extent must lie inside the domain's " + num(box.lo[d]) + " to " + num(box.hi[d]) + " there)");
      if (b.lo[d] >= box.hi[d] || b.hi[d] <= box.lo[d])
        fail(w.where, std::string("the wall body lies outside the domain along ") + kAxisName[d]);
    }
    solids.push_back(s);
    // A repulsive body: the one layer within a spacing of its surface.
    const int layers = w.treatment == "repulsive" ? 1 : w.layers > 0 ? w.layers : default_layers;
    thickness.push_back(layers * dx);
    max_thickness = std::max(max_thickness, layers * dx);
  }

  // The particles are made in two passes over the fluid bodies' lattices, and every value of every
  // particle is computed on every build (so that any build refuses what the whole scene's would,
  // and its whole-scene sums are the serial ones to the bit), but only the share's particles are
  // kept: the global indices [first, first + kept) of the whole scene's order (fluid bodies in
  // order, then the domain walls, then the wall bodies in order). The first pass counts each fluid
  // body's points and finds its highest; the walls are listed next (their lists are the surface's
  // size); the second pass places everything.
  // Points exactly half a spacing from a wall body (a face on a half-lattice line) are kept as fluid
  // and exactly on a periodic face are placed once, to a tolerance above the rounding of the inputs:
  // single-precision meshes (binary STL, PLY) give their coordinates to 2^-24 of their magnitude.
  double magnitude = 0.0;
  for (int d = 0; d < D; ++d) magnitude = std::max({magnitude, std::abs(box.lo[d]), std::abs(box.hi[d])});
  const double tol = 1e-9 * dx + 4.0 * std::numeric_limits<float>::epsilon() * magnitude;
  struct FluidBody {
    ShapePtr<D> shape;
    Bounds<D> b;
    Lattice<D> lat;
    double mass, rho0, step;  // step: the lattice's spacing along y (its row spacing)
    std::size_t count = 0;
    Vec<D> highest{};         // the first of its points highest against the body force
  };
  std::vector<FluidBody> fluid;
  for (std::size_t k = 0; k < spec.fluid.size(); ++k) {
    const auto& f = spec.fluid[k];
    FluidBody B;
    B.shape = make_shape<D>(f.shape);
    B.b = B.shape->bounds();
    // Finite extents must lie in the domain; unbounded ones (half-spaces) are cut to it. A shape's
    // box need not be tight (a difference keeps its first part's): where it reaches out, the body is
    // refused only if a lattice point outside the domain lies inside it.
    Bounds<D> reach = B.b;
    int out_axis = -1;
    for (int d = 0; d < D; ++d) {
      if (!std::isfinite(reach.lo[d]) || !std::isfinite(reach.hi[d])) {
        reach.lo[d] = std::max(reach.lo[d], box.lo[d]);
        reach.hi[d] = std::min(reach.hi[d], box.hi[d]);
      } else if (out_axis < 0 && (reach.lo[d] < box.lo[d] - tol || reach.hi[d] > box.hi[d] + tol)) {
        out_axis = d;
      }
    }
    if (out_axis >= 0) {
      bool outside = false;
      cubic.for_each_in(reach, [&](const Vec<D>& p) {
        if (outside) return;
        bool in_box = true;
        for (int d = 0; d < D; ++d) in_box = in_box && p[d] > box.lo[d] && p[d] < box.hi[d];
        if (!in_box && B.shape->signed_distance(p) < 0.0) outside = true;
      });
      const int d = out_axis;
      if (outside)
        fail(f.where, std::string("the fluid body extends outside the domain along ") + kAxisName[d] + " (" +
                          num(B.b.lo[d]) + " to " + num(B.b.hi[d]) + " m; domain " + num(box.lo[d]) + " to " + num(box.hi[d]) + " m)");
    }
    for (int d = 0; d < D; ++d) {
      B.b.lo[d] = std::max(B.b.lo[d], box.lo[d]);
      B.b.hi[d] = std::min(B.b.hi[d], box.hi[d]);
    }
    B.lat = cubic;
    double m = m_cubic;
    if (f.lattice == LatticeType::hexagonal) {
      B.lat.type = LatticeType::hexagonal;
      // The first row half a spacing above the lower face, as on the cubic lattice.
      B.lat.origin[1] += 0.5 * dx - 0.5 * B.lat.row_spacing();
      if (dom.boundary[1] == AxisBoundary::periodic) {
        const double rows = (box.hi[1] - box.lo[1]) / B.lat.row_spacing();
        const double even = 2.0 * std::round(rows / 2.0);
        if (even < 2.0 || std::abs(rows - even) > 1e-6 * rows)
          fail(f.where_lattice, "a periodic y axis needs an even number of hexagonal rows (dx sqrt(3)/2 = " +
                                    num(B.lat.row_spacing()) + " m apart) across the domain; its length " +
                                    num(box.hi[1] - box.lo[1]) + " m holds " + num(rows));
      }
      if constexpr (D == 2) m = hexagonal_lattice_mass(disc.particle_mass, disc.kernel, rho0, dx, h);
    }
    B.rho0 = f.density > 0.0 ? f.density : rho0;
    // The lattice mass is proportional to rho0 (scenes/lattice_mass.hpp).
    B.mass = m * B.rho0 / rho0;
    B.step = B.lat.type == LatticeType::hexagonal ? B.lat.row_spacing() : dx;
    fluid.push_back(std::move(B));
  }
  // The points body k places, in lattice order: fn(position); returns the lattice points inside its
  // shape (placed or not).
  const auto for_each_fluid_point = [&](std::size_t k, auto&& fn) {
    const auto& f = spec.fluid[k];
    const FluidBody& B = fluid[k];
    std::size_t filled = 0;
    B.lat.for_each_in(B.b, [&](Vec<D> p) {
      // On a periodic face (the shifted hexagonal rows put points there) the point on the upper face
      // stands for both: tested just inside, placed at the lower face.
      Vec<D> q = p;
      for (int d = 0; d < D; ++d) {
        if (dom.boundary[d] != AxisBoundary::periodic) continue;
        if (p[d] > box.hi[d] - tol) q[d] = box.hi[d] - tol, p[d] -= box.hi[d] - box.lo[d];
        else if (p[d] < box.lo[d] + tol) return;  // the image of the point on the upper face, which counts
      }
      if (!(B.shape->signed_distance(q) < 0.0)) return;
      ++filled;
      // Already placed by an earlier fluid body: on the same lattice exactly the points inside it; on
      // another lattice also those closer than half a spacing to it.
      for (std::size_t j = 0; j < k; ++j) {
        const double margin = spec.fluid[j].lattice == f.lattice ? 0.0 : 0.5 * dx - tol;
        if (fluid[j].shape->signed_distance(q) < margin) return;
      }
      for (const auto& solid : solids)
        if (solid->signed_distance(q) < 0.5 * dx - tol) return;
      // A lattice other than the walls' may come closer than half a spacing to a domain wall.
      for (int d = 0; d < D; ++d) {
        if (dom.boundary[d] != AxisBoundary::wall) continue;
        if ((!dom.open[2 * d] && p[d] - box.lo[d] < 0.5 * dx - tol) || (!dom.open[2 * d + 1] && box.hi[d] - p[d] < 0.5 * dx - tol)) return;
      }
      fn(p);
    });
    return filled;
  };

  // Against the body force: s = x . up is the height.
  Vec<D> g{};
  for (int d = 0; d < D && d < static_cast<int>(config.fluid.body_force.size()); ++d) g[d] = config.fluid.body_force[d];
  const double gn = norm<D>(g);
  const Vec<D> up = gn > 0.0 ? (-1.0 / gn) * g : Vec<D>{};
  int up_axis = -1;
  for (int d = 0; d < D; ++d)
    if (std::abs(up[d]) == 1.0) up_axis = d;

  // First pass: counts and highest points.
  for (std::size_t k = 0; k < spec.fluid.size(); ++k) {
    FluidBody& B = fluid[k];
    double best = -std::numeric_limits<double>::infinity();
    const std::size_t filled = for_each_fluid_point(k, [&](const Vec<D>& p) {
      const double s = dot<D>(p, up);
      if (B.count == 0 || s > best) best = s, B.highest = p;
      ++B.count;
    });
    if (filled == 0)
      fail(spec.fluid[k].where, "the fluid body holds no lattice point at the spacing " + num(dx) +
                                    " m (it is smaller than a spacing, or outside the domain)");
    if (B.count == 0) fail(spec.fluid[k].where, "every lattice point of the fluid body lies in an earlier fluid body or in a wall body");
  }

  // Initial pressure -> density. Hydrostatic: p = p_top + rho0_k |g| (s_top - s), s the height against
  // the body force and s_top the body's free surface, half a lattice step above its highest particle;
  // p_top is 0, or for a body below another hydrostatic body (the point one lattice step above its
  // highest particle lies in that body) that body's pressure at s_top. Bodies from the highest down,
  // so that the one above is done first.
  std::vector<double> top(spec.fluid.size(), 0.0), p_top(spec.fluid.size(), 0.0);
  std::vector<std::size_t> by_top;
  for (std::size_t k = 0; k < spec.fluid.size(); ++k) {
    if (!spec.fluid[k].hydrostatic) continue;
    if (!(gn > 0.0)) fail(spec.fluid[k].where_pressure, "hydrostatic pressure needs a body force (fluid.body_force)");
    top[k] = dot<D>(fluid[k].highest, up) + 0.5 * (up_axis == 1 ? fluid[k].step : dx);
    by_top.push_back(k);
  }
  std::stable_sort(by_top.begin(), by_top.end(), [&](std::size_t a, std::size_t b) { return top[a] > top[b]; });
  for (std::size_t n = 0; n < by_top.size(); ++n) {
    const std::size_t k = by_top[n];
    const Vec<D> above = fluid[k].highest + (0.5 * (up_axis == 1 ? fluid[k].step : dx) + 0.5 * dx) * up;
    for (std::size_t m = 0; m < n; ++m) {
      const std::size_t j = by_top[m];
      if (!(top[j] > top[k]) || !(fluid[j].shape->signed_distance(above) < 0.0)) continue;
      p_top[k] = p_top[j] + fluid[j].rho0 * gn * (top[j] - top[k]);
      break;
    }
  }

  // The walls' points: the domain walls (boundary axes `wall`, minus the open faces), then each wall
  // body's layers inside the domain box (the domain walls own what lies beyond its faces), not
  // already in an earlier body.
  std::array<bool, 2 * D> open{};
  for (int d = 0; d < D; ++d)
    for (int side = 0; side < 2; ++side)
      open[2 * d + side] = dom.boundary[d] != AxisBoundary::wall || dom.open[2 * d + side];
  std::vector<WallPoint<D>> domain_walls;
  if (!ghost) domain_walls = box_container_walls<D>(box.lo, box.hi, open, cubic, default_layers * dx);
  std::vector<std::vector<WallPoint<D>>> body_walls(solids.size());
  for (std::size_t k = 0; k < solids.size(); ++k) {
    const auto& w = spec.walls[k];
    if (is_ghost_body(w, config)) continue;  // no particles: its images are made at every evaluation
    const Bounds<D> region = box.grown(dx);
    for (const auto& q : wall_layer<D>(*solids[k], cubic, thickness[k], &region)) {
      if (!box.contains(q.x)) continue;
      bool taken = false;
      for (std::size_t j = 0; j < k && !taken; ++j) taken = solids[j]->signed_distance(q.x) < 0.0;
      if (!taken) body_walls[k].push_back(q);
    }
  }

  // The share: [first, first + kept) of the whole scene's n particles.
  std::size_t n_fluid_whole = 0, n_whole = domain_walls.size();
  for (const auto& B : fluid) n_fluid_whole += B.count;
  for (const auto& b : body_walls) n_whole += b.size();
  n_whole += n_fluid_whole;
  if (share.count < 1 || share.index >= share.count) throw std::invalid_argument("build_scene: no share " + std::to_string(share.index) + " of " + std::to_string(share.count));
  const std::size_t first = share.begin(n_whole), last = share.end(n_whole);
  out.first = first;
  out.whole_size = n_whole;
  out.whole_fluid = n_fluid_whole;
  const auto mine = [&](std::size_t i) { return i >= first && i < last; };
  VelocityScaleSums<D> scale(config.fluid.body_force);

  // Second pass: the fluid, with the seeded displacement of the lattice (scenes/position_noise.hpp:
  // the same draws, in the same order, whichever particles are kept).
  PositionNoise<D> noise(disc.position_noise * dx);
  std::vector<std::size_t> kept(spec.fluid.size(), 0);
  std::size_t i = 0;  // global index
  for (std::size_t k = 0; k < spec.fluid.size(); ++k) {
    const auto& f = spec.fluid[k];
    const FluidBody& B = fluid[k];
    for_each_fluid_point(k, [&](const Vec<D>& p) {
      double rho = B.rho0;
      if (f.hydrostatic || f.pressure != 0.0) {
        const double pk = f.hydrostatic ? p_top[k] + B.rho0 * gn * (top[k] - dot<D>(p, up)) : f.pressure;
        try {
          rho = density_at_pressure(config, pk, B.rho0);
        } catch (const std::invalid_argument& e) {
          fail(f.where_pressure, e.what());
        }
      }
      std::array<double, D> v{};
      for (std::size_t d = 0; d < f.velocity.size(); ++d) v[d] = (*f.velocity[d])(padded<D>(p));
      for (int d = 0; d < D; ++d)
        if (!std::isfinite(v[d]))
          fail(f.where, "the velocity expression '" + f.velocity[static_cast<std::size_t>(d)]->text() + "' is not finite at a particle");
      std::array<double, D> x{};
      for (int d = 0; d < D; ++d) x[d] = p[d];
      noise.displace(x);
      scale.add(x, v, true);
      out.fluid_mass += B.mass;
      double v2 = 0.0;
      for (int d = 0; d < D; ++d) v2 += v[d] * v[d];
      out.fluid_kinetic_energy += 0.5 * B.mass * v2;
      if (mine(i)) {
        out.particles.add(Kind::Fluid, x, v, B.mass, rho);
        ++kept[k];
      }
      ++i;
    });
    out.fluid_counts.push_back(B.count);
  }
  {
    // The volume the fluid could fill: the cubic lattice cells of the domain outside the wall bodies
    // (by the same half-spacing rule), against the cells the fluid particles stand for.
    std::size_t free_cells = 0;
    cubic.for_each_in(box, [&](const Vec<D>& p) {
      for (const auto& solid : solids)
        if (solid->signed_distance(p) < 0.5 * dx - tol) return;
      ++free_cells;
    });
    double fluid_volume = 0.0;
    for (std::size_t k = 0; k < spec.fluid.size(); ++k) {
      Lattice<D> lat = cubic;
      if (spec.fluid[k].lattice == LatticeType::hexagonal) lat.type = LatticeType::hexagonal;
      fluid_volume += static_cast<double>(out.fluid_counts[k]) * lat.cell_volume();
    }
    out.fills_domain = fluid_volume >= 0.99 * static_cast<double>(free_cells) * cubic.cell_volume();
    out.open_faces = dom.has_open_face();
  }

  // Domain walls.
  if (ghost) {
    out.ghost = true;
    for (int d = 0; d < D; ++d)
      for (int side = 0; side < 2; ++side) {
        auto& w = out.walls[d][side];
        w.present = !open[2 * d + side];
        w.position = side == 0 ? box.lo[d] : box.hi[d];
        w.no_slip = disc.wall_slip != "free_slip";
      }
    out.ghost_planes = ghost_planes<D>(spec, config, out.walls, dx, support);
  } else {
    for (const auto& w : domain_walls) {
      scale.add(w.x, {}, false);
      if (mine(i)) out.particles.add(Kind::Wall, w.x, {}, m_cubic, rho0, w.normal, w.depth);
      ++i;
    }
  }
  std::vector<WallPoint<D>>().swap(domain_walls);

  // Wall bodies.
  for (std::size_t k = 0; k < solids.size(); ++k) {
    const auto& w = spec.walls[k];
    if (is_ghost_body(w, config)) {
      out.body_names.push_back(w.name);
      out.particles.free_slip_body.push_back(w.free_slip ? 1 : 0);
      out.particles.body_treatment.push_back(WallTreatment::ghost);
      out.particles.body_repulsion.push_back({});
      continue;
    }
    const std::string& treatment = w.treatment.empty() ? disc.wall_pressure : w.treatment;
    const bool repulsive = treatment == "repulsive";
    const auto& pts = body_walls[k];
    if (pts.empty()) fail(w.where, "the wall body holds no lattice point inside the domain at the spacing " + num(dx) + " m");
    std::array<double, D> v0{};
    for (std::size_t d = 0; d < w.velocity.size(); ++d) v0[d] = w.velocity[d];
    // A moving body's walls start with its motion's velocity at t = 0 (Particles::set_motion), which
    // the velocity scale reads for every wall particle, kept or not: `one` holds a copy of each
    // (the body's walls, a surface's size) to get it from the motion.
    std::int32_t motion = -1;
    if (w.motion) {
      try {
        motion = out.particles.add_motion(wall_motion<D>(*w.motion));
      } catch (const std::invalid_argument& e) {
        fail(w.motion->where, e.what());
      }
    }
    Particles<D> one;
    one.motions = out.particles.motions;
    for (const auto& q : pts) {
      std::array<double, D> v = v0;
      if (motion >= 0) {
        one.add(Kind::Wall, q.x, v0, 0.0, rho0, q.normal, q.depth);
        one.set_motion(one.size() - 1, motion);
        for (int d = 0; d < D; ++d) v[d] = one.v[d].back();
      }
      scale.add(q.x, v, false);
      if (mine(i)) {
        // Repulsive particles are massless: they act by their force alone (boundary/repulsive_force.hpp).
        out.particles.add(Kind::Wall, q.x, v0, repulsive ? 0.0 : m_cubic, rho0, q.normal, q.depth);
        out.particles.body.back() = static_cast<std::int32_t>(k);
        out.particles.stationary.back() = (w.motion ? w.motion->stationary : w.belt) ? 1 : 0;
        if (motion >= 0) out.particles.set_motion(out.particles.size() - 1, motion);
      }
      ++i;
    }
    out.body_names.push_back(w.name);
    out.particles.free_slip_body.push_back(w.free_slip ? 1 : 0);
    out.particles.body_treatment.push_back(repulsive              ? WallTreatment::repulsive
                                           : treatment == "dynamic" ? WallTreatment::dynamic
                                           : treatment == "extrapolated" ? WallTreatment::extrapolated
                                                                         : WallTreatment::rest);
    BodyRepulsion law;  // r0 = 0: no force
    if (repulsive) law = {w.repulsion.strength, w.repulsion.p1, w.repulsion.p2, w.repulsion.r0 * dx};
    out.particles.body_repulsion.push_back(law);
  }
  out.velocity_scale = scale.value(n_fluid_whole, dx);
  // A repulsive body without a strength: D = U^2, U the scene's velocity scale (Niedoba 2012, §3.3:
  // D of the order of the largest squared speed, g H for a water column).
  for (std::size_t k = 0; k < solids.size(); ++k) {
    auto& law = out.particles.body_repulsion[k];
    if (law.r0 == 0.0 || law.strength > 0.0) continue;
    const double U = out.velocity_scale;
    if (!(U > 0.0))
      fail(spec.walls[k].where_treatment, "the scene has no velocity scale (no body force and nothing moves) to set the repulsive "
                                          "strength from; give repulsive: {strength: D} in m^2/s^2");
    law.strength = U * U;
  }
  // Fluid bodies with their own rest density: every particle's rho0 (walls: fluid.density).
  if (std::any_of(fluid.begin(), fluid.end(), [rho0](const FluidBody& f) { return f.rho0 != rho0; })) {
    auto& r = out.particles.rest_density;
    for (std::size_t k = 0; k < fluid.size(); ++k) r.insert(r.end(), kept[k], fluid[k].rho0);
    r.resize(out.particles.size(), rho0);
  }

  // Morris' viscosity with each fluid body's own mu = rho0_k nu_k, where that differs from one body to
  // another (its own kinematic_viscosity, or its own rest density at the common nu).
  if (disc.viscosity == "morris") {
    std::vector<double> mu_k;
    for (std::size_t k = 0; k < fluid.size(); ++k)
      mu_k.push_back(fluid[k].rho0 * (spec.fluid[k].viscosity >= 0.0 ? spec.fluid[k].viscosity : config.fluid.kinematic_viscosity));
    if (std::any_of(mu_k.begin(), mu_k.end(), [&](double m) { return m != rho0 * config.fluid.kinematic_viscosity; })) {
      auto& mu = out.particles.viscosity;
      for (std::size_t k = 0; k < fluid.size(); ++k) mu.insert(mu.end(), kept[k], mu_k[k]);
      mu.resize(out.particles.size(), 0.0);
    }
  }
  for (int d = 0; d < D; ++d) {
    out.domain.periodic[d] = dom.boundary[d] == AxisBoundary::periodic;
    const double grow = out.domain.periodic[d] ? 0.0 : max_thickness;
    out.domain.lo[d] = box.lo[d] - grow;
    out.domain.hi[d] = box.hi[d] + grow;
    // Open axes and open faces let fluid out (run/outflow.hpp); beyond a wall face it is a blow-up.
    for (int side = 0; side < 2; ++side)
      out.domain.outflow[d][side] = dom.boundary[d] == AxisBoundary::open ||
                                    (dom.boundary[d] == AxisBoundary::wall && dom.open[2 * d + side]);
  }
  return out;
}

template BuiltScene<2> build_scene<2>(const SceneSpec&, const Config&, SceneShare);
template BuiltScene<3> build_scene<3>(const SceneSpec&, const Config&, SceneShare);

}  // namespace sphmol
