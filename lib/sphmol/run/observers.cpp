#include "sphmol/run/observers.hpp"

namespace sphmol {

template <int D>
std::vector<std::unique_ptr<OutputObserver<D>>> make_observers(const Config&) {
  std::vector<std::unique_ptr<OutputObserver<D>>> list;
  return list;
}

template std::vector<std::unique_ptr<OutputObserver<1>>> make_observers<1>(const Config&);
template std::vector<std::unique_ptr<OutputObserver<2>>> make_observers<2>(const Config&);
template std::vector<std::unique_ptr<OutputObserver<3>>> make_observers<3>(const Config&);

}  // namespace sphmol
