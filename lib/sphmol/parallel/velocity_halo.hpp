#pragma once
// The halo columns of a rank's viscous operator (time/remote_columns.hpp): the velocities of the
// halo particles of one halo plan (halo.hpp), fetched from their owners by that plan. The operator
// keeps the plan it was recorded with, so that arkode_imex's frozen operator L_n stays applicable
// after the stage evaluations of the step have planned the halo again (the owned particles, and so
// the rows, change only with a new partition, after which the integrator starts again).
#include <cstddef>
#include <cstdint>
#include <memory>

#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/halo.hpp"
#include "sphmol/time/remote_columns.hpp"

namespace sphmol::parallel {

template <int D>
class VelocityHalo final : public RemoteColumns {
 public:
  // whole_fluid: fluid particles over every rank; distribution: the partition's number (the same on
  // every rank, a new one for every partition).
  VelocityHalo(const Communicator& comm, std::shared_ptr<const Halo<D>> plan, std::size_t whole_fluid, std::uint64_t distribution)
      : comm_(comm), plan_(std::move(plan)), whole_fluid_(whole_fluid), distribution_(distribution) {}
  std::size_t size() const override { return plan_->size(); }
  // The halo's wall particles get columns too (their velocity is not used: walls are in b).
  void fetch(const double* v, std::size_t rows, int components, double* ext, std::size_t stride) const override;
  N_Vector new_vector(std::size_t length, SUNContext ctx) const override;
  std::uint64_t distribution() const override { return distribution_; }

 private:
  Communicator comm_;
  std::shared_ptr<const Halo<D>> plan_;
  std::size_t whole_fluid_;
  std::uint64_t distribution_;
};

extern template class VelocityHalo<1>;
extern template class VelocityHalo<2>;
extern template class VelocityHalo<3>;

}  // namespace sphmol::parallel
