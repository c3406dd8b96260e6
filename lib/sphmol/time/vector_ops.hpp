#pragma once
// N_VLinearSum and N_VScale of a serial vector, compiled with the project's flags: the Krylov solves
// of the implicit integrators spend a fifth of their instructions in these two operations, which
// the distribution's SUNDIALS library runs without vector instructions (docs/performance.md).
//
// The results are SUNDIALS' own to the bit. Its N_VLinearSum_Serial computes z = a x + b y
// elementwise, but for a = b it forms a (x + y) and for a = -b a (x - y), each unless a or b is
// +-1; with a or b equal to +-1 its special forms (x + y, y - x, c v + w, ...) are the generic
// a x + b y in value, since multiplying by +-1 is exact and IEEE addition commutes. N_VScale is
// c x in every case.
#include <sundials/sundials_nvector.h>

namespace sphmol {

// Replaces N_VLinearSum and N_VScale of a serial vector (and of every vector cloned from it).
void use_compiled_linear_ops(N_Vector v);

}  // namespace sphmol
