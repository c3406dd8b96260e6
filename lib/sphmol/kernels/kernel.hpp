#pragma once
// What every SPH kernel provides. Kernels are stateless structs templated on the dimension D;
// hot loops are instantiated per kernel type (no virtual call per pair), everything else uses
// the runtime KernelInfo from kernels/registry.hpp.
//
// Convention (shared by every kernel file): W(r, h) = sigma_D / h^D * f(r/h), with compact
// support r < support * h. The sources write kernels either in R = r/h (seed 000, 001, 002) or in
// R = r/(kappa h) (seed 003); each kernel file converts to r/h and says so.
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

}  // namespace sphmol
