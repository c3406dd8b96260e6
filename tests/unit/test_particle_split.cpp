// time/particle_split.hpp: element-wise loops over a state of particle blocks split by particle.
// Every element is visited once, and entry i of every block goes to the thread of particle i (the
// thread the RHS's static loops over particles give it), for any thread count and with a tail.
#include <catch2/catch.hpp>

#include <omp.h>
#include <vector>

#include "sphmol/time/particle_split.hpp"

using namespace sphmol;

TEST_CASE("for_each_by_particle visits every element once, a particle's entries on one thread", "[unit][threads]") {
  for (const int threads : {1, 2, 3}) {
    for (const std::size_t tail : {std::size_t{0}, std::size_t{7}}) {
      INFO("threads " << threads << ", tail " << tail);
      const std::size_t L = 1001, blocks = 5, lo = 2 * L, hi = blocks * L + tail;  // blocks 2..4, then the tail
      std::vector<int> visits(hi, 0), owner(hi, -1), particle_owner(L, -1);
      omp_set_num_threads(threads);
#pragma omp parallel
      {
        for_each_by_particle(lo, hi, L, [&](std::size_t k) {
          ++visits[k];  // each k by one thread only, checked below
          owner[k] = omp_get_thread_num();
        });
#pragma omp for schedule(static)
        for (std::size_t i = 0; i < L; ++i) particle_owner[i] = omp_get_thread_num();  // the RHS's split
      }
      omp_set_num_threads(1);
      for (std::size_t k = 0; k < hi; ++k) REQUIRE(visits[k] == (k >= lo ? 1 : 0));
      for (std::size_t k = lo; k < blocks * L; ++k) REQUIRE(owner[k] == particle_owner[k % L]);
    }
  }
}

TEST_CASE("for_each_by_particle without block structure splits the range as one loop", "[unit][threads]") {
  std::vector<int> visits(100, 0);
  omp_set_num_threads(2);
#pragma omp parallel
  for_each_by_particle(10, 100, 0, [&](std::size_t k) { ++visits[k]; });  // block 0: the tail is everything
  omp_set_num_threads(1);
  for (std::size_t k = 0; k < 100; ++k) REQUIRE(visits[k] == (k >= 10 ? 1 : 0));
}
