// A SIGINT/SIGTERM that arrives while gnuplot draws the plots at the end of a run is not lost: gnuplot
// is stopped, no PNG is left under its name, and sph-mol ends as interrupted (exit 128 + signal,
// summary "status": "interrupted", a checkpoint at t_end, from which a restart draws the plots and
// completes the run). A stand-in gnuplot that never finishes
// (first on PATH) makes the timing certain.
#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <fstream>
#include <thread>
#include <vector>

#include "run_helpers.hpp"

using namespace run_helpers;

TEST_CASE("signals: a signal during the plots ends the run as interrupted", "[signals][integration][plots]") {
  for (const int sig : {SIGTERM, SIGINT}) {
    DYNAMIC_SECTION("signal " << sig) {
      const fs::path dir = scratch("plot-signal-" + std::to_string(sig));
      const fs::path bin = dir / "bin";
      fs::create_directories(bin);
      {
        std::ofstream g(bin / "gnuplot");
        g << "#!/bin/sh\n: > gnuplot-started\nexec sleep 30\n";  // runs in the output directory
      }
      fs::permissions(bin / "gnuplot", fs::perms::owner_all);
      const fs::path out = dir / "run";
      const std::string path_env = "PATH=" + bin.string() + ":/usr/bin:/bin";
      const std::vector<std::string> args = {"--config", std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml", "-q",
                                             "--set", "discretization.particles_across=10", "--set", "geometry.channel_length=1.0e-3", "--set", "time.t_end=0.002",
                                             "--set", "output.times=[0.002]", "--set", "output.plots=true",
                                             "--output", out.string()};
      const pid_t pid = ::fork();
      REQUIRE(pid >= 0);
      if (pid == 0) {
        std::freopen((dir / "err").c_str(), "w", stderr);
        std::freopen("/dev/null", "w", stdout);
        ::putenv(const_cast<char*>(path_env.c_str()));
        std::vector<char*> argv{const_cast<char*>(SPHMOL_BINARY)};
        for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(SPHMOL_BINARY, argv.data());
        ::_exit(127);
      }
      const auto t0 = std::chrono::steady_clock::now();
      while (!fs::exists(out / "gnuplot-started") && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60))
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      REQUIRE(fs::exists(out / "gnuplot-started"));
      const auto t1 = std::chrono::steady_clock::now();
      ::kill(pid, sig);
      int status = 0;
      ::waitpid(pid, &status, 0);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
      INFO(slurp(dir / "err"));
      REQUIRE(WIFEXITED(status));
      CHECK(WEXITSTATUS(status) == 128 + sig);
      CHECK(seconds < 10.0);  // not held up by the 30 s gnuplot
      const auto s = json_file(out / "summary.json");
      CHECK(s["status"] == "interrupted");
      CHECK(s["signal"] == sig);
      CHECK(s["t_reached"].get<double>() == Approx(0.002));
      CHECK(fs::exists(out / "checkpoint-0.002" / "checkpoint.json"));
      CHECK_FALSE(fs::exists(out / "profiles.png"));
      CHECK(fs::exists(out / "plot_profiles.gp"));  // docs/output.md: draw the plot with it
      for (const auto& e : fs::directory_iterator(out))  // no temporary (the run's lock file stays)
        if (e.path().filename() != ".sph-mol.lock") CHECK(e.path().filename().string().front() != '.');
      // The checkpoint at t_end finishes the run: the plots drawn (by the real gnuplot), the run completed.
      const auto r = sph_mol("-q --restart '" + (out / "checkpoint-0.002").string() + "'", dir / "restart-err");
      INFO(slurp(dir / "restart-err"));
      CHECK(r.code == 0);
      const auto done = json_file(out / "summary.json");
      CHECK(done["status"] == "completed");
      CHECK(done["steps"] == s["steps"]);
      CHECK(fs::exists(out / "profiles.png"));
    }
  }
}
