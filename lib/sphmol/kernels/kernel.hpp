#pragma once
// What every SPH kernel provides. Kernels are stateless structs templated on the dimension D;
// hot loops are instantiated per kernel type (no virtual call per pair), everything else uses
// the runtime KernelInfo from kernels/registry.hpp.
//
// Convention (shared by every kernel file): W(r, h) = sigma_D / h^D * f(r/h), with compact
// support r < support * h. The sources write kernels either in R = r/h (Vukčević 2012; Vukčević et
// al. 2012; Potapov & Reshetnikova 2021) or in R = r/(kappa h) (Niedoba 2012); each kernel file
// converts to r/h and says so.
//
// Optional members (read through the helpers below, so older kernels need not define them):
//   source               — where the formula comes from ("Potapov & Reshetnikova 2021, eq 9 / Niedoba 2012, eq 2.41")
//   unavailable_reason   — why `available` is false in this D
//   derivative_is_exact  — false when dWdr is not d/dr of W (Potapov & Reshetnikova 2021 composite kernel, eq 13b)
//   dWdr_k(r, h, k)      — derivative that depends on the smoothing coefficient k = h/d too
//   mass()               — integral of W over R^D when it is deliberately not 1 (unrenormalised
//                          truncated Gaussian); 1 otherwise
#include <concepts>
#include <string_view>

namespace sphmol {

template <class K>
concept SphKernel = requires(double r, double h, double& w, double& dw) {
  { K::dimension } -> std::convertible_to<int>;
  { K::name } -> std::convertible_to<std::string_view>;
  { K::support } -> std::convertible_to<double>;  // radius of the support in units of h
  { K::available } -> std::convertible_to<bool>;  // false where the source defines no such D
  { K::W(r, h) } -> std::same_as<double>;
  { K::dWdr(r, h) } -> std::same_as<double>;
  K::eval(r, h, w, dw);  // value and radial derivative at once (the hot-loop entry)
};

// W and dW/dr as separate calls, derived from a kernel's eval(r, h, w, dw) (CRTP base of every kernel).
template <class K>
struct KernelFromEval {
  static double W(double r, double h) {
    double w, dw;
    K::eval(r, h, w, dw);
    return w;
  }
  static double dWdr(double r, double h) {
    double w, dw;
    K::eval(r, h, w, dw);
    return dw;
  }
};

// W and (dW/dr)/r at h = 1, r = q: what the kernel passes need (rhs/kernel_pass.hpp). A kernel whose
// derivative carries a factor q defines eval_unit_over_r without the division; otherwise dW/dr / q
// (0 at q = 0).
template <class K>
inline void kernel_unit_over_r(double q, double& w, double& f) {
  if constexpr (requires { K::eval_unit_over_r(q, w, f); }) {
    K::eval_unit_over_r(q, w, f);
  } else {
    double dw;
    K::eval(q, 1.0, w, dw);
    f = q > 0.0 ? dw / q : 0.0;
  }
}

// h^D without pow().
template <int D>
constexpr double h_power(double h) {
  double hd = h;
  for (int d = 1; d < D; ++d) hd *= h;
  return hd;
}

template <class K>
constexpr std::string_view kernel_source() {
  if constexpr (requires { K::source; }) return K::source; else return "";
}
template <class K>
constexpr std::string_view kernel_unavailable_reason() {
  if constexpr (requires { K::unavailable_reason; }) return K::unavailable_reason;
  else return "not defined in this dimension by its source";
}
template <class K>
constexpr bool kernel_derivative_is_exact() {
  if constexpr (requires { K::derivative_is_exact; }) return K::derivative_is_exact; else return true;
}
template <class K>
double kernel_mass() {
  if constexpr (requires { K::mass(); }) return K::mass(); else return 1.0;
}
// Radial derivative when the particle spacing d = h/k is known. Only kernels whose derivative
// is a separate, k-dependent function (Potapov & Reshetnikova 2021, eq 13b) differ from dWdr.
template <class K>
double kernel_dWdr_k(double r, double h, double k) {
  if constexpr (requires { K::dWdr_k(r, h, k); }) return K::dWdr_k(r, h, k); else return K::dWdr(r, h);
}

}  // namespace sphmol
