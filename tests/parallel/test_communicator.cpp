// The communicator's collectives give the values their definitions say, on any number of ranks.
#include <catch2/catch.hpp>

#include <cstring>

#include "sphmol/parallel/communicator.hpp"

using namespace sphmol::parallel;

TEST_CASE("communicator: reductions and gathers", "[parallel][communicator]") {
  const Communicator comm;
  const int P = comm.size(), me = comm.rank();
  CHECK(comm.sum(static_cast<double>(me + 1)) == P * (P + 1) / 2.0);
  CHECK(comm.sum(static_cast<std::uint64_t>(me)) == static_cast<std::uint64_t>(P * (P - 1) / 2));
  CHECK(comm.max(static_cast<double>(me)) == P - 1);
  CHECK(comm.min(static_cast<double>(me)) == 0);
  CHECK(comm.all(true));
  CHECK(comm.all(me != P - 1) == (P == 0));
  const std::vector<int> ranks = comm.all_gather(me);
  for (int r = 0; r < P; ++r) CHECK(ranks[r] == r);
  // Rank r contributes r copies of r.
  const std::vector<int> v = comm.all_gather_v(std::vector<int>(static_cast<std::size_t>(me), me));
  std::vector<int> expected;
  for (int r = 0; r < P; ++r) expected.insert(expected.end(), static_cast<std::size_t>(r), r);
  CHECK(v == expected);
  // The tests run on one machine: every rank shares it.
  CHECK(comm.ranks_on_this_machine() == P);
}

TEST_CASE("communicator: all-to-all of bytes delivers each rank's message in rank order", "[parallel][communicator]") {
  const Communicator comm;
  const int P = comm.size(), me = comm.rank();
  // To rank r: (me + 1) * (r + 1) bytes, each holding me * 16 + r.
  std::vector<std::vector<std::byte>> send(static_cast<std::size_t>(P));
  for (int r = 0; r < P; ++r) send[r].assign(static_cast<std::size_t>((me + 1) * (r + 1)), static_cast<std::byte>(me * 16 + r));
  std::vector<std::size_t> from;
  const std::vector<std::byte> got = comm.all_to_all_v(send, from);
  REQUIRE(from.size() == static_cast<std::size_t>(P));
  std::size_t at = 0, wrong = 0;
  for (int s = 0; s < P; ++s) {
    CHECK(from[s] == static_cast<std::size_t>((s + 1) * (me + 1)));
    for (std::size_t k = 0; k < from[s]; ++k) wrong += got[at + k] != static_cast<std::byte>(s * 16 + me);
    at += from[s];
  }
  CHECK(at == got.size());
  CHECK(wrong == 0);
  CHECK_THROWS_WITH(comm.all_to_all_v({}, from), Catch::Contains("send buffers"));
}
