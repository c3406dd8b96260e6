// The summary's step and solver counters continue from a checkpoint: a Couette run stopped at
// t = 0.05 and restarted to 0.1 reports the run's totals, not the restarted process's own. The
// leapfrog restarts bit for bit, so its counters equal the uninterrupted run's; the SUNDIALS
// integrators start their history again (other steps after the restart), so their totals are checked
// as the checkpoint's counts plus what the restarted process counted, measured by restarting from
// a copy of the checkpoint with its counters removed (also how a checkpoint written before they were
// saved loads: missing counters are 0).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "run_helpers.hpp"

using namespace run_helpers;

namespace {

struct Counter {
  std::string summary;     // "steps", "rejected_steps" at the top; others in the "integrator" object
  std::string checkpoint;  // its key in the checkpoint's integrator_state
};

long summary_count(const nlohmann::json& s, const std::string& key) {
  if (key == "steps" || key == "rejected_steps") return s.at(key).get<long>();
  return s.at("integrator").at(key).get<long>();
}

}  // namespace

TEST_CASE("restart: step and solver counters continue from the checkpoint", "[restart][integration][imex]") {
  const std::vector<Counter> steps{{"steps", "steps"}, {"rejected_steps", "rejected_steps"}};
  const std::vector<Counter> limited{{"stability_limited_steps", "stability_limited_steps"},
                                     {"accuracy_limited_steps", "accuracy_limited_steps"}};
  struct Case {
    std::string integrator, extra;
    std::vector<Counter> counters;  // besides steps and rejected_steps
    bool bit_identical;
  };
  const std::vector<Case> cases{
      {"cvode_adams", "", {}, false},
      {"arkode_erk", "", limited, false},
      {"arkode_imex",
       " --set time.table=ARKODE_ARK324L2SA_ERK_4_2_3",
       {{"stage_solves", "stage_solves"},
        {"implicit_solves", "stage_solves"},
        {"krylov_iterations", "krylov_iterations"},
        limited[0],
        limited[1]},
       false},
      {"leapfrog_imex", "", {{"implicit_solves", "implicit_solves"}, {"krylov_iterations", "krylov_iterations"}}, true},
  };
  for (const auto& c : cases) {
    DYNAMIC_SECTION(c.integrator) {
      const fs::path dir = scratch("restart-counters-" + c.integrator);
      const std::string common =
          couette("--set output.times=[0.05] --set output.checkpoint_every=0.05 --set time.integrator=" + c.integrator + c.extra);
      REQUIRE(sph_mol(common + " --output '" + (dir / "whole").string() + "' --set time.t_end=0.1", dir / "e1").code == 0);
      REQUIRE(sph_mol(common + " --output '" + (dir / "first").string() + "' --set time.t_end=0.05", dir / "e2").code == 0);
      const fs::path cp = dir / "first" / "checkpoint-0.05";
      const auto restart = [&](const fs::path& from, const std::string& out) {
        const auto r = sph_mol("-q --restart '" + from.string() + "' --output '" + (dir / out).string() + "' --set time.t_end=0.1",
                               dir / ("e-" + out));
        INFO(r.err);
        REQUIRE(r.code == 0);
        return json_file(dir / out / "summary.json");
      };
      const auto restarted = restart(cp, "second");
      // The same checkpoint without its counters: the restarted process's own counts.
      const fs::path bare = dir / "bare" / "checkpoint-0.05";
      fs::create_directories(bare.parent_path());
      fs::copy(cp, bare, fs::copy_options::recursive);
      auto j = json_file(bare / "checkpoint.json");
      const nlohmann::json saved = j.at("integrator_state");
      auto& state = j["integrator_state"];
      for (const char* key : {"stage_solves", "implicit_solves", "krylov_iterations", "stability_limited_steps", "accuracy_limited_steps"})
        state.erase(key);
      // arkode_erk, arkode_imex and the leapfrogs have always saved steps (required); cvode_adams saved nothing.
      for (const char* key : {"steps", "rejected_steps"})
        if (state.contains(key)) {
          if (c.integrator == "cvode_adams") state.erase(key);
          else state[key] = 0;
        }
      std::ofstream(bare / "checkpoint.json") << j.dump();
      const auto own = restart(bare, "own");
      const auto whole = json_file(dir / "whole" / "summary.json");

      std::vector<Counter> all = steps;
      all.insert(all.end(), c.counters.begin(), c.counters.end());
      for (const auto& k : all) {
        INFO(c.integrator << " " << k.summary);
        const long total = summary_count(restarted, k.summary), after = summary_count(own, k.summary);
        const long before = k.summary == "rejected_steps" && !saved.contains(k.checkpoint) ? 0 : saved.value(k.checkpoint, -1L);
        INFO("checkpoint " << before << ", restarted process " << after << ", restarted total " << total << ", uninterrupted "
                           << summary_count(whole, k.summary));
        CHECK(before >= 0);
        CHECK(total == before + after);
        if (c.bit_identical) CHECK(total == summary_count(whole, k.summary));
      }
      // Counts that are positive on both sides of the checkpoint (the step count and the solves).
      for (const auto& k : all)
        if (k.summary != "rejected_steps" && k.summary.find("limited") == std::string::npos) {
          INFO(c.integrator << " " << k.summary);
          CHECK(saved.value(k.checkpoint, 0L) > 0);
          CHECK(summary_count(own, k.summary) > 0);
        }
    }
  }
}
