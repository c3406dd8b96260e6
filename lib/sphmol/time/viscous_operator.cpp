#include "sphmol/time/viscous_operator.hpp"

#include <algorithm>
#include <stdexcept>

namespace sphmol {

void ViscousOperator::begin(std::size_t rows, int components, const std::uint32_t* row_capacity,
                            const std::uint32_t* order) {
  n_ = rows;
  dims_ = components;
  remote_.reset();
  stride_ = rows;
  start_.assign(row_capacity, row_capacity + rows);
  count_.assign(rows, 0);
  state_.resize(rows);
  for (std::size_t i = 0; i < rows; ++i) state_[i] = order ? order[i] : static_cast<std::uint32_t>(i);
  const std::size_t entries = rows > 0 ? row_capacity[rows] - row_capacity[0] : 0;
  if (rows > 0 && row_capacity[0] != 0)
    for (auto& s : start_) s -= row_capacity[0];
  col_.resize(entries);
  coef_.resize(entries);
  diag_.assign(rows, 0.0);
  b_.assign(size(), 0.0);
}

void ViscousOperator::finish_row(std::size_t i, std::uint32_t count, double diagonal, const double* b) {
  count_[i] = count;
  diag_[i] = diagonal;
  for (int d = 0; d < dims_; ++d) b_[i * static_cast<std::size_t>(dims_) + static_cast<std::size_t>(d)] = b[d];
}

void ViscousOperator::end() {
  diag_state_.resize(n_);
  b_state_.resize(size());
  for (std::size_t i = 0; i < n_; ++i) {
    diag_state_[state_[i]] = diag_[i];
    for (int d = 0; d < dims_; ++d)
      b_state_[static_cast<std::size_t>(d) * n_ + state_[i]] = b_[i * static_cast<std::size_t>(dims_) + static_cast<std::size_t>(d)];
  }
}

void ViscousOperator::owned_rows(const ViscousOperator& local, const std::vector<std::uint32_t>& row,
                                 const std::vector<std::uint32_t>& column, std::size_t rows,
                                 std::shared_ptr<const RemoteColumns> remote) {
  n_ = rows;
  dims_ = local.dims_;
  remote_ = std::move(remote);
  stride_ = rows + (remote_ ? remote_->size() : 0);
  start_.clear();
  count_.clear();
  state_.clear();
  col_.clear();
  coef_.clear();
  diag_.clear();
  b_.clear();
  const auto D = static_cast<std::size_t>(dims_);
  for (std::size_t i = 0; i < local.n_; ++i) {
    const std::uint32_t r = row[local.state_[i]];
    if (r == kNoRow) continue;
    start_.push_back(static_cast<std::uint32_t>(col_.size()));
    count_.push_back(local.count_[i]);
    state_.push_back(r);
    for (std::uint32_t k = local.start_[i]; k < local.start_[i] + local.count_[i]; ++k) {
      col_.push_back(column[local.col_[k]]);
      coef_.push_back(local.coef_[k]);
    }
    diag_.push_back(local.diag_[i]);
    b_.insert(b_.end(), local.b_.begin() + static_cast<std::ptrdiff_t>(i * D), local.b_.begin() + static_cast<std::ptrdiff_t>((i + 1) * D));
  }
  if (state_.size() != rows) throw std::logic_error("ViscousOperator::owned_rows: the local operator lacks owned rows");
  end();
}

void ViscousOperator::apply(const double* v, double* out) const {
  const std::size_t n = n_;
  const int D = dims_;
  // Columns index the block itself, or (with halo columns) a copy of it followed by the halo values.
  std::size_t stride = n;
  if (remote_) {
    ext_.resize(static_cast<std::size_t>(D) * stride_);
    for (int d = 0; d < D; ++d)
      std::copy(v + static_cast<std::size_t>(d) * n, v + static_cast<std::size_t>(d + 1) * n, ext_.data() + static_cast<std::size_t>(d) * stride_);
    remote_->fetch(v, n, D, ext_.data(), stride_);
    v = ext_.data();
    stride = stride_;
  }
  if (n == 0) return;
  switch (D) {
    case 1: apply_rows<1>(v, stride, out); break;
    case 2: apply_rows<2>(v, stride, out); break;
    case 3: apply_rows<3>(v, stride, out); break;
    default: throw std::logic_error("ViscousOperator: 1 to 3 components");
  }
}

// The D components' sums of a row advance together: each keeps its own order of additions (the
// same bits as one component at a time), but the D chains of dependent additions overlap, and each
// entry's column and coefficient are loaded once.
template <int D>
void ViscousOperator::apply_rows(const double* v, std::size_t stride, double* out) const {
  const std::size_t n = n_;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t s = state_[i];
    const std::uint32_t* c = col_.data() + start_[i];
    const double* a = coef_.data() + start_[i];
    const std::uint32_t m = count_[i];
    double sum[D] = {};
    for (std::uint32_t k = 0; k < m; ++k)
      for (int d = 0; d < D; ++d) sum[d] += a[k] * v[static_cast<std::size_t>(d) * stride + c[k]];
    for (int d = 0; d < D; ++d)
      out[static_cast<std::size_t>(d) * n + s] = diag_[i] * v[static_cast<std::size_t>(d) * stride + s] - sum[d];
  }
}

void ViscousOperator::apply_affine(const double* v, double* out) const {
  apply(v, out);
  const std::size_t m = size();
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < m; ++k) out[k] += b_state_[k];
}

std::size_t ViscousOperator::off_diagonal_entries() const {
  std::size_t total = 0;
  for (auto c : count_) total += c;
  return total;
}

}  // namespace sphmol
