#pragma once
// A run that became unphysical or numerically broken (NaN/Inf, a particle outside the domain,
// density <= 0, step-size collapse). Thrown by the step hook or an integrator; the run loop ends
// the run cleanly, writes the last good state and reports status "blown_up" with this cause.
#include <stdexcept>
#include <string>

namespace sphmol {

struct BlowUp : std::runtime_error {
  BlowUp(double t_, long particle_, std::string cause_)
      : std::runtime_error("blown up at t = " + std::to_string(t_) +
                           (particle_ >= 0 ? ", particle " + std::to_string(particle_) : std::string()) + ": " + cause_),
        t(t_),
        particle(particle_),
        cause(std::move(cause_)) {}
  double t;
  long particle;  // -1: not tied to one particle (e.g. step-size collapse)
  std::string cause;
};

}  // namespace sphmol
