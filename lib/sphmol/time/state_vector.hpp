#pragma once
// How a SUNDIALS integrator wraps the state it advances in an N_Vector, without copying it. An
// OdeSystem whose state is one process's whole state says nothing, and the integrator makes its own
// serial (or OpenMP) vector. An OdeSystem whose state is split over processes
// (parallel/distributed_system.hpp) also derives from StateVectorMaker, as a system with a stiff
// part derives from ImexSystem, and supplies a vector whose reductions (error norms, dot products,
// minima) span every process: all of them see the same norms and so take the same steps.
// make_state_vector is where an integrator gets its vector either way.
#include <sundials/sundials_context.h>
#include <sundials/sundials_nvector.h>

#include <cstddef>

namespace sphmol {

class StateVectorMaker {
 public:
  virtual ~StateVectorMaker() = default;
  // An N_Vector over `length` doubles at `data` (this process's part of the state), owned by the
  // caller (N_VDestroy). Collective when the state is split over processes. When the state's share
  // changes between steps (a repartition), the vector and every vector cloned from it, the
  // integrator's history, move with the particles: the vector then wraps the state's new storage
  // and the clones hold their values in the new share (parallel/vector_family.hpp).
  virtual N_Vector wrap_state(double* data, std::size_t length, SUNContext ctx) const = 0;
};

class OdeSystem;

// The integrator's N_Vector over the state at `y` (sys.size() doubles, no copy), owned by the caller:
// the system's own when it is a StateVectorMaker; else an OpenMP vector on `threads` > 1 threads or a
// serial one, either with the order-independent norm of time/fixed_point_norm.hpp, so that the error
// norms, and with them the steps, are the same on any thread or rank count.
N_Vector make_state_vector(const OdeSystem& sys, double* y, int threads, SUNContext ctx);

}  // namespace sphmol
