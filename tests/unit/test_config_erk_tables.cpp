// The ERK table names accepted by time.table, checked against SUNDIALS itself: each loads by
// name, matches the table of the same ARKODE_ERKTableID, and the list covers every id.
#include <catch2/catch.hpp>

#include <cstdio>  // arkode_butcher.h uses FILE without including it

#include <arkode/arkode_butcher_erk.h>

#include "sphmol/config/erk_tables.hpp"

TEST_CASE("config: explicit table list matches SUNDIALS", "[config]") {
  const auto& names = sphmol::erk_table_names();
  REQUIRE(names.size() == static_cast<std::size_t>(ARKODE_MAX_ERK_NUM - ARKODE_MIN_ERK_NUM + 1));
  for (std::size_t i = 0; i < names.size(); ++i) {
    INFO(names[i]);
    ARKodeButcherTable by_name = ARKodeButcherTable_LoadERKByName(names[i].c_str());
    ARKodeButcherTable by_id = ARKodeButcherTable_LoadERK(static_cast<ARKODE_ERKTableID>(ARKODE_MIN_ERK_NUM + i));
    REQUIRE(by_name != nullptr);
    REQUIRE(by_id != nullptr);
    CHECK(by_name->stages == by_id->stages);
    CHECK(by_name->q == by_id->q);
    CHECK(by_name->p == by_id->p);
    CHECK(by_name->b[by_name->stages - 1] == by_id->b[by_id->stages - 1]);
    ARKodeButcherTable_Free(by_name);
    ARKodeButcherTable_Free(by_id);
  }
  CHECK(sphmol::is_erk_table_name("ARKODE_DORMAND_PRINCE_7_4_5"));
  CHECK_FALSE(sphmol::is_erk_table_name("ARKODE_SDIRK_2_1_2"));   // implicit
  CHECK_FALSE(sphmol::is_erk_table_name("DORMAND_PRINCE_7_4_5"));  // deprecated id macro, not a name
  CHECK_FALSE(sphmol::is_erk_table_name("ARKODE_ERK_NONE"));
}
