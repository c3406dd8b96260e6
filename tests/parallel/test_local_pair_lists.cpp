// The local systems' pair lists over ranks: built once per halo plan, never rebuilt by their own
// displacement test (the plan's test over every rank's particles comes first), and the run still the
// serial run to the bit. Where the local list keeps its own test (a variable h, ghost walls) it is
// not skipped.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "sphmol/cases/case_module.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/distributed_system.hpp"
#include "sphmol/parallel/mpi_run.hpp"
#include "sphmol/time/integrator.hpp"
#include "serial_reference.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
using namespace sphmol::parallel::testing;

namespace {

struct Stepped {
  long plans = 0, rebuilds = 0, serial_rebuilds = 0;
  bool same = false;
};

// `t_end` of the config's integrator on the whole scene and on this rank's share; the same state on
// rank 0 (the others report true).
template <int D>
Stepped step_both(const Config& c, double t_end) {
  const Communicator comm;
  const auto serial_case = make_case<D>(c), split_case = make_case<D>(c);
  const auto serial = serial_case->build(c);
  const auto whole = split_case->build(c);
  const std::vector<double> y0 = serial->initial_state();
  DistributedSystem<D> split(comm, c, *whole, y0, 0.0, MpiRunPartitioner::default_tolerance, 1e9);
  std::vector<double> y = split.take_initial_state(), y_serial = y0, y_whole;
  const auto serial_steps = make_integrator(c.time), split_steps = make_integrator(c.time);
  serial_steps->initialize(*serial, 0.0, y_serial.data());
  serial_steps->advance(t_end);
  split_steps->initialize(split, 0.0, y.data());
  split_steps->advance(t_end);
  const bool root = split.gather(y.data(), y_whole);
  Stepped s;
  s.plans = split.stats().plans;
  s.rebuilds = split.stats().rebuilds;
  s.serial_rebuilds = serial->pair_list().rebuilds();
  s.same = !root || differing_bits(y_whole, y_serial) == 0;
  return s;
}

}  // namespace

TEST_CASE("distributed system: a local pair list is built once per halo plan, never by its own test",
          "[parallel][local_pair_lists]") {
  // The dam break at a coarse spacing to t = 0.1 s: the column falls and the halo is planned again
  // several times (the skin is 0.15 h).
  const Config c = load_config(verification("dam_break.yaml"), {"discretization.spacing=0.05", "time.t_end=0.1"});
  const Stepped s = step_both<2>(c, 0.1);
  INFO(s.plans << " halo plans, " << s.rebuilds << " local list builds, " << s.serial_rebuilds << " serial rebuilds");
  CHECK(s.plans > 2);
  CHECK(s.rebuilds == s.plans);
  CHECK(s.same);
}

TEST_CASE("distributed system: with a variable h the local pair list keeps its own test",
          "[parallel][local_pair_lists]") {
  // The 1D shock tube (h from dh/dt): the local supports follow the local largest h, which the plan's
  // test does not watch. The run stays the serial run to the bit.
  const Config c = load_config(verification("shock_tube_1d.yaml"), {"discretization.spacing=5e-3", "time.t_end=0.02"});
  const Stepped s = step_both<1>(c, 0.02);
  INFO(s.plans << " halo plans, " << s.rebuilds << " local list builds, " << s.serial_rebuilds << " serial rebuilds");
  CHECK(s.plans >= 1);
  CHECK(s.rebuilds >= s.plans);
  CHECK(s.same);
}
