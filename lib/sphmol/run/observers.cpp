#include "sphmol/run/observers.hpp"

#include "sphmol/probes/probe_observer.hpp"
#include "sphmol/run/vtk_observer.hpp"

namespace sphmol {

template <int D>
std::vector<std::unique_ptr<OutputObserver<D>>> make_observers(const Config& config, const OwnedPiece<D>& start) {
  std::vector<std::unique_ptr<OutputObserver<D>>> list;
  if (config.output.vtk) list.push_back(std::make_unique<VtkObserver<D>>(config.output.vtk_walls, config.output.vtk_ghosts));
  if (!config.probes.empty()) list.push_back(std::make_unique<ProbeObserver<D>>(config, start));
  return list;
}

template std::vector<std::unique_ptr<OutputObserver<1>>> make_observers<1>(const Config&, const OwnedPiece<1>&);
template std::vector<std::unique_ptr<OutputObserver<2>>> make_observers<2>(const Config&, const OwnedPiece<2>&);
template std::vector<std::unique_ptr<OutputObserver<3>>> make_observers<3>(const Config&, const OwnedPiece<3>&);

}  // namespace sphmol
