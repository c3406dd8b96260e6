// A case's monitors over ranks (rhs/monitor.hpp): every rank watches its own fluid particles at every
// evaluation, and the results are combined over the ranks where the case reads them, so the dam
// break's wall penetrations and closest approach to a wall, and the water column's largest drift,
// are the serial run's exactly, at every output time and in the summary. The scenes are made so
// that what is measured happens between output times: particles that cross a wall and come back,
// a drift that peaks and falls again. Rank 0 runs the serial reference.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "sphmol/cases/case_module.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/mpi_run.hpp"
#include "sphmol/time/integrator.hpp"
#include "serial_reference.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
using namespace sphmol::parallel::testing;

namespace {

// The measurements `keys` at every output time equal the serial run's (rank 0).
void check_same_at_outputs(const Finished& split, const Config& c, const std::vector<std::string>& keys) {
  if (Communicator().rank() != 0) return;
  const nlohmann::json& mine = split.summary["errors"];
  const nlohmann::json& serial = serial_run(c).summary["errors"];
  REQUIRE(mine.size() == serial.size());
  for (std::size_t k = 0; k < mine.size(); ++k)
    for (const auto& key : keys) {
      INFO("t = " << mine[k]["t"] << ", " << key);
      CHECK(mine[k][key] == serial[k][key]);
    }
}

}  // namespace

TEST_CASE("distributed run: the dam break's wall penetrations and closest wall approach are the serial run's",
          "[parallel][run][monitors]") {
  // A slow sound speed (15 m/s) lets the surge that hits the right wall push particles through it;
  // the wall pushes some of them back before the next output time. Measured with the monitor at
  // output times only (on rank 0), 2 ranks: 2 penetrations and a closest approach of 1.7e-3 dx
  // against the serial 4 and 6.1e-4 dx.
  const Config c = load_config(verification("dam_break.yaml"),
                               {"discretization.spacing=0.04", "geometry.box=[2.0, 3.0]", "fluid.eos.sound_speed=15",
                                "time.t_end=0.4", "output.times=[0.2,0.4]", "output.plots=false"});
  const auto crossed = [&] {
    if (Communicator().rank() == 0) CHECK(serial_run(c).summary["final_errors"]["wall_penetrations"].get<long>() > 0);
  };
  SECTION("one partition") {
    const Finished split = check_same_as_serial(c);
    crossed();
    check_same_at_outputs(split, c, {"wall_penetrations"});
    CHECK(split.summary["parallel"]["terms_not_run"] == nlohmann::json::array());
  }
  SECTION("partitioned again at every re-plan: the particles that crossed migrate") {
    // The leapfrog's start on the new share evaluates the step's end state, which the serial
    // drift-kick-drift leapfrog never evaluates: the monitors must not see it.
    const Finished split = check_same_as_serial(c, 1.0);
    if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 3);
    crossed();
    check_same_at_outputs(split, c, {"wall_penetrations"});
  }
}

TEST_CASE("distributed run: the water column's largest drift is the serial run's", "[parallel][run][monitors]") {
  // Gravity switched on at once: the column sinks under its weight, overshoots and rebounds, its
  // largest displacement peaking near t = 0.07 s, between the output times. Measured with the monitor
  // at output times only, 2 ranks: max_drift 0.076 dx against the serial 0.130 dx.
  const std::vector<std::string> settings{"discretization.particles_across=10", "fluid.body_force_ramp=0",
                                         "time.t_end=0.12", "output.times=[0.04,0.12]", "output.plots=false"};
  SECTION("one partition") {
    const Config c = load_config(verification("hydrostatic.yaml"), settings);
    const Finished split = check_same_as_serial(c);
    check_same_at_outputs(split, c, {"max_drift"});
    CHECK(split.summary["parallel"]["terms_not_run"] == nlohmann::json::array());
  }
  SECTION("partitioned again at every re-plan, which a small skin makes frequent") {
    // The leapfrog's start on each new share evaluates the state its step ended in, which the serial
    // drift-kick-drift leapfrog does not: watched, it raises the largest drift near its peak.
    std::vector<std::string> more = settings;
    more.push_back("discretization.skin=0.02");
    const Config c = load_config(verification("hydrostatic.yaml"), more);
    const Finished split = check_same_as_serial(c, 1.0);
    // (Two ranks split the symmetric column evenly: it is never out of balance.)
    if (Communicator().size() > 2) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 10);
    check_same_at_outputs(split, c, {"max_drift"});
  }
}

TEST_CASE("distributed run: the integrator's start on a new share is not watched by the monitors", "[parallel][run][monitors]") {
  // A repartition starts the leapfrog again on the new share, evaluating the state the step ended in,
  // which the serial drift-kick-drift leapfrog never evaluates. Here that state has one particle below
  // the tank's floor: the start must not count it, while the next evaluation of the same state does.
  const Communicator comm;
  const Config c = load_config(verification("dam_break.yaml"), {"discretization.spacing=0.04", "output.plots=false"});
  auto dam_break = make_case<2>(c);
  auto whole = dam_break->build(c);
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, 1.0);
  auto part = partitioner.partition(c, *whole, whole->initial_state(), 0.0);
  auto integrator = make_integrator(c.time);
  OdeSystem& ode = part->system();
  integrator->initialize(ode, 0.0, part->state().data());
  // The first owned fluid particle of rank 0 below the floor (y < 0).
  const std::size_t n = ode.block_length();
  if (comm.rank() == 0) {
    REQUIRE(n > 0);
    part->state()[n] = -0.01;
  }
  const auto penetrations = [&] {
    part->combine_monitors();
    return dam_break->final_errors(nlohmann::json::array())["wall_penetrations"].get<long>();
  };
  REQUIRE(penetrations() == 0);
  part->rebalance(*integrator, 0.0);
  const bool moved = part->describe()["repartitions"].get<long>() == 1;
  CHECK(moved == (comm.size() > 1));
  CHECK(penetrations() == 0);
  std::vector<double> rates(ode.size());
  ode.rhs(0.0, part->state().data(), rates.data());
  CHECK(penetrations() == 1);
}
