#include "sphmol/parallel/halo.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace sphmol::parallel {

namespace {

// Distance from x to the interval [lo, hi] (0 inside).
double gap(double x, double lo, double hi) { return std::max({lo - x, x - hi, 0.0}); }

// The same, to the nearest periodic image of the interval when L > 0.
double periodic_gap(double x, double lo, double hi, double L) {
  double g = gap(x, lo, hi);
  if (L > 0.0) g = std::min({g, gap(x + L, lo, hi), gap(x - L, lo, hi)});
  return g;
}

constexpr int halo_tag = 7301;

}  // namespace

template <int D>
void Halo<D>::plan(const Communicator& comm, const Domain<D>& domain, const std::vector<geometry::Bounds<D>>& regions,
                   const std::array<const double*, D>& x, std::size_t n_owned, double range) {
  const std::size_t P = static_cast<std::size_t>(comm.size());
  if (regions.size() != P)
    throw std::invalid_argument("halo: " + std::to_string(regions.size()) + " regions for " + std::to_string(P) + " ranks");
  if (!(range >= 0.0) || !std::isfinite(range)) throw std::invalid_argument("halo: the range must be finite and >= 0");
  if (n_owned > UINT32_MAX) throw std::length_error("halo: more owned particles than a 32-bit index holds");
  n_owned_ = n_owned;
  send_.assign(P, {});
  const double range2 = range * range;
  for (std::size_t r = 0; r < P; ++r) {
    if (static_cast<int>(r) == comm.rank()) continue;
    // In a periodic direction every particle lies in [lo, hi): a region reaches no further (a cut
    // box is infinite at the outside), and its images are one period away.
    geometry::Bounds<D> box = regions[r];
    for (int d = 0; d < D; ++d)
      if (domain.periodic[d]) {
        box.lo[d] = std::max(box.lo[d], domain.lo[d]);
        box.hi[d] = std::min(box.hi[d], domain.hi[d]);
      }
    for (std::size_t i = 0; i < n_owned; ++i) {
      double g2 = 0.0;
      for (int d = 0; d < D; ++d) {
        const double g = periodic_gap(x[d][i], box.lo[d], box.hi[d], domain.period(d));
        g2 += g * g;
      }
      if (g2 <= range2) send_[r].push_back(static_cast<std::uint32_t>(i));
    }
  }
  // How many copies come from each rank.
  std::vector<int> send_count(P), recv_count(P);
  for (std::size_t r = 0; r < P; ++r) send_count[r] = mpi_count(send_[r].size(), "halo plan");
  MPI_Alltoall(send_count.data(), 1, MPI_INT, recv_count.data(), 1, MPI_INT, comm.handle());
  recv_offset_.assign(P + 1, 0);
  owner_.clear();
  for (std::size_t r = 0; r < P; ++r) {
    recv_offset_[r + 1] = recv_offset_[r] + static_cast<std::size_t>(recv_count[r]);
    owner_.insert(owner_.end(), static_cast<std::size_t>(recv_count[r]), static_cast<int>(r));
  }
}

template <int D>
std::size_t Halo<D>::sent() const {
  std::size_t s = 0;
  for (const auto& l : send_) s += l.size();
  return s;
}

template <int D>
void Halo<D>::post_receives(const Communicator& comm, std::size_t bytes, std::byte* halo) const {
  const std::size_t P = send_.size();
  if (P != static_cast<std::size_t>(comm.size())) throw std::logic_error("halo: exchange before plan");
  requests_.clear();
  requests_.reserve(2 * P);
  for (std::size_t r = 0; r < P; ++r) {
    const std::size_t count = recv_offset_[r + 1] - recv_offset_[r];
    if (count == 0) continue;
    requests_.emplace_back();
    MPI_Irecv(halo + recv_offset_[r] * bytes, mpi_count(count * bytes, "halo exchange"), MPI_BYTE, static_cast<int>(r),
              halo_tag, comm.handle(), &requests_.back());
  }
}

template <int D>
void Halo<D>::post_sends(const Communicator& comm, std::size_t bytes, const std::byte* packed) const {
  std::size_t at = 0;
  for (std::size_t r = 0; r < send_.size(); ++r) {
    if (send_[r].empty()) continue;
    requests_.emplace_back();
    MPI_Isend(packed + at, mpi_count(send_[r].size() * bytes, "halo exchange"), MPI_BYTE, static_cast<int>(r), halo_tag,
              comm.handle(), &requests_.back());
    at += send_[r].size() * bytes;
  }
}

template <int D>
void Halo<D>::wait() const {
  MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE);
  requests_.clear();
}

template <int D>
void Halo<D>::exchange_bytes(const Communicator& comm, const std::byte* owned, std::size_t bytes, std::byte* halo) const {
  post_receives(comm, bytes, halo);
  buffer_.resize(sent() * bytes);
  std::size_t at = 0;
  for (const auto& list : send_)
    for (std::uint32_t i : list) {
      std::memcpy(buffer_.data() + at, owned + static_cast<std::size_t>(i) * bytes, bytes);
      at += bytes;
    }
  post_sends(comm, bytes, buffer_.data());
  wait();
}

template class Halo<1>;
template class Halo<2>;
template class Halo<3>;

}  // namespace sphmol::parallel
