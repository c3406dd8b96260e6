#pragma once
// The pair list of a unit-test workspace: every pair within `radius` of the workspace positions (the
// all-pairs reference search, so a test of a term does not depend on the fast searches), then the
// kernel pass of kernel K into the workspace's active-pair list.
#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"
#include "sphmol/neighbors/all_pairs_search.hpp"
#include "sphmol/rhs/kernel_pass.hpp"

template <int D, class K>
void build_workspace_pairs(sphmol::Workspace<D>& w, const sphmol::Particles<D>& P, const sphmol::Domain<D>& dom,
                           double radius, sphmol::PairList& verlet) {
  sphmol::SearchInput<D> in;
  for (int d = 0; d < D; ++d) in.x[d] = w.x[d].data();
  in.kind = P.kind.data();
  in.n = w.n;
  in.domain = &dom;
  in.radius = radius;
  sphmol::AllPairsSearch<D>().build(in, verlet);
  sphmol::KernelPassFor<D, K>().apply(verlet, w);
}
