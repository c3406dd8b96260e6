// Ghost (mirror) walls over ranks (parallel/distributed_system.hpp): every rank's local system
// mirrors its own fluid particles, owned and halo, so an owned particle's images come from its halo
// sources, in the serial order, with their sources' fields computed there as on their owners. The
// final state, the steps and the RHS evaluations are the serial run's to the bit on any rank count:
// the 2D Sod tube (free-slip walls along the tube, which every cut crosses; h by dh/dt, so the images
// follow a growing support), the lid-driven cavity (no-slip walls, a moving lid, corner images) and a
// water column (images under gravity carry a hydrostatic pressure; summation density: a two-radius
// halo whose outer rows need their own images). Rank 0 runs the serial reference. A column partly
// behind its bottom mirror, cut there by the partition, needs the halo's mirror margin
// (DistributedSystem::mirror_margin()): its distributed system is checked against the serial one.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "sphmol/cases/case_module.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/kernels/registry.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/distributed_system.hpp"
#include "sphmol/parallel/mpi_run.hpp"
#include "sphmol/run/run_case.hpp"
#include "sphmol/time/integrator.hpp"
#include "serial_reference.hpp"
#include "short_shock_tube.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
using namespace sphmol::parallel::testing;

namespace {

// The mirror walls are what this file is about. `evaluations_per_start`: as check_same_as_serial's.
Finished check_ghost_same_as_serial(const Config& c, double rebalance = 1.2, long evaluations_per_start = 1) {
  REQUIRE(c.discretization.boundary == "ghost");
  return check_same_as_serial(c, rebalance, evaluations_per_start);
}

Config cavity(const std::string& integrator) {
  return load_config(verification("cavity.yaml"),
                     {"discretization.boundary=ghost", "discretization.wall_model=prescribed", "discretization.particles_across=20",
                      "time.integrator=" + integrator, "time.t_end=0.1", "output.times=[0.05,0.1]", "output.plots=false"});
}

}  // namespace

TEST_CASE("distributed run: the 2D Sod tube with free-slip ghost walls equals the serial run bit for bit", "[parallel][run][ghost]") {
  SECTION("leapfrog, one partition") {
    const Config c = short_shock_tube("sod.yaml");
    REQUIRE(c.discretization.smoothing_length == "ode");
    const Finished split = check_ghost_same_as_serial(c);
    CHECK(split.summary["parallel"]["halo_plans"].get<long>() > 1);
  }
  SECTION("leapfrog, partitioned again at every re-plan") {
    const Finished split = check_ghost_same_as_serial(short_shock_tube("sod.yaml"), 1.0);
    if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 0);
  }
  SECTION("cvode_adams") { check_ghost_same_as_serial(short_shock_tube("sod.yaml", {"time.integrator=cvode_adams"}), 1.2, 0); }
}

TEST_CASE("distributed run: the lid-driven cavity with no-slip ghost walls equals the serial run bit for bit",
          "[parallel][run][ghost]") {
  // Four no-slip mirrors: the lid's images move at 2 U - v, the corners' particles have three images.
  SECTION("leapfrog, one partition") { check_ghost_same_as_serial(cavity("leapfrog")); }
  SECTION("leapfrog, partitioned again at every re-plan") {
    const Finished split = check_ghost_same_as_serial(cavity("leapfrog"), 1.0);
    if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 0);
  }
  SECTION("arkode_erk") { check_ghost_same_as_serial(cavity("arkode_erk"), 1.2, 0); }
}

TEST_CASE("distributed run: a water column with ghost walls under gravity equals the serial run bit for bit",
          "[parallel][run][ghost]") {
  // Summation density (two dependent passes: the halo reaches two list radii) with the bottom and side
  // mirrors, whose images carry p_i + rho_i g.(x_g - x_i).
  const Config c = load_config(verification("hydrostatic.yaml"),
                               {"discretization.boundary=ghost", "discretization.wall_pressure=rest", "fluid.eos.sound_speed=29.7",
                                "discretization.kernel=cubic_spline", "discretization.smoothing_ratio=1.3",
                                "discretization.density=summation", "discretization.particle_mass=summation",
                                "discretization.density_diffusion=0",
                                "fluid.eos.clamp_negative=true",
                                "discretization.particles_across=20", "time.dt=5.0e-4", "time.t_end=0.05",
                                "output.times=[0.025,0.05]", "output.plots=false"});
  const Finished split = check_ghost_same_as_serial(c);
  CHECK(split.summary["parallel"]["halo_depth_list_radii"].get<int>() >= 2);
}

TEST_CASE("distributed run: a water column that falls through its bottom mirror equals the serial run bit for bit",
          "[parallel][run][ghost]") {
  // Gravity of 100 m/s^2 switched on at once: the column slams into its bottom mirror and particles
  // pass behind it (y < 0 from t = 0.25 s on; the halo's mirror margin is reported, > 0). A particle
  // behind a mirror has images of its neighbours nearer than the neighbours themselves, and its own
  // images lie in front of the mirror. (Setting the margin to zero does not change this run: no pair
  // fell in the band the margin adds while it crossed a rank boundary; the next test's scene does.)
  const Config c = load_config(verification("hydrostatic.yaml"),
                               {"discretization.boundary=ghost", "discretization.wall_pressure=rest", "fluid.eos.sound_speed=29.7",
                                "discretization.kernel=cubic_spline", "discretization.smoothing_ratio=1.3",
                                "discretization.density=continuity", "fluid.eos.clamp_negative=true",
                                "geometry.box=[0.25, 0.6]", "discretization.particles_across=5", "time.dt=2.5e-4", "time.t_end=0.3",
                                "discretization.skin=0.1", "fluid.body_force=[0, -100]", "fluid.body_force_ramp=0",
                                "output.times=[0.15,0.3]", "output.plots=false"});
  const Finished split = check_ghost_same_as_serial(c);
  CHECK(split.summary["parallel"]["ghost_mirror_margin_max"].get<double>() > 0.0);
}

namespace {

// The state the run starts from: the column lowered so that the rows of one rank's share (half of them
// on one rank) lie behind the bottom mirror, a quarter spacing off the lattice so that no image falls
// on a particle. RCB cuts the tall column into horizontal slabs, one cut at the mirror or a row above
// it: the ranks above read images of the deep particles of the rank below, nearer to them than their
// sources by up to twice the depth, which lie farther than the support plus the skin from their slabs
// (on two ranks the rank below, wholly behind the mirror, reads images of particles in front so too).
std::vector<double> lowered_through_mirror(const SphSystem<2>& sys, int ranks) {
  std::vector<double> y = sys.initial_state();
  const std::size_t n = sys.layout().n, at = sys.layout().position(1);
  const auto [lo, hi] = std::minmax_element(y.begin() + static_cast<long>(at), y.begin() + static_cast<long>(at + n));
  const double dx = sys.spacing();
  const long rows = std::lround((*hi - *lo) / dx) + 1;
  const long behind = rows / std::max(2, ranks);
  const double drop = *lo + (static_cast<double>(behind) - 0.25) * dx;  // the lowest row at (0.25 - behind) dx
  for (std::size_t i = 0; i < n; ++i) y[at + i] -= drop;
  return y;
}

// The pairs that only the margin brings onto a rank: a fluid row q reads the image, through the bottom
// mirror y = 0, of a particle s that another rank owns and that lies farther than the support plus
// the skin from the bounding box of the particles q's rank owns. `owner`: each fluid particle's rank.
std::size_t pairs_beyond_plain_halo(const std::vector<double>& y, std::size_t n, const std::vector<int>& owner, int ranks,
                                    double support, double skin) {
  const double* x[2] = {y.data(), y.data() + n};
  std::vector<std::array<double, 4>> box(static_cast<std::size_t>(ranks), {INFINITY, -INFINITY, INFINITY, -INFINITY});
  for (std::size_t i = 0; i < n; ++i) {
    auto& b = box[static_cast<std::size_t>(owner[i])];
    b = {std::min(b[0], x[0][i]), std::max(b[1], x[0][i]), std::min(b[2], x[1][i]), std::max(b[3], x[1][i])};
  }
  std::size_t pairs = 0;
  for (std::size_t s = 0; s < n; ++s) {
    if (!(x[1][s] < support)) continue;  // no image: as far from the mirror as the support
    for (std::size_t q = 0; q < n; ++q) {
      if (owner[q] == owner[s] || std::hypot(x[0][q] - x[0][s], x[1][q] + x[1][s]) >= support) continue;
      const auto& b = box[static_cast<std::size_t>(owner[q])];
      const double gx = std::max({b[0] - x[0][s], x[0][s] - b[1], 0.0}), gy = std::max({b[2] - x[1][s], x[1][s] - b[3], 0.0});
      pairs += std::hypot(gx, gy) > support + skin;
    }
  }
  return pairs;
}

}  // namespace

TEST_CASE("distributed system: a water column partly behind its bottom mirror evaluates and steps as the serial system bit for bit",
          "[parallel][ghost][mirror_margin]") {
  // The falling column's scene (5 x 12 particles, cubic spline at h = 1.3 dx, skin 0.1 h), built twice
  // on every rank: the serial reference and the whole scene the distributed system is made from.
  const Communicator comm;
  const Config c = load_config(verification("hydrostatic.yaml"),
                               {"discretization.boundary=ghost", "discretization.wall_pressure=rest", "fluid.eos.sound_speed=29.7",
                                "discretization.kernel=cubic_spline", "discretization.smoothing_ratio=1.3",
                                "discretization.density=continuity", "fluid.eos.clamp_negative=true",
                                "geometry.box=[0.25, 0.6]", "discretization.particles_across=5", "time.dt=2.5e-4",
                                "discretization.skin=0.1", "fluid.body_force=[0, -100]", "fluid.body_force_ramp=0"});
  const auto serial_case = make_case<2>(c), split_case = make_case<2>(c);
  const auto serial = serial_case->build(c), whole = split_case->build(c);
  const std::vector<double> y0 = lowered_through_mirror(*serial, comm.size());
  REQUIRE(y0 == lowered_through_mirror(*whole, comm.size()));

  DistributedSystem<2> split(comm, c, *whole, y0, 0.0, MpiRunPartitioner::default_tolerance, 1.2);
  std::vector<double> y = split.local_part(y0), f(split.size()), f_whole;
  // The partition puts a cut at the mirror (more than one rank) and some image beyond the plain halo.
  const std::size_t n = serial->layout().n;
  std::vector<std::array<std::uint64_t, 2>> mine;
  for (const std::uint64_t g : split.gid()) mine.push_back({g, static_cast<std::uint64_t>(comm.rank())});
  std::vector<int> owner(n, -1);
  for (const auto& [g, r] : comm.all_gather_v(mine)) owner[g] = static_cast<int>(r);
  const double h = serial->smoothing_length(), support = kernel_info<2>(c.discretization.kernel).support * h;
  const std::size_t beyond = pairs_beyond_plain_halo(y0, n, owner, comm.size(), support, c.discretization.skin * h);
  INFO(beyond << " image pairs beyond a halo of the support plus the skin");
  CHECK((beyond > 0) == (comm.size() > 1));
  split.rhs(0.0, y.data(), f.data());
  // The whole rates on rank 0 only: the other ranks take part in the gather and receive nothing.
  const bool root = split.gather(f.data(), f_whole);
  CHECK(root == (comm.rank() == 0));
  CHECK((root || f_whole.empty()));
  std::vector<double> f_serial(serial->size());
  serial->rhs(0.0, y0.data(), f_serial.data());
  INFO(comm.size() << " ranks, rank " << comm.rank() << ", " << f_serial.size() << " values");
  CHECK(std::all_of(f_serial.begin(), f_serial.end(), [](double v) { return std::isfinite(v); }));
  CHECK(split.stats().mirror_margin_max > 0.0);
  if (root) CHECK(differing_bits(f_whole, f_serial) == 0);

  // Then 0.02 s of leapfrog steps, the particles moving (and the halo planned again) as they go.
  const double t_end = 0.02;
  std::vector<double> y_serial = y0, y_whole;
  const auto serial_steps = make_integrator(c.time), split_steps = make_integrator(c.time);
  serial_steps->initialize(*serial, 0.0, y_serial.data());
  serial_steps->advance(t_end);
  split_steps->initialize(split, 0.0, y.data());
  split_steps->advance(t_end);
  split.gather(y.data(), y_whole);
  CHECK(std::all_of(y_serial.begin(), y_serial.end(), [](double v) { return std::isfinite(v); }));
  CHECK(split_steps->stats().steps == serial_steps->stats().steps);
  INFO("halo plans " << split.stats().plans);
  if (root) CHECK(differing_bits(y_whole, y_serial) == 0);
}
