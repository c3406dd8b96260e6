// The family of a state vector (parallel/vector_family.hpp): the clones made from the root or from
// its clones are members until destroyed, and a move gives every member that owns data its moved
// values at the new local length and points the root at the state's new storage, the global length
// and the fixed-point norms unchanged.
#include <catch2/catch.hpp>
#include <nvector/nvector_parallel.h>
#include <sundials/sundials_context.h>

#include <algorithm>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/fixed_point_norm_mpi.hpp"
#include "sphmol/parallel/vector_family.hpp"

using namespace sphmol::parallel;

namespace {

std::vector<double> values(N_Vector v) {
  const double* d = NV_DATA_P(v);
  return {d, d + NV_LOCLENGTH_P(v)};
}

// Entry k of the whole vector of tag `tag`.
double entry(std::size_t k, int tag) { return 1.0 + 0.25 * static_cast<double>(k) + 100.0 * tag; }

}  // namespace

TEST_CASE("a state vector's family records its clones and moves them with a new share", "[parallel][vector_family]") {
  const Communicator comm;
  const int P = comm.size(), r = comm.rank();
  SUNContext ctx = nullptr;
  REQUIRE(SUNContext_Create(nullptr, &ctx) == 0);
  // Rank r holds 3 + r entries, at the whole vector's offset of its rank; afterwards 3 + (P - 1 - r)
  // entries, the whole vector's entries taken from its end (every entry on another rank or place).
  std::size_t whole = 0, offset = 0;
  for (int q = 0; q < P; ++q) {
    if (q < r) offset += 3 + static_cast<std::size_t>(q);
    whole += 3 + static_cast<std::size_t>(q);
  }
  const std::size_t n = 3 + static_cast<std::size_t>(r);
  std::vector<double> y(n);
  for (std::size_t k = 0; k < n; ++k) y[k] = entry(offset + k, 0);

  N_Vector root = make_fixed_point_norm_vector(comm.handle(), y.data(), n, whole, ctx);
  const std::shared_ptr<VectorFamily> family = family_of(root);
  REQUIRE(family);
  CHECK(family->root() == root);
  N_Vector a = N_VClone(root);
  N_Vector b = N_VClone(a);  // a clone's clone joins the family too
  N_Vector* pair = N_VCloneVectorArray(2, root);
  N_Vector gone = N_VClone(b);
  N_Vector empty = N_VCloneEmpty(root);
  CHECK(family->members() == std::vector<N_Vector>{root, a, b, pair[0], pair[1], gone, empty});
  N_VDestroy(gone);
  CHECK(family->members() == std::vector<N_Vector>{root, a, b, pair[0], pair[1], empty});
  N_Vector others[] = {a, b, pair[0], pair[1]};
  for (int tag = 1; tag <= 4; ++tag)
    for (std::size_t k = 0; k < n; ++k) NV_DATA_P(others[tag - 1])[k] = entry(offset + k, tag);
  const double norm_before = N_VWrmsNorm(a, b);
  const double dot_before = N_VDotProd(pair[0], pair[1]);

  // The move: every array gathered whole and the new share taken, as migration would.
  const std::size_t m = 3 + static_cast<std::size_t>(P - 1 - r);
  std::size_t new_offset = 0;
  for (int q = 0; q < r; ++q) new_offset += 3 + static_cast<std::size_t>(P - 1 - q);
  const auto reshare = [&](std::vector<double>& v) {
    std::vector<double> all = comm.all_gather_v(v);
    std::reverse(all.begin(), all.end());
    v.assign(all.begin() + static_cast<long>(new_offset), all.begin() + static_cast<long>(new_offset + m));
  };
  {
    FamilyMove move({family}, y.data(), y.size());
    auto arrays = move.arrays();
    REQUIRE(arrays.size() == 4);  // the members that own data: not the root, not the empty clone
    reshare(y);
    for (auto* v : arrays) reshare(*v);
    move.finish(y.data(), y.size());
  }

  CHECK(NV_DATA_P(root) == y.data());
  for (N_Vector v : {root, a, b, pair[0], pair[1], empty}) {
    CHECK(static_cast<std::size_t>(NV_LOCLENGTH_P(v)) == m);
    CHECK(static_cast<std::size_t>(NV_GLOBLENGTH_P(v)) == whole);
  }
  CHECK(NV_DATA_P(empty) == nullptr);
  for (int tag = 1; tag <= 4; ++tag) {
    std::vector<double> expected(m);
    for (std::size_t k = 0; k < m; ++k) expected[k] = entry(whole - 1 - (new_offset + k), tag);
    CHECK(values(others[tag - 1]) == expected);
  }
  // The fixed-point reductions do not see the new share.
  CHECK(N_VWrmsNorm(a, b) == norm_before);
  CHECK(N_VDotProd(pair[0], pair[1]) == dot_before);
  // Clones made afterwards are of the new length, and members.
  N_Vector later = N_VClone(root);
  CHECK(static_cast<std::size_t>(NV_LOCLENGTH_P(later)) == m);
  CHECK(family_of(later) == family);

  SECTION("a clone given storage it does not own cannot move") {
    std::vector<double> storage(m, 0.0);
    N_VSetArrayPointer(storage.data(), empty);
    CHECK_THROWS_AS(FamilyMove({family}, y.data(), y.size()), std::logic_error);
    N_VSetArrayPointer(nullptr, empty);
  }
  SECTION("a root over other storage than the state's cannot move") {
    std::vector<double> other = y;
    CHECK_THROWS_AS(FamilyMove({family}, other.data(), other.size()), std::logic_error);
  }

  N_VDestroy(later);
  N_VDestroyVectorArray(pair, 2);
  N_VDestroy(empty);
  N_VDestroy(b);
  N_VDestroy(a);
  N_VDestroy(root);
  CHECK(family.use_count() == 1);  // only this test's copy: the registry forgot the family
  SUNContext_Free(&ctx);
}
