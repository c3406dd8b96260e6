#pragma once
// MPI's lifetime for a program: MPI_Init_thread on construction, MPI_Finalize on destruction (only
// when this object started MPI). Threads: the ranks run OpenMP loops, and only the main thread calls
// MPI (MPI_THREAD_FUNNELED).
#include <mpi.h>

namespace sphmol::parallel {

class MpiEnvironment {
 public:
  MpiEnvironment(int& argc, char**& argv);
  ~MpiEnvironment();
  MpiEnvironment(const MpiEnvironment&) = delete;
  MpiEnvironment& operator=(const MpiEnvironment&) = delete;

 private:
  bool owns_ = false;
};

}  // namespace sphmol::parallel
