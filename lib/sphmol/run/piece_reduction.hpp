#pragma once
// Sums, largest and smallest values over the particles of a run's pieces (run/owned_piece.hpp) that
// do not depend on how the particles are split over ranks or ordered within them: a serial run (one
// piece, run/whole_piece.hpp) and a run over any number of ranks measure the same doubles, to the bit.
//
// Why: an ordinary floating-point sum rounds differently in another order, and a run over ranks
// would add its particles in another order than the serial run (by rank, then by row).
//
// How: each sum's terms are put on the integer grid of its largest |term| and added as integers
// (time/fixed_point_norm.hpp: the largest by a max, then the chunks by an integer sum, both exact
// in any order); the integer sum is rounded to a double once, so the result is the exact sum up to
// the terms' parts below 2^-96 of the largest (a relative error of at most N 2^-96). Largest and
// smallest values are maxima, exact in any order. A whole measurement takes two collectives, one
// max and one integer sum, however many quantities it reduces.
//
// Values that are not finite: a sum with a NaN term, or with both +inf and -inf terms, is NaN; with
// +inf (-inf) terms only, +inf (-inf). A largest or smallest value over NaN values is NaN; over no
// values -inf (largest) or +inf (smallest).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "sphmol/run/owned_piece.hpp"
#include "sphmol/time/fixed_point_norm.hpp"

namespace sphmol {

class PieceReduction {
 public:
  using Slot = std::size_t;
  // New quantities; the same on every rank, in the same order.
  Slot sum() { return add_slot(Kind::sum); }
  Slot largest() { return add_slot(Kind::largest); }
  Slot smallest() { return add_slot(Kind::smallest); }
  // Slots of each kind at once (bins of a profile).
  Slot sums(std::size_t n) {
    const Slot first = slots_.size();
    for (std::size_t k = 0; k < n; ++k) add_slot(Kind::sum);
    return first;
  }

  // A term of a sum, or a value of a largest / smallest, from this rank's particles.
  void add(Slot s, double v) {
    Quantity& q = slots_.at(s);
    if (q.kind == Kind::sum) {
      q.terms.push_back(v);
    } else if (std::isnan(v)) {
      q.nan = true;
    } else {
      q.value = q.kind == Kind::largest ? std::max(q.value, v) : std::min(q.value, v);
    }
  }

  // Collective over the piece's ranks (every rank with the same slots): afterwards value() is the
  // whole run's on every rank.
  void reduce(const PieceCollectives& piece) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    // One max over: per sum, the largest |term| (finite) and whether a NaN, +inf or -inf term was
    // seen; per largest / smallest, the value (the smallest negated) and whether a NaN was seen.
    std::vector<double> local;
    local.reserve(4 * slots_.size());
    for (const Quantity& q : slots_) {
      if (q.kind == Kind::sum) {
        double largest = 0.0;
        bool nan = false, plus = false, minus = false;
        for (const double v : q.terms) {
          if (std::isnan(v)) nan = true;
          else if (v == inf) plus = true;
          else if (v == -inf) minus = true;
          else largest = std::max(largest, std::abs(v));
        }
        local.insert(local.end(), {largest, nan ? 1.0 : 0.0, plus ? 1.0 : 0.0, minus ? 1.0 : 0.0});
      } else {
        local.insert(local.end(), {q.kind == Kind::largest ? q.value : -q.value, q.nan ? 1.0 : 0.0});
      }
    }
    const std::vector<double> all = local.empty() ? local : piece.max_each(local);
    if (all.size() != local.size()) throw std::logic_error("PieceReduction: the ranks' quantities differ");
    // Then one integer sum of the chunks of every finite, non-zero sum.
    std::vector<std::uint64_t> chunks;
    std::vector<int> shifts(slots_.size(), 0);
    std::size_t at = 0;
    for (std::size_t s = 0; s < slots_.size(); ++s) {
      Quantity& q = slots_[s];
      if (q.kind != Kind::sum) {
        const double v = q.kind == Kind::largest ? all[at] : -all[at];
        q.result = all[at + 1] != 0.0 ? std::numeric_limits<double>::quiet_NaN() : v;
        at += 2;
        continue;
      }
      const double largest = all[at];
      const bool nan = all[at + 1] != 0.0, plus = all[at + 2] != 0.0, minus = all[at + 3] != 0.0;
      at += 4;
      if (nan || (plus && minus)) q.result = std::numeric_limits<double>::quiet_NaN();
      else if (plus) q.result = inf;
      else if (minus) q.result = -inf;
      else if (largest == 0.0) q.result = 0.0;
      else {
        // Non-finite terms are excluded above: none is left on any rank.
        shifts[s] = fixed_point_shift(largest);
        const FixedPointChunks c = fixed_point_values(q.terms.data(), q.terms.size(), shifts[s]);
        chunks.insert(chunks.end(), c.begin(), c.end());
        q.pending = true;
      }
    }
    const std::vector<std::uint64_t> summed = chunks.empty() ? chunks : piece.sum_each(chunks);
    if (summed.size() != chunks.size()) throw std::logic_error("PieceReduction: the ranks' sums differ");
    at = 0;
    for (std::size_t s = 0; s < slots_.size(); ++s) {
      Quantity& q = slots_[s];
      if (!q.pending) continue;
      q.result = fixed_point_sum({summed[at], summed[at + 1], summed[at + 2]}, shifts[s]);
      q.pending = false;
      at += 3;
    }
    reduced_ = true;
  }

  // After reduce(): the whole run's quantity.
  double value(Slot s) const {
    if (!reduced_) throw std::logic_error("PieceReduction::value before reduce");
    return slots_.at(s).result;
  }

 private:
  enum class Kind { sum, largest, smallest };
  struct Quantity {
    Kind kind;
    std::vector<double> terms;  // sum: this rank's terms
    double value = 0.0;         // largest / smallest: of this rank's values
    bool nan = false, pending = false;
    double result = 0.0;
  };
  Slot add_slot(Kind k) {
    Quantity q{k, {}};
    q.value = k == Kind::largest ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
    slots_.push_back(std::move(q));
    reduced_ = false;
    return slots_.size() - 1;
  }
  std::vector<Quantity> slots_;
  bool reduced_ = false;
};

}  // namespace sphmol
