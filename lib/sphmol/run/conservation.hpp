#pragma once
// Conserved quantities of the fluid at output times: total momentum sum_i m_i v_i per component,
// kinetic energy sum_i m_i |v_i|^2 / 2 and, when the state holds the specific internal energy e
// (energy equation, Niedoba 2012, eq 2.66), the total energy sum_i m_i (|v_i|^2 / 2 + e_i) (fluid
// particles only; walls are prescribed). Momentum is conserved only in periodic directions without
// walls or body forces acting along them, so the summary lists which directions are periodic and
// the drift P(t) - P(0) per component, also relative to the momentum scale sum_i m_i |v_i| (its
// maximum over the records). The total energy is conserved by the compressible formulation with
// fixed walls (the artificial-viscosity work, Niedoba 2012, eq 2.72, goes into e): its drift E(t) - E(0)
// and relative drift / E(0) are reported.
#include <algorithm>
#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "sphmol/rhs/sph_system.hpp"
#include "sphmol/run/piece_reduction.hpp"
#include "sphmol/run/whole_piece.hpp"

namespace sphmol {

// Sums over the fluid particles of the state y: mass, momentum, kinetic and internal energy, the sum
// of m |v| (the momentum scale) and the largest speed. Exact sums over the pieces of a run
// (run/piece_reduction.hpp): a serial run (one piece) and a run over any number of ranks have the
// same totals to the bit.
template <int D>
struct FluidTotals {
  std::array<double, D> momentum{};
  double mass = 0.0, kinetic = 0.0, internal = 0.0, momentum_scale = 0.0, max_speed = 0.0;
};

// Collective over the piece's ranks: the totals on every rank.
template <int D>
FluidTotals<D> fluid_totals(const OwnedPiece<D>& piece) {
  const auto& L = piece.system->layout();
  const auto& m = piece.system->particles().mass;
  const double* y = piece.y;
  PieceReduction r;
  std::array<PieceReduction::Slot, D> momentum{};
  for (int d = 0; d < D; ++d) momentum[d] = r.sum();
  const auto mass = r.sum(), kinetic = r.sum(), internal = r.sum(), scale = r.sum(), speed = r.largest();
  for (const std::size_t i : piece.fluid_rows) {
    double v2 = 0.0;
    for (int d = 0; d < D; ++d) {
      const double v = y[L.velocity(d) + i];
      r.add(momentum[d], m[i] * v);
      v2 += v * v;
    }
    const double s = std::sqrt(v2);
    r.add(mass, m[i]);
    r.add(kinetic, 0.5 * m[i] * v2);
    r.add(scale, m[i] * s);
    r.add(speed, s);
    if (L.has_energy) r.add(internal, m[i] * y[L.energy() + i]);
  }
  r.reduce(piece);
  FluidTotals<D> f;
  for (int d = 0; d < D; ++d) f.momentum[d] = r.value(momentum[d]);
  f.mass = r.value(mass);
  f.kinetic = r.value(kinetic);
  f.internal = r.value(internal);
  f.momentum_scale = r.value(scale);
  const double fastest = r.value(speed);
  f.max_speed = fastest < 0.0 ? 0.0 : fastest;  // no fluid: -infinity
  return f;
}

// The whole system's totals (serial: the run's one piece).
template <int D>
FluidTotals<D> fluid_totals(const SphSystem<D>& sys, const double* y) {
  return fluid_totals(whole_piece(sys, y));
}

template <int D>
class ConservationLog {
 public:
  // The log of a run starting at t from `start` (collective over its ranks: each rank's particles as
  // the run starts, run/start_piece.hpp): the fluid mass, the exact sum the measurements take
  // (run/piece_reduction.hpp), so the two agree to the bit, and the first record, without a rank
  // holding the whole scene.
  ConservationLog(const OwnedPiece<D>& start, double t) {
    fluid_mass_ = record_totals(start, t).mass;
  }
  void record(const SphSystem<D>& sys, const double* y, double t) { record(whole_piece(sys, y), t); }
  // Collective over the piece's ranks: every rank records the whole run's totals.
  void record(const OwnedPiece<D>& piece, double t) { record_totals(piece, t); }

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
    j["fluid_mass"] = fluid_mass_;
    j["momentum_scale"] = momentum_scale_;
    if (momentum_.size() >= 2) {
      std::vector<double> drift(D), rel(D);
      for (int d = 0; d < D; ++d) {
        drift[d] = momentum_.back()[d] - momentum_.front()[d];
        rel[d] = momentum_scale_ > 0.0 ? drift[d] / momentum_scale_ : 0.0;
      }
      j["momentum_drift"] = drift;
      j["momentum_drift_relative"] = rel;
    }
    if (!total_.empty()) {
      j["total_energy"] = total_;
      if (total_.size() >= 2) {
        const double drift = total_.back() - total_.front();
        j["total_energy_drift"] = drift;
        j["total_energy_drift_relative"] = total_.front() != 0.0 ? drift / std::abs(total_.front()) : 0.0;
      }
    }
    return j;
  }

 private:
  FluidTotals<D> record_totals(const OwnedPiece<D>& piece, double t) {
    const auto& L = piece.system->layout();
    const FluidTotals<D> f = fluid_totals(piece);
    const auto& p = f.momentum;
    const double ke = f.kinetic, scale = f.momentum_scale, internal = f.internal;
    times_.push_back(t);
    momentum_.push_back(p);
    kinetic_.push_back(ke);
    momentum_scale_ = std::max(momentum_scale_, scale);
    if (L.has_energy) total_.push_back(ke + internal);
    return f;
  }

  std::vector<double> times_;
  std::vector<std::array<double, D>> momentum_;
  std::vector<double> kinetic_;
  std::vector<double> total_;
  double momentum_scale_ = 0.0;
  double fluid_mass_ = 0.0;
};

}  // namespace sphmol
