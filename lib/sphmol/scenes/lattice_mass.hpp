#pragma once
// Particle mass that makes summation density return exactly rho0 on an infinite square/cubic lattice
// of spacing dx: m = rho0 / sum_lattice W(|r|, h). With m = rho0 dx^D instead, the lattice sum's
// discretisation error (~1e-3 for the cubic spline at h = 1.3 dx) would show up as a density
// mismatch against wall particles held at rho0, i.e. as a spurious wall pressure.
#include <cmath>

#include "sphmol/kernels/registry.hpp"

namespace sphmol {

template <int D>
double lattice_particle_mass(std::string_view kernel, double rho0, double dx, double h) {
  const auto K = kernel_info<D>(kernel);
  const int m = static_cast<int>(std::ceil(K.support * h / dx)) + 1;
  double sum = 0.0;
  int idx[3] = {0, 0, 0};
  const int span = 2 * m + 1;
  int total = 1;
  for (int d = 0; d < D; ++d) total *= span;
  for (int c = 0; c < total; ++c) {
    double r2 = 0.0;
    for (int d = 0, cc = c; d < D; ++d, cc /= span) {
      idx[d] = cc % span - m;
      r2 += (idx[d] * dx) * (idx[d] * dx);
    }
    sum += K.W(std::sqrt(r2), h);
  }
  return rho0 / sum;
}

}  // namespace sphmol
