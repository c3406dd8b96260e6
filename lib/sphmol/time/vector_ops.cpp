#include "sphmol/time/vector_ops.hpp"

#include <nvector/nvector_serial.h>

#include <stdexcept>

namespace sphmol {

namespace {

void linear_sum(sunrealtype a, N_Vector x, sunrealtype b, N_Vector y, N_Vector z) {
  const sunindextype n = NV_LENGTH_S(x);
  const sunrealtype* xd = NV_DATA_S(x);
  const sunrealtype* yd = NV_DATA_S(y);
  sunrealtype* zd = NV_DATA_S(z);
  const bool unit = a == 1.0 || a == -1.0 || b == 1.0 || b == -1.0;
  if (!unit && a == b) {
    for (sunindextype i = 0; i < n; ++i) zd[i] = a * (xd[i] + yd[i]);
  } else if (!unit && a == -b) {
    for (sunindextype i = 0; i < n; ++i) zd[i] = a * (xd[i] - yd[i]);
  } else {
    for (sunindextype i = 0; i < n; ++i) zd[i] = a * xd[i] + b * yd[i];
  }
}

void scale(sunrealtype c, N_Vector x, N_Vector z) {
  const sunindextype n = NV_LENGTH_S(x);
  const sunrealtype* xd = NV_DATA_S(x);
  sunrealtype* zd = NV_DATA_S(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = c * xd[i];
}

}  // namespace

void use_compiled_linear_ops(N_Vector v) {
  if (N_VGetVectorID(v) != SUNDIALS_NVEC_SERIAL) throw std::invalid_argument("use_compiled_linear_ops: a serial vector is needed");
  v->ops->nvlinearsum = &linear_sum;
  v->ops->nvscale = &scale;
}

}  // namespace sphmol
