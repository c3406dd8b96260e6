#pragma once
// The whole system's per-particle fields at an output time of a run over ranks, without evaluating
// the whole scene. Each rank's local system has just been refreshed at the output state
// (DistributedSystem::refresh_local), so its owned rows hold the values the whole system's
// evaluation would give, to the bit (distributed_system.hpp); they travel to rank 0 by global id,
// which is the particle's index in the whole scene, and are set there (SphSystem::set_fields). Rank
// 0 then measures as the serial run does, and neither evaluates the whole scene nor builds its
// neighbour list. What the measurements and observers read of the whole system is exactly this:
// the scene's own particles' density, pressure, sound speed (fluid and walls: the force probes read
// the walls'), energy and h, besides the state itself; nothing reads its pair list or its ghost images.
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/distributed_system.hpp"
#include "sphmol/rhs/sph_system.hpp"

namespace sphmol::parallel {

// Collective, after split.refresh_local(t, y): the owned rows' fields of every rank set on `whole`
// on rank 0 (`whole` may be null elsewhere; it is not touched there).
template <int D>
void gather_whole_fields(const Communicator& comm, const DistributedSystem<D>& split, SphSystem<D>* whole);

extern template void gather_whole_fields<1>(const Communicator&, const DistributedSystem<1>&, SphSystem<1>*);
extern template void gather_whole_fields<2>(const Communicator&, const DistributedSystem<2>&, SphSystem<2>*);
extern template void gather_whole_fields<3>(const Communicator&, const DistributedSystem<3>&, SphSystem<3>*);

}  // namespace sphmol::parallel
