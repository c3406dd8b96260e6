#pragma once
// Every per-particle array of Particles<D> (one value per particle), visited in one fixed order:
// what moves with a particle from one rank to another. The per-body tables (motions, treatments,
// free-slip flags, repulsion laws) are the same on every rank and stay. rest_density and viscosity
// may be empty (every particle then has the fluid's value); an empty array is visited all the same
// and the caller skips it.
#include <cstddef>

#include "sphmol/core/particles.hpp"

namespace sphmol::parallel {

// f(std::vector<T>&) for each array; P is Particles<D> or const Particles<D>.
template <class P, class F>
void for_each_particle_column(P& p, F&& f) {
  for (auto& c : p.x) f(c);
  for (auto& c : p.v) f(c);
  f(p.mass);
  f(p.rho);
  f(p.kind);
  for (auto& c : p.x_ref) f(c);
  for (auto& c : p.wall_normal) f(c);
  f(p.wall_depth);
  f(p.stationary);
  f(p.body);
  f(p.rest_density);
  f(p.viscosity);
  f(p.motion);
}

// The per-body tables of `from` into `to` (what every subset of a scene keeps whole).
template <int D>
void copy_body_tables(Particles<D>& to, const Particles<D>& from) {
  to.free_slip_body = from.free_slip_body;
  to.body_treatment = from.body_treatment;
  to.body_repulsion = from.body_repulsion;
  to.motions = from.motions;
}

// A member added to Particles must be added above (or, if it is per body, named here): every
// std::vector has the same size, so the struct's size counts them. 4 D-arrays and 9 arrays per
// particle, 4 tables per body, and n_fluid.
template <int D>
inline constexpr std::size_t particles_members_counted =
    sizeof(std::size_t) + (4 * D + 9 + 4) * sizeof(std::vector<double>);
static_assert(sizeof(Particles<1>) == particles_members_counted<1> && sizeof(Particles<2>) == particles_members_counted<2> &&
                  sizeof(Particles<3>) == particles_members_counted<3>,
              "Particles gained or lost a member: update for_each_particle_column");

}  // namespace sphmol::parallel
