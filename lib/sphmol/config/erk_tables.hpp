#pragma once
// Names of the SUNDIALS explicit (ERK) Butcher tables, from ARKODE_ERKTableID in
// arkode/arkode_butcher_erk.h (SUNDIALS 6.4.1). Kept here because
// ARKodeButcherTable_LoadERKByName prints "[ARKODE ERROR] Unknown Butcher table" to stderr for
// an unknown name; a unit test loads every listed name and checks the list is complete.
#include <string>
#include <vector>

namespace sphmol {

const std::vector<std::string>& erk_table_names();
bool is_erk_table_name(const std::string& name);

}  // namespace sphmol
