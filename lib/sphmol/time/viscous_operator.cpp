#include "sphmol/time/viscous_operator.hpp"

#include <algorithm>

namespace sphmol {

void ViscousOperator::begin(std::size_t rows, int components, const std::uint32_t* row_capacity,
                            const std::uint32_t* order) {
  n_ = rows;
  dims_ = components;
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

void ViscousOperator::apply(const double* v, double* out) const {
  const std::size_t n = n_;
  const int D = dims_;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t s = state_[i];
    const std::uint32_t* c = col_.data() + start_[i];
    const double* a = coef_.data() + start_[i];
    const std::uint32_t m = count_[i];
    for (int d = 0; d < D; ++d) {
      const double* vd = v + static_cast<std::size_t>(d) * n;
      double sum = 0.0;
      for (std::uint32_t k = 0; k < m; ++k) sum += a[k] * vd[c[k]];
      out[static_cast<std::size_t>(d) * n + s] = diag_[i] * vd[s] - sum;
    }
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
