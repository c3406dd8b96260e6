#pragma once
// A term of the right-hand side: one pass over particles (and their pairs). The RHS is a list of
// terms chosen once per scene, so a term that is off costs nothing and no pair loop branches on
// configuration.
//
// Dimensions: every term declares the dimensions its formula holds in (dimensions() below), and
// assemble_system rejects a term built in any other, naming the configuration key that chose it
// (require_dimension). The default is 1, 2 and 3: the pair sums are written per Cartesian direction
// and their formulas carry no dimension-specific constant, so a term overrides dimensions() only when
// its formula, calibration or data layout holds in some dimensions alone. Kernels declare theirs in
// kernels/registry.hpp (a kernel unavailable in D is rejected there).
#include <stdexcept>
#include <string>
#include <string_view>

#include "sphmol/rhs/workspace.hpp"

namespace sphmol {

// A set of dimensions among 1, 2 and 3.
class Dimensions {
 public:
  static constexpr Dimensions all() { return Dimensions(0b1110u); }
  static constexpr Dimensions only(int d) { return Dimensions(d >= 1 && d <= 3 ? 1u << d : 0u); }
  constexpr Dimensions operator|(Dimensions o) const { return Dimensions(bits_ | o.bits_); }
  constexpr bool contains(int d) const { return d >= 1 && d <= 3 && ((bits_ >> d) & 1u) != 0; }
  constexpr bool operator==(const Dimensions&) const = default;
  // "1, 2 or 3", "2", "2 or 3" ("none" for the empty set).
  std::string text() const {
    std::string s;
    int count = 0, seen = 0;
    for (int d = 1; d <= 3; ++d) count += contains(d) ? 1 : 0;
    for (int d = 1; d <= 3; ++d) {
      if (!contains(d)) continue;
      ++seen;
      if (seen > 1) s += seen == count ? " or " : ", ";
      s += std::to_string(d);
    }
    return count == 0 ? "none" : s;
  }

 private:
  explicit constexpr Dimensions(unsigned bits) : bits_(bits) {}
  unsigned bits_;  // bit d: valid in dimension d
};

template <int D>
class Term {
 public:
  virtual ~Term() = default;
  virtual std::string_view name() const = 0;
  virtual void apply(Workspace<D>& w) const = 0;
  // True for a term that reads the stored active-pair list (Workspace::pairs). Pair terms written row
  // by row (rhs/pair_term.hpp) say true too but can also run in a fused pass instead.
  virtual bool reads_stored_pairs() const { return false; }
  // The dimensions the term is valid in (see the top of this file).
  virtual Dimensions dimensions() const { return Dimensions::all(); }
  // The part of an implicit-explicit split f = f_E + f_I the term belongs to (time/viscous_operator.hpp).
  // Implicit: the viscous sum, linear in the fluid velocities at fixed positions, which records its
  // coefficients in Workspace::implicit when that is set instead of adding to dv/dt, and the wall
  // velocity models it reads. Every other term is explicit and always adds to the rates.
  virtual bool implicit() const { return false; }
  // True when apply() is written for every thread of an enclosing parallel region to call together:
  // orphaned `omp for` loops, serial parts in `omp single`, and a barrier before it returns, so its
  // results are visible to every thread. The system then runs such terms inside one region per
  // evaluation (each region start and end is a synchronisation that stalls when a thread is
  // descheduled). Called outside a region, such an apply() runs on one thread. False: apply() is
  // called by one thread, outside any region (it may open its own).
  virtual bool runs_in_team() const { return false; }
};

// Throws std::invalid_argument "KEY: 'NAME' is not available in DD (only in ...)" when `term` does not
// hold in D; `key` is the configuration key that chose the term (e.g. "discretization.viscosity").
template <int D>
void require_dimension(const Term<D>& term, std::string_view key) {
  const Dimensions dims = term.dimensions();
  if (dims.contains(D)) return;
  throw std::invalid_argument(std::string(key) + ": '" + std::string(term.name()) + "' is not available in " +
                              std::to_string(D) + "D (only in " + dims.text() + "D)");
}

}  // namespace sphmol
