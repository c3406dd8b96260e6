#pragma once
// Repulsive virtual boundary particles of Lennard-Jones type, Niedoba 2012, eq 2.76 (Monaghan
// 1994):
//   F_ij = D [ (r0/r)^p1 - (r0/r)^p2 ] x_ij / r^2   for r <= r0,   0 for r > r0,
// added to the acceleration of fluid particle i for every virtual (wall) particle j. D [m^2/s^2] is of
// the order of the largest squared velocity (g H for a water column); p1 > p2 (12 and 4 after Monaghan,
// 9.5 and 4 in Niedoba 2012, §3.3). The virtual particles are massless walls (scenes place them),
// so this is the only way they act: they add nothing to density sums, pressure or viscous terms.
#include <cmath>

#include "sphmol/rhs/term.hpp"

namespace sphmol {

struct RepulsiveLaw {
  double D = 0.0, p1 = 12.0, p2 = 4.0, r0 = 0.0;
  // Force per unit mass divided by r (so that F = factor(r) * x_ij); 0 outside r0.
  double factor(double r) const {
    if (r <= 0.0 || r > r0) return 0.0;
    const double q = r0 / r;
    return D * (std::pow(q, p1) - std::pow(q, p2)) / (r * r);
  }
};

template <int D>
class RepulsiveBoundary final : public Term<D> {
 public:
  explicit RepulsiveBoundary(RepulsiveLaw law) : law_(law) {}
  std::string_view name() const override { return "repulsive_boundary"; }
  bool reads_stored_pairs() const override { return true; }
  void apply(Workspace<D>& w) const override {
    const auto& P = w.pairs;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < w.n_fluid; ++i) {
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
        const std::uint32_t j = P.j[k];
        if (j < w.n_fluid) continue;  // rows are sorted: walls form the tail
        double r2 = 0.0;
        for (int d = 0; d < D; ++d) r2 += w.dx[d][k] * w.dx[d][k];
        const double s = law_.factor(std::sqrt(r2));
        for (int d = 0; d < D; ++d) w.dvdt[d][i] += s * w.dx[d][k];
      }
    }
  }

 private:
  RepulsiveLaw law_;
};

}  // namespace sphmol
