#pragma once
// A unit-test workspace: load_workspace fills it from the particles (positions, velocities and
// densities; zero pressure, sound speed and energy; h everywhere), and build_workspace_pairs makes its
// pair list: every pair within `radius` of the workspace positions (the all-pairs reference search,
// so a test of a term does not depend on the fast searches), then the kernel pass of kernel K into the
// workspace's active-pair list.
#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"
#include "sphmol/neighbors/all_pairs_search.hpp"
#include "sphmol/rhs/kernel_pass.hpp"

template <int D>
void load_workspace(sphmol::Workspace<D>& w, const sphmol::Particles<D>& P, const sphmol::Domain<D>& dom, double h) {
  w.n = P.size();
  w.n_fluid = P.n_fluid;
  w.particles = &P;
  w.domain = &dom;
  w.h = h;
  for (int d = 0; d < D; ++d) {
    w.x[d] = P.x[d];
    w.v[d] = P.v[d];
  }
  w.rho = P.rho;
  w.p.assign(w.n, 0.0);
  w.c.assign(w.n, 0.0);
  w.e.assign(w.n, 0.0);
  w.hs.assign(w.n, h);
}

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
