// Over ranks the whole system is never evaluated and never builds a neighbour list: at output times
// (and probe sampling times) its fields come from the ranks' evaluations of their own particles
// (parallel/whole_fields.hpp). What rank 0 measures and writes with it stays the serial run's to
// the bit: the case's measurements at every output time, the conservation log, the probe files and
// the VTK pieces. The dam break (continuity density, wall densities in the state), a water column
// with ghost walls (the case reads pressure and density) and a tank with a block and probes (point,
// line, height gauge and the force on the block, which reads the walls' fields; sampled at output
// times and at their own times). Rank 0 runs the serial reference.
#include <unistd.h>

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/mpi_run.hpp"
#include "sphmol/run/run_case.hpp"
#include "run_into.hpp"
#include "support/files.hpp"
#include "support/vtk_pieces.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
namespace fs = std::filesystem;
using sphmol::parallel::testing::run_into;

namespace {

std::string source(const std::string& path) { return std::string(SPHMOL_SOURCE_DIR) + "/" + path; }

// The files a run wrote whose names start with `prefix`.
std::vector<std::string> files_named(const nlohmann::json& summary, const std::string& prefix) {
  std::vector<std::string> out;
  for (const auto& f : summary["files"]) {
    const std::string name = f.get<std::string>();
    if (name.rfind(prefix, 0) == 0) out.push_back(name);
  }
  return out;
}

// Runs c over the ranks and (rank 0) serially into temporary folders and compares. Returns the
// number of probe files compared (rank 0).
std::size_t check_whole_never_evaluated(const Config& c, const std::string& name, double rebalance = 1.2) {
  const Communicator comm;
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, rebalance);
  const long pid = comm.all_gather(static_cast<long>(::getpid()))[0];
  const fs::path dir = fs::temp_directory_path() / ("sphmol-whole-" + name + "-" + std::to_string(pid) + "-" + std::to_string(comm.size()));
  const nlohmann::json split = run_into(c, &partitioner, dir / "split");
  CHECK(split["status"] == "completed");
  std::size_t probes = 0;
  comm.barrier();
  if (comm.rank() == 0) {
    INFO(name << ", " << comm.size() << " ranks");
    // Summed over the ranks: no rank evaluates the whole scene or builds its neighbour list.
    CHECK(split["parallel"]["whole_scene_evaluations"].get<long>() == 0);
    CHECK(split["parallel"]["whole_scene_neighbour_rebuilds"].get<long>() == 0);
    const nlohmann::json serial = run_into(c, nullptr, dir / "serial");
    REQUIRE(serial["status"] == "completed");
    REQUIRE(serial["errors"].size() >= 2);
    CHECK(split["errors"] == serial["errors"]);
    CHECK(split["final_errors"] == serial["final_errors"]);
    CHECK(split["conservation"] == serial["conservation"]);
    CHECK(split["discretization"]["pair_list_radius"] == serial["discretization"]["pair_list_radius"]);
    const std::vector<std::string> probe_files = files_named(serial, "probe_");
    CHECK(files_named(split, "probe_") == probe_files);
    for (const auto& f : probe_files) {
      INFO(f);
      CHECK(test_support::slurp(dir / "split" / f) == test_support::slurp(dir / "serial" / f));
    }
    probes = probe_files.size();
    for (const auto& vtp : files_named(serial, "fluid_")) {
      if (vtp.size() < 4 || vtp.substr(vtp.size() - 4) != ".vtp") continue;
      const std::string pvtp = vtp.substr(0, vtp.size() - 4) + ".pvtp";
      INFO(pvtp);
      CHECK(vtk_pieces::difference(vtk_pieces::read_pvtp(dir / "split" / pvtp), vtk_pieces::read_vtp(dir / "serial" / vtp)) == "");
    }
  }
  comm.barrier();
  if (comm.rank() == 0) fs::remove_all(dir);
  return probes;
}

}  // namespace

TEST_CASE("distributed run: the whole system is never evaluated, and rank 0 measures and writes what the serial run does",
          "[parallel][run][whole_fields]") {
  const bool root = Communicator().rank() == 0;
  SECTION("the dam break, with VTK pieces") {
    check_whole_never_evaluated(load_config(source("verification/dam_break.yaml"),
                                            {"discretization.spacing=0.04", "time.t_end=0.06", "output.times=[0.03,0.06]",
                                             "output.plots=false", "output.vtk=true"}),
                                "dam");
  }
  SECTION("the dam break, partitioned again at every re-plan") {
    check_whole_never_evaluated(load_config(source("verification/dam_break.yaml"),
                                            {"discretization.spacing=0.04", "time.t_end=0.06", "output.times=[0.03,0.06]",
                                             "output.plots=false"}),
                                "dam-rebalanced", 1.0);
  }
  SECTION("a water column with ghost walls") {
    check_whole_never_evaluated(
        load_config(source("verification/hydrostatic.yaml"),
                    {"discretization.boundary=ghost", "discretization.wall_pressure=rest", "discretization.kernel=cubic_spline",
                     "discretization.smoothing_ratio=1.3", "discretization.density=summation", "discretization.density_diffusion=0",
                     "discretization.particle_mass=summation", "fluid.eos.clamp_negative=true",
                     "discretization.particles_across=20", "time.dt=5.0e-4", "time.t_end=0.05", "output.times=[0.025,0.05]",
                     "output.plots=false"}),
        "column-ghost");
  }
  SECTION("a tank with a block and probes") {
    // The example's scene with probes sampled at the output times and at their own times.
    std::string yaml = test_support::slurp(source("examples/tank_obstacle_2d.yaml"));
    yaml = yaml.substr(0, yaml.find("\nprobes:")) + R"(
probes:
  - {name: bottom, type: point, at: [0.15, 0.05], fields: [p, rho, velocity], every: 0.005}
  - {name: section, type: line, from: [0.05, 0.02], to: [0.55, 0.02], points: 7, fields: [p, rho, velocity]}
  - {name: surface, type: height_gauge, at: [0.15], every: 0.005}
  - {name: block, type: force, body: block}
  - {name: block_often, type: force, body: block, every: 0.005}
)";
    const Config c = load_config_string(yaml, {"discretization.spacing=0.02", "time.t_end=0.02", "output.times=[0.01,0.02]",
                                               "output.plots=false", "output.vtk=true"});
    const std::size_t probes = check_whole_never_evaluated(c, "tank-probes");
    CHECK((probes == 5 || !root));
  }
}
