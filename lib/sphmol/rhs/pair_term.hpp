#pragma once
// A term that sums over each particle's active pairs, written as one row at a time so that it runs
// either over the stored active-pair list (apply) or inside a fused pass that evaluates the kernel
// for a row and hands the row to every term of the pass in turn (rhs/fused_pair_pass.hpp).
// Derived classes implement row_impl(w, i, row) and inherit both entry points through PairTermFor
// (CRTP), so the stored loop calls row_impl directly, with no virtual call per row.
#include <omp.h>
#include <utility>

#include "sphmol/rhs/kernel_pass.hpp"
#include "sphmol/rhs/pair_row.hpp"
#include "sphmol/rhs/row_schedule.hpp"
#include "sphmol/rhs/term.hpp"

namespace sphmol {

// Which rows a pair term sums: fluid particles, the dynamic wall particles (walls whose density is
// in the state), or every row of the list.
enum class PairRows { fluid, dynamic_walls, all };

template <int D>
std::pair<std::size_t, std::size_t> row_range(PairRows rows, const Workspace<D>& w) {
  switch (rows) {
    case PairRows::fluid: return {0, w.n_fluid};
    case PairRows::dynamic_walls: return {w.n_fluid, w.n_fluid + w.n_wall_density};
    case PairRows::all: return {0, w.n};
  }
  return {0, 0};
}

template <int D>
class PairTerm : public Term<D> {
 public:
  bool reads_stored_pairs() const override { return true; }
  virtual PairRows rows() const { return PairRows::fluid; }
  // True when a later term reads this term's output at neighbouring particles (summation density's
  // rho_j, the transport-velocity shift du_j): a fused pass must end after this term.
  virtual bool feeds_neighbours() const { return false; }
  // True when every per-pair contribution of the term is exactly zero for W = F = 0, as for a pair
  // beyond the kernel support: a fused pass whose terms all say so hands them every Verlet pair of the
  // row, skin pairs included, and skips compacting the row to the active pairs (rhs/kernel_pass.hpp).
  // Sums are unchanged bit for bit: adding a zero to a sum that starts at +0 changes nothing.
  virtual bool zero_beyond_support() const { return false; }
  // Once per evaluation, before any row (sizing per-particle scratch).
  virtual void prepare(Workspace<D>&) const {}
  // True when prepare() is written for every thread of a region to call together (as
  // Term::runs_in_team), which lets a fused pass run inside the system's region.
  virtual bool prepares_in_team() const { return false; }
  virtual void row(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const = 0;

  // Symmetric form (optional; rhs/fused_pair_pass.hpp, neighbors/pair_twins.hpp): the term's result
  // for a pair i-j follows from one record of numbers computed once for the pair, so a fused pass may
  // evaluate each fluid pair once instead of twice. The record must give exactly the numbers row()
  // adds for either direction, and the sums must run in row() order, so both forms agree bit for bit.
  // Doubles per record; 0: no symmetric form.
  virtual std::size_t pair_record_size() const { return 0; }
  // Whether this evaluation may use the records (read after prepare()'s barrier).
  virtual bool pair_records_now() const { return false; }
  // The records of fluid rows [i0, i1): row i's upper part (its Verlet entries j[k] > i, in order,
  // skin pairs included, whose F is 0) is vj[up[i] .. off[i + 1]), and its records go to
  // records[(first[i] + k) * pair_record_size()]. The term forms the separations with
  // kernel.geometry() and F with kernel.gradient_factors (a kernel pass with uniform_h()), in blocks,
  // so that no per-pair buffer is written and read back between the kernel and the term. A range of
  // rows per call, so that the term's choices for this evaluation are made once, not per row.
  virtual void pair_records(Workspace<D>&, std::size_t /*i0*/, std::size_t /*i1*/, const std::uint32_t* /*off*/,
                            const std::uint32_t* /*up*/, const std::uint32_t* /*vj*/, const std::uint32_t* /*first*/,
                            const KernelPass<D>&, double* /*records*/) const {}
  // Fluid row i from records: its n_lower lower pairs through twin[k] (record indices into `all`),
  // then its n_upper own records `upper`, in row order.
  virtual void sum_pair_records(Workspace<D>&, std::size_t, const std::uint32_t* /*twin*/, std::uint32_t /*n_lower*/,
                                const double* /*upper*/, std::uint32_t /*n_upper*/, const double* /*all*/) const {}
};

template <int D, class Derived>
class PairTermFor : public PairTerm<D> {
 public:
  void row(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const final {
    static_cast<const Derived*>(this)->row_impl(w, i, r);
  }
  // Over the stored list, called by every thread of the system's region (Term::runs_in_team): the
  // set-up in `single`, the term's preparation, the rows, and a barrier after them.
  bool runs_in_team() const final { return true; }
  void apply(Workspace<D>& w) const final {
    const bool team_prepare = this->prepares_in_team();
    const auto* self = static_cast<const Derived*>(this);
#pragma omp single
    {
      if (!team_prepare) this->prepare(w);
      const auto range = row_range(this->rows(), w);
      // Rows shared by their active pairs in contiguous ranges, with helping at the end (rhs/row_schedule.hpp).
      schedule_.reset(omp_get_num_threads(), 1);
      schedule_.place(0, w.pairs.offset.data(), range.first, range.second);
    }
    if (team_prepare) this->prepare(w);  // ends with a barrier
    schedule_.run(omp_get_thread_num(), [&](int, std::size_t i0, std::size_t i1) {
      for (std::size_t i = i0; i < i1; ++i) self->row_impl(w, i, stored_row(w, i));
    });
#pragma omp barrier
  }

 private:
  mutable RowSchedule schedule_;
};

}  // namespace sphmol
