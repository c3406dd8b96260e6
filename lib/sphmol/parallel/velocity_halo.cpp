#include "sphmol/parallel/velocity_halo.hpp"

#include <array>
#include <stdexcept>
#include <vector>

#include "sphmol/parallel/fixed_point_norm_mpi.hpp"

namespace sphmol::parallel {

template <int D>
void VelocityHalo<D>::fetch(const double* v, std::size_t rows, int components, double* ext, std::size_t stride) const {
  if (components != D) throw std::invalid_argument("VelocityHalo::fetch: not a velocity block of this dimension");
  // One record per owned particle, fluid first (the rows), walls after them with zeros.
  std::vector<std::array<double, D>> mine(plan_->owned(), std::array<double, D>{});
  for (std::size_t o = 0; o < rows; ++o)
    for (int d = 0; d < D; ++d) mine[o][static_cast<std::size_t>(d)] = v[static_cast<std::size_t>(d) * rows + o];
  const std::vector<std::array<double, D>> halo = plan_->exchange(comm_, mine);
  for (std::size_t h = 0; h < halo.size(); ++h)
    for (int d = 0; d < D; ++d) ext[static_cast<std::size_t>(d) * stride + rows + h] = halo[h][static_cast<std::size_t>(d)];
}

template <int D>
N_Vector VelocityHalo<D>::new_vector(std::size_t length, SUNContext ctx) const {
  return new_fixed_point_vector(comm_.handle(), length, D * whole_fluid_, ctx);
}

template class VelocityHalo<1>;
template class VelocityHalo<2>;
template class VelocityHalo<3>;

}  // namespace sphmol::parallel
