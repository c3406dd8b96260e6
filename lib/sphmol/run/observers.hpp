#pragma once
// The output observers a config asks for (VTK files, checkpoints, ...), created once per run.
#include <memory>
#include <vector>

#include "sphmol/run/case.hpp"

namespace sphmol {

template <int D>
// `sys`: the built scene (probes check their positions against it and take its kernel).
std::vector<std::unique_ptr<OutputObserver<D>>> make_observers(const Config& config, const SphSystem<D>& sys);

}  // namespace sphmol
