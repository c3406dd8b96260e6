#pragma once
// Ideal-gas equation of state, Niedoba 2012, eq 2.73 (2.18): p = (gamma - 1) rho e, with the sound
// speed it implies, c = sqrt(gamma p / rho) = sqrt(gamma (gamma - 1) e), for the artificial
// viscosity and the CFL limit. Needs e, i.e. the energy equation. Walls use their fixed rho and e.
#include <cmath>

#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class IdealGasEos final : public Term<D> {
 public:
  explicit IdealGasEos(double gamma) : gamma_(gamma) {}
  std::string_view name() const override { return "eos_ideal_gas"; }
  bool runs_in_team() const override { return true; }  // one worksharing loop (Term::runs_in_team)
  void apply(Workspace<D>& w) const override {
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < w.n; ++i) {
      const double e = std::max(w.e[i], 0.0);  // a negative e (overshoot) would make c imaginary
      w.p[i] = (gamma_ - 1.0) * w.rho[i] * w.e[i];
      w.c[i] = std::sqrt(gamma_ * (gamma_ - 1.0) * e);
    }
  }

 private:
  double gamma_;
};

}  // namespace sphmol
