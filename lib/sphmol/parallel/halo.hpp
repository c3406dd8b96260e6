#pragma once
// Halo particles: the copies of other ranks' particles that a rank's own particles interact with.
// plan() decides, once per neighbour-list rebuild, which owned particles each other rank needs:
// those within `range` (the kernel support plus the Verlet skin) of that rank's region, by the
// nearest periodic image in periodic directions. exchange() then sends any per-particle field of
// those particles, owner to receiver, as often as the field changes (positions after every drift,
// densities before the pass that reads them, ...).
//
// A halo copy keeps its owner's coordinates, wrapped into the domain as they are: the receiver's
// neighbour search pairs it with its own particles by the minimum image, as the serial search
// pairs particles across a periodic face, so no shifted copies are made. The plan stays valid while
// no particle has moved more than half the skin since it was made: a pair within the support then
// was within support + skin at planning time (the Verlet list's own rule).
//
// Halo particles arrive ordered by owner rank, then by the owner's local index: a fixed order for
// one decomposition. Sums that must not depend on the decomposition order their terms by global id.
#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "sphmol/core/domain.hpp"
#include "sphmol/geometry/vec.hpp"
#include "sphmol/parallel/communicator.hpp"

namespace sphmol::parallel {

template <int D>
class Halo {
 public:
  // Collective. regions[r] holds every particle rank r owns (region_bounds.hpp, or the cut boxes);
  // x: the n_owned local positions, inside the domain in periodic directions.
  void plan(const Communicator& comm, const Domain<D>& domain, const std::vector<geometry::Bounds<D>>& regions,
            const std::array<const double*, D>& x, std::size_t n_owned, double range);

  std::size_t size() const { return owner_.size(); }      // halo particles on this rank
  std::size_t owned() const { return n_owned_; }           // owned particles the plan was made for
  const std::vector<int>& owner() const { return owner_; } // per halo particle, the rank that owns it
  const std::vector<std::uint32_t>& sent_to(int rank) const { return send_[static_cast<std::size_t>(rank)]; }
  std::size_t sent() const;                                // copies this rank sends, over all ranks

  // The owners' values of a per-particle field: halo[k] for the k-th halo particle, from owned[i]
  // on its owner (size() values). Collective over the ranks that exchange with this one.
  template <class T>
  void exchange(const Communicator& comm, const T* owned, T* halo) const {
    static_assert(std::is_trivially_copyable_v<T>);
    exchange_bytes(comm, reinterpret_cast<const std::byte*>(owned), sizeof(T), reinterpret_cast<std::byte*>(halo));
  }
  template <class T>
  std::vector<T> exchange(const Communicator& comm, const std::vector<T>& owned) const {
    std::vector<T> halo(size());
    exchange(comm, owned.data(), halo.data());
    return halo;
  }
  // Rows of `width` doubles per particle (a width known at run time: the state blocks a scene has)
  // without an array of every owned row: pack(i, row) writes owned particle i's row, only for the
  // particles sent; halo[k * width ...] receives the k-th halo particle's; overlap() runs while the
  // messages travel (work on this rank's own data). A state of a million particles is then not
  // copied to send a few thousand.
  template <class Pack, class Overlap>
  void exchange_rows(const Communicator& comm, std::size_t width, Pack&& pack, double* halo, Overlap&& overlap) const {
    const std::size_t bytes = width * sizeof(double);
    post_receives(comm, bytes, reinterpret_cast<std::byte*>(halo));
    rows_.resize(sent() * width);
    double* row = rows_.data();
    for (const auto& list : send_)
      for (std::uint32_t i : list) {
        pack(i, row);
        row += width;
      }
    post_sends(comm, bytes, reinterpret_cast<const std::byte*>(rows_.data()));
    overlap();
    wait();
  }

 private:
  void exchange_bytes(const Communicator& comm, const std::byte* owned, std::size_t bytes, std::byte* halo) const;
  // The pieces of an exchange: receives straight into the halo (each rank's copies one contiguous
  // block), sends of the packed copies in rank order, and the wait for both.
  void post_receives(const Communicator& comm, std::size_t bytes, std::byte* halo) const;
  void post_sends(const Communicator& comm, std::size_t bytes, const std::byte* packed) const;
  void wait() const;

  std::size_t n_owned_ = 0;
  std::vector<std::vector<std::uint32_t>> send_;  // per rank: the owned indices it needs, ascending
  std::vector<std::size_t> recv_offset_;          // per rank + 1: where its copies start in the halo
  std::vector<int> owner_;
  mutable std::vector<std::byte> buffer_;         // packed sends, kept between exchanges
  mutable std::vector<double> rows_;              // the same for packed rows
  mutable std::vector<MPI_Request> requests_;     // of the exchange in progress
};

extern template class Halo<1>;
extern template class Halo<2>;
extern template class Halo<3>;

}  // namespace sphmol::parallel
