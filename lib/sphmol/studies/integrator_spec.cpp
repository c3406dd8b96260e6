#include "sphmol/studies/integrator_spec.hpp"

#include <arkode/arkode_butcher_erk.h>

#include <stdexcept>

#include "sphmol/config/ark_pairs.hpp"
#include "sphmol/config/erk_tables.hpp"

namespace sphmol {

int erk_table_order(const std::string& table) {
  if (!is_erk_table_name(table)) throw std::invalid_argument("'" + table + "' is not a SUNDIALS ERK table");
  ARKodeButcherTable B = ARKodeButcherTable_LoadERKByName(table.c_str());
  if (!B) throw std::invalid_argument("cannot load ERK table '" + table + "'");
  const int q = B->q;
  ARKodeButcherTable_Free(B);
  return q;
}

int IntegratorSpec::order() const {
  if (integrator == "leapfrog" || integrator == "leapfrog_kdk" || integrator == "leapfrog_imex") return 2;
  if (integrator == "arkode_erk") return erk_table_order(table);
  if (integrator == "arkode_imex") {
    const auto pair = ark_pair_of(table);
    return pair ? erk_table_order(pair->erk) : 0;
  }
  return 0;
}

void IntegratorSpec::apply(TimeConfig& time) const {
  time.integrator = integrator;
  if (integrator == "arkode_erk" || integrator == "arkode_imex") time.table = table;
}

std::vector<IntegratorSpec> parse_integrator_list(const std::string& list, const std::string& default_table) {
  std::vector<IntegratorSpec> out;
  if (list.empty()) throw std::invalid_argument("empty integrator list");
  // Every comma-separated entry, the one after a trailing comma too (getline would drop it).
  for (std::size_t start = 0, end = 0; end != std::string::npos; start = end + 1) {
    end = list.find(',', start);
    const std::string item = list.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (item.empty()) throw std::invalid_argument("an empty entry in '" + list + "' (a doubled or trailing comma)");
    IntegratorSpec s;
    s.label = item;
    const auto colon = item.find(':');
    s.integrator = item.substr(0, colon);
    if (s.integrator == "arkode_erk") {
      s.table = colon == std::string::npos ? default_table : item.substr(colon + 1);
      if (!is_erk_table_name(s.table))
        throw std::invalid_argument("integrator '" + item + "': '" + s.table + "' is not a SUNDIALS ERK table");
    } else if (s.integrator == "arkode_imex") {
      s.table = colon == std::string::npos ? "ARKODE_ARK324L2SA_ERK_4_2_3" : item.substr(colon + 1);
      if (!ark_pair_of(s.table))
        throw std::invalid_argument("integrator '" + item + "': '" + s.table + "' is not one table of a SUNDIALS ARK ImEx pair");
    } else if (colon != std::string::npos) {
      throw std::invalid_argument("integrator '" + item + "': only arkode_erk and arkode_imex take a table (arkode_erk:TABLE)");
    } else if (s.integrator != "leapfrog" && s.integrator != "leapfrog_kdk" && s.integrator != "cvode_adams" &&
               s.integrator != "leapfrog_imex") {
      throw std::invalid_argument("unknown integrator '" + item +
                                  "' (known: leapfrog, leapfrog_kdk, leapfrog_imex, arkode_erk, arkode_erk:TABLE, cvode_adams, "
                                  "arkode_imex, arkode_imex:TABLE)");
    }
    for (const auto& o : out)
      if (o.integrator == s.integrator && o.table == s.table)
        throw std::invalid_argument("integrator '" + item + "' is listed twice (as '" + o.label + "')");
    out.push_back(s);
  }
  return out;
}

}  // namespace sphmol
