#pragma once
// VTK XML PolyData output (ParaView, VisIt). At every output time one file per particle group:
// fluid_NNNN.vtp, walls_NNNN.vtp (output.vtk_walls, when the scene has wall particles) and
// ghosts_NNNN.vtp (output.vtk_ghosts, when ghost walls made images), and a particles.pvd collection
// that lists them with their physical time (`timestep`) and group (`part` 0 fluid, 1 walls,
// 2 ghosts), so ParaView shows each group as a block and can colour or hide it alone.
// Encoding: raw appended binary (`header_type="UInt64"`, little-endian): each array is a UInt64
// byte count followed by its values, exact for every double and about half the size of 17-digit
// ASCII (docs/output.md gives the measured sizes).
// Point data: `id` (the particle's index in the scene's initial particle set, the same in every
// output; ghosts -1: they are regenerated at every evaluation), `mass`, `velocity` (3 components,
// zero-padded below 3D), `density`, `pressure`, `kind` (0 fluid, 1 wall, 2 ghost); fluid files also
// carry each further state block of the layout (energy, h, ...) under its field name, an integrated
// density being the `density` array itself. Wall particles
// are where the solver places them (Particles::wall_position: belts such as a cavity lid stay put),
// ghosts as generated at the most recent RHS evaluation (the run loop evaluates the RHS at the written
// state first). Each file carries its time as the FieldData array `TimeValue`, which ParaView reads.
// Over several ranks (at_output_pieces) each rank writes the particles it owns as a piece,
// `fluid_NNNN_r<rank>.vtp`, and rank 0 a `fluid_NNNN.pvtp` naming the pieces (run/pvtp_file.hpp),
// which the collection then lists: the same particles and values as the serial file, split. A
// rank's ghost piece holds the images of the fluid particles it owns (not of its halo copies), so
// the pieces hold every serial image once, each piece in the serial order of its sources.
#include <cstdint>
#include <string>
#include <vector>

#include "sphmol/run/case.hpp"
#include "sphmol/run/pvtp_file.hpp"

namespace sphmol {

enum class VtkPart { fluid = 0, walls = 1, ghosts = 2 };

template <int D>
class VtkObserver final : public OutputObserver<D> {
 public:
  explicit VtkObserver(bool walls, bool ghosts = false) : walls_(walls), ghosts_(ghosts) {}
  void at_output(const SphSystem<D>& sys, const double* y, double t, const OutputSink& out) override;
  bool writes_pieces() const override { return true; }
  void at_output_pieces(const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t, const OutputSink& out) override;
  nlohmann::json save_state() const override;
  void restore_state(const nlohmann::json& state, const OutputSink& out) override;

 private:
  struct Entry {
    double t;
    int part;
    std::string file;
  };
  void write_collection(const OutputSink& out) const;  // particles.pvd
  bool walls_, ghosts_;
  std::vector<Entry> written_;  // every file so far, for the .pvd
  std::size_t outputs_ = 0;     // output times written (the NNNN of the file names)
};

// Number of particles of `part` in the state y (walls: the scene's wall particles; ghosts: the
// images of the most recent RHS evaluation).
template <int D>
std::size_t vtk_part_size(const SphSystem<D>& sys, VtkPart part);

// The .vtp content (XML header and raw appended binary data) of one part of the state y at time t
// (exposed for tests).
template <int D>
std::string vtp_file(const SphSystem<D>& sys, const double* y, double t, VtkPart part);

// A piece of one part: the rows `rows` of sys (all of that part) with the ids `ids`, in the arrays
// of the serial file (a fluid piece declares every state block, even with no fluid in sys).
template <int D>
std::string vtp_piece_file(const SphSystem<D>& sys, const double* y, double t, VtkPart part,
                           const std::vector<std::size_t>& rows, const std::vector<std::int64_t>& ids);

// The point arrays and points that a piece of `part` of sys declares (for the .pvtp).
template <int D>
VtkArrayLayout vtk_array_layout(const SphSystem<D>& sys, VtkPart part);

}  // namespace sphmol
