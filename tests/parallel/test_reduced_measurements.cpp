// The case's measurements and the conservation sums over ranks from each rank's own particles
// (Case::measure_pieces, run/piece_reduction.hpp): exact sums over the ranks, so the summary's
// errors and conservation log are the serial run's to the bit on any rank count, and an output time
// gathers neither the whole state nor the whole fields when the case measures from pieces and every
// observer writes pieces (VTK) or samples from them (probes, at their own times and at the output
// times); only the end still gathers the whole state (for the final observers and the final state).
// Rank 0 runs the serial references.
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
#include "serial_reference.hpp"
#include "short_shock_tube.hpp"
#include "support/files.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
using namespace sphmol::parallel::testing;
namespace fs = std::filesystem;

namespace {

// c over the ranks and (rank 0) serially: the same measurements and conservation log, to the bit
// (JSON numbers compare as doubles). Returns the summary over the ranks.
nlohmann::json check_measurements_equal_serial(const Config& c) {
  const Communicator comm;
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, 1.2);
  const Finished split = run(c, &partitioner);
  REQUIRE(split.summary["status"] == "completed");
  if (comm.rank() == 0) {
    INFO(c.case_name << ", " << comm.size() << " ranks");
    const Finished& serial = serial_run(c);
    REQUIRE(serial.summary["status"] == "completed");
    CHECK(same_bits(split.y, serial.y));
    CHECK(split.summary["errors"].size() == c.output.times.size());
    CHECK(split.summary["errors"] == serial.summary["errors"]);
    CHECK(split.summary["final_errors"] == serial.summary["final_errors"]);
    CHECK(split.summary["conservation"] == serial.summary["conservation"]);
  }
  return split.summary;
}

Config taylor_green() {
  return load_config(verification("taylor_green.yaml"), {"discretization.particles_across=24", "time.t_end=0.06",
                                                         "output.times=[0.02,0.04,0.06]", "output.plots=false"});
}

Config channel(const std::string& file) {
  return load_config(verification(file), {"discretization.particles_across=20", "time.integrator=leapfrog", "time.t_end=0.03",
                                          "output.times=[0.01,0.02,0.03]", "output.plots=false"});
}

Config beltrami() {
  return load_config(verification("beltrami_3d.yaml"), {"discretization.particles_across=8", "time.t_end=0.01",
                                                         "output.times=[0.005,0.01]", "output.plots=false"});
}

Config duct() {
  return load_config(verification("duct_3d.yaml"), {"discretization.particles_across=8", "geometry.length=1.0e-3", "time.integrator=leapfrog",
                                                    "time.t_end=0.02", "output.times=[0.01,0.02]", "output.plots=false"});
}

// The lid-driven cavity with ghost walls: its Ghia-point fits are kernel sums over the fluid.
Config cavity() {
  return load_config(verification("cavity.yaml"),
                     {"discretization.boundary=ghost", "discretization.wall_model=prescribed", "discretization.particles_across=20",
                      "time.integrator=leapfrog", "time.t_end=0.1", "output.times=[0.05,0.1]", "output.plots=false"});
}

// c over the ranks and (rank 0) serially, writing files: every CSV file the serial run writes is
// written over the ranks with the same bytes. Returns the summary over the ranks.
nlohmann::json check_files_equal_serial(const Config& c, const fs::path& dir, std::size_t csv_expected) {
  const Communicator comm;
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, 1.2);
  const nlohmann::json split = run_into(c, &partitioner, dir / "split");
  REQUIRE(split["status"] == "completed");
  comm.barrier();
  if (comm.rank() == 0) {
    INFO(c.case_name << ", " << comm.size() << " ranks");
    const nlohmann::json serial = run_into(c, nullptr, dir / "serial");
    REQUIRE(serial["status"] == "completed");
    CHECK(split["errors"] == serial["errors"]);
    CHECK(split["conservation"] == serial["conservation"]);
    std::size_t compared = 0;
    for (const auto& f : serial["files"]) {
      const std::string name = f.get<std::string>();
      if (name.size() < 4 || name.substr(name.size() - 4) != ".csv") continue;
      INFO(name);
      CHECK(test_support::slurp(dir / "split" / name) == test_support::slurp(dir / "serial" / name));
      ++compared;
    }
    CHECK(compared == csv_expected);
  }
  comm.barrier();
  return split;
}

}  // namespace

TEST_CASE("reduced measurements: a case measured from pieces equals the serial measurement to the bit, without gathers",
          "[parallel][run][measurements_reduced]") {
  const std::vector<Config> cases{
      taylor_green(), channel("couette.yaml"), channel("poiseuille.yaml"),
      load_config(verification("hydrostatic.yaml"),
                  {"discretization.particles_across=10", "time.t_end=0.02", "output.times=[0.01,0.02]", "output.plots=false"}),
      load_config(verification("dam_break.yaml"),
                  {"discretization.spacing=0.04", "time.t_end=0.06", "output.times=[0.03,0.06]", "output.plots=false"}),
      load_config(verification("scene_tank.yaml"), {"time.t_end=0.02", "output.times=[0.01,0.02]", "output.plots=false"}),
      beltrami(), duct(), cavity()};
  for (const Config& c : cases) {
    const nlohmann::json split = check_measurements_equal_serial(c);
    // The final state only (the end's observers and the final state); no output time gathers.
    CHECK(split["parallel"]["whole_state_gathers"].get<long>() == 1);
    CHECK(split["parallel"]["whole_field_gathers"].get<long>() == 0);
    // One piece per output time (the case and the conservation sums share it).
    CHECK(split["parallel"]["owned_pieces"].get<long>() == static_cast<long>(c.output.times.size()));
  }
}

TEST_CASE("reduced measurements: the shock tubes' bins, mid-lines and total energy equal the serial ones to the bit",
          "[parallel][run][measurements_reduced][energy]") {
  // The energy equation: the conservation log's total energy too; 1D and 2D (the mid-line rows).
  for (const char* file : {"shock_tube_1d.yaml", "shock_tube.yaml"}) {
    const Config c = short_shock_tube(file, {"discretization.smoothing_length=constant"});
    const nlohmann::json split = check_measurements_equal_serial(c);
    CHECK(split["parallel"]["whole_state_gathers"].get<long>() == 1);
  }
}

TEST_CASE("reduced measurements: VTK pieces and probes with `every` leave the output times without gathers, the files "
          "the serial run's",
          "[parallel][run][measurements_reduced]") {
  const Communicator comm;
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, 1.2);
  const long pid = comm.all_gather(static_cast<long>(::getpid()))[0];
  const fs::path dir = fs::temp_directory_path() / ("sphmol-reduced-" + std::to_string(pid) + "-" + std::to_string(comm.size()));
  std::string yaml = test_support::slurp(verification("couette.yaml"));
  yaml += R"(
probes:
  - {name: middle, type: point, at: [2.0e-4, 5.0e-4], fields: [velocity], every: 0.005}
)";
  const Config with_probe = load_config_string(yaml, {"discretization.particles_across=20", "time.integrator=leapfrog",
                                                      "time.t_end=0.02", "output.times=[0.01,0.02]", "output.plots=false",
                                                      "output.vtk=true"});
  const nlohmann::json split = check_files_equal_serial(with_probe, dir / "couette", 3);  // 2 profiles, the probe
  CHECK(split["parallel"]["whole_state_gathers"].get<long>() == 1);
  CHECK(split["parallel"]["whole_field_gathers"].get<long>() == 0);
  // The other cases' files: the duct's profiles and peaks, the column's pressures, the decays, the front.
  check_files_equal_serial(duct(), dir / "duct", 3);
  check_files_equal_serial(beltrami(), dir / "beltrami", 1);
  check_files_equal_serial(taylor_green(), dir / "taylor_green", 1);
  check_files_equal_serial(cavity(), dir / "cavity", 4);  // the centre lines at both output times
  check_files_equal_serial(short_shock_tube("shock_tube.yaml", {"discretization.smoothing_length=constant"}), dir / "shock_tube",
                           4);  // the binned profiles and the mid-lines
  check_files_equal_serial(load_config(verification("hydrostatic.yaml"), {"discretization.particles_across=10", "time.t_end=0.02",
                                                                         "output.times=[0.01,0.02]", "output.plots=false"}),
                           dir / "hydrostatic", 2);
  check_files_equal_serial(load_config(verification("dam_break.yaml"), {"discretization.spacing=0.04", "time.t_end=0.06",
                                                                       "output.times=[0.03,0.06]", "output.plots=false"}),
                           dir / "dam_break", 1);
  // Probes without `every` sample the output times (and t = 0) from the pieces too, their files the
  // serial run's, and still no output time gathers (the scenes' force probes: test_distributed_probes).
  yaml += R"(  - {name: outputs, type: point, at: [2.0e-4, 5.0e-4], fields: [velocity, p]}
  - {name: across, type: line, from: [2.0e-4, 0.0], to: [2.0e-4, 1.0e-3], points: 7, fields: [rho, velocity]}
)";
  const Config at_outputs = load_config_string(yaml, {"discretization.particles_across=20", "time.integrator=leapfrog",
                                                      "time.t_end=0.02", "output.times=[0.01,0.02]", "output.plots=false"});
  const nlohmann::json again = check_files_equal_serial(at_outputs, dir / "couette-outputs", 5);  // 2 profiles, 3 probes
  CHECK(again["parallel"]["whole_state_gathers"].get<long>() == 1);
  CHECK(again["parallel"]["whole_field_gathers"].get<long>() == 0);
  comm.barrier();
  if (comm.rank() == 0) fs::remove_all(dir);
}
