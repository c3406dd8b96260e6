// The health check's physical bounds over ranks (parallel/distributed_health_check.hpp): a run
// that the serial check stops on the scene's speed bound or on its energy budget stops over any
// rank count at the same step with the serial message (the particle named by its serial index),
// on every rank, and rank 0 writes the serial run's last_good_state.csv; a healthy run is not
// stopped. Rank 0 runs the serial reference. The numerical tests (NaN/Inf, a particle through a face
// of the domain closed to outflow, density <= 0) find a fault put into one rank's state, with the
// serial cause and particle on every rank; a particle beyond a face open to outflow is no fault: every
// rank learns its global id, for the run to take it out (run/outflow.hpp).
#include <catch2/catch.hpp>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "sphmol/cases/case_module.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/distributed_health_check.hpp"
#include "sphmol/parallel/distributed_system.hpp"
#include "sphmol/parallel/mpi_run.hpp"
#include "sphmol/run/health_limits.hpp"
#include "sphmol/run/start_piece.hpp"
#include "sphmol/parallel/piece_collectives.hpp"
#include "sphmol/time/blow_up.hpp"
#include "serial_reference.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
using namespace sphmol::parallel::testing;
namespace fs = std::filesystem;

namespace {

std::string contents(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// Every rank's text, in rank order.
std::vector<std::string> every_rank(const Communicator& comm, const std::string& text) {
  const std::vector<char> all = comm.all_gather_v(std::vector<char>(text.begin(), text.end()));
  const std::vector<int> lengths = comm.all_gather(static_cast<int>(text.size()));
  std::vector<std::string> out;
  std::size_t at = 0;
  for (const int n : lengths) {
    out.emplace_back(all.begin() + static_cast<long>(at), all.begin() + static_cast<long>(at) + n);
    at += static_cast<std::size_t>(n);
  }
  return out;
}

// c over every rank and (rank 0) serially, both writing files: the same blow-up, with `cause` at
// its start, at the same time, on every rank, and the same last good state file.
void check_same_blow_up(const Config& c, const std::string& name, const std::string& cause) {
  const Communicator comm;
  const long pid = comm.all_gather(static_cast<long>(::getpid()))[0];
  const fs::path base = fs::temp_directory_path() / ("sphmol-" + name + "-" + std::to_string(pid) + "-" + std::to_string(comm.size()));
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, 1.2);
  const Finished split = run(c, &partitioner, "", (base / "ranks").string());
  INFO(comm.size() << " ranks: " << split.summary.dump());
  REQUIRE(split.summary["status"] == "blown_up");
  const auto& b = split.summary["blow_up"];
  const std::string message = b["message"].get<std::string>();
  CHECK(b["cause"].get<std::string>().rfind(cause, 0) == 0);
  for (const std::string& m : every_rank(comm, message)) CHECK(m == message);
  const auto steps = comm.all_gather(split.summary["steps"].get<long>());
  for (const long s : steps) CHECK(s == steps[0]);
  // Rank 0 alone from here: CHECK, not REQUIRE, so that a failure still reaches the barrier below.
  if (comm.rank() == 0) {
    const Finished serial = run(c, nullptr, "", (base / "serial").string());
    CHECK(serial.summary["status"] == "blown_up");
    const auto& sb = serial.summary["blow_up"];
    CHECK(b["message"] == sb.value("message", ""));
    CHECK(b["t"] == sb.value("t", -1.0));
    CHECK(b["last_good_t"] == sb.value("last_good_t", -1.0));
    CHECK(b.value("particle", -1L) == sb.value("particle", -1L));
    CHECK(split.summary["steps"] == serial.summary["steps"]);
    CHECK(b.value("state_file", "") == "last_good_state.csv");
    const std::string mine = contents(base / "ranks" / "last_good_state.csv");
    CHECK(!mine.empty());
    CHECK(mine == contents(base / "serial" / "last_good_state.csv"));
  }
  comm.barrier();
  if (comm.rank() == 0) fs::remove_all(base);
}

}  // namespace

TEST_CASE("distributed health: the speed bound stops a run over ranks as it stops the serial run", "[parallel][health]") {
  // A fixed leapfrog step 5x past the viscous limit: the fluid next to the plate passes 10 times
  // the plate speed at the second step (particle 760 serially).
  check_same_blow_up(load_config(verification("couette.yaml"), {"time.integrator=leapfrog", "time.dt=1e-3", "time.t_end=0.1",
                                                                "output.times=[0.1]", "output.plots=false"}),
                     "health-speed", "speed ");
}

TEST_CASE("distributed health: the energy budget stops a run over ranks as it stops the serial run", "[parallel][health]") {
  // The Taylor-Green vortex at a fixed step 2.7x the stable one gains kinetic energy with no input
  // (no walls, no body force): past the budget at the third step.
  check_same_blow_up(load_config(verification("taylor_green.yaml"),
                                 {"time.dt=0.01", "time.t_end=0.25", "output.times=[0.25]", "output.plots=false"}),
                     "health-energy", "kinetic energy ");
}

TEST_CASE("distributed health: a healthy run is not stopped by the physical bounds", "[parallel][health]") {
  // The Taylor-Green vortex at its CFL step. (The runs of test_distributed_run.cpp, which must
  // complete as the serial runs, cover gravity's work in the budget, the dam break, and moving walls.)
  check_same_as_serial(load_config(verification("taylor_green.yaml"),
                                   {"discretization.particles_across=30", "time.t_end=0.05", "output.times=[0.05]",
                                    "output.plots=false"}));
}

TEST_CASE("distributed health: the numerical tests find a fault in one rank's state, with the serial cause and particle",
          "[parallel][health]") {
  // The dam break at dp = 0.04 (1250 fluid particles), as the serial check's test
  // (tests/unit/test_health_limits.cpp): a state that passes, then one fault at a time in particle
  // 700, held by one rank only; every rank must stop with its cause and name the particle.
  const Communicator comm;
  const Config c = load_config(verification("dam_break.yaml"), {"discretization.spacing=0.04"});
  const auto serial_case = make_case<2>(c), split_case = make_case<2>(c);
  const auto serial = serial_case->build(c), whole = split_case->build(c);
  const std::vector<double> y0 = serial->initial_state();
  std::vector<double> f0(y0.size());
  serial->rhs(0.0, y0.data(), f0.data());
  const HealthLimits lim = health_limits<2>(c, serial_case->velocity_scale(c), serial_case->free_surface(), *serial, y0.data());

  DistributedSystem<2> split(comm, c, *whole, y0, 0.0, MpiRunPartitioner::default_tolerance, 1.2);
  const std::vector<double> y_local = split.local_part(y0);
  std::vector<double> f(split.size());
  split.rhs(0.0, y_local.data(), f.data());
  DistributedHealthCheck<2> check(comm, split, y_local, 0.0, lim);
  const auto& L = split.layout();
  REQUIRE(L.has_density);
  const std::uint64_t p = 700;
  REQUIRE(p < serial->layout().n);
  long here = -1;  // particle p's owned row on this rank
  for (std::size_t o = 0; o < L.n; ++o)
    if (split.gid()[o] == p) here = static_cast<long>(o);
  // On every rank: the cause and particle of the check's blow-up ("" when it passes).
  const auto verdict = [&](const std::vector<double>& y) -> std::pair<std::string, long> {
    try {
      check(1e-3, y.data(), 0);
    } catch (const BlowUp& b) {
      return {b.cause, b.particle};
    }
    return {"", -1};
  };
  CHECK(verdict(y_local).first.empty());
  const double inf = std::numeric_limits<double>::infinity();
  const auto& dom = split.domain();
  struct Fault {
    std::size_t block;  // the state's offset of the particle's block
    double value;
    std::string cause;
  };
  const std::vector<Fault> faults = {
      {L.position(0), std::nan(""), "NaN/Inf in the position (component 0)"},
      {L.position(1), -inf, "NaN/Inf in the position (component 1)"},
      {L.velocity(0), inf, "NaN/Inf in the velocity (component 0)"},
      {L.velocity(1), std::nan(""), "NaN/Inf in the velocity (component 1)"},
      {L.density(), std::nan(""), "NaN/Inf in a state field"},
      // The dam break's floor is closed to outflow (Domain::outflow).
      {L.position(1), dom.lo[1] - 0.5, "particle left the domain in direction 1 through a face closed to outflow"},
  };
  REQUIRE(dom.outflow[0][1]);
  REQUIRE_FALSE(dom.outflow[1][0]);
  // The last good state is the last state that passed: a step that passes replaces it, one that
  // fails leaves it (the check copies the state as its tests read it).
  std::vector<double> moved = y_local;
  for (std::size_t k = L.velocities_begin(); k < L.velocities_end(); ++k) moved[k] += 1e-3;
  CHECK(verdict(moved).first.empty());
  CHECK(check.last_good_state() == moved);
  CHECK(verdict(y_local).first.empty());
  CHECK(check.last_good_state() == y_local);
  for (const Fault& fault : faults) {
    INFO(comm.size() << " ranks, rank " << comm.rank() << ", expected " << fault.cause);
    std::vector<double> y = y_local;
    if (here >= 0) y[fault.block + static_cast<std::size_t>(here)] = fault.value;
    const auto [cause, particle] = verdict(y);
    CHECK(cause.rfind(fault.cause, 0) == 0);
    CHECK(particle == static_cast<long>(p));
    CHECK(check.last_good_state() == y_local);
  }
  // A density <= 0 in the latest evaluation (the local system's density the check reads).
  std::vector<double> y = y_local;
  if (here >= 0) y[L.density() + static_cast<std::size_t>(here)] = -1.0;
  split.rhs(0.0, y.data(), f.data());
  const auto [cause, particle] = verdict(y);
  INFO(comm.size() << " ranks, rank " << comm.rank());
  CHECK(cause.rfind("density <= 0", 0) == 0);
  CHECK(particle == static_cast<long>(p));
  {
    // Beyond a face open to outflow (the dam break's right side) the particle is no blow-up: the
    // check passes and names it, by global id, on every rank, as the serial check notes it
    // (exits()) for the run to take out (run/outflow.hpp).
    INFO(comm.size() << " ranks, rank " << comm.rank() << ", an exit");
    REQUIRE(dom.outflow[0][1]);
    split.rhs(0.0, y_local.data(), f.data());  // the densities of the healthy state again
    std::vector<double> out = y_local;
    if (here >= 0) out[L.position(0) + static_cast<std::size_t>(here)] = dom.hi[0] + 0.5;
    CHECK(verdict(out).first.empty());
    CHECK(check.exits());
    CHECK(check.leavers() == std::vector<std::size_t>{p});
    // Its mass from its owner (the ranks other than 0 release the whole scene's particles).
    CHECK(check.leaver_masses() == std::vector<double>{whole->particles().mass[p]});
    CHECK(check.last_good_state() == out);
    // Taken out (on its owner, Kind::Out), it is no exit at the next check, and no blow-up either.
    split.take_out(check.leavers(), out.data());
    if (here >= 0) CHECK(out[L.velocity(0) + static_cast<std::size_t>(here)] == 0.0);
    CHECK(verdict(out).first.empty());
    CHECK_FALSE(check.exits());
    CHECK(check.leavers().empty());
    CHECK(check.leaver_masses().empty());
  }
}

TEST_CASE("distributed health: the limits from the ranks' own particles are the serial limits", "[parallel][health]") {
  // Over ranks no rank evaluates or sums the whole scene for the health limits: the sums at the
  // start come from each rank's starting particles (run/start_piece.hpp), the elastic energy of the
  // budget from the densities of the ranks' evaluations of their own particles, all summed exactly,
  // so they are the serial limits to the bit. Taylor-Green (summation density: the densities come
  // from the evaluation), the dam break (continuity density, walls, gravity) and a user scene built
  // in shares (two liquids, moving walls).
  const Communicator comm;
  const SceneShare share{static_cast<std::size_t>(comm.rank()), static_cast<std::size_t>(comm.size())};
  const std::vector<std::pair<std::string, std::vector<std::string>>> scenes = {
      {"taylor_green.yaml", {"discretization.particles_across=20"}},
      {"dam_break.yaml", {"discretization.spacing=0.04"}},
      {"../examples/tank_obstacle_2d.yaml", {"discretization.spacing=0.02", "probes=[]"}}};
  for (const auto& [file, sets] : scenes) {
    INFO(file << ", " << comm.size() << " ranks");
    const Config c = load_config(verification(file), sets);
    const auto serial_case = make_case<2>(c), split_case = make_case<2>(c);
    const auto serial = serial_case->build(c);
    const auto mine = split_case->builds_shares() ? split_case->build_share(c, share) : split_case->build(c);
    CHECK(mine->is_share() == (split_case->builds_shares() && comm.size() > 1));
    const std::vector<double> y0 = serial->initial_state();
    std::vector<double> f0(y0.size());
    serial->rhs(0.0, y0.data(), f0.data());
    const HealthLimits expected =
        health_limits<2>(c, serial_case->velocity_scale(c), serial_case->free_surface(), *serial, y0.data());

    const std::vector<double> y_mine = mine->initial_state();
    HealthSums sums = health_sums(start_piece(*mine, y_mine.data(), share, piece_collectives(comm)));
    DistributedSystem<2> split(comm, c, *mine, y_mine, 0.0, MpiRunPartitioner::default_tolerance, 1.2);
    const std::vector<double> y_local = split.local_part(y0);
    std::vector<double> f(split.size());
    split.rhs(0.0, y_local.data(), f.data());
    sums.el0 = DistributedHealthCheck<2>::elastic_energy(comm, split, elastic_energy(c));
    const HealthLimits lim = health_limits<2>(c, split_case->velocity_scale(c), split_case->free_surface(), sums);
    CHECK(mine->rhs_evaluations() == 0);
    CHECK(lim.energy_budget == expected.energy_budget);
    CHECK(lim.energy_floor == expected.energy_floor);
    CHECK(lim.max_speed == expected.max_speed);
    CHECK(lim.max_compression == expected.max_compression);
    CHECK(lim.frame.on == expected.frame.on);
  }
}
