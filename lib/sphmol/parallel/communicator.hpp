#pragma once
// The ranks that share one particle set, and the collective operations the decomposition uses.
// Wraps an MPI communicator it does not own (MPI_COMM_WORLD by default); counts travel as int, as MPI
// takes them, and a message past INT_MAX bytes is refused with an error rather than truncated.
#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

namespace sphmol::parallel {

class Communicator {
 public:
  explicit Communicator(MPI_Comm comm = MPI_COMM_WORLD);

  MPI_Comm handle() const { return comm_; }
  int rank() const { return rank_; }
  int size() const { return size_; }

  double sum(double v) const;
  std::uint64_t sum(std::uint64_t v) const;
  double max(double v) const;
  int max(int v) const;
  double min(double v) const;
  bool all(bool v) const;  // true on every rank
  // The ranks on this rank's machine (sharing its memory), this one included (collective).
  int ranks_on_this_machine() const;
  // Element by element over the ranks (every rank passes as many values): the largest, and the sum
  // modulo 2^64.
  std::vector<double> max(const std::vector<double>& v) const;
  std::vector<std::uint64_t> sum(const std::vector<std::uint64_t>& v) const;
  void barrier() const;

  // Every rank's value, in rank order.
  template <class T>
  std::vector<T> all_gather(const T& v) const {
    static_assert(std::is_trivially_copyable_v<T>);
    std::vector<T> out(static_cast<std::size_t>(size_));
    all_gather_bytes(&v, sizeof(T), out.data());
    return out;
  }
  // Every rank's vector, concatenated in rank order.
  template <class T>
  std::vector<T> all_gather_v(const std::vector<T>& v) const {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::vector<std::byte> b = all_gather_v_bytes(v.data(), v.size() * sizeof(T));
    std::vector<T> out(b.size() / sizeof(T));
    if (!b.empty()) std::memcpy(out.data(), b.data(), b.size());
    return out;
  }

  // Every rank's vector, concatenated in rank order, on rank `root` only (empty elsewhere): what
  // only one rank reads, without a copy of the whole on every rank.
  template <class T>
  std::vector<T> gather_v(const std::vector<T>& v, int root = 0) const {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::vector<std::byte> b = gather_v_bytes(v.data(), v.size() * sizeof(T), root);
    std::vector<T> out(b.size() / sizeof(T));
    if (!b.empty()) std::memcpy(out.data(), b.data(), b.size());
    return out;
  }

  // Rank `root`'s value, on every rank (what one rank alone can compute, such as a sum over the
  // whole scene that only the root still holds).
  template <class T>
  void broadcast(T& v, int root = 0) const {
    static_assert(std::is_trivially_copyable_v<T>);
    broadcast_bytes(&v, sizeof(T), root);
  }

  void broadcast_bytes(void* v, std::size_t bytes, int root = 0) const;

  // Personalised all-to-all of bytes: send[r] goes to rank r; returns what every rank sent here,
  // concatenated in rank order, with from[r] the number of bytes that came from rank r.
  std::vector<std::byte> all_to_all_v(const std::vector<std::vector<std::byte>>& send, std::vector<std::size_t>& from) const;

 private:
  void all_gather_bytes(const void* v, std::size_t bytes, void* out) const;
  std::vector<std::byte> all_gather_v_bytes(const void* v, std::size_t bytes) const;
  std::vector<std::byte> gather_v_bytes(const void* v, std::size_t bytes, int root) const;

  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
};

// A byte count as MPI's int, or an error naming what was too large.
int mpi_count(std::size_t bytes, const char* what);

}  // namespace sphmol::parallel
