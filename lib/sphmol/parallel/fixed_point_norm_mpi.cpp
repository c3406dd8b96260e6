#include "sphmol/parallel/fixed_point_norm_mpi.hpp"

#include <nvector/nvector_parallel.h>

#include <cmath>
#include <stdexcept>

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

}  // namespace

N_Vector make_fixed_point_norm_vector(MPI_Comm comm, double* data, std::size_t local, std::size_t whole, SUNContext ctx) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  // The chunks' 64-bit sums hold 2^16 parts, and the whole sum 2^31 entries (fixed_point_norm.hpp).
  if (ranks > (1 << 16) || whole >= (std::size_t{1} << 31))
    throw std::length_error("make_fixed_point_norm_vector: more than 2^16 ranks or 2^31 state entries");
  N_Vector v = N_VMake_Parallel(comm, static_cast<sunindextype>(local), static_cast<sunindextype>(whole), data, ctx);
  if (!v) throw std::runtime_error("N_VMake_Parallel failed");
  v->ops->nvwrmsnorm = &fixed_point_wrms_mpi;
  return v;
}

}  // namespace sphmol::parallel
