#include "sphmol/parallel/migration.hpp"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "sphmol/parallel/particle_columns.hpp"

namespace sphmol::parallel {

template <int D>
void migrate(const Communicator& comm, Particles<D>& p, std::vector<std::uint64_t>& gid, const std::vector<int>& destination,
             const std::vector<std::vector<double>*>& extra) {
  const std::size_t n = p.size();
  // Bad input is refused on every rank at once, so that no rank waits in a collective alone.
  std::string error;
  if (gid.size() != n || destination.size() != n)
    error = "migration: " + std::to_string(n) + " particles, " + std::to_string(gid.size()) + " global ids, " +
            std::to_string(destination.size()) + " destinations";
  for (std::size_t i = 0; i < n && error.empty(); ++i)
    if (destination[i] < 0 || destination[i] >= comm.size())
      error = "migration: particle " + std::to_string(gid[i]) + " sent to rank " + std::to_string(destination[i]) +
              " of " + std::to_string(comm.size());
  for (const auto* e : extra)
    if (error.empty() && (e == nullptr || e->size() != n))
      error = "migration: an extra array does not hold one value per particle";
  // Which columns travel: those filled on some rank (bit k for the k-th column visited).
  std::uint32_t filled = 0;
  int column = 0;
  for_each_particle_column(p, [&](auto& c) {
    if (!c.empty()) filled |= 1u << column;
    if (!c.empty() && c.size() != n && error.empty())
      error = "migration: per-particle array " + std::to_string(column) + " holds " + std::to_string(c.size()) +
              " values for " + std::to_string(n) + " particles";
    ++column;
  });
  std::uint32_t travel = 0;
  for (std::uint32_t f : comm.all_gather(filled)) travel |= f;
  if (error.empty() && n > 0 && filled != travel) error = "migration: a per-particle array is empty here but not on another rank";
  if (!comm.all(error.empty())) throw std::invalid_argument(error.empty() ? "migration: bad input on another rank" : error);

  // One row of bytes per particle: the global id, the extras, then the travelling columns in visiting
  // order; kind_at is where the kind sits in a row.
  std::size_t row = sizeof(std::uint64_t) + extra.size() * sizeof(double), kind_at = 0;
  column = 0;
  for_each_particle_column(p, [&](auto& c) {
    using T = typename std::decay_t<decltype(c)>::value_type;
    if (travel & (1u << column)) {
      if constexpr (std::is_same_v<T, Kind>) kind_at = row;
      row += sizeof(T);
    }
    ++column;
  });
  const std::size_t gid_at = 0;
  std::vector<std::vector<std::byte>> send(static_cast<std::size_t>(comm.size()));
  for (std::size_t i = 0; i < n; ++i) {
    auto& out = send[static_cast<std::size_t>(destination[i])];
    const std::size_t at = out.size();
    out.resize(at + row);
    std::byte* b = out.data() + at;
    std::memcpy(b + gid_at, &gid[i], sizeof(std::uint64_t));
    std::size_t o = sizeof(std::uint64_t);
    for (const auto* e : extra) {
      std::memcpy(b + o, &(*e)[i], sizeof(double));
      o += sizeof(double);
    }
    column = 0;
    for_each_particle_column(p, [&](auto& c) {
      using T = typename std::decay_t<decltype(c)>::value_type;
      if (travel & (1u << column)) {
        std::memcpy(b + o, &c[i], sizeof(T));
        o += sizeof(T);
      }
      ++column;
    });
  }
  std::vector<std::size_t> from;
  const std::vector<std::byte> got = comm.all_to_all_v(send, from);
  const std::size_t m = got.size() / row;

  // The received rows: fluid first, then by global id. Fluid taken out of the run (Kind::Out,
  // run/outflow.hpp) is fluid still: its state rows travel with it.
  auto gid_of = [&](std::size_t k) {
    std::uint64_t g;
    std::memcpy(&g, got.data() + k * row + gid_at, sizeof g);
    return g;
  };
  auto wall = [&](std::size_t k) {
    Kind kd;
    std::memcpy(&kd, got.data() + k * row + kind_at, sizeof kd);
    return kd == Kind::Wall;
  };
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const bool wa = wall(a), wb = wall(b);
    return wa != wb ? wb : gid_of(a) < gid_of(b);
  });

  gid.resize(m);
  for (auto* e : extra) e->resize(m);
  for (std::size_t k = 0; k < m; ++k) {
    const std::byte* b = got.data() + order[k] * row;
    std::memcpy(&gid[k], b + gid_at, sizeof(std::uint64_t));
    std::size_t o = sizeof(std::uint64_t);
    for (auto* e : extra) {
      std::memcpy(&(*e)[k], b + o, sizeof(double));
      o += sizeof(double);
    }
  }
  std::size_t o_columns = sizeof(std::uint64_t) + extra.size() * sizeof(double);
  column = 0;
  for_each_particle_column(p, [&](auto& c) {
    using T = typename std::decay_t<decltype(c)>::value_type;
    if (travel & (1u << column)) {
      c.resize(m);
      for (std::size_t k = 0; k < m; ++k) std::memcpy(&c[k], got.data() + order[k] * row + o_columns, sizeof(T));
      o_columns += sizeof(T);
    } else {
      c.clear();
    }
    ++column;
  });
  std::size_t fluid = 0;
  for (Kind kd : p.kind) fluid += kd != Kind::Wall;
  p.n_fluid = fluid;
}

template void migrate<1>(const Communicator&, Particles<1>&, std::vector<std::uint64_t>&, const std::vector<int>&,
                         const std::vector<std::vector<double>*>&);
template void migrate<2>(const Communicator&, Particles<2>&, std::vector<std::uint64_t>&, const std::vector<int>&,
                         const std::vector<std::vector<double>*>&);
template void migrate<3>(const Communicator&, Particles<3>&, std::vector<std::uint64_t>&, const std::vector<int>&,
                         const std::vector<std::vector<double>*>&);

}  // namespace sphmol::parallel
