#pragma once
// The additive Runge-Kutta ImEx pairs of SUNDIALS 6.4.1 (Kennedy & Carpenter 2003, 2019): an
// explicit table in arkode/arkode_butcher_erk.h and its implicit partner in arkode_butcher_dirk.h,
// named alike with ERK and DIRK (ARKODE_ARK324L2SA_ERK_4_2_3 / ARKODE_ARK324L2SA_DIRK_4_2_3).
// time.table names a pair by either of its tables. A unit test loads every table listed.
#include <optional>
#include <string>
#include <vector>

namespace sphmol {

struct ArkPair {
  std::string erk, dirk;
};
// The pair `table` (either half) belongs to; nullopt when it is not one half of a pair.
std::optional<ArkPair> ark_pair_of(const std::string& table);
// The explicit table names of all pairs (for messages and docs).
std::vector<std::string> ark_pair_names();

}  // namespace sphmol
