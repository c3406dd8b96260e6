#include "sphmol/rhs/kernel_pass_variable_h.hpp"

#include "sphmol/kernels/registry.hpp"

namespace sphmol {

template <int D>
std::unique_ptr<KernelPass<D>> make_variable_h_kernel_pass(std::string_view kernel_name) {
  return dispatch_kernel<D>(kernel_name, []<class K>(K) -> std::unique_ptr<KernelPass<D>> {
    return std::make_unique<KernelPassVariableH<D, K>>();
  });
}

template std::unique_ptr<KernelPass<1>> make_variable_h_kernel_pass<1>(std::string_view);
template std::unique_ptr<KernelPass<2>> make_variable_h_kernel_pass<2>(std::string_view);
template std::unique_ptr<KernelPass<3>> make_variable_h_kernel_pass<3>(std::string_view);

}  // namespace sphmol
