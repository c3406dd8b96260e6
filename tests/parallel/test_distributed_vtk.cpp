// VTK output over ranks (run/vtk_observer.hpp, at_output_pieces): each rank writes the particles it
// owns as a piece, rank 0 a .pvtp naming the pieces, and the collection lists the .pvtp files. On
// every rank count the pieces of each output together hold exactly the particles of the serial
// run's .vtp (fluid, walls and ghost images), with the same arrays and values to the bit, and no
// particle twice (ghost images, all with id -1, as sorted multisets); the collection lists the same
// times and groups; the summary lists every piece. Rank 0 runs the serial reference.
#include <unistd.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/mpi_run.hpp"
#include "sphmol/run/run_case.hpp"
#include "run_into.hpp"
#include "short_shock_tube.hpp"
#include "support/vtk_pieces.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
namespace fs = std::filesystem;
using sphmol::parallel::testing::run_into;

namespace {

// Which groups the serial run wrote files of (known on rank 0).
struct Groups {
  bool walls = false, ghosts = false;
};

// The pieces of the run over ranks against the serial files, output by output and group by group.
Groups check_pieces_equal_serial(const Config& c, const std::string& name, double rebalance = 1.2) {
  const Communicator comm;
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, rebalance);
  const long pid = comm.all_gather(static_cast<long>(::getpid()))[0];
  const fs::path dir = fs::temp_directory_path() / ("sphmol-vtk-" + name + "-" + std::to_string(pid) + "-" + std::to_string(comm.size()));
  Groups groups;
  const nlohmann::json split = run_into(c, &partitioner, dir / "split");
  CHECK(split["status"] == "completed");
  comm.barrier();
  if (comm.rank() == 0) {
    const nlohmann::json serial = run_into(c, nullptr, dir / "serial");
    REQUIRE(serial["status"] == "completed");
    const auto pvd_split = mini_xml::parse(test_support::slurp(dir / "split" / "particles.pvd"));
    const auto pvd_serial = mini_xml::parse(test_support::slurp(dir / "serial" / "particles.pvd"));
    const auto sets = pvd_split->child("Collection")->all("DataSet");
    const auto serial_sets = pvd_serial->child("Collection")->all("DataSet");
    REQUIRE(sets.size() == serial_sets.size());
    REQUIRE(sets.size() >= 2);
    const std::vector<std::string> files = split["files"].get<std::vector<std::string>>();
    const auto listed = [&](const std::string& f) { return std::find(files.begin(), files.end(), f) != files.end(); };
    for (std::size_t k = 0; k < sets.size(); ++k) {
      const auto& a = sets[k]->attr;
      const auto& b = serial_sets[k]->attr;
      CHECK(a.at("timestep") == b.at("timestep"));
      CHECK(a.at("part") == b.at("part"));
      CHECK(a.at("name") == b.at("name"));
      groups.walls = groups.walls || b.at("name") == "walls";
      groups.ghosts = groups.ghosts || b.at("name") == "ghosts";
      // fluid_0001.vtp over ranks: fluid_0001.pvtp, with the pieces fluid_0001_r<rank>.vtp.
      const std::string stem = b.at("file").substr(0, b.at("file").size() - 4);
      CHECK(a.at("file") == stem + ".pvtp");
      CHECK(listed(stem + ".pvtp"));
      for (int r = 0; r < comm.size(); ++r) CHECK(listed(stem + "_r" + std::to_string(r) + ".vtp"));
      CHECK_FALSE(fs::exists(dir / "split" / b.at("file")));
      const vtk_pieces::Particles pieces = vtk_pieces::read_pvtp(dir / "split" / a.at("file"));
      const vtk_pieces::Particles whole = vtk_pieces::read_vtp(dir / "serial" / b.at("file"));
      INFO(comm.size() << " ranks, " << a.at("file"));
      CHECK(pieces.pieces == static_cast<std::size_t>(comm.size()));
      CHECK(whole.values.size() + whole.unkeyed.size() > 0);
      CHECK(vtk_pieces::difference(pieces, whole) == "");
    }
  }
  comm.barrier();
  if (comm.rank() == 0) fs::remove_all(dir);
  return groups;
}

}  // namespace

TEST_CASE("distributed run: the VTK pieces of every rank are the serial run's .vtp files", "[parallel][run][vtk]") {
  // Continuity density with dynamic wall densities in the state; the particles move far enough to
  // plan the halo again between outputs.
  const Config dam = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml",
                                 {"discretization.spacing=0.04", "time.t_end=0.06", "output.times=[0.03,0.06]",
                                  "output.plots=false", "output.vtk=true"});
  const bool root = Communicator().rank() == 0;
  SECTION("the dam break") { CHECK((check_pieces_equal_serial(dam, "dam").walls || !root)); }
  SECTION("the dam break, partitioned again at every re-plan") {
    CHECK((check_pieces_equal_serial(dam, "dam-rebalanced", 1.0).walls || !root));
  }
  // Summation density (a two-radius halo) and wall velocities.
  SECTION("Couette") {
    const bool walls = check_pieces_equal_serial(
        load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml",
                    {"discretization.particles_across=20", "time.t_end=0.02", "output.times=[0.01,0.02]", "output.plots=false",
                     "output.vtk=true"}),
        "couette").walls;
    CHECK((walls || !root));
  }
  // Wall pressures extrapolated from the fluid: walls the sloshing surface has left hold their own
  // density's pressure, not a value kept from an earlier evaluation (which differs between a rank's
  // local system, made anew at each halo plan, and the serial one).
  SECTION("a tank with extrapolated wall pressures") {
    const bool walls = check_pieces_equal_serial(
        load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/scene_tank.yaml",
                    {"time.t_end=0.5", "output.times=[0.25,0.5]", "output.vtk=true"}),
        "tank").walls;
    CHECK((walls || !root));
  }
  // Further state blocks (energy, smoothing length) as point arrays of the fluid pieces.
  SECTION("a shock tube with the energy equation and variable h") {
    check_pieces_equal_serial(short_shock_tube("sod_1d.yaml", {"output.vtk=true"}), "sod");
  }
}

TEST_CASE("distributed run: the ghost pieces of every rank hold the serial run's ghost images", "[parallel][run][vtk][ghost]") {
  // No-slip mirrors on all four sides, a moving lid, three images at each corner particle: each rank
  // writes the images of the fluid it owns (not of its halo copies), so the pieces hold every image
  // of the serial file once. Ghost images carry no id, so they are compared as sorted multisets.
  const auto cavity = [](const std::string& integrator) {
    return load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/cavity.yaml",
                       {"discretization.boundary=ghost", "discretization.wall_model=prescribed",
                        "discretization.particles_across=20", "time.integrator=" + integrator, "time.t_end=0.1",
                        "output.times=[0.05,0.1]", "output.plots=false", "output.vtk=true", "output.vtk_ghosts=true"});
  };
  const bool root = Communicator().rank() == 0;
  SECTION("leapfrog") { CHECK((check_pieces_equal_serial(cavity("leapfrog"), "cavity-ghosts").ghosts || !root)); }
  SECTION("leapfrog, partitioned again at every re-plan") {
    CHECK((check_pieces_equal_serial(cavity("leapfrog"), "cavity-ghosts-rebalanced", 1.0).ghosts || !root));
  }
  // A variable h (the 2D Sod tube, h by dh/dt): images are made within kappa times the largest h of
  // all ranks, as in the serial run, not of each rank's own particles.
  SECTION("the 2D Sod tube with free-slip ghost walls and a variable h") {
    CHECK((check_pieces_equal_serial(short_shock_tube("sod.yaml", {"output.vtk=true", "output.vtk_ghosts=true"}), "sod-ghosts")
               .ghosts ||
           !root));
  }
}
