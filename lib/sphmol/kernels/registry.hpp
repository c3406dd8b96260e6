#pragma once
// Name -> kernel. dispatch_kernel<D>(name, f) calls f(K{}) with the kernel type, so the caller
// instantiates its hot loop once per kernel; kernel_info<D>(name) gives a runtime handle for
// diagnostics and analysis. To add a kernel: write kernels/<name>.hpp and list it in KernelTypes.
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "sphmol/kernels/cubic_spline.hpp"
#include "sphmol/kernels/kernel.hpp"

namespace sphmol {

template <int D>
using KernelTypes = std::tuple<CubicSpline<D>>;

template <int D>
struct KernelInfo {
  std::string_view name;
  double support = 0.0;  // in units of h
  double (*W)(double r, double h) = nullptr;
  double (*dWdr)(double r, double h) = nullptr;
};

namespace detail {
template <int D, class F, std::size_t I = 0>
decltype(auto) dispatch_kernel_impl(std::string_view name, F&& f) {
  using Tuple = KernelTypes<D>;
  if constexpr (I == std::tuple_size_v<Tuple>) {
    std::string known;
    std::apply([&](auto... k) { ((known += (known.empty() ? "" : ", ") + std::string(k.name)), ...); }, Tuple{});
    throw std::invalid_argument("unknown kernel '" + std::string(name) + "' (known: " + known + ")");
    return f(std::tuple_element_t<0, Tuple>{});
  } else {
    using K = std::tuple_element_t<I, Tuple>;
    if (name == K::name) {
      if constexpr (!K::available) {
        throw std::invalid_argument("kernel '" + std::string(name) + "' is not defined in " +
                                    std::to_string(D) + "D by its source");
        return f(std::tuple_element_t<0, Tuple>{});
      } else {
        return f(K{});
      }
    }
    return dispatch_kernel_impl<D, F, I + 1>(name, std::forward<F>(f));
  }
}
}  // namespace detail

template <int D, class F>
decltype(auto) dispatch_kernel(std::string_view name, F&& f) {
  return detail::dispatch_kernel_impl<D>(name, std::forward<F>(f));
}

template <int D>
KernelInfo<D> kernel_info(std::string_view name) {
  return dispatch_kernel<D>(name, []<class K>(K) {
    return KernelInfo<D>{K::name, K::support, &K::W, &K::dWdr};
  });
}

// All kernel names (including those unavailable in D, which dispatch rejects with a reason).
template <int D>
std::vector<std::string_view> kernel_names() {
  std::vector<std::string_view> names;
  std::apply([&](auto... k) { (names.push_back(k.name), ...); }, KernelTypes<D>{});
  return names;
}

}  // namespace sphmol
