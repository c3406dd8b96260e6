// Catch2 entry point. Tests run single-threaded unless a test sets the thread count itself (CTest
// runs test processes in parallel, and results must not depend on the thread count anyway).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <omp.h>

int main(int argc, char* argv[]) {
  omp_set_num_threads(1);
  return Catch::Session().run(argc, argv);
}
