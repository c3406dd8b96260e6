// The per-output-time files a case's plot draws (run/timed_output_files.hpp): every name the run
// wrote as <prefix><t>.csv, sorted by t, and nothing else.
#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

#include "sphmol/run/timed_output_files.hpp"

using namespace sphmol;

TEST_CASE("timed output files: whole-number times are found, other names are not", "[output][plots]") {
  // strtod took "1." of "profile_t1.csv" and left "csv": the file of t = 1 (the Couette and Poiseuille
  // end time) was never drawn, and a restart that wrote only it drew no plot at all.
  OutputSink out{"unused", false};
  for (const char* f : {"profile_t1.csv", "profile_t0.5.csv", "profile_t1e-05.csv", "profile_t20.csv", "profile_t0.1125.csv",
                        "profile_t.csv", "profile_tx.csv", "profile_t1.csv.bak", "profile_t1'.csv", "midline_t1.csv", "summary.json"})
    out.record(f);
  const auto files = timed_output_files(out, "profile_t");
  const std::vector<std::pair<double, std::string>> expected = {
      {1e-05, "profile_t1e-05.csv"}, {0.1125, "profile_t0.1125.csv"}, {0.5, "profile_t0.5.csv"}, {1.0, "profile_t1.csv"}, {20.0, "profile_t20.csv"}};
  CHECK(files == expected);
  CHECK(timed_output_files(out, "midline_t") == std::vector<std::pair<double, std::string>>{{1.0, "midline_t1.csv"}});
}
