#pragma once
// Repulsive virtual boundary particles of Lennard-Jones type, Niedoba 2012, eq 2.76 (Monaghan
// 1994):
//   F_ij = D [ (r0/r)^p1 - (r0/r)^p2 ] x_ij / r^2   for r <= r0,   0 for r > r0,
// added to the acceleration of fluid particle i for every virtual (wall) particle j. D [m^2/s^2] is of
// the order of the largest squared velocity (g H for a water column); p1 > p2 (12 and 4 after Monaghan,
// 9.5 and 4 in Niedoba 2012, §3.3). The virtual particles are massless walls (scenes place them),
// so this is the only way they act: they add nothing to density sums, pressure or viscous terms.
// A scene's repulsive wall bodies (Particles::body_repulsion) each carry their own law; the pairs
// with the particles of other walls then see a law with r0 = 0, which exerts nothing.
#include <algorithm>
#include <cmath>
#include <vector>

#include "sphmol/core/particles.hpp"

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
  // One law for every wall particle (boundary: virtual_repulsive).
  explicit RepulsiveBoundary(RepulsiveLaw law) : law_(law) {}
  // Per wall body (Particles::body_repulsion, indexed by body; body_count: Particles::body_count()):
  // only the particles of bodies with r0 > 0 repel; walls of no body, or past `bodies`, do not.
  RepulsiveBoundary(const std::vector<BodyRepulsion>& bodies, std::size_t body_count) : per_body_(true) {
    laws_.assign(std::max(bodies.size(), body_count) + 1, RepulsiveLaw{0.0, 12.0, 4.0, 0.0});
    for (std::size_t b = 0; b < bodies.size(); ++b)
      laws_[b + 1] = RepulsiveLaw{bodies[b].strength, bodies[b].p1, bodies[b].p2, bodies[b].r0};
  }
  std::string_view name() const override { return per_body_ ? "repulsive_bodies" : "repulsive_boundary"; }
  bool reads_stored_pairs() const override { return true; }
  void apply(Workspace<D>& w) const override {
    if (!per_body_) return run(w, [this](std::uint32_t) -> const RepulsiveLaw& { return law_; });
    const std::int32_t* body = w.particles->body.data();
    run(w, [this, body](std::uint32_t j) -> const RepulsiveLaw& { return laws_[static_cast<std::size_t>(body[j] + 1)]; });
  }

 private:
  template <class LawOf>
  void run(Workspace<D>& w, LawOf law_of) const {
    const auto& P = w.pairs;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < w.n_fluid; ++i) {
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
        const std::uint32_t j = P.j[k];
        if (j < w.n_fluid) continue;  // rows are sorted: walls form the tail
        double r2 = 0.0;
        for (int d = 0; d < D; ++d) r2 += w.dx[d][k] * w.dx[d][k];
        const double s = law_of(j).factor(std::sqrt(r2));
        for (int d = 0; d < D; ++d) w.dvdt[d][i] += s * w.dx[d][k];
      }
    }
  }

  RepulsiveLaw law_;
  std::vector<RepulsiveLaw> laws_;  // laws_[body + 1]
  bool per_body_ = false;
};

}  // namespace sphmol
