#pragma once
// All particles of a scene in structure-of-arrays form. Fluid particles occupy [0, n_fluid) and are
// integrated; boundary (wall) particles follow and move by prescription, never by the ODE.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "sphmol/core/wall_motion.hpp"

namespace sphmol {

// Out: a fluid particle taken out of the simulation after it left the domain through a face open
// to outflow (Domain::outflow, run/outflow.hpp). It keeps its place among the fluid rows and its
// mass in the state, but the neighbour searches list no pair with it and SphSystem sets its rates
// to zero, so it stays frozen where it left.
enum class Kind : std::uint8_t { Fluid = 0, Wall = 1, Out = 2 };

// How a wall body's particles act on the fluid (a scene's walls[i].treatment): wall particles whose
// pressure is the rest pressure, extrapolated from the fluid (Adami et al. 2012) or evolved as dynamic
// boundary particles (Crespo et al. 2007), or massless repulsive particles (Monaghan 1994).
// ghost: a mirror plane of a scene (boundary/ghost_particles.hpp), a body without particles.
enum class WallTreatment : std::uint8_t { rest, extrapolated, dynamic, repulsive, ghost };

// The Lennard-Jones law of a repulsive body (Niedoba 2012, eq 2.76): strength D [m^2/s^2], exponents
// p1 > p2 and cut-off r0 [m]. r0 = 0: no force (a body that is not repulsive).
struct BodyRepulsion {
  double strength = 0.0, p1 = 12.0, p2 = 4.0, r0 = 0.0;
};

template <int D>
struct Particles {
  std::size_t n_fluid = 0;
  std::array<std::vector<double>, D> x;  // positions
  // velocities (walls: the prescribed velocity; for a wall that follows a motion, its velocity at
  // t = 0: wall_velocity() gives it at t)
  std::array<std::vector<double>, D> v;
  std::vector<double> mass;
  std::vector<double> rho;               // density (walls: fixed rest density)
  std::vector<Kind> kind;
  // Reference positions of the walls (as built): wall_state() gives where they are at time t.
  std::array<std::vector<double>, D> x_ref;
  // For a wall particle: the unit normal of its wall surface, pointing into the fluid, and its depth
  // below that surface (>= 0). Zero for fluid particles. Used by the Morris wall-velocity model. As
  // built (t = 0): a rotating wall's normal at t is wall_normal_at().
  std::array<std::vector<double>, D> wall_normal;
  std::vector<double> wall_depth;
  // 1 for a wall that stays at x_ref while carrying the velocity v (a belt, such as the lid of a
  // driven cavity: its surface moves, its particles must not leave the box). 0 otherwise. Walls that
  // follow a motion use the motion's own flag instead.
  std::vector<std::uint8_t> stationary;
  // The solid body a wall particle belongs to (an index into the scene's list of wall bodies, for
  // force probes and per-body motion); -1 for fluid particles and for walls of no named body.
  std::vector<std::int32_t> body;
  // Per wall body (indexed by body): 1 for a free-slip body, whose particles exert no viscous stress
  // (boundary/free_slip_walls.hpp). Shorter than the body count, or empty: the rest are no-slip.
  std::vector<std::uint8_t> free_slip_body;
  bool free_slip(std::size_t i) const {
    const std::int32_t b = body[i];
    return b >= 0 && static_cast<std::size_t>(b) < free_slip_body.size() && free_slip_body[static_cast<std::size_t>(b)] != 0;
  }
  // Per wall body (indexed by body): its treatment and, for a repulsive body, its law. Shorter than the
  // body count, or empty: the rest (and walls of no body) follow `global` in treatment_mask.
  std::vector<WallTreatment> body_treatment;
  std::vector<BodyRepulsion> body_repulsion;
  // mask[b + 1] = 1 when wall body b has treatment t; mask[0] is for walls of no body (domain walls),
  // which have the global treatment. A term indexes it with body[i] + 1: no branch on configuration.
  std::vector<std::uint8_t> treatment_mask(WallTreatment t, WallTreatment global) const {
    std::vector<std::uint8_t> m(std::max(body_treatment.size(), body_count()) + 1, global == t);
    for (std::size_t b = 0; b < body_treatment.size(); ++b) m[b + 1] = body_treatment[b] == t;
    return m;
  }
  // One past the largest body index any particle carries (0: none).
  std::size_t body_count() const {
    std::int32_t top = -1;
    for (std::int32_t b : body) top = std::max(top, b);
    return static_cast<std::size_t>(top + 1);
  }
  bool any_body_treatment(WallTreatment t) const {
    return std::find(body_treatment.begin(), body_treatment.end(), t) != body_treatment.end();
  }
  // Per particle: the rest density rho0 of its fluid body (fluid.density for walls), which the EOS
  // reads (physics/eos_tait.hpp). Empty: every particle has fluid.density.
  std::vector<double> rest_density;
  // Per particle: the dynamic viscosity mu = rho0 nu of its fluid body [Pa s] (walls: 0, unused: a
  // wall pair takes the fluid particle's), which the Morris term reads (physics/morris_viscosity.hpp).
  // Empty: every fluid particle has fluid.density * fluid.kinematic_viscosity.
  std::vector<double> viscosity;

  // The prescribed motions of wall bodies (core/wall_motion.hpp) and, per particle, the index of the
  // one it follows; -1 (the default) for a wall that moves with its own v (x_ref + v t, or stays at
  // x_ref when stationary) and for fluid particles.
  std::vector<WallMotion<D>> motions;
  std::vector<std::int32_t> motion;

  std::size_t size() const { return mass.size(); }
  std::size_t n_wall() const { return size() - n_fluid; }

  // Position, velocity and normal of wall particle i at time t: the one rule the solver and every
  // writer share. wall_state(i, frames) takes the frames of every motion at t (motion_frames(t)), so
  // that a loop over many particles evaluates the trigonometry once per body.
  struct WallState {
    std::array<double, D> x{}, v{}, n{};
  };
  using Frames = std::vector<typename WallMotion<D>::Frame>;
  Frames motion_frames(double t) const {
    Frames f;
    f.reserve(motions.size());
    for (const auto& m : motions) f.push_back(m.frame(t));
    return f;
  }
  WallState wall_state(std::size_t i, const Frames& frames, double t) const {
    const std::int32_t k = motion[i];
    return k < 0 ? own_state(i, t) : moved_state(i, motions[k], frames[k]);
  }
  WallState wall_state(std::size_t i, double t) const {
    const std::int32_t k = motion[i];
    return k < 0 ? own_state(i, t) : moved_state(i, motions[k], motions[k].frame(t));
  }
  double wall_position(int d, std::size_t i, double t) const {
    return motion[i] < 0 ? own_position(d, i, t) : wall_state(i, t).x[d];
  }
  double wall_velocity(int d, std::size_t i, double t) const { return motion[i] < 0 ? v[d][i] : wall_state(i, t).v[d]; }
  double wall_normal_at(int d, std::size_t i, double t) const {
    return motion[i] < 0 ? wall_normal[d][i] : wall_state(i, t).n[d];
  }
  // True when some wall's normal turns with time (the solver then updates the normals it reads).
  bool has_turning_walls() const {
    return std::any_of(motions.begin(), motions.end(), [](const WallMotion<D>& m) { return m.rotates() && !m.stationary; });
  }
  // The largest speed any wall particle reaches (over all time): bounds the work walls do on the fluid.
  double max_wall_speed() const {
    double s = 0.0;
    // Over the scene's own walls: a particle generator (ghosts) extends only mass, rho and kind.
    for (std::size_t i = n_fluid; i < motion.size(); ++i) {
      if (motion[i] < 0) {
        double v2 = 0.0;
        for (int d = 0; d < D; ++d) v2 += v[d][i] * v[d][i];
        s = std::max(s, std::sqrt(v2));
        continue;
      }
      std::array<double, D> xr{}, nr{};
      for (int d = 0; d < D; ++d) {
        xr[d] = x_ref[d][i];
        nr[d] = wall_normal[d][i];
      }
      s = std::max(s, motions[motion[i]].max_speed(xr, nr, wall_depth[i]));
    }
    return s;
  }

  // Adds a motion to the table (validated) and returns its index.
  std::int32_t add_motion(const WallMotion<D>& m) {
    motions.push_back(m.validated());
    return static_cast<std::int32_t>(motions.size() - 1);
  }
  // Makes wall particle i follow motion `index`; its v becomes the motion's velocity at t = 0.
  void set_motion(std::size_t i, std::int32_t index) {
    if (i < n_fluid || i >= size()) throw std::invalid_argument("wall motion: particle " + std::to_string(i) + " is not a wall particle");
    if (index < -1 || index >= static_cast<std::int32_t>(motions.size()))
      throw std::invalid_argument("wall motion: no motion " + std::to_string(index));
    motion[i] = index;
    const WallState s = wall_state(i, 0.0);
    for (int d = 0; d < D; ++d) v[d][i] = s.v[d];
  }
  // Adds motion m and attaches it to every wall particle of body `b`; returns the motion's index.
  // A body with no wall particle is an error: the motion would silently move nothing.
  std::int32_t attach_motion(std::int32_t b, const WallMotion<D>& m) {
    std::vector<std::size_t> members;
    for (std::size_t i = n_fluid; i < size(); ++i)
      if (body[i] == b) members.push_back(i);
    if (b < 0 || members.empty()) throw std::invalid_argument("wall motion: body " + std::to_string(b) + " has no wall particles");
    const std::int32_t k = add_motion(m);
    for (std::size_t i : members) set_motion(i, k);
    return k;
  }

  void add(Kind k, const std::array<double, D>& pos, const std::array<double, D>& vel, double m, double density,
           const std::array<double, D>& normal = {}, double depth = 0.0) {
    for (int d = 0; d < D; ++d) {
      x[d].push_back(pos[d]);
      v[d].push_back(vel[d]);
      x_ref[d].push_back(pos[d]);
      wall_normal[d].push_back(normal[d]);
    }
    wall_depth.push_back(depth);
    stationary.push_back(0);
    body.push_back(-1);
    motion.push_back(-1);
    mass.push_back(m);
    rho.push_back(density);
    kind.push_back(k);
    if (k == Kind::Fluid) ++n_fluid;
  }

 private:
  double own_position(int d, std::size_t i, double t) const { return x_ref[d][i] + (stationary[i] ? 0.0 : v[d][i] * t); }
  WallState own_state(std::size_t i, double t) const {
    WallState s;
    for (int d = 0; d < D; ++d) {
      s.x[d] = own_position(d, i, t);
      s.v[d] = v[d][i];
      s.n[d] = wall_normal[d][i];
    }
    return s;
  }
  WallState moved_state(std::size_t i, const WallMotion<D>& m, const typename WallMotion<D>::Frame& f) const {
    std::array<double, D> xr{}, nr{};
    for (int d = 0; d < D; ++d) {
      xr[d] = x_ref[d][i];
      nr[d] = wall_normal[d][i];
    }
    WallState s;
    m.apply(f, xr, nr, wall_depth[i], s.x, s.v, s.n);
    return s;
  }
};

}  // namespace sphmol
