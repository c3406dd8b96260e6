// SIGTERM / SIGINT during a run: exit code 128 + signal, summary.json with "status": "interrupted",
// and a checkpoint at the time reached, from which --restart finishes the run with the same final
// state as an uninterrupted run (leapfrog and leapfrog_kdk: bit for bit; the signal is seen between
// steps, so a CFL-stepped run also stops within one step).
#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <thread>
#include <utility>
#include <vector>

#include "run_helpers.hpp"

using namespace run_helpers;

TEST_CASE("signals: interrupted run writes checkpoint + summary and restarts exactly", "[signals][integration]") {
  for (const auto& [sig, integrator] : std::vector<std::pair<int, std::string>>{
           {SIGTERM, "leapfrog"}, {SIGINT, "leapfrog"}, {SIGTERM, "leapfrog_kdk"}}) {
    DYNAMIC_SECTION("signal " << sig << ", " << integrator) {
      const fs::path dir = scratch("signal-" + std::to_string(sig) + "-" + integrator);
      const std::string cfg = std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml";
      const std::vector<std::string> args = {"--config", cfg, "--set", "discretization.particles_across=20",
                                             "--set", "output.plots=false", "--set", "time.integrator=" + integrator,
                                             "--set", "time.t_end=1.0", "--set", "output.checkpoint_every=0.05", "-q",
                                             "--output", (dir / "run").string()};
      const pid_t pid = spawn(args, dir / "err");
      REQUIRE(pid > 0);
      // Signal once the run is under way (first checkpoint written, ~5% of the run).
      const auto t0 = std::chrono::steady_clock::now();
      while (!fs::exists(dir / "run" / "checkpoint-0.05") && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60))
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      ::kill(pid, sig);
      int status = 0;
      ::waitpid(pid, &status, 0);
      INFO(slurp(dir / "err"));
      REQUIRE(WIFEXITED(status));
      CHECK(WEXITSTATUS(status) == 128 + sig);
      const auto s = json_file(dir / "run" / "summary.json");
      CHECK(s["status"] == "interrupted");
      CHECK(s["signal"] == sig);
      const double t = s["t_reached"].get<double>();
      CHECK(t > 0.0);
      CHECK(t < 1.0);
      char name[64];
      std::snprintf(name, sizeof name, "checkpoint-%.10g", t);
      REQUIRE(fs::exists(dir / "run" / name / "checkpoint.json"));

      const auto r = sph_mol("-q --restart '" + (dir / "run" / name).string() + "' --output '" + (dir / "rest").string() + "'",
                             dir / "e2");
      INFO(r.err);
      REQUIRE(r.code == 0);
      CHECK(json_file(dir / "rest" / "summary.json")["status"] == "completed");
      // Uninterrupted reference run.
      REQUIRE(sph_mol(couette("--set time.integrator=" + integrator + " --set time.t_end=1.0 --set output.checkpoint_every=0.05 --output '" +
                              (dir / "whole").string() + "'"),
                      dir / "e3")
                  .code == 0);
      CHECK(json_file(dir / "rest" / "checkpoint-1" / "checkpoint.json")["state"] ==
            json_file(dir / "whole" / "checkpoint-1" / "checkpoint.json")["state"]);
    }
  }
}

TEST_CASE("signals: a CVODE run with one output time stops within a step of SIGTERM", "[signals][integration][cvode]") {
  // CVODE used to integrate to the next output time in one call and see the signal only there.
  const fs::path dir = scratch("signal-cvode");
  const std::string cfg = std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml";
  const std::vector<std::string> args = {"--config", cfg, "--set", "discretization.particles_across=20", "--set",
                                         "output.plots=false", "--set", "time.integrator=cvode_adams", "--set",
                                         "time.t_end=1000", "--set", "output.times=[]", "-q", "--output",
                                         (dir / "run").string()};
  const pid_t pid = spawn(args, dir / "err");
  REQUIRE(pid > 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // the scene is built, CVODE is stepping
  const auto sent = std::chrono::steady_clock::now();
  ::kill(pid, SIGTERM);
  int status = 0;
  bool ended = false;
  while (std::chrono::steady_clock::now() - sent < std::chrono::seconds(20))
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      ended = true;
      break;
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  if (!ended) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
  }
  INFO(slurp(dir / "err"));
  REQUIRE(ended);
  CHECK(seconds < 3.0);  // one step and the checkpoint: well under a second unloaded
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 143);
  const auto s = json_file(dir / "run" / "summary.json");
  CHECK(s["status"] == "interrupted");
  const double t = s["t_reached"].get<double>();
  CHECK(t > 0.0);
  CHECK(t < 1000.0);
  char name[64];
  std::snprintf(name, sizeof name, "checkpoint-%.10g", t);
  CHECK(fs::exists(dir / "run" / name / "checkpoint.json"));
}
