// Catch2 entry point of the MPI tests, run by mpirun on 1 to 4 ranks: every rank runs every test.
// Assertions that could differ between ranks are CHECKs (they do not throw), so that no rank leaves a
// collective call the others are waiting in; the process fails when any rank saw a failure.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <omp.h>

#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/mpi_environment.hpp"

int main(int argc, char* argv[]) {
  sphmol::parallel::MpiEnvironment mpi(argc, argv);
  omp_set_num_threads(1);
  const int failed = Catch::Session().run(argc, argv);
  // One verdict for all ranks, so mpirun's exit code does not depend on which rank ended first.
  const bool all_passed = sphmol::parallel::Communicator().all(failed == 0);
  return all_passed ? 0 : 1;
}
