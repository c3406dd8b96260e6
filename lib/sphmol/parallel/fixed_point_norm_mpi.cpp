#include "sphmol/parallel/fixed_point_norm_mpi.hpp"

#include <nvector/nvector_parallel.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "sphmol/parallel/vector_family.hpp"
#include "sphmol/time/fixed_point_norm.hpp"

namespace sphmol::parallel {

namespace {

sunrealtype fixed_point_wrms_mpi(N_Vector x, N_Vector w) {
  const MPI_Comm comm = NV_COMM_P(x);
  const double* xs = NV_DATA_P(x);
  const double* ws = NV_DATA_P(w);
  const auto n = static_cast<std::size_t>(NV_LOCLENGTH_P(x));
  const double length = static_cast<double>(NV_GLOBLENGTH_P(x));
  const double mine = largest_weighted_square(xs, ws, n);  // +inf for a NaN: MPI_MAX of NaN is undefined
  double largest = 0.0;
  MPI_Allreduce(&mine, &largest, 1, MPI_DOUBLE, MPI_MAX, comm);
  if (largest == 0.0 || std::isinf(largest)) return std::sqrt(largest);
  const int shift = fixed_point_shift(largest);
  const FixedPointChunks part = fixed_point_squares(xs, ws, n, shift);
  FixedPointChunks all{};
  MPI_Allreduce(part.data(), all.data(), 3, MPI_UINT64_T, MPI_SUM, comm);
  return fixed_point_wrms(all, shift, length);
}

// The dot product the same way: the largest |x_i y_i| by an MPI max, the signed fixed-point sums
// (modulo 2^128, fixed_point_norm.hpp) by an integer MPI sum.
sunrealtype fixed_point_dot_mpi(N_Vector x, N_Vector y) {
  const MPI_Comm comm = NV_COMM_P(x);
  const auto n = static_cast<std::size_t>(NV_LOCLENGTH_P(x));
  const double mine = largest_product(NV_DATA_P(x), NV_DATA_P(y), n);
  double largest = 0.0;
  MPI_Allreduce(&mine, &largest, 1, MPI_DOUBLE, MPI_MAX, comm);
  if (largest == 0.0) return 0.0;
  if (std::isinf(largest)) return std::numeric_limits<double>::quiet_NaN();
  const int shift = fixed_point_shift(largest);
  const FixedPointChunks part = fixed_point_products(NV_DATA_P(x), NV_DATA_P(y), n, shift);
  FixedPointChunks all{};
  MPI_Allreduce(part.data(), all.data(), 3, MPI_UINT64_T, MPI_SUM, comm);
  return fixed_point_sum(all, shift);
}

void check_sizes(MPI_Comm comm, std::size_t whole) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  // The chunks' 64-bit sums hold 2^16 parts, and the whole sum 2^31 entries (fixed_point_norm.hpp).
  if (ranks > (1 << 16) || whole >= (std::size_t{1} << 31))
    throw std::length_error("fixed-point MPI vector: more than 2^16 ranks or 2^31 entries");
}

N_Vector with_fixed_point_reductions(N_Vector v) {
  if (!v) throw std::runtime_error("creating an MPI vector failed");
  v->ops->nvwrmsnorm = &fixed_point_wrms_mpi;
  v->ops->nvdotprod = &fixed_point_dot_mpi;
  // Every dot product through the one above: no fused or local-then-reduced forms.
  v->ops->nvdotprodmulti = nullptr;
  v->ops->nvdotprodlocal = nullptr;
  v->ops->nvdotprodmultilocal = nullptr;
  v->ops->nvdotprodmultiallreduce = nullptr;
  return v;
}

}  // namespace

N_Vector make_fixed_point_norm_vector(MPI_Comm comm, double* data, std::size_t local, std::size_t whole, SUNContext ctx) {
  check_sizes(comm, whole);
  N_Vector v = with_fixed_point_reductions(
      N_VMake_Parallel(comm, static_cast<sunindextype>(local), static_cast<sunindextype>(whole), data, ctx));
  try {
    track_clones(v);
  } catch (...) {
    N_VDestroy(v);
    throw;
  }
  return v;
}

N_Vector new_fixed_point_vector(MPI_Comm comm, std::size_t local, std::size_t whole, SUNContext ctx) {
  check_sizes(comm, whole);
  return with_fixed_point_reductions(N_VNew_Parallel(comm, static_cast<sunindextype>(local), static_cast<sunindextype>(whole), ctx));
}

}  // namespace sphmol::parallel
