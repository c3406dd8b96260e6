#pragma once
// Name -> kernel. dispatch_kernel<D>(name, f) calls f(K{}) with the kernel type, so the caller
// instantiates its hot loop once per kernel; kernel_info<D>(name) gives a runtime handle for
// diagnostics and analysis. To add a kernel: write kernels/<name>.hpp and list it in KernelTypes.
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "sphmol/kernels/composite.hpp"
#include "sphmol/kernels/cubic_spline.hpp"
#include "sphmol/kernels/desbrun_spiky.hpp"
#include "sphmol/kernels/gaussian.hpp"
#include "sphmol/kernels/kernel.hpp"
#include "sphmol/kernels/lucy.hpp"
#include "sphmol/kernels/muller_poly6.hpp"
#include "sphmol/kernels/quadratic_johnson.hpp"
#include "sphmol/kernels/quartic_liu.hpp"
#include "sphmol/kernels/quintic_morris.hpp"
#include "sphmol/kernels/super_gaussian.hpp"
#include "sphmol/kernels/truncated_exponential.hpp"
#include "sphmol/kernels/wendland_c2.hpp"

namespace sphmol {

template <int D>
using KernelTypes =
    std::tuple<CubicSpline<D>, LucyKernel<D>, GaussianKernel<D>, TruncatedExponentialKernel<D>,
               QuarticLiuKernel<D>, QuinticMorrisKernel<D>, QuadraticJohnsonKernel<D>,
               SuperGaussianKernel<D>, DesbrunSpikyKernel<D>, MullerPoly6Kernel<D>,
               CompositeKernel<D>, WendlandC2Kernel<D>>;

template <int D>
struct KernelInfo {
  std::string_view name;
  double support = 0.0;  // in units of h
  double (*W)(double r, double h) = nullptr;
  double (*dWdr)(double r, double h) = nullptr;
  // Additive extensions (see kernel.hpp for the optional kernel members they read).
  std::string_view source;
  bool derivative_is_exact = true;
  double (*dWdr_k)(double r, double h, double k) = nullptr;  // derivative given k = h/d
  double mass = 1.0;                                          // integral of W over R^D
};

// One catalogue line per kernel type, also for kernels unavailable in D (W is null then).
template <int D>
struct KernelEntry {
  std::string_view name;
  bool available = false;
  std::string_view unavailable_reason;
  KernelInfo<D> info;
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
        throw std::invalid_argument("kernel '" + std::string(name) + "' is not available in " +
                                    std::to_string(D) + "D: " + std::string(kernel_unavailable_reason<K>()));
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

template <class K>
KernelInfo<K::dimension> make_kernel_info() {
  return KernelInfo<K::dimension>{K::name, K::support, &K::W, &K::dWdr, kernel_source<K>(),
                                  kernel_derivative_is_exact<K>(), &kernel_dWdr_k<K>, kernel_mass<K>()};
}

template <int D>
KernelInfo<D> kernel_info(std::string_view name) {
  return dispatch_kernel<D>(name, []<class K>(K) {
    return make_kernel_info<K>();
  });
}

template <int D>
std::vector<KernelEntry<D>> kernel_catalogue() {
  std::vector<KernelEntry<D>> out;
  std::apply([&]<class... K>(K...) {
    (([&] {
       KernelEntry<D> e{K::name, K::available, kernel_unavailable_reason<K>(), {}};
       if constexpr (K::available) e.info = make_kernel_info<K>();
       out.push_back(e);
     }()), ...);
  }, KernelTypes<D>{});
  return out;
}

// All kernel names (including those unavailable in D, which dispatch rejects with a reason).
template <int D>
std::vector<std::string_view> kernel_names() {
  std::vector<std::string_view> names;
  std::apply([&](auto... k) { (names.push_back(k.name), ...); }, KernelTypes<D>{});
  return names;
}

}  // namespace sphmol
