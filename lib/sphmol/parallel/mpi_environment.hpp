#pragma once
// MPI's lifetime for a program: MPI_Init_thread on construction, MPI_Finalize on destruction (only
// when this object started MPI). Threads: the ranks run OpenMP loops, and only the main thread calls
// MPI (MPI_THREAD_FUNNELED).
#include <mpi.h>

namespace sphmol::parallel {

class MpiEnvironment {
 public:
  MpiEnvironment(int& argc, char**& argv);
  // True when an MPI launcher started this process (mpirun/mpiexec of Open MPI, MPICH's Hydra, or a
  // PMIx launcher such as srun): its environment says so. A program that may also run on its own
  // starts MPI only then, since a stand-alone MPI_Init needs the MPI runtime (Open MPI spawns a
  // daemon for it) where a serial run needs none.
  static bool launched();
  // This process's rank as its launcher's environment gives it (0 if not launched, or if the launcher
  // does not say): known before MPI starts, for messages about the command line, which every rank
  // would print alike.
  static int launched_rank();
  ~MpiEnvironment();
  MpiEnvironment(const MpiEnvironment&) = delete;
  MpiEnvironment& operator=(const MpiEnvironment&) = delete;

 private:
  bool owns_ = false;
};

}  // namespace sphmol::parallel
