#include "sphmol/parallel/whole_fields.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace sphmol::parallel {

template <int D>
void gather_whole_fields(const Communicator& comm, const DistributedSystem<D>& split, SphSystem<D>* whole) {
  const bool root = comm.rank() == 0;
  const SphSystem<D>& local = split.local_system();
  const std::vector<std::uint32_t>& rows = split.owned_rows();
  // Field by field (one value per owned particle each): rank 0 holds one field of the scene in
  // transit at a time, and no message nears MPI's int count.
  const std::vector<std::uint64_t> ids = comm.gather_v(split.gid());
  const std::size_t n = root ? whole->base_particles() : 0;
  if (root && ids.size() != n)
    throw std::logic_error("gather_whole_fields: the ranks own " + std::to_string(ids.size()) + " particles, the scene has " +
                           std::to_string(n));
  ParticleFieldValues f;
  const auto gather = [&](const std::vector<double>& from, std::vector<double>& to) {
    std::vector<double> mine(rows.size());
    for (std::size_t o = 0; o < rows.size(); ++o) mine[o] = from[rows[o]];
    const std::vector<double> all = comm.gather_v(mine);
    if (!root) return;
    to.assign(n, 0.0);
    for (std::size_t k = 0; k < ids.size(); ++k) to[ids[k]] = all[k];
  };
  gather(local.density(), f.density);
  gather(local.pressure(), f.pressure);
  gather(local.sound_speed(), f.sound_speed);
  gather(local.energy(), f.energy);
  gather(local.smoothing_lengths(), f.smoothing_length);
  if (root) whole->set_fields(f);
}

template void gather_whole_fields<1>(const Communicator&, const DistributedSystem<1>&, SphSystem<1>*);
template void gather_whole_fields<2>(const Communicator&, const DistributedSystem<2>&, SphSystem<2>*);
template void gather_whole_fields<3>(const Communicator&, const DistributedSystem<3>&, SphSystem<3>*);

}  // namespace sphmol::parallel
