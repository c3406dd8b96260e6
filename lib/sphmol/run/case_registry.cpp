#include "sphmol/run/case_registry.hpp"

#include "sphmol/scenes/cavity_case.hpp"
#include "sphmol/scenes/channel_case.hpp"
#include "sphmol/scenes/dam_break_case.hpp"
#include "sphmol/scenes/hydrostatic_case.hpp"
#include "sphmol/scenes/taylor_green_case.hpp"
#include "sphmol/scenes/shock_tube_case.hpp"

namespace sphmol {

const std::map<std::string, CaseFactory>& case_registry() {
  static const std::map<std::string, CaseFactory> registry = {
      {"couette", {nullptr, [] { return std::make_unique<ChannelCase>(); }, nullptr, "two-dimensional only"}},
      {"taylor_green", {nullptr, [] { return std::make_unique<TaylorGreenCase>(); }, nullptr, "two-dimensional only"}},
      {"hydrostatic", {nullptr, [] { return std::make_unique<HydrostaticCase>(); }, nullptr, "two-dimensional only"}},
      {"cavity", {nullptr, [] { return std::make_unique<CavityCase>(); }, nullptr, "two-dimensional only"}},
      {"dam_break", {nullptr, [] { return std::make_unique<DamBreakCase>(); }, nullptr, "two-dimensional only"}},
      {"poiseuille", {nullptr, [] { return std::make_unique<ChannelCase>(); }, nullptr, "two-dimensional only"}},
      {"shock_tube", {[] { return std::make_unique<ShockTubeCase<1>>(); }, [] { return std::make_unique<ShockTubeCase<2>>(); },
                      nullptr, "one- or two-dimensional"}},
  };
  return registry;
}

}  // namespace sphmol
