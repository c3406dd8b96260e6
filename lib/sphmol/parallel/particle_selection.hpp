#pragma once
// Subsets and unions of particle sets, column by column over every per-particle array of
// Particles<D> (particle_columns.hpp); the per-body tables are kept. A distributed run takes a
// rank's share of the whole scene with these, and joins its own particles with the halo copies.
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "sphmol/parallel/particle_columns.hpp"

namespace sphmol::parallel {

// The particles from[index[k]], in that order; the first n_fluid of them must be the fluid ones.
// Column by column from `from`, without a copy of the whole set (a rank takes its share of the
// whole scene with this).
template <int D, class Index>
Particles<D> select_particles(const Particles<D>& from, const std::vector<Index>& index, std::size_t n_fluid) {
  Particles<D> to;
  copy_body_tables(to, from);
  std::vector<const void*> cols;
  for_each_particle_column(from, [&](const auto& c) { cols.push_back(&c); });
  std::size_t k = 0;
  for_each_particle_column(to, [&](auto& c) {
    const auto& f = *static_cast<const std::remove_reference_t<decltype(c)>*>(cols[k++]);
    if (f.empty()) return;  // an optional array nobody fills
    c.resize(index.size());
    for (std::size_t j = 0; j < index.size(); ++j) c[j] = f[index[j]];
  });
  to.n_fluid = n_fluid;
  return to;
}

// Appends every per-particle array of `from` to the same array of `to` (columns are visited in one
// fixed order, so the k-th column of one set is the k-th of the other, of the same type). The result
// is a plain list: its n_fluid is the caller's to set (select_particles). An optional array filled in
// one set and empty in the other, with particles, is an error.
template <int D>
void append_particles(Particles<D>& to, const Particles<D>& from) {
  std::vector<const void*> cols;
  for_each_particle_column(from, [&](const auto& c) { cols.push_back(&c); });
  std::size_t k = 0;
  const std::size_t n_to = to.size(), n_from = from.size();
  for_each_particle_column(to, [&](auto& c) {
    const auto& f = *static_cast<const std::remove_reference_t<decltype(c)>*>(cols[k++]);
    if (c.empty() && f.empty()) return;
    if ((c.empty() && n_to > 0) || (f.empty() && n_from > 0))
      throw std::invalid_argument("append_particles: an optional per-particle array is filled in one set only");
    c.insert(c.end(), f.begin(), f.end());
  });
}

}  // namespace sphmol::parallel
