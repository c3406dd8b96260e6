#pragma once
// VTK XML PolyData output (ParaView, VisIt): one particles_NNNN.vtp per output time and a
// particles.pvd collection listing them with their physical times. ASCII with 17 significant
// digits: readable and diffable, exact round trip of every double, no base64/endianness handling;
// the files are larger than binary ones, which is fine at the particle counts this code runs.
// Fields: every per-particle quantity the system exposes — position and velocity (3 components,
// zero-padded below 3D), density, pressure, kind (0 fluid, 1 wall, 2 ghost), then each further state
// block of the layout (energy, h, ... as other scenes add them) under its field name (walls and
// ghosts: 0). Ghost (mirror) particles are those generated at the most recent RHS evaluation
// (output.vtk_ghosts; the run loop evaluates the RHS at the written state first), after the walls.
#include <string>
#include <utility>
#include <vector>

#include "sphmol/run/case.hpp"

namespace sphmol {

template <int D>
class VtkObserver final : public OutputObserver<D> {
 public:
  explicit VtkObserver(bool walls, bool ghosts = false) : walls_(walls), ghosts_(ghosts) {}
  void at_output(const SphSystem<D>& sys, const double* y, double t, const OutputSink& out) override;
  nlohmann::json save_state() const override;
  void restore_state(const nlohmann::json& state, const OutputSink& out) override;

 private:
  bool walls_, ghosts_;
  std::vector<std::pair<double, std::string>> written_;  // (time, file) for the .pvd
};

// The .vtp text of the state y at time t (exposed for tests).
template <int D>
std::string vtp_text(const SphSystem<D>& sys, const double* y, double t, bool walls, bool ghosts = false);

}  // namespace sphmol
