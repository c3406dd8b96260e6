// Per-rank VTK pieces (VtkObserver::at_output_pieces, run/pvtp_file.hpp) without MPI: one system's
// particles split into pieces as two ranks would own them, each piece written by its own observer,
// rank 0's .pvtp naming both. The pieces together are the serial .vtp (the tests' own reader,
// support/vtk_pieces.hpp), a rank that owns nothing writes an empty piece with the same arrays
// (further state blocks included), and the .pvd lists the .pvtp files.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "sphmol/cases/channel/channel_case.hpp"
#include "sphmol/cases/shock_tube/shock_tube_case.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/run/vtk_observer.hpp"
#include "support/vtk_pieces.hpp"

using namespace sphmol;
namespace fs = std::filesystem;

namespace {

// The piece of rank `rank` of `ranks`: the rows of sys that owns(row, rank) gives it.
template <int D>
OwnedPiece<D> piece_of(const SphSystem<D>& sys, const double* y, int rank, int ranks, bool (*owns)(std::size_t, int)) {
  OwnedPiece<D> p;
  p.system = &sys;
  p.y = y;
  p.rank = rank;
  p.ranks = ranks;
  p.barrier = [] {};
  const std::size_t nf = sys.particles().n_fluid, n = sys.particles().size();
  for (std::size_t i = 0; i < n; ++i)
    if (owns(i, rank)) {
      (i < nf ? p.fluid_rows : p.wall_rows).push_back(i);
      (i < nf ? p.fluid_ids : p.wall_ids).push_back(static_cast<std::int64_t>(i));
    }
  return p;
}

// Writes the pieces (rank 1 first, as any rank may finish first) and the serial files of sys.
template <int D>
void write_both(const SphSystem<D>& sys, const std::vector<double>& y, double t, const fs::path& dir,
                bool (*owns)(std::size_t, int)) {
  fs::create_directories(dir / "pieces");
  fs::create_directories(dir / "serial");
  const OutputSink pieces{(dir / "pieces").string(), true};
  VtkObserver<D> rank1(true), rank0(true);
  rank1.at_output_pieces(sys, piece_of(sys, y.data(), 1, 2, owns), t, OutputSink{(dir / "pieces").string(), true});
  rank0.at_output_pieces(sys, piece_of(sys, y.data(), 0, 2, owns), t, pieces);
  VtkObserver<D> serial(true);
  serial.at_output(sys, y.data(), t, OutputSink{(dir / "serial").string(), true});
  // Rank 0 lists both pieces and its .pvtp among the run's files.
  for (const char* f : {"fluid_0000_r0.vtp", "fluid_0000_r1.vtp", "fluid_0000.pvtp"})
    CHECK(std::find(pieces.written().begin(), pieces.written().end(), f) != pieces.written().end());
}

}  // namespace

TEST_CASE("vtk pieces: two ranks' pieces named by a .pvtp hold the serial file's particles", "[vtk][output][pieces]") {
  const fs::path dir = fs::temp_directory_path() / ("sphmol-vtk-pieces-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  ChannelCase c;
  auto sys = c.build(load_config_string(R"(case: couette
fluid: {density: 1000, kinematic_viscosity: 1.0e-6, eos: {sound_speed: 0.005}}
geometry: {channel_height: 1.0e-3, channel_length: 5.0e-4, wall_velocity: 2.5e-5}
discretization: {particles_across: 12}
time: {t_end: 0.1}
)"));
  std::vector<double> y = sys->initial_state(), ydot(y.size());
  const double t = 0.0125;
  sys->rhs(t, y.data(), ydot.data());
  // Interleaved ownership: every piece holds fluid and walls.
  write_both<2>(*sys, y, t, dir, [](std::size_t i, int r) { return static_cast<int>(i % 2) == r; });
  for (const std::string group : {"fluid", "walls"}) {
    INFO(group);
    const vtk_pieces::Particles split = vtk_pieces::read_pvtp(dir / "pieces" / (group + "_0000.pvtp"));
    const vtk_pieces::Particles whole = vtk_pieces::read_vtp(dir / "serial" / (group + "_0000.vtp"));
    CHECK(split.pieces == 2);
    CHECK(whole.values.size() > 10);
    CHECK(vtk_pieces::difference(split, whole) == "");
  }
  const auto pvd = mini_xml::parse(test_support::slurp(dir / "pieces" / "particles.pvd"));
  const auto sets = pvd->child("Collection")->all("DataSet");
  REQUIRE(sets.size() == 2);
  CHECK(sets[0]->attr.at("file") == "fluid_0000.pvtp");
  CHECK(sets[1]->attr.at("file") == "walls_0000.pvtp");
  CHECK(std::stod(sets[1]->attr.at("timestep")) == t);
  // A piece that misses a particle (or holds one twice) is not the serial file.
  const fs::path r1 = dir / "pieces" / "fluid_0000_r1.vtp";
  fs::copy_file(dir / "pieces" / "fluid_0000_r0.vtp", r1, fs::copy_options::overwrite_existing);
  CHECK_THROWS(vtk_pieces::read_pvtp(dir / "pieces" / "fluid_0000.pvtp"));
  fs::remove_all(dir);
}

TEST_CASE("vtk pieces: a rank that owns nothing writes an empty piece with the same arrays", "[vtk][output][pieces]") {
  const fs::path dir = fs::temp_directory_path() / ("sphmol-vtk-pieces-blocks-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  ShockTubeCase<1> c;
  auto sys = c.build(load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/shock_tube_1d.yaml"));
  std::vector<double> y = sys->initial_state(), ydot(y.size());
  sys->rhs(0.0, y.data(), ydot.data());
  REQUIRE(sys->layout().extra_blocks() >= 2);
  // Rank 1 owns nothing: empty pieces with the arrays of rank 0's.
  write_both<1>(*sys, y, 0.0, dir, [](std::size_t, int r) { return r == 0; });
  const vtk_pieces::Particles split = vtk_pieces::read_pvtp(dir / "pieces" / "fluid_0000.pvtp");
  const vtk_pieces::Particles whole = vtk_pieces::read_vtp(dir / "serial" / "fluid_0000.vtp");
  CHECK(split.pieces == 2);
  CHECK(vtk_pieces::read_vtp(dir / "pieces" / "fluid_0000_r1.vtp").values.empty());
  CHECK(vtk_pieces::difference(split, whole) == "");
  fs::remove_all(dir);
}
