// Outflow over ranks (run/outflow.hpp): a serial run takes fluid that leaves the domain out and goes
// on; a run over ranks does not, and ends as blown up at the step the particle leaves, on every rank,
// with a cause that says why, rather than continue with another fluid than the serial run's.
#include <catch2/catch.hpp>

#include <string>

#include "serial_reference.hpp"
#include "shot_scene.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/mpi_run.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
using namespace sphmol::parallel::testing;

TEST_CASE("distributed outflow: a particle leaving the domain ends a run over ranks with a clear cause", "[parallel][outflow]") {
  // A block at rest and one particle shot through the open face (x = 0.34 with the wall layer's room).
  const Config c = sphmol::testing::shot_scene({"time.t_end=0.02", "output.times=[0.02]"});
  const Communicator comm;
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, 1.2);
  const Finished serial = run(c, nullptr);
  REQUIRE(serial.summary["status"] == "completed");
  REQUIRE(serial.summary["outflow"]["particles"] == 1);
  const Finished split = run(c, &partitioner);
  INFO(comm.size() << " ranks");
  REQUIRE(split.summary["status"] == "blown_up");
  const std::string cause = split.summary["blow_up"]["cause"];
  CHECK(cause.rfind("particle left the domain in direction 0", 0) == 0);
  CHECK(cause.find("a run over MPI ranks does not take fluid that leaves the domain out of the run") != std::string::npos);
  CHECK(split.summary["blow_up"]["particle"] == serial.summary["outflow"]["first_particle"]);
  CHECK(split.summary["blow_up"]["t"].get<double>() == serial.summary["outflow"]["t_first"].get<double>());
}
