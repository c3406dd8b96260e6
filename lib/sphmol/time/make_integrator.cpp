#include <stdexcept>

#include "sphmol/time/arkode_erk.hpp"
#include "sphmol/time/cvode_adams.hpp"
#include "sphmol/time/integrator.hpp"
#include "sphmol/time/leapfrog.hpp"
#include "sphmol/time/leapfrog_kdk.hpp"

namespace sphmol {

std::unique_ptr<Integrator> make_integrator(const TimeConfig& time) {
  if (time.integrator == "arkode_erk")
    return std::make_unique<ArkodeErk>(ArkodeErk::Options{time.table, time.rtol, time.atol, time.dt, time.max_steps});
  if (time.integrator == "leapfrog") return std::make_unique<Leapfrog>(Leapfrog::Options{time.dt, time.max_steps});
  if (time.integrator == "leapfrog_kdk") return std::make_unique<LeapfrogKdk>(LeapfrogKdk::Options{time.dt, time.max_steps});
  if (time.integrator == "cvode_adams")
    return std::make_unique<CvodeAdams>(CvodeAdams::Options{time.rtol, time.atol, time.max_steps});
  throw std::invalid_argument("unknown integrator '" + time.integrator + "' (known: arkode_erk, leapfrog, leapfrog_kdk, cvode_adams)");
}

}  // namespace sphmol
