// Probes over ranks at their own sampling times (`every`, probes/probe_observer.hpp,
// at_time_pieces): each rank sends rank 0 only its terms of the probes' sums (its own fluid near the
// sample points and gauge lines, its own fluid's pairs with the force probe's walls), which rank 0
// adds in the serial order. On every rank count the probe files are the serial run's byte for byte
// (point, line, plane, height gauge and force probes, a 3D piston's force on its moving plate, a
// periodic channel's line across its period, and after a restart from a checkpoint written over
// the ranks), and a probe sample gathers neither the
// whole state nor the whole fields: the summary's counts of those gathers do not grow with the
// number of samples. The probes without `every` sample the output times (and t = 0) the same way
// (at_output_time_pieces), so the output times gather nothing for them either. The values themselves (the files print 12 digits) are the serial sample's to
// the bit, at a state the leapfrog has moved, also when the samples are handed a whole scene whose
// particles they must not read (the ranks other than 0 drop them after the set-up). Rank 0 runs the
// serial references.
#include <unistd.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "sphmol/cases/case_module.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/mpi_run.hpp"
#include "sphmol/probes/probe_observer.hpp"
#include "sphmol/rhs/kernel_pass.hpp"
#include "sphmol/rhs/sph_system.hpp"
#include "sphmol/run/checkpoint.hpp"
#include "sphmol/run/run_case.hpp"
#include "sphmol/time/integrator.hpp"
#include "run_into.hpp"
#include "support/files.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
namespace fs = std::filesystem;
using sphmol::parallel::testing::run_into;

namespace {

std::string source(const std::string& path) { return std::string(SPHMOL_SOURCE_DIR) + "/" + path; }

std::vector<std::string> probe_files(const nlohmann::json& summary) {
  std::vector<std::string> out;
  for (const auto& f : summary["files"]) {
    const std::string name = f.get<std::string>();
    if (name.rfind("probe_", 0) == 0 && name.size() > 4 && name.substr(name.size() - 4) == ".csv") out.push_back(name);
  }
  return out;
}

// A scratch folder shared by the ranks (rank 0's process id), per test and rank count.
fs::path scratch(const Communicator& comm, const std::string& name) {
  const long pid = comm.all_gather(static_cast<long>(::getpid()))[0];
  return fs::temp_directory_path() / ("sphmol-probes-" + name + "-" + std::to_string(pid) + "-" + std::to_string(comm.size()));
}

// Rank 0: the probe files of the folders `a` and `b` (the serial run's list `files`) are the same
// bytes. Returns how many were compared.
std::size_t same_probe_files(const std::vector<std::string>& files, const fs::path& a, const fs::path& b) {
  for (const auto& f : files) {
    INFO(f);
    const std::string serial = test_support::slurp(b / f);
    CHECK(serial.size() > 0);
    CHECK(test_support::slurp(a / f) == serial);
  }
  return files.size();
}

// The tank of examples/tank_obstacle_2d.yaml, coarse and short, with probes of every kind sampled
// every `every` seconds (and a line and a force probe at the output times).
Config tank(const std::string& every, const std::vector<std::string>& more = {}) {
  std::string yaml = test_support::slurp(source("examples/tank_obstacle_2d.yaml"));
  yaml = yaml.substr(0, yaml.find("\nprobes:")) + R"(
probes:
  - {name: bottom, type: point, at: [0.15, 0.05], fields: [p, rho, velocity], every: EVERY}
  - {name: corner, type: point, at: [0.585, 0.015], fields: [velocity, p], every: EVERY}
  - {name: dry, type: point, at: [0.3, 0.38], fields: [p], every: EVERY}
  - {name: section, type: line, from: [0.05, 0.02], to: [0.55, 0.28], points: 9, fields: [rho, p], every: EVERY}
  - {name: section_out, type: line, from: [0.05, 0.02], to: [0.55, 0.02], points: 7, fields: [p]}
  - {name: surface, type: height_gauge, at: [0.15], every: EVERY}
  - {name: surface_right, type: height_gauge, at: [0.5], range: [0.2, 0.35], every: EVERY}
  - {name: block, type: force, body: block}
  - {name: block_often, type: force, body: block, every: EVERY}
)";
  for (std::size_t at = yaml.find("EVERY"); at != std::string::npos; at = yaml.find("EVERY")) yaml.replace(at, 5, every);
  std::vector<std::string> set = {"discretization.spacing=0.02", "time.t_end=0.02", "output.times=[0.01,0.02]",
                                  "output.plots=false", "output.vtk=false"};
  set.insert(set.end(), more.begin(), more.end());
  return load_config_string(yaml, set);
}

// c over the ranks and (rank 0) serially: the same probe files. Returns the summary over the ranks.
nlohmann::json check_probes_equal_serial(const Config& c, const std::string& name, std::size_t files_expected) {
  const Communicator comm;
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, 1.2);
  const fs::path dir = scratch(comm, name);
  const nlohmann::json split = run_into(c, &partitioner, dir / "split");
  CHECK(split["status"] == "completed");
  comm.barrier();
  if (comm.rank() == 0) {
    INFO(name << ", " << comm.size() << " ranks");
    const nlohmann::json serial = run_into(c, nullptr, dir / "serial");
    REQUIRE(serial["status"] == "completed");
    const std::vector<std::string> files = probe_files(serial);
    CHECK(probe_files(split) == files);
    CHECK(same_probe_files(files, dir / "split", dir / "serial") == files_expected);
  }
  comm.barrier();
  if (comm.rank() == 0) fs::remove_all(dir);
  return split;
}

}  // namespace

TEST_CASE("distributed probes: sampled from each rank's own particles, the serial files to the bit",
          "[parallel][run][probes_reduced]") {
  SECTION("a tank with a block: points, lines, height gauges and forces") {
    check_probes_equal_serial(tank("0.002"), "tank", 9);
  }
  SECTION("the same with artificial viscosity (the force reads the sound speeds)") {
    check_probes_equal_serial(tank("0.004", {"discretization.artificial_viscosity.alpha=0.1"}), "tank-av", 9);
  }
  SECTION("a 3D tank with a moving piston: its force, gauges and a plane") {
    std::string yaml = test_support::slurp(source("examples/piston_3d.yaml"));
    REQUIRE(yaml.find("\nprobes:") != std::string::npos);
    yaml += R"(
  - {name: slab, type: plane, origin: [0.1, 0.02, 0.02], edge_1: [0.8, 0.0, 0.0], edge_2: [0.0, 0.15, 0.1], points: [7, 4], fields: [p, velocity], every: 0.005}
)";
    check_probes_equal_serial(load_config_string(yaml, {"time.t_end=0.03", "output.times=[0.015,0.03]", "output.plots=false",
                                                        "output.vtk=false"}),
                              "piston", 5);
  }
  SECTION("a periodic channel: a line across the period") {
    std::string yaml = test_support::slurp(source("verification/poiseuille.yaml"));
    yaml += R"(
probes:
  - {name: across, type: line, from: [0.0, 5.0e-4], to: [5.0e-4, 5.0e-4], points: 11, fields: [velocity, rho], every: 0.005}
  - {name: seam, type: point, at: [1.0e-6, 2.0e-5], fields: [velocity], every: 0.005}
)";
    check_probes_equal_serial(load_config_string(yaml, {"time.t_end=0.03", "output.times=[0.03]", "output.plots=false"}),
                              "channel", 2);
  }
}

TEST_CASE("distributed probes: ranks that build only their share of the scene write the serial files to the bit",
          "[parallel][probes][shares]") {
  // Every rank builds only the particles it starts with (Case::build_share): the probes' box comes
  // from the ranks' extremes, the force probes' walls are gathered from their shares; no rank holds
  // the whole scene after the set-up.
  const nlohmann::json split = check_probes_equal_serial(tank("0.004"), "tank-shares", 9);
  const Communicator comm;
  if (comm.rank() == 0) {
    const auto n = split["particles"]["fluid"].get<std::size_t>() + split["particles"]["wall"].get<std::size_t>();
    const auto built = split["parallel"]["scene_particles_built"].get<std::vector<std::size_t>>();
    const auto held = split["parallel"]["whole_scene_particles_held"].get<std::vector<std::size_t>>();
    const auto R = static_cast<std::size_t>(comm.size());
    REQUIRE(built.size() == R);
    REQUIRE(held.size() == R);
    for (std::size_t r = 0; r < R; ++r) {
      CHECK(built[r] == n * (r + 1) / R - n * r / R);
      CHECK(held[r] == (R == 1 ? n : 0));
    }
  }
}

TEST_CASE("distributed probes: a probe sample gathers neither the whole state nor the whole fields",
          "[parallel][run][probes_reduced]") {
  // The same run with 2 and with 10 samples per output interval: the gathers of the whole state and
  // of the whole fields stay those of checkpoints and the end.
  const Communicator comm;
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, 1.2);
  const fs::path dir = scratch(comm, "gathers");
  const nlohmann::json few = run_into(tank("0.005"), &partitioner, dir / "few");
  const nlohmann::json many = run_into(tank("0.001"), &partitioner, dir / "many");
  REQUIRE(few["status"] == "completed");
  REQUIRE(many["status"] == "completed");
  const auto& a = few["parallel"];
  const auto& b = many["parallel"];
  CHECK(b["whole_state_gathers"] == a["whole_state_gathers"]);
  CHECK(b["whole_field_gathers"] == a["whole_field_gathers"]);
  // The probes without `every` (a line, a force) sample the output times and t = 0 from the pieces
  // too: the end alone gathers the whole state, and nothing the whole fields.
  CHECK(a["whole_field_gathers"].get<long>() == 0);
  CHECK(a["whole_state_gathers"].get<long>() == 1);
  // One piece per sampling time: 0, 0.001, ..., 0.02.
  CHECK(b["owned_pieces"].get<long>() == 21);
  CHECK(a["owned_pieces"].get<long>() == 5);
  comm.barrier();
  if (comm.rank() == 0) fs::remove_all(dir);
}

TEST_CASE("distributed probes: a restart from a checkpoint written over the ranks continues the series",
          "[parallel][run][probes_reduced][restart]") {
  const Communicator comm;
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, 1.2);
  const fs::path dir = scratch(comm, "restart");
  const Config c = tank("0.002", {"output.checkpoint_every=0.01"});
  const nlohmann::json split = run_into(c, &partitioner, dir / "split");
  REQUIRE(split["status"] == "completed");
  comm.barrier();  // the checkpoint is on disk
  RunOptions opt;
  opt.write_files = true;
  opt.output_dir = (dir / "continued").string();
  opt.partitioner = &partitioner;
  opt.restart_from = (dir / "split" / checkpoint_name(0.01)).string();
  const nlohmann::json continued = run_case(c, opt);
  CHECK(continued["status"] == "completed");
  comm.barrier();
  if (comm.rank() == 0) {
    const nlohmann::json serial = run_into(c, nullptr, dir / "serial");
    REQUIRE(serial["status"] == "completed");
    const std::vector<std::string> files = probe_files(serial);
    CHECK(same_probe_files(files, dir / "continued", dir / "serial") == 9);
    CHECK(same_probe_files(files, dir / "split", dir / "serial") == 9);
  }
  comm.barrier();
  if (comm.rank() == 0) fs::remove_all(dir);
}

namespace {

// The whole scene as the ranks other than 0 hold it after the set-up, which drop its per-particle
// arrays (the probe observer was made before): here a system of the scene's domain whose particles
// are poisoned (masses, velocities, densities, normals, depths, viscosities NaN; positions moved by
// 1 m; walls of no body), so a sample that still read them would differ from the serial one.
template <int D>
std::unique_ptr<SphSystem<D>> blind_whole(const SphSystem<D>& whole) {
  Particles<D> P = whole.particles();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto poison = [&](std::vector<double>& c) { std::fill(c.begin(), c.end(), nan); };
  for (int d = 0; d < D; ++d) {
    poison(P.v[d]);
    poison(P.wall_normal[d]);
    for (double& x : P.x[d]) x += 1.0;
    for (double& x : P.x_ref[d]) x += 1.0;
  }
  poison(P.mass);
  poison(P.rho);
  poison(P.wall_depth);
  poison(P.rest_density);
  poison(P.viscosity);
  std::fill(P.body.begin(), P.body.end(), -1);
  return std::make_unique<SphSystem<D>>(std::move(P), whole.domain(), whole.smoothing_length(),
                                        make_kernel_pass<D>(whole.kernel_name()), std::vector<std::unique_ptr<Term<D>>>{},
                                        nullptr, CflLimits{});
}

// c advanced a few leapfrog steps to t_sample over the ranks and serially (the same state, to the
// bit), then sampled once each way, at t_sample (a sample time of the `every` probes) and as at an
// output time; every value of every probe compared as bits. `blind`: the pieces are sampled with
// blind_whole in place of the whole scene. n_every, n_outputs: the probes with and without `every`;
// finite_every, finite_outputs: how many of their values must be finite and non-zero at least.
template <int D>
void samples_equal_serial(const Config& c, double t_sample, bool blind, std::size_t n_every, std::size_t n_outputs,
                          std::size_t finite_every, std::size_t finite_outputs) {
  const Communicator comm;
  const auto advance = [&](OdeSystem& ode, double* y) {
    auto integrator = make_integrator(c.time);
    integrator->initialize(ode, 0.0, y);
    double t = 0.0;
    while (t < t_sample) t = integrator->step_toward(t_sample);
    return t;
  };
  using Values = std::map<std::string, std::vector<double>>;
  const auto recorder = [](Values& into) {
    return [&into](const std::string& name, double, const std::vector<double>& v) { into[name] = v; };
  };
  const OutputSink none{"", false};

  auto split_case = make_case<D>(c);
  auto whole = split_case->build(c);
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, 1.2);
  auto part = partitioner.partition(c, *whole, whole->initial_state(), 0.0);
  const double t = advance(part->system(), part->state().data());
  REQUIRE(t == t_sample);
  ProbeObserver<D> split(c, *whole);
  if (blind) whole = blind_whole<D>(*whole);  // the observer's set-up is done
  Values got, got_outputs;
  split.on_sample = recorder(got);
  const OwnedPiece<D> piece = part->owned_piece(t);
  split.at_time_pieces(*whole, piece, t, none);
  // The probes without `every`, as at an output time.
  split.on_sample = recorder(got_outputs);
  split.at_output_time_pieces(*whole, piece, t, none);

  if (comm.rank() == 0) {
    auto serial_case = make_case<D>(c);
    const auto sys = serial_case->build(c);
    std::vector<double> y = sys->initial_state(), scratch;
    REQUIRE(advance(*sys, y.data()) == t);
    sys->refresh_fields(t, y.data(), scratch);
    ProbeObserver<D> serial(c, *sys);
    Values want, want_outputs;
    serial.on_sample = recorder(want);
    serial.at_time(*sys, y.data(), t, none);
    serial.on_sample = recorder(want_outputs);
    serial.at_output(*sys, y.data(), t, none);
    REQUIRE(want.size() == n_every);
    REQUIRE(want_outputs.size() == n_outputs);
    const auto compare_bits = [&](const Values& wanted, Values& gotten) {
      CHECK(gotten.size() == wanted.size());
      std::size_t finite = 0;
      for (const auto& [name, w] : wanted) {
        INFO(name << ", " << comm.size() << " ranks");
        const std::vector<double>& g = gotten[name];
        REQUIRE(g.size() == w.size());
        for (std::size_t k = 0; k < w.size(); ++k) {
          INFO("value " << k << ": " << g[k] << " against " << w[k]);
          CHECK(std::memcmp(&g[k], &w[k], sizeof(double)) == 0);
          if (std::isfinite(w[k]) && w[k] != 0.0) ++finite;
        }
      }
      return finite;
    };
    CHECK(compare_bits(want, got) >= finite_every);
    CHECK(compare_bits(want_outputs, got_outputs) >= finite_outputs);
  }
  comm.barrier();
}

}  // namespace

TEST_CASE("distributed probes: the sampled values are the serial sample's to the bit", "[parallel][probes_reduced]") {
  // Of the `every` probes' 30 values 21 at least are non-trivial sums (pressures, densities, speeds,
  // heights, forces); of the others' 9 (the line's 7 pressures, the force's 2 components) 6.
  samples_equal_serial<2>(tank("0.002"), 0.004, false, 7, 2, 21, 6);
}

TEST_CASE("distributed probes: after the set-up the samples read no particle of the whole scene",
          "[parallel][probes_reduced][released]") {
  // The ranks other than 0 drop the whole scene's per-particle arrays after the set-up: the samples
  // over ranks take the fluid's masses from each rank's own system and the force probes' walls from
  // the observer's copy, and stay the serial ones to the bit.
  SECTION("the tank: points, lines, height gauges and a fixed body's force") {
    samples_equal_serial<2>(tank("0.002"), 0.004, true, 7, 2, 21, 6);
  }
  SECTION("the same with artificial viscosity and the Morris wall velocity (the walls' normals and depths)") {
    samples_equal_serial<2>(tank("0.002", {"discretization.artificial_viscosity.alpha=0.1", "discretization.wall_model=morris"}),
                            0.004, true, 7, 2, 21, 6);
  }
  const std::vector<std::string> short_run = {"time.t_end=0.03", "output.times=[0.015,0.03]", "output.plots=false",
                                               "output.vtk=false"};
  const std::string piston = test_support::slurp(source("examples/piston_3d.yaml"));
  SECTION("a 3D piston: the force on its moving plate (the walls' copy moves with its velocity)") {
    samples_equal_serial<3>(load_config_string(piston, short_run), 0.01, true, 4, 0, 4, 0);
  }
  SECTION("the piston's plate oscillating (the walls' copy follows the scene's motion)") {
    const std::string plate = "      velocity: [0.2, 0.0, 0.0]";
    const std::size_t at = piston.find(plate);
    REQUIRE(at != std::string::npos);
    std::string yaml = piston;
    yaml.replace(at, plate.size(), "      motion: {type: oscillation, amplitude: [0.01, 0.0, 0.0], frequency: 8}\n     ");
    samples_equal_serial<3>(load_config_string(yaml, short_run), 0.01, true, 4, 0, 4, 0);
  }
}
