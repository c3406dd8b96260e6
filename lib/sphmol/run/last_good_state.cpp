#include "sphmol/run/last_good_state.hpp"

#include <iomanip>
#include <sstream>

#include "sphmol/io/atomic_file.hpp"

namespace sphmol {

template <int D>
void write_last_good_state(const SphSystem<D>& sys, const double* y, const std::string& path) {
  const auto& L = sys.layout();
  std::ostringstream s;
  s << "id [-]";
  for (int d = 0; d < D; ++d) s << ",x" << d << " [m]";
  for (int d = 0; d < D; ++d) s << ",v" << d << " [m/s]";
  s << '\n' << std::setprecision(17);
  for (std::size_t i = 0; i < L.n; ++i) {
    s << i;
    for (int d = 0; d < D; ++d) s << ',' << y[L.position(d) + i];
    for (int d = 0; d < D; ++d) s << ',' << y[L.velocity(d) + i];
    s << '\n';
  }
  write_file_atomically(path, s.str());
}

template void write_last_good_state<1>(const SphSystem<1>&, const double*, const std::string&);
template void write_last_good_state<2>(const SphSystem<2>&, const double*, const std::string&);
template void write_last_good_state<3>(const SphSystem<3>&, const double*, const std::string&);

}  // namespace sphmol
