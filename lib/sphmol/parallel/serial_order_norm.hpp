#pragma once
// The weighted RMS norm of a state split over ranks, summed in the serial run's order: the norm
// ARKODE and CVODE take of their error estimates and Newton/fixed-point corrections.
//
// Why not the MPI vector's own norm: it adds each rank's partial sum, a different rounding from the
// serial run's one sum in index order. That alone would be harmless, but an adaptive integrator's
// step-size and order choices amplify it: on the dam break, changing rtol by one part in 1e15 gives
// ARKODE another step sequence within 0.01 s of simulated time, and CVODE within 0.005 s; the runs
// then agree only to the tolerance. Summed in the serial order instead, the norm is the serial
// run's to the bit, and so are the steps and the final state, on any rank count.
//
// How: each rank squares its weighted entries (as N_VWrmsNorm_Serial does, x_i w_i then its
// square), rank 0 gathers them, places them at their index in the whole state, adds them in that
// order and divides by the whole length, and every rank receives the result. The price: rank 0
// receives one double per state entry per norm (a few norms per step), a serial part that grows
// with the problem.
//
// Installed on SUNDIALS' MPI vector (nvector_parallel) by replacing its wrmsnorm operation; the
// vectors an integrator clones from it copy the operation. The vector's communicator (a duplicate
// made for this purpose) carries the norm as an MPI attribute, which is how the operation finds it.
#include <mpi.h>
#include <sundials/sundials_nvector.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sphmol::parallel {

class SerialOrderNorm {
 public:
  // Collective. `comm` is duplicated (released by the destructor, also collective).
  explicit SerialOrderNorm(MPI_Comm comm);
  ~SerialOrderNorm();
  SerialOrderNorm(const SerialOrderNorm&) = delete;
  SerialOrderNorm& operator=(const SerialOrderNorm&) = delete;

  // Collective: the index in the whole state of each entry of this rank's part (the whole state's
  // length is the sum of the parts'). Call again when the parts change.
  void set_order(const std::vector<std::uint64_t>& whole_index);

  // Collective: sqrt(sum_i (x_i w_i)^2 / N) over the whole state, summed in whole-state order.
  double wrms(const double* x, const double* w, std::size_t n) const;

  // Collective: an MPI vector over `length` doubles at `data` (no copy), with this norm.
  N_Vector wrap(double* data, std::size_t length, SUNContext ctx) const;

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0;
  std::vector<int> counts_, displs_;  // entries per rank (on rank 0)
  std::vector<std::uint64_t> index_;  // every rank's whole-state indices, in rank order (on rank 0)
  std::size_t whole_ = 0, local_ = 0;
  mutable std::vector<double> terms_, gathered_, placed_;  // work arrays of wrms()
};

}  // namespace sphmol::parallel
