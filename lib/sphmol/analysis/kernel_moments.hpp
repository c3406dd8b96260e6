#pragma once
// Continuous kernel moments (Vukčević 2012, eqs 64 and 69), by GSL quadrature, in any dimension.
//   M_k  = int (x - x')_1^k W(x - x', h) dx'        (eq 64: M_0 = 1, M_k = 0 for k >= 1 is the
//                                                   ideal; even M_k > 0 for a positive kernel)
//   M'_k = int (x - x')_1^k dW/dx'_1 dx'           (eq 69: M'_0 = 0, M'_1 = 1, others 0)
// (x - x')_1 is the component along one axis, so in 1D these are exactly Vukčević's moments and in
// D > 1 they are the moments of the kernel's 1D marginal. For a radial kernel the angular part
// is exact: int n_1^k dOmega, leaving a radial integral over the kernel's pieces. Odd moments
// vanish by the kernel's parity, so they are reported as 0 without integration.
// By parts, M'_k = k M_{k-1} for a kernel that vanishes at its support edge; it differs for a
// kernel that jumps there (truncated_exponential) or whose derivative is not dW/dr (composite).
//   M''_k = int (x - x')_1^k d^2W/dx'_1^2 dx'       (eq 76: M''_2 = 2, M''_0 = M''_1 = 0)
// with d_1^2 W = W'' n_1^2 + W'/r (1 - n_1^2); W'' is a central difference of the kernel's own
// derivative (so for the composite kernel, of eq 13b), taken inside each smooth piece. For a
// smooth compact kernel M''_k = k(k-1) M_(k-2); a jump of W or W' at the support edge (the
// truncated Gaussians, the composite kernel) adds surface terms that this volume integral omits.
#include <array>
#include <functional>

#include "sphmol/kernels/registry.hpp"

namespace sphmol::analysis {

struct KernelMoments {
  std::array<double, 5> M{};   // M_0..M_4 in units of h^k
  std::array<double, 5> dM{};  // M'_0..M'_4 in units of h^(k-1)
  std::array<double, 5> d2M{};  // M''_0..M''_4 in units of h^(k-2)
};

// Integral over R^D of |x|^p W(|x|) times the angular factor for x_1^k (k = p - ...); exposed
// for tests. Returns int_0^{support h} g(r) r^(D-1+p) dr for g = W or dW/dr.
double radial_integral(int D, double support, double h, int p, double (*g)(double, double));
// Same with power r^(D-1+p) applied to an arbitrary radial function g(r).
double radial_integral(int D, double support, double h, int p, const std::function<double(double)>& g);
// int over the unit sphere S^(D-1) of n_1^k.
double angular_factor(int D, int k);

KernelMoments kernel_moments(int D, double support, double (*W)(double, double),
                             double (*dWdr)(double, double), double h = 1.0);

template <int D>
KernelMoments kernel_moments(const KernelInfo<D>& k, double h = 1.0) {
  return kernel_moments(D, k.support, k.W, k.dWdr, h);
}

}  // namespace sphmol::analysis
