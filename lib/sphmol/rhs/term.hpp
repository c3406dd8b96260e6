#pragma once
// A term of the right-hand side: one pass over particles (and their pairs). The RHS is a list of
// terms chosen once per scene, so a term that is off costs nothing and no pair loop branches on
// configuration.
#include <string_view>

#include "sphmol/rhs/workspace.hpp"

namespace sphmol {

template <int D>
class Term {
 public:
  virtual ~Term() = default;
  virtual std::string_view name() const = 0;
  virtual void apply(Workspace<D>& w) const = 0;
  // True for a term that reads the stored active-pair list (Workspace::pairs). Pair terms written row
  // by row (rhs/pair_term.hpp) say true too but can also run in a fused pass instead.
  virtual bool reads_stored_pairs() const { return false; }
};

}  // namespace sphmol
