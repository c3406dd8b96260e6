#pragma once
// The implicit part of an implicit-explicit (IMEX) split of the particle ODE, f = f_E + f_I, for the
// fluid velocities: at fixed positions and densities the Morris, Fox & Zhu (1997) viscous sum is
// affine in the fluid velocities,
//   f_I,i = sum_j c_ij (v_i - v_j) = L v + b,
// the same scalar matrix L for each Cartesian component, with b the contribution of the wall
// particles' (prescribed) velocities. The implicit terms record L and b row by row during an
// evaluation (Workspace::implicit, rhs/term.hpp); the integrators (time/arkode_imex.hpp,
// time/leapfrog_imex.hpp) apply L, its diagonal (Jacobi preconditioner) and b. Rows are kept in the
// evaluation's workspace order with state indices, so an operator stays valid after later evaluations
// reorder the workspace.
//
// Vectors are velocity blocks in state layout: component d of fluid particle i at d * rows() + i.
//
// Over MPI ranks a rank's operator holds the rows of its owned fluid particles, taken from the
// operator its local system recorded over owned and halo particles (owned_rows); its columns are
// the owned rows' velocities and, after them, halo values that apply() fetches from their owners
// (time/remote_columns.hpp).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "sphmol/time/remote_columns.hpp"

namespace sphmol {

class ViscousOperator {
 public:
  // Before an evaluation records into it: `rows` fluid particles, `components` = D, the capacity of
  // each workspace row (offsets of the pair list the rows are drawn from, rows + 1 entries) and the
  // workspace -> state index map (null: identity).
  void begin(std::size_t rows, int components, const std::uint32_t* row_capacity, const std::uint32_t* order);
  // Recording (by the implicit terms, one thread per row): row i (workspace index) starts its
  // off-diagonal entries at first(i); the term writes columns (state indices) and coefficients c_ij,
  // then finish_row with the entry count, the diagonal sum_j c_ij and b_i (components() values).
  std::uint32_t first(std::size_t i) const { return start_[i]; }
  std::uint32_t* columns() { return col_.data(); }
  double* coefficients() { return coef_.data(); }
  void finish_row(std::size_t i, std::uint32_t count, double diagonal, const double* b);
  // After the evaluation: the diagonal in state order (Jacobi preconditioner).
  void end();
  // The rows of `local` whose state index s has row[s] != kNoRow, as rows row[s] of this operator
  // (`rows` of them), in local's order and with their entries in local's order (the same sums);
  // column c of local becomes column[c], which is a row of this operator or rows + h for the h-th
  // column of `remote`.
  static constexpr std::uint32_t kNoRow = ~std::uint32_t{0};
  void owned_rows(const ViscousOperator& local, const std::vector<std::uint32_t>& row, const std::vector<std::uint32_t>& column,
                  std::size_t rows, std::shared_ptr<const RemoteColumns> remote);
  // The halo columns (null: every column is a row of this operator).
  const RemoteColumns* remote() const { return remote_.get(); }

  std::size_t rows() const { return n_; }
  int components() const { return dims_; }
  std::size_t size() const { return n_ * static_cast<std::size_t>(dims_); }
  bool empty() const { return n_ == 0; }
  // out = L v (v and out: velocity blocks, not aliased). Collective when remote() is set.
  void apply(const double* v, double* out) const;
  // out = L v + b.
  void apply_affine(const double* v, double* out) const;
  // diag(L) per fluid particle, in state order (the same for every component).
  const std::vector<double>& diagonal() const { return diag_state_; }
  // b in velocity-block layout.
  const std::vector<double>& affine() const { return b_state_; }
  // Entries of L that are not on the diagonal (nonzeros of one component's matrix).
  std::size_t off_diagonal_entries() const;

 private:
  template <int D>
  void apply_rows(const double* v, std::size_t stride, double* out) const;

  std::size_t n_ = 0;
  int dims_ = 0;
  std::vector<std::uint32_t> start_, count_, state_;  // per workspace row: first entry, entries, state index
  std::vector<std::uint32_t> col_;
  std::vector<double> coef_, diag_, b_;  // b_: per workspace row, components() values
  std::vector<double> diag_state_, b_state_;
  std::shared_ptr<const RemoteColumns> remote_;
  std::size_t stride_ = 0;           // of a component in the vector the columns index: rows + halo columns
  mutable std::vector<double> ext_;  // that vector, when there are halo columns
};

}  // namespace sphmol
