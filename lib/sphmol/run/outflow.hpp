#pragma once
// Outflow: a fluid particle found outside the domain along a non-periodic axis at the end of an
// accepted step has left through a face open to outflow (Domain::outflow: the scene's open axes and
// faces, the open top of a tank; beyond a closed face the health check ends the run as blown up).
// It is taken out of the simulation, as DualSPHysics excludes its "out" particles (Domínguez et al. 2022): its velocity is set to zero and SphSystem::
// retire() keeps it out of every pair (neighbour lists, ghost images, wall extrapolation) and zeroes
// its rates, so it stays frozen where it left, with its mass in the state. The run then starts its
// integrator again at (t, y) (Integrator::restart): between two such events f(t, y) stays a pure
// function of the state.
// The set taken out follows from the state alone: a particle taken out sits frozen outside the
// domain, and every other one is inside at each step's end (the run takes the leavers out right
// after the step). So a restart from a checkpoint takes out the particles outside the domain before
// its first evaluation, and needs no field of its own.
// An open tank that loses much of its fluid is not a sound run: beyond health.max_outflow_fraction
// of the fluid mass the run ends as blown up.
// Walls are not in the state and never leave.
// Over MPI ranks every rank keeps an Outflow of the whole scene: the ranks' health checks gather the
// global ids and masses of the particles that left in a step (parallel/distributed_health_check.hpp),
// every rank takes those out of the whole system's record with take_out(sys, leaving, masses, t) (the
// same count, masses added in the same order, the same first exit and the same BlowUp past the limit
// on every rank as in the serial run), and each rank takes them out of its own particles and their
// halo copies (PartitionedRun::take_out).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "sphmol/rhs/sph_system.hpp"
#include "sphmol/run/owned_piece.hpp"
#include "sphmol/time/fixed_point_norm.hpp"
#include "sphmol/time/blow_up.hpp"

namespace sphmol {

// The fluid particles (state indices, ascending) outside the domain along a non-periodic axis that
// have not been taken out yet. The health check has passed the step, so each is beyond a face open to
// outflow (Domain::outflow) and none beyond a closed one.
template <int D>
std::vector<std::size_t> fluid_outside_domain(const SphSystem<D>& sys, const double* y) {
  const auto& L = sys.layout();
  const auto& dom = sys.domain();
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < L.n; ++i) {
    if (sys.is_retired(i)) continue;
    for (int d = 0; d < D; ++d)
      if (dom.outside(d, y[L.position(d) + i])) {
        out.push_back(i);
        break;
      }
  }
  return out;
}

template <int D>
class Outflow {
 public:
  // max_fraction: health.max_outflow_fraction, of the fluid mass M of the scene (the exact sum of
  // the fluid's masses, as the conservation log's: over ranks from the ranks' starting particles,
  // run/conservation.hpp's fluid_totals, for which no rank needs the whole scene).
  Outflow(double fluid_mass, double max_fraction) : max_fraction_(max_fraction), fluid_mass_(fluid_mass) {}
  Outflow(const SphSystem<D>& sys, double max_fraction)
      : Outflow(fixed_point_total(sys.particles().mass.data(), sys.layout().n), max_fraction) {}
  // Takes out the fluid outside the domain at (t, y): velocities zeroed in y, SphSystem::retire().
  // Returns whether any particle was taken out; the caller then restarts the integrator. Throws
  // BlowUp once more than max_fraction of the fluid mass has left.
  bool take_out(SphSystem<D>& sys, double* y, double t) {
    const std::vector<std::size_t> leaving = fluid_outside_domain(sys, y);
    const auto& L = sys.layout();
    for (const std::size_t i : leaving)
      for (int d = 0; d < D; ++d) y[L.velocity(d) + i] = 0.0;
    return take_out(sys, leaving, t);
  }
  // The state the run starts from (a checkpoint's), whose particles outside the domain left before
  // it: counted apart, with no exit time of this run. Collective over the ranks of `start`, the
  // rank's particles as the run starts (run/start_piece.hpp): each rank finds those among its own
  // particles; every rank receives all of them, by global id in ascending order with their masses,
  // counts them as the serial run does, and takes those its system holds out of it (a share: its own
  // rows), zeroing their velocities in y (sys's own state). Over ranks the partition then carries
  // their kind to the ranks' particles.
  bool take_out_at_start(SphSystem<D>& sys, double* y, const OwnedPiece<D>& start, double t) {
    const auto& L = sys.layout();
    const auto& dom = sys.domain();
    const auto& m = sys.particles().mass;
    struct Leaver {
      std::uint64_t id;
      double mass;
    };
    std::vector<Leaver> mine;
    for (std::size_t k = 0; k < start.fluid_rows.size(); ++k) {
      const std::size_t i = start.fluid_rows[k];
      if (sys.is_retired(i)) continue;
      for (int d = 0; d < D; ++d)
        if (dom.outside(d, y[L.position(d) + i])) {
          mine.push_back({static_cast<std::uint64_t>(start.fluid_ids[k]), m[i]});
          break;
        }
    }
    std::vector<std::byte> bytes(mine.size() * sizeof(Leaver));
    if (!mine.empty()) std::memcpy(bytes.data(), mine.data(), bytes.size());
    bytes = start.all_gather_bytes(bytes);  // in rank order: ascending ids
    std::vector<Leaver> all(bytes.size() / sizeof(Leaver));
    if (!all.empty()) std::memcpy(all.data(), bytes.data(), bytes.size());
    std::vector<std::size_t> leaving, rows;
    std::vector<double> masses;
    const std::size_t first = sys.whole_scene().first;
    for (const Leaver& l : all) {
      leaving.push_back(static_cast<std::size_t>(l.id));
      masses.push_back(l.mass);
      if (l.id < first || l.id - first >= L.n) continue;
      rows.push_back(static_cast<std::size_t>(l.id - first));
      for (int d = 0; d < D; ++d) y[L.velocity(d) + rows.back()] = 0.0;
    }
    sys.retire(rows);
    return count(leaving, masses, t, true);
  }
  // The same for particles found to have left elsewhere: `leaving`, fluid state indices in ascending
  // order, not taken out yet (over ranks: the global ids the ranks' checks found, whose velocities
  // each rank zeroes in its own state). y is not touched.
  bool take_out(SphSystem<D>& sys, const std::vector<std::size_t>& leaving, double t) {
    const auto& m = sys.particles().mass;
    std::vector<double> masses(leaving.size());
    for (std::size_t k = 0; k < leaving.size(); ++k) masses[k] = m[leaving[k]];
    return take_out(sys, leaving, masses, t);
  }
  // The same with the leavers' masses given, in the same order: over ranks they come from their
  // owners, since only rank 0 keeps the whole scene's particles (SphSystem::release_particles).
  bool take_out(SphSystem<D>& sys, const std::vector<std::size_t>& leaving, const std::vector<double>& masses, double t) {
    if (leaving.empty()) return false;
    sys.retire(leaving);
    return count(leaving, masses, t, false);
  }
  std::size_t count() const { return count_; }
  double fraction() const { return fluid_mass_ > 0.0 ? mass_ / fluid_mass_ : 0.0; }
  // The summary's "outflow" object.
  // t_first and first_particle: the first exit during this run (null when none; a restart's
  // particles out at its start are counted in at_start).
  nlohmann::json to_json() const {
    const bool exit = count_ > at_start_;
    return {{"particles", count_},
            {"at_start", at_start_},
            {"mass", mass_},
            {"mass_fraction", fraction()},
            {"max_mass_fraction", max_fraction_},
            {"t_first", exit ? nlohmann::json(t_first_) : nlohmann::json(nullptr)},
            {"first_particle", exit ? nlohmann::json(first_) : nlohmann::json(nullptr)}};
  }
  // The summary's warning when fluid has left ("" when none has).
  std::string warning() const {
    if (count_ == 0) return "";
    char buf[320];
    if (count_ == at_start_)
      std::snprintf(buf, sizeof buf,
                    "outflow: %zu fluid particle(s) (%.4g of the fluid mass) had left the domain before the run's "
                    "start; they stay out of the run, frozen where they left (summary \"outflow\")",
                    count_, fraction());
    else
      std::snprintf(buf, sizeof buf,
                    "outflow: %zu fluid particle(s) (%.4g of the fluid mass) left the domain, the first at t = %g s; "
                    "they were taken out of the run and stay frozen where they left (summary \"outflow\")",
                    count_, fraction(), t_first_);
    return buf;
  }

 private:
  // Counts the particles `leaving` (ascending ids) with their masses; BlowUp past the limit.
  bool count(const std::vector<std::size_t>& leaving, const std::vector<double>& masses, double t, bool at_start) {
    if (leaving.empty()) return false;
    if (masses.size() != leaving.size()) throw std::invalid_argument("Outflow::take_out: one mass per particle");
    for (const double m : masses) mass_ += m;  // in index order, as any rank count adds them
    if (at_start) {
      at_start_ += leaving.size();
    } else if (count_ == at_start_) {
      t_first_ = t;
      first_ = leaving.front();
    }
    count_ += leaving.size();
    if (fraction() > max_fraction_) {
      char buf[320];
      std::snprintf(buf, sizeof buf,
                    "outflow: %zu fluid particle(s), %.4g of the fluid mass, left the domain, more than "
                    "health.max_outflow_fraction = %g (an open tank losing that much is not a sound run)",
                    count_, fraction(), max_fraction_);
      throw BlowUp(t, static_cast<long>(leaving.front()), buf);
    }
    return true;
  }

  double max_fraction_;
  double fluid_mass_ = 0.0, mass_ = 0.0;
  std::size_t count_ = 0, first_ = 0, at_start_ = 0;
  double t_first_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace sphmol
