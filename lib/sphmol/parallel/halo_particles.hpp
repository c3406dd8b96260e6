#pragma once
// The halo copies of a halo plan as particles of their own: every per-particle array of the owners
// (particle_columns.hpp) sent through the plan, once per plan. Per-body tables are the same on
// every rank and are copied from `owned`.
#include <type_traits>
#include <vector>

#include "sphmol/parallel/halo.hpp"
#include "sphmol/parallel/particle_columns.hpp"

namespace sphmol::parallel {

// Collective. `owned`: the particles the plan was made for (halo.owned() of them).
template <int D>
Particles<D> exchange_halo_particles(const Communicator& comm, const Halo<D>& halo, const Particles<D>& owned) {
  Particles<D> h = owned;  // the per-body tables; every column is replaced below
  std::vector<void*> cols;
  for_each_particle_column(h, [&](auto& c) { cols.push_back(&c); });
  std::size_t k = 0;
  for_each_particle_column(owned, [&](const auto& c) {
    auto& to = *static_cast<std::remove_cvref_t<decltype(c)>*>(cols[k++]);
    // Optional arrays travel when some rank fills them: every rank decides alike (the exchange is
    // collective), and a rank without particles has every array empty.
    const bool filled = comm.max(c.empty() ? 0.0 : 1.0) > 0.0;
    to.clear();
    if (filled) to = halo.exchange(comm, c);
  });
  h.n_fluid = 0;  // a plain list of copies: the caller orders it (select_particles)
  return h;
}

}  // namespace sphmol::parallel
