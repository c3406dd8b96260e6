#pragma once
// Moves particles between ranks with every per-particle array they carry (particle_columns.hpp), a
// global id and any number of extra per-particle double arrays (ODE state, rates). Afterwards each
// rank holds the particles sent to it, fluid first (the layout Particles<D> requires; fluid taken out
// of the run, Kind::Out, is fluid), fluid and walls each in ascending global id: the local order depends on what a rank owns, never on where the particles
// came from.
#include <cstdint>
#include <vector>

#include "sphmol/core/particles.hpp"
#include "sphmol/parallel/communicator.hpp"

namespace sphmol::parallel {

// destination[i]: the rank that gets local particle i (a rank may keep it). Collective. Arrays of
// Particles that are empty on every rank stay empty; one that is empty on some rank holding
// particles while others fill it is an error, as is a destination outside the communicator.
template <int D>
void migrate(const Communicator& comm, Particles<D>& p, std::vector<std::uint64_t>& gid, const std::vector<int>& destination,
             const std::vector<std::vector<double>*>& extra = {});

extern template void migrate<1>(const Communicator&, Particles<1>&, std::vector<std::uint64_t>&, const std::vector<int>&,
                                const std::vector<std::vector<double>*>&);
extern template void migrate<2>(const Communicator&, Particles<2>&, std::vector<std::uint64_t>&, const std::vector<int>&,
                                const std::vector<std::vector<double>*>&);
extern template void migrate<3>(const Communicator&, Particles<3>&, std::vector<std::uint64_t>&, const std::vector<int>&,
                                const std::vector<std::vector<double>*>&);

}  // namespace sphmol::parallel
