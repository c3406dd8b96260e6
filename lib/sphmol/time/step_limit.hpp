#pragma once
// time.max_steps: the steps of the whole run, restarts included. SUNDIALS' own limit
// (ERKStepSetMaxNumSteps and the like) counts the steps of one call, and the integrators here call
// once per step, so every integrator checks this count itself before it steps.
#include <stdexcept>
#include <string>

#include "sphmol/config/yaml_reader.hpp"

namespace sphmol {

inline void check_step_limit(const std::string& integrator, long steps, long max_steps, double t) {
  if (steps >= max_steps)
    throw std::runtime_error(integrator + ": time.max_steps = " + std::to_string(max_steps) + " reached at t = " +
                             number_text(t) + " s (raise time.max_steps)");
}

}  // namespace sphmol
