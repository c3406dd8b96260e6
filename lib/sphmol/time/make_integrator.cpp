#include <stdexcept>

#include "sphmol/time/arkode_erk.hpp"
#include "sphmol/time/arkode_imex.hpp"
#include "sphmol/time/cvode_adams.hpp"
#include "sphmol/time/integrator.hpp"
#include "sphmol/time/leapfrog.hpp"
#include "sphmol/time/leapfrog_imex.hpp"
#include "sphmol/time/leapfrog_kdk.hpp"

namespace sphmol {

std::unique_ptr<Integrator> make_integrator(const TimeConfig& time) {
  if (time.integrator == "arkode_erk")
    return std::make_unique<ArkodeErk>(ArkodeErk::Options{time.table, time.rtol, time.atol, time.dt, time.max_steps});
  if (time.integrator == "leapfrog") return std::make_unique<Leapfrog>(Leapfrog::Options{time.dt, time.max_steps});
  if (time.integrator == "leapfrog_kdk") return std::make_unique<LeapfrogKdk>(LeapfrogKdk::Options{time.dt, time.max_steps});
  const KrylovOptions krylov{time.krylov.solver, time.krylov.tolerance, time.krylov.max_iterations};
  if (time.integrator == "leapfrog_imex")
    return std::make_unique<LeapfrogImex>(LeapfrogImex::Options{time.dt, time.max_steps}, krylov);
  if (time.integrator == "arkode_imex")
    return std::make_unique<ArkodeImex>(ArkodeImex::Options{time.table, time.rtol, time.atol, time.dt, time.max_steps, krylov});
  if (time.integrator == "cvode_adams")
    return std::make_unique<CvodeAdams>(CvodeAdams::Options{time.rtol, time.atol, time.max_steps});
  throw std::invalid_argument("unknown integrator '" + time.integrator + "' (known: arkode_erk, leapfrog, leapfrog_kdk, cvode_adams, leapfrog_imex, arkode_imex)");
}

}  // namespace sphmol
