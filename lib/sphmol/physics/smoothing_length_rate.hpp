#pragma once
// Smoothing length as an ODE, Niedoba 2012, eq 2.68 (Benz 1989):
//   dh_i/dt = -(1/D) (h_i / rho_i) drho_i/dt
// Runs after the density rate (continuity density) in the term list; h is part of the state.
#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class SmoothingLengthRate final : public Term<D> {
 public:
  std::string_view name() const override { return "smoothing_length_rate"; }
  void apply(Workspace<D>& w) const override {
    for (std::size_t i = 0; i < w.n_fluid; ++i) w.dhdt[i] = -w.hs[i] / (D * w.rho[i]) * w.drhodt[i];
  }
};

}  // namespace sphmol
