#pragma once
// An integrator named as in the study command lines: leapfrog, leapfrog_kdk, arkode_erk,
// arkode_erk:TABLE, cvode_adams, leapfrog_imex, arkode_imex, arkode_imex:TABLE (either table of an
// ARK ImEx pair). Applies itself to a TimeConfig and knows its nominal order.
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

namespace sphmol {

struct IntegratorSpec {
  std::string label;       // as given, e.g. "arkode_erk:ARKODE_HEUN_EULER_2_1_2"
  std::string integrator;  // time.integrator
  std::string table;       // time.table (arkode_erk, arkode_imex)
  // Has an error-controlled mode (rtol sweep in compare); the leapfrogs have fixed or CFL steps only.
  bool adaptive() const { return integrator == "arkode_erk" || integrator == "cvode_adams" || integrator == "arkode_imex"; }
  // Nominal order: 2 for the leapfrogs, the Butcher table's q for ERK and ARK; 0 for cvode_adams (variable).
  int order() const;
  // Sets time.integrator / time.table; leaves the accuracy setting to the study.
  void apply(TimeConfig& time) const;
};

// Parses a comma-separated list; throws std::invalid_argument naming a bad entry.
// `default_table` is used for a bare "arkode_erk"; a bare "arkode_imex" takes ARKODE_ARK324L2SA_ERK_4_2_3.
std::vector<IntegratorSpec> parse_integrator_list(const std::string& list, const std::string& default_table);

// Nominal order q of a SUNDIALS ERK table, read from the table itself.
int erk_table_order(const std::string& table);

}  // namespace sphmol
