#include "sphmol/time/state_vector.hpp"

#include <nvector/nvector_openmp.h>
#include <nvector/nvector_serial.h>

#include "sphmol/time/fixed_point_norm.hpp"
#include "sphmol/time/ode_system.hpp"
#include "sphmol/time/vector_ops.hpp"

namespace sphmol {

N_Vector make_state_vector(const OdeSystem& sys, double* y, int threads, SUNContext ctx) {
  if (const auto* split = dynamic_cast<const StateVectorMaker*>(&sys)) return split->wrap_state(y, sys.size(), ctx);
  const auto n = static_cast<sunindextype>(sys.size());
  N_Vector v = threads > 1 ? N_VMake_OpenMP(n, y, threads, ctx) : N_VMake_Serial(n, y, ctx);
  use_fixed_point_norm(v);
  if (threads <= 1) use_compiled_linear_ops(v);
  return v;
}

}  // namespace sphmol
