#pragma once
// Particle masses of the start lattices (discretization.particle_mass).
//
// summation: the mass that makes summation density return exactly rho0 on an infinite square/cubic
// lattice of spacing dx: m = rho0 / sum_lattice W(|r|, h). With m = rho0 dx^D instead, the lattice
// sum's discretisation error (~1e-3 for the cubic spline at h = 1.3 dx) would show up as a density
// mismatch against wall particles held at rho0, i.e. as a spurious wall pressure.
//
// gradient: the mass that makes the symmetric SPH pressure gradient (Monaghan 1992, sec. 3; here
// momentum: symmetric_117, Vukčević 2012, eq 117: grad p_i = rho_i sum_j m_j (p_i / rho_i^2 +
// p_j / rho_j^2) grad_i W_ij, and eq 116 alike at uniform rho) exact for a linear field on the same
// lattice. At uniform rho0 and with sum_j grad_i W_ij = 0 on the symmetric lattice it reads
// (m / rho0) sum_j (p_j - p_i) grad_i W_ij; with p = a . x and grad_i W_ij = W'(r) (x_i - x_j) / r
// that is (m / rho0) M a, M = sum_j -(x_j - x_i) (x) (x_j - x_i) W'(r_ij) / r_ij, which the lattice's
// symmetry makes a multiple of the identity. So m = rho0 / M_xx, M_xx = sum_j -x_j^2 W'(r_j) / r_j
// (the x-direction second moment of W'). The summation mass reads a linear field at
// M_xx m_summation / rho0: 0.99800 of its slope for Wendland C2 at h = 2 dx on the square lattice
// (0.99886 on the cubic one), and a water column at rest settles that much steeper than
// g rho. Continuity density does not use the mass to set rho (it starts at rho0 whatever the mass);
// the mass enters only as the volumes m / rho of the gradient and divergence operators, so there
// the gradient mass removes that bias. Summation density needs the summation mass (the loader
// allows `gradient` with continuity density only).
#include <cmath>
#include <string_view>

#include "sphmol/kernels/registry.hpp"

namespace sphmol {

namespace detail {
// sum over the square/cubic lattice points x_j (origin included) within the support of f(x_j).
template <int D, class F>
double cubic_lattice_sum(const KernelInfo<D>& K, double dx, double h, F&& f) {
  const int m = static_cast<int>(std::ceil(K.support * h / dx)) + 1;
  double sum = 0.0;
  double x[3] = {0.0, 0.0, 0.0};
  const int span = 2 * m + 1;
  int total = 1;
  for (int d = 0; d < D; ++d) total *= span;
  for (int c = 0; c < total; ++c) {
    for (int d = 0, cc = c; d < D; ++d, cc /= span) x[d] = (cc % span - m) * dx;
    sum += f(x);
  }
  return sum;
}

// The same over the 2D hexagonal lattice (rows dx sqrt(3)/2 apart, every other row shifted by dx/2).
template <class F>
double hexagonal_lattice_sum(double support, double dx, double h, F&& f) {
  const double row = dx * std::sqrt(3.0) / 2.0;
  const int m = static_cast<int>(std::ceil(support * h / row)) + 1;
  double sum = 0.0;
  for (int j = -m; j <= m; ++j)
    for (int i = -m - 1; i <= m + 1; ++i) {
      const double x[3] = {(i + ((j & 1) ? 0.5 : 0.0)) * dx, j * row, 0.0};
      sum += f(x);
    }
  return sum;
}

template <int D>
double radius(const double* x) {
  double r2 = 0.0;
  for (int d = 0; d < D; ++d) r2 += x[d] * x[d];
  return std::sqrt(r2);
}

// -x^2 W'(r) / r at the lattice point x (0 at the origin, where the pair does not exist).
template <int D>
double gradient_moment(const KernelInfo<D>& K, const double* x, double h) {
  const double r = radius<D>(x);
  return r > 0.0 ? -x[0] * x[0] / r * K.dWdr(r, h) : 0.0;
}
}  // namespace detail

// m = rho0 / sum_j W(r_j): summation density is rho0 on the square/cubic lattice.
template <int D>
double lattice_particle_mass(std::string_view kernel, double rho0, double dx, double h) {
  const auto K = kernel_info<D>(kernel);
  return rho0 / detail::cubic_lattice_sum<D>(K, dx, h, [&](const double* x) { return K.W(detail::radius<D>(x), h); });
}

// m = rho0 / sum_j -(x_j^2 / r_j) W'(r_j): the symmetric gradient of a linear field is exact on the
// square/cubic lattice (see the top of this file).
template <int D>
double lattice_gradient_mass(std::string_view kernel, double rho0, double dx, double h) {
  const auto K = kernel_info<D>(kernel);
  return rho0 / detail::cubic_lattice_sum<D>(K, dx, h, [&](const double* x) { return detail::gradient_moment<D>(K, x, h); });
}

// The hexagonal counterparts (2D): the same sums over the hexagonal lattice, whose six-fold symmetry
// also makes the second moment M a multiple of the identity.
inline double hexagonal_particle_mass(std::string_view kernel, double rho0, double dx, double h) {
  const auto K = kernel_info<2>(kernel);
  return rho0 / detail::hexagonal_lattice_sum(K.support, dx, h, [&](const double* x) { return K.W(detail::radius<2>(x), h); });
}

inline double hexagonal_gradient_mass(std::string_view kernel, double rho0, double dx, double h) {
  const auto K = kernel_info<2>(kernel);
  return rho0 / detail::hexagonal_lattice_sum(K.support, dx, h, [&](const double* x) { return detail::gradient_moment<2>(K, x, h); });
}

// The mass discretization.particle_mass names ("summation" or "gradient").
template <int D>
double lattice_mass(std::string_view particle_mass, std::string_view kernel, double rho0, double dx, double h) {
  return particle_mass == "gradient" ? lattice_gradient_mass<D>(kernel, rho0, dx, h)
                                     : lattice_particle_mass<D>(kernel, rho0, dx, h);
}

inline double hexagonal_lattice_mass(std::string_view particle_mass, std::string_view kernel, double rho0, double dx, double h) {
  return particle_mass == "gradient" ? hexagonal_gradient_mass(kernel, rho0, dx, h)
                                     : hexagonal_particle_mass(kernel, rho0, dx, h);
}

}  // namespace sphmol
