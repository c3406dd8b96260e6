#pragma once
// Conserved quantities of the fluid at output times: total momentum sum_i m_i v_i per component
// and kinetic energy sum_i m_i |v_i|^2 / 2 (fluid particles only; walls are prescribed). Momentum is
// conserved only in periodic directions without walls or body forces acting along them, so the
// summary lists which directions are periodic and the drift P(t) - P(0) per component.
#include <array>
#include <nlohmann/json.hpp>
#include <vector>

#include "sphmol/rhs/sph_system.hpp"

namespace sphmol {

template <int D>
class ConservationLog {
 public:
  void record(const SphSystem<D>& sys, const double* y, double t) {
    const auto& L = sys.layout();
    const auto& m = sys.particles().mass;
    std::array<double, D> p{};
    double ke = 0.0;
    for (std::size_t i = 0; i < L.n; ++i) {
      double v2 = 0.0;
      for (int d = 0; d < D; ++d) {
        const double v = y[L.velocity(d) + i];
        p[d] += m[i] * v;
        v2 += v * v;
      }
      ke += 0.5 * m[i] * v2;
    }
    times_.push_back(t);
    momentum_.push_back(p);
    kinetic_.push_back(ke);
  }

  nlohmann::json to_json(const SphSystem<D>& sys) const {
    nlohmann::json j;
    j["times"] = times_;
    j["momentum"] = nlohmann::json::array();
    for (const auto& p : momentum_) j["momentum"].push_back(std::vector<double>(p.begin(), p.end()));
    j["kinetic_energy"] = kinetic_;
    std::vector<int> periodic;
    for (int d = 0; d < D; ++d)
      if (sys.domain().periodic[d]) periodic.push_back(d);
    j["periodic_directions"] = periodic;
    double mass = 0.0;
    for (std::size_t i = 0; i < sys.layout().n; ++i) mass += sys.particles().mass[i];
    j["fluid_mass"] = mass;
    if (momentum_.size() >= 2) {
      std::vector<double> drift(D);
      for (int d = 0; d < D; ++d) drift[d] = momentum_.back()[d] - momentum_.front()[d];
      j["momentum_drift"] = drift;
    }
    return j;
  }

 private:
  std::vector<double> times_;
  std::vector<std::array<double, D>> momentum_;
  std::vector<double> kinetic_;
};

}  // namespace sphmol
