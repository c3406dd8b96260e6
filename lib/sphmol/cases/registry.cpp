// The registered cases. Adding a case: its folder under cases/ defines `CaseModule NAME_module()`;
// declare it and list it here, one line each.
#include <algorithm>
#include <stdexcept>

#include "sphmol/cases/case_module.hpp"

namespace sphmol {

CaseModule couette_module();
CaseModule poiseuille_module();
CaseModule taylor_green_module();
CaseModule hydrostatic_module();
CaseModule cavity_module();
CaseModule shock_tube_module();
CaseModule dam_break_module();
CaseModule duct_module();
CaseModule beltrami_module();
CaseModule scene_module();

const std::vector<CaseModule>& case_modules() {
  static const std::vector<CaseModule> all = {
      couette_module(), poiseuille_module(), taylor_green_module(), hydrostatic_module(),
      cavity_module(),  shock_tube_module(), dam_break_module(),
      duct_module(),    beltrami_module(),   scene_module(),
  };
  return all;
}

const CaseModule* find_case_module(const std::string& name) {
  const auto& all = case_modules();
  const auto it = std::find_if(all.begin(), all.end(), [&](const CaseModule& m) { return m.name == name; });
  return it == all.end() ? nullptr : &*it;
}

std::vector<std::string> case_names() {
  std::vector<std::string> names;
  for (const auto& m : case_modules()) names.push_back(m.name);
  return names;
}

template <int D>
std::unique_ptr<Case<D>> make_case(const Config& config) {
  const CaseModule* m = find_case_module(config.case_name);
  if (!m) throw std::invalid_argument("case: unknown case '" + config.case_name + "'");
  std::unique_ptr<Case<D>> c;
  if constexpr (D == 1) if (m->make1) c = m->make1();
  if constexpr (D == 2) if (m->make2) c = m->make2();
  if constexpr (D == 3) if (m->make3) c = m->make3();
  if (!c)
    throw std::invalid_argument("dimension: case '" + config.case_name + "' is built in dimension " + m->dimensions_text() +
                                ", not " + std::to_string(D));
  return c;
}

template std::unique_ptr<Case<1>> make_case<1>(const Config&);
template std::unique_ptr<Case<2>> make_case<2>(const Config&);
template std::unique_ptr<Case<3>> make_case<3>(const Config&);

std::string CaseModule::dimensions_text() const {
  std::string s;
  for (std::size_t i = 0; i < dimensions.size(); ++i)
    s += (i == 0 ? "" : i + 1 == dimensions.size() ? " or " : ", ") + std::to_string(dimensions[i]);
  return s;
}

}  // namespace sphmol
