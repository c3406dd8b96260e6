#include "sphmol/config/erk_tables.hpp"

#include <algorithm>

namespace sphmol {

const std::vector<std::string>& erk_table_names() {
  // In ARKODE_ERKTableID order (ids ARKODE_MIN_ERK_NUM .. ARKODE_MAX_ERK_NUM).
  static const std::vector<std::string> names = {
      "ARKODE_HEUN_EULER_2_1_2",     "ARKODE_BOGACKI_SHAMPINE_4_2_3", "ARKODE_ARK324L2SA_ERK_4_2_3",
      "ARKODE_ZONNEVELD_5_3_4",      "ARKODE_ARK436L2SA_ERK_6_3_4",   "ARKODE_SAYFY_ABURUB_6_3_4",
      "ARKODE_CASH_KARP_6_4_5",      "ARKODE_FEHLBERG_6_4_5",         "ARKODE_DORMAND_PRINCE_7_4_5",
      "ARKODE_ARK548L2SA_ERK_8_4_5", "ARKODE_VERNER_8_5_6",           "ARKODE_FEHLBERG_13_7_8",
      "ARKODE_KNOTH_WOLKE_3_3",      "ARKODE_ARK437L2SA_ERK_7_3_4",   "ARKODE_ARK548L2SAb_ERK_8_4_5",
  };
  return names;
}

bool is_erk_table_name(const std::string& name) {
  const auto& n = erk_table_names();
  return std::find(n.begin(), n.end(), name) != n.end();
}

}  // namespace sphmol
