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
};

}  // namespace sphmol
