#include "sphmol/config/ark_pairs.hpp"

namespace sphmol {

namespace {
const std::vector<ArkPair>& pairs() {
  static const std::vector<ArkPair> p{
      {"ARKODE_ARK324L2SA_ERK_4_2_3", "ARKODE_ARK324L2SA_DIRK_4_2_3"},
      {"ARKODE_ARK436L2SA_ERK_6_3_4", "ARKODE_ARK436L2SA_DIRK_6_3_4"},
      {"ARKODE_ARK437L2SA_ERK_7_3_4", "ARKODE_ARK437L2SA_DIRK_7_3_4"},
      {"ARKODE_ARK548L2SA_ERK_8_4_5", "ARKODE_ARK548L2SA_DIRK_8_4_5"},
      {"ARKODE_ARK548L2SAb_ERK_8_4_5", "ARKODE_ARK548L2SAb_DIRK_8_4_5"},
  };
  return p;
}
}  // namespace

std::optional<ArkPair> ark_pair_of(const std::string& table) {
  for (const auto& p : pairs())
    if (p.erk == table || p.dirk == table) return p;
  return std::nullopt;
}

std::vector<std::string> ark_pair_names() {
  std::vector<std::string> names;
  for (const auto& p : pairs()) names.push_back(p.erk);
  return names;
}

}  // namespace sphmol
