// Outflow over ranks (run/outflow.hpp): fluid that leaves the domain through an open face is taken
// out of a run over ranks as the serial run takes it out, at the same step on every rank: the same
// steps, the same final state to the bit (the frozen particle with zero velocity where it left), the
// same summary "outflow" object and warning, for every integrator that runs over ranks, partitioned
// once or again at every re-plan (the retired particles migrating with their kind); the limit
// health.max_outflow_fraction ends the run as blown up as serially; probes over the ranks leave
// the fluid taken out out of their sums as the serial probes do.
#include <unistd.h>

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "run_into.hpp"
#include "serial_reference.hpp"
#include "shot_scene.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/mpi_run.hpp"
#include "support/files.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
using namespace sphmol::parallel::testing;

namespace {

// The IMEX integrators need a viscous term to split off.
std::vector<std::string> integrator_settings(const std::string& integrator) {
  std::vector<std::string> set = {"time.integrator=" + integrator};
  if (integrator.find("imex") != std::string::npos)
    set.insert(set.end(), {"fluid.kinematic_viscosity=1e-4", "discretization.viscosity=morris", "discretization.wall_model=prescribed"});
  return set;
}

bool warns_of_outflow(const nlohmann::json& summary) {
  for (const auto& w : summary.value("warnings", nlohmann::json::array()))
    if (w.get<std::string>().rfind("outflow: ", 0) == 0) return true;
  return false;
}

// check_same_as_serial, and the exits: as many as serially (at least `exits`), with the same summary
// object and warning.
Finished check_outflow_as_serial(const Config& c, std::size_t exits, double rebalance, long evaluations_per_start) {
  const Finished split = check_same_as_serial(c, rebalance, evaluations_per_start);
  if (Communicator().rank() == 0) {
    const Finished& serial = serial_run(c);
    INFO(serial.summary["outflow"].dump());
    REQUIRE(serial.summary["outflow"]["particles"].get<std::size_t>() >= exits);
    CHECK(split.summary["outflow"] == serial.summary["outflow"]);
    CHECK(warns_of_outflow(split.summary));
  }
  return split;
}

}  // namespace

TEST_CASE("distributed outflow: a particle shot through an open face is taken out as in the serial run", "[parallel][outflow]") {
  // A block at rest and one particle shot through the open face (x = 0.34 with the wall layer's room).
  for (const std::string integrator : {"leapfrog", "leapfrog_kdk", "leapfrog_imex", "arkode_erk", "arkode_imex", "cvode_adams"}) {
    DYNAMIC_SECTION(integrator << ", " << Communicator().size() << " ranks") {
      std::vector<std::string> set = integrator_settings(integrator);
      set.insert(set.end(), {"time.t_end=0.03", "output.times=[0.015, 0.03]"});
      const long per_start = integrator == "leapfrog_imex" ? 2 : integrator == "cvode_adams" || integrator == "arkode_erk" ? 0 : 1;
      const Finished split = check_outflow_as_serial(sphmol::testing::shot_scene(set), 1, 1.2, per_start);
      if (Communicator().rank() == 0) CHECK(split.summary["outflow"]["particles"] == 1);
    }
  }
}

TEST_CASE("distributed outflow: a falling block leaves through the open floor, partitioned again after every exit",
          "[parallel][outflow]") {
  // Gravity pulls the whole block through the open bottom face: whole rows leave in one step, their
  // particles on several ranks, and the run goes on until most of the fluid has left. Partitioned
  // again at every re-plan (every integrator moves its particles, retired ones included).
  for (const std::string integrator : {"leapfrog", "leapfrog_kdk", "leapfrog_imex", "arkode_erk", "arkode_imex", "cvode_adams"}) {
    DYNAMIC_SECTION(integrator << ", " << Communicator().size() << " ranks") {
      std::vector<std::string> set = integrator_settings(integrator);
      set.insert(set.end(), {"fluid.body_force=[0.0, -9.81]", "health.max_outflow_fraction=1", "time.t_end=0.18",
                             "output.times=[0.09, 0.18]"});
      // The vectors of arkode_erk and cvode_adams move without an evaluation; arkode_imex records its
      // operator again with one.
      const long per_start = integrator == "leapfrog_imex" ? 2 : integrator == "cvode_adams" || integrator == "arkode_erk" ? 0 : 1;
      const Finished split = check_outflow_as_serial(sphmol::testing::shot_scene(set), 12, 1.0, per_start);
      if (Communicator().rank() == 0 && Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 0);
    }
  }
}

TEST_CASE("distributed outflow: beyond health.max_outflow_fraction the run over ranks ends as the serial run does",
          "[parallel][outflow]") {
  const Config c = sphmol::testing::shot_scene({"health.max_outflow_fraction=0.005"});
  const Communicator comm;
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, 1.2);
  const Finished split = run(c, &partitioner);
  INFO(comm.size() << " ranks");
  REQUIRE(split.summary["status"] == "blown_up");
  if (comm.rank() == 0) {
    const Finished serial = run(c, nullptr);
    REQUIRE(serial.summary["status"] == "blown_up");
    CHECK(split.summary["blow_up"] == serial.summary["blow_up"]);
    CHECK(split.summary["outflow"] == serial.summary["outflow"]);
    const std::string cause = split.summary["blow_up"]["cause"];
    CHECK(cause.rfind("outflow: 1 fluid particle(s)", 0) == 0);
  }
}

TEST_CASE("distributed outflow: the dam break past its first exits equals the serial run", "[parallel][outflow][dam_break]") {
  // The surge runs up the right wall and over its top, an open face, from about t = 1.4 s (dp = 0.04).
  const Config c = load_config(verification("dam_break.yaml"), {"discretization.spacing=0.04", "time.t_end=1.5",
                                                                "output.times=[0.75, 1.5]", "output.plots=false"});
  check_outflow_as_serial(c, 1, 1.2, 1);
}

TEST_CASE("distributed outflow: probes over ranks see no fluid taken out, as the serial probes", "[parallel][outflow][probes_reduced]") {
  // Points beside the open face, within the kernel support (0.08) both of the shot particle where it
  // stays after leaving (x just past 0.34, y = 0.19) and of the block's right column (x = 0.29):
  // serially the particle taken out has no volume and weighs nothing in the samples, which the
  // ranks' pieces, that own it as well, must match. At the output times and every 0.005 s.
  const Config c = sphmol::testing::shot_scene({"time.t_end=0.03", "output.times=[0.015, 0.03]"}, R"(
probes:
  - {name: outlet, type: point, at: [0.33, 0.19], fields: [p, rho, velocity]}
  - {name: outlet_often, type: point, at: [0.33, 0.19], fields: [p, rho, velocity], every: 0.005}
  - {name: across, type: line, from: [0.3, 0.12], to: [0.36, 0.24], points: 5, fields: [p]}
)");
  const Communicator comm;
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, 1.2);
  const long pid = comm.all_gather(static_cast<long>(::getpid()))[0];
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("sphmol-outflow-probes-" + std::to_string(pid) + "-" + std::to_string(comm.size()));
  const nlohmann::json split = run_into(c, &partitioner, dir / "split");
  REQUIRE(split["status"] == "completed");
  comm.barrier();
  if (comm.rank() == 0) {
    INFO(comm.size() << " ranks");
    const nlohmann::json serial = run_into(c, nullptr, dir / "serial");
    REQUIRE(serial["status"] == "completed");
    REQUIRE(serial["outflow"]["particles"] == 1);
    for (const char* f : {"probe_outlet.csv", "probe_outlet_often.csv", "probe_across.csv"}) {
      INFO(f);
      const std::string want = test_support::slurp(dir / "serial" / f);
      CHECK(want.size() > 100);
      CHECK(test_support::slurp(dir / "split" / f) == want);
    }
  }
  comm.barrier();
  if (comm.rank() == 0) std::filesystem::remove_all(dir);
}
