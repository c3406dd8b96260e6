#include "sphmol/parallel/communicator.hpp"

#include <climits>
#include <stdexcept>
#include <string>

namespace sphmol::parallel {

int mpi_count(std::size_t bytes, const char* what) {
  if (bytes > static_cast<std::size_t>(INT_MAX))
    throw std::length_error(std::string(what) + ": " + std::to_string(bytes) + " bytes exceed one MPI message (" +
                            std::to_string(INT_MAX) + ")");
  return static_cast<int>(bytes);
}

Communicator::Communicator(MPI_Comm comm) : comm_(comm) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
}

double Communicator::sum(double v) const {
  double out = 0.0;
  MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, MPI_SUM, comm_);
  return out;
}

std::uint64_t Communicator::sum(std::uint64_t v) const {
  std::uint64_t out = 0;
  MPI_Allreduce(&v, &out, 1, MPI_UINT64_T, MPI_SUM, comm_);
  return out;
}

double Communicator::max(double v) const {
  double out = 0.0;
  MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, MPI_MAX, comm_);
  return out;
}

int Communicator::max(int v) const {
  int out = 0;
  MPI_Allreduce(&v, &out, 1, MPI_INT, MPI_MAX, comm_);
  return out;
}

double Communicator::min(double v) const {
  double out = 0.0;
  MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, MPI_MIN, comm_);
  return out;
}

int Communicator::ranks_on_this_machine() const {
  MPI_Comm node = MPI_COMM_NULL;
  MPI_Comm_split_type(comm_, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  int n = 1;
  MPI_Comm_size(node, &n);
  MPI_Comm_free(&node);
  return n;
}

bool Communicator::all(bool v) const {
  int in = v ? 1 : 0, out = 0;
  MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_LAND, comm_);
  return out != 0;
}

std::vector<double> Communicator::max(const std::vector<double>& v) const {
  std::vector<double> out(v.size());
  MPI_Allreduce(v.data(), out.data(), mpi_count(v.size(), "max"), MPI_DOUBLE, MPI_MAX, comm_);
  return out;
}

std::vector<std::uint64_t> Communicator::sum(const std::vector<std::uint64_t>& v) const {
  std::vector<std::uint64_t> out(v.size());
  MPI_Allreduce(v.data(), out.data(), mpi_count(v.size(), "sum"), MPI_UINT64_T, MPI_SUM, comm_);
  return out;
}

void Communicator::barrier() const { MPI_Barrier(comm_); }

void Communicator::all_gather_bytes(const void* v, std::size_t bytes, void* out) const {
  const int n = mpi_count(bytes, "all_gather");
  MPI_Allgather(v, n, MPI_BYTE, out, n, MPI_BYTE, comm_);
}

std::vector<std::byte> Communicator::all_gather_v_bytes(const void* v, std::size_t bytes) const {
  const int n = mpi_count(bytes, "all_gather_v");
  std::vector<int> counts(static_cast<std::size_t>(size_)), displ(static_cast<std::size_t>(size_));
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_);
  std::size_t total = 0;
  for (int r = 0; r < size_; ++r) {
    displ[r] = mpi_count(total, "all_gather_v");
    total += static_cast<std::size_t>(counts[r]);
  }
  mpi_count(total, "all_gather_v");
  std::vector<std::byte> out(total);
  MPI_Allgatherv(v, n, MPI_BYTE, out.data(), counts.data(), displ.data(), MPI_BYTE, comm_);
  return out;
}

void Communicator::broadcast_bytes(void* v, std::size_t bytes, int root) const {
  MPI_Bcast(v, mpi_count(bytes, "broadcast"), MPI_BYTE, root, comm_);
}

std::vector<std::byte> Communicator::gather_v_bytes(const void* v, std::size_t bytes, int root) const {
  const int n = mpi_count(bytes, "gather_v");
  std::vector<int> counts(static_cast<std::size_t>(size_)), displ(static_cast<std::size_t>(size_));
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, root, comm_);
  std::size_t total = 0;
  if (rank_ == root)
    for (int r = 0; r < size_; ++r) {
      displ[r] = mpi_count(total, "gather_v");
      total += static_cast<std::size_t>(counts[r]);
    }
  mpi_count(total, "gather_v");
  std::vector<std::byte> out(total);
  MPI_Gatherv(v, n, MPI_BYTE, out.data(), counts.data(), displ.data(), MPI_BYTE, root, comm_);
  return out;
}

std::vector<std::byte> Communicator::all_to_all_v(const std::vector<std::vector<std::byte>>& send,
                                                  std::vector<std::size_t>& from) const {
  if (send.size() != static_cast<std::size_t>(size_))
    throw std::invalid_argument("all_to_all_v: " + std::to_string(send.size()) + " send buffers for " +
                                std::to_string(size_) + " ranks");
  const std::size_t P = static_cast<std::size_t>(size_);
  std::vector<int> scount(P), sdispl(P), rcount(P), rdispl(P);
  std::vector<std::byte> sbuf;
  for (std::size_t r = 0; r < P; ++r) {
    sdispl[r] = mpi_count(sbuf.size(), "all_to_all_v");
    scount[r] = mpi_count(send[r].size(), "all_to_all_v");
    sbuf.insert(sbuf.end(), send[r].begin(), send[r].end());
  }
  mpi_count(sbuf.size(), "all_to_all_v");
  MPI_Alltoall(scount.data(), 1, MPI_INT, rcount.data(), 1, MPI_INT, comm_);
  std::size_t total = 0;
  from.assign(P, 0);
  for (std::size_t r = 0; r < P; ++r) {
    rdispl[r] = mpi_count(total, "all_to_all_v");
    from[r] = static_cast<std::size_t>(rcount[r]);
    total += from[r];
  }
  mpi_count(total, "all_to_all_v");
  std::vector<std::byte> out(total);
  MPI_Alltoallv(sbuf.data(), scount.data(), sdispl.data(), MPI_BYTE, out.data(), rcount.data(), rdispl.data(), MPI_BYTE,
                comm_);
  return out;
}

}  // namespace sphmol::parallel
