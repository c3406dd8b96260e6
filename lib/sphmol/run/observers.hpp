#pragma once
// The output observers a config asks for (VTK files, checkpoints, ...), created once per run.
#include <memory>
#include <vector>

#include "sphmol/run/case.hpp"

namespace sphmol {

// `start`: the rank's particles of the built scene at its initial state (run/start_piece.hpp; a
// serial run: the whole scene). Probes check their positions against the whole scene and take its
// kernel. Collective over the ranks of `start`.
template <int D>
std::vector<std::unique_ptr<OutputObserver<D>>> make_observers(const Config& config, const OwnedPiece<D>& start);

}  // namespace sphmol
