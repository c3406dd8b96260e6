#include "sphmol/parallel/mpi_environment.hpp"

#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace sphmol::parallel {

MpiEnvironment::MpiEnvironment(int& argc, char**& argv) {
  int started = 0;
  MPI_Initialized(&started);
  if (started) return;
  int provided = 0;
  if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    throw std::runtime_error("MPI_Init_thread failed");
  owns_ = true;
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    throw std::runtime_error("the MPI library does not support MPI_THREAD_FUNNELED");
  }
}

bool MpiEnvironment::launched() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

int MpiEnvironment::launched_rank() {
  for (const char* v : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
    if (const char* rank = std::getenv(v)) {
      char* end = nullptr;
      const long r = std::strtol(rank, &end, 10);
      return end != rank && *end == '\0' && r >= 0 && r <= std::numeric_limits<int>::max() ? static_cast<int>(r) : 0;
    }
  return 0;
}

MpiEnvironment::~MpiEnvironment() {
  int finished = 0;
  MPI_Finalized(&finished);
  if (owns_ && !finished) MPI_Finalize();
}

}  // namespace sphmol::parallel
