#include "sphmol/parallel/serial_order_norm.hpp"

#include <nvector/nvector_parallel.h>

#include <cmath>
#include <numeric>
#include <stdexcept>

namespace sphmol::parallel {

namespace {

// The attribute key under which a vector's communicator holds its SerialOrderNorm.
int norm_key() {
  static const int key = [] {
    int k = MPI_KEYVAL_INVALID;
    MPI_Comm_create_keyval(MPI_COMM_NULL_COPY_FN, MPI_COMM_NULL_DELETE_FN, &k, nullptr);
    return k;
  }();
  return key;
}

sunrealtype serial_order_wrms_norm(N_Vector x, N_Vector w) {
  void* attr = nullptr;
  int found = 0;
  MPI_Comm_get_attr(NV_COMM_P(x), norm_key(), &attr, &found);
  if (!found) MPI_Abort(NV_COMM_P(x), 1);  // not a vector made by SerialOrderNorm::wrap
  return static_cast<const SerialOrderNorm*>(attr)->wrms(NV_DATA_P(x), NV_DATA_P(w), static_cast<std::size_t>(NV_LOCLENGTH_P(x)));
}

}  // namespace

SerialOrderNorm::SerialOrderNorm(MPI_Comm comm) {
  MPI_Comm_dup(comm, &comm_);
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_set_attr(comm_, norm_key(), this);
}

SerialOrderNorm::~SerialOrderNorm() {
  if (comm_ != MPI_COMM_NULL) MPI_Comm_free(&comm_);
}

void SerialOrderNorm::set_order(const std::vector<std::uint64_t>& whole_index) {
  int size = 1;
  MPI_Comm_size(comm_, &size);
  local_ = whole_index.size();
  const int mine = static_cast<int>(local_);
  counts_.assign(static_cast<std::size_t>(size), 0);
  MPI_Gather(&mine, 1, MPI_INT, counts_.data(), 1, MPI_INT, 0, comm_);
  displs_.assign(static_cast<std::size_t>(size), 0);
  if (rank_ == 0) std::exclusive_scan(counts_.begin(), counts_.end(), displs_.begin(), 0);
  std::uint64_t local = local_, whole = 0;
  MPI_Allreduce(&local, &whole, 1, MPI_UINT64_T, MPI_SUM, comm_);
  whole_ = whole;
  index_.assign(rank_ == 0 ? whole_ : 0, 0);
  MPI_Gatherv(whole_index.data(), mine, MPI_UINT64_T, index_.data(), counts_.data(), displs_.data(), MPI_UINT64_T, 0, comm_);
  if (rank_ == 0) {
    // Every whole-state index exactly once: the parts must tile the whole state.
    std::vector<char> seen(whole_, 0);
    for (const std::uint64_t i : index_) {
      if (i >= whole_ || seen[i]) throw std::logic_error("SerialOrderNorm: the parts do not tile the whole state");
      seen[i] = 1;
    }
  }
  terms_.assign(local_, 0.0);
  gathered_.assign(rank_ == 0 ? whole_ : 0, 0.0);
  placed_.assign(rank_ == 0 ? whole_ : 0, 0.0);
}

double SerialOrderNorm::wrms(const double* x, const double* w, std::size_t n) const {
  if (n != local_) MPI_Abort(comm_, 1);  // a vector of another length than the order was set for
  for (std::size_t i = 0; i < n; ++i) {
    const double p = x[i] * w[i];  // rounded before squaring, as the serial vector does
    terms_[i] = p * p;
  }
  MPI_Gatherv(terms_.data(), static_cast<int>(n), MPI_DOUBLE, gathered_.data(), counts_.data(), displs_.data(), MPI_DOUBLE, 0, comm_);
  double norm = 0.0;
  if (rank_ == 0) {
    for (std::size_t k = 0; k < whole_; ++k) placed_[index_[k]] = gathered_[k];
    double sum = 0.0;
    for (std::size_t i = 0; i < whole_; ++i) sum += placed_[i];
    norm = std::sqrt(sum / static_cast<double>(whole_));
  }
  MPI_Bcast(&norm, 1, MPI_DOUBLE, 0, comm_);
  return norm;
}

N_Vector SerialOrderNorm::wrap(double* data, std::size_t length, SUNContext ctx) const {
  if (length != local_) throw std::invalid_argument("SerialOrderNorm::wrap: not the length the order was set for");
  N_Vector v = N_VMake_Parallel(comm_, static_cast<sunindextype>(length), static_cast<sunindextype>(whole_), data, ctx);
  if (!v) throw std::runtime_error("N_VMake_Parallel failed");
  v->ops->nvwrmsnorm = &serial_order_wrms_norm;
  return v;
}

}  // namespace sphmol::parallel
