#pragma once
// A unit-test workspace for pair terms over given particles: every pair listed (the kernel pass keeps
// those inside the support), all particles fluid, outputs (dx/dt, dv/dt, drho/dt, de/dt, dh/dt) in
// owned buffers. Fill P (and, for a variable h, w.hs), then call finish(h). The fixture is filled in
// place: the workspace points into it.
#include <array>
#include <vector>

#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"
#include "sphmol/rhs/kernel_pass.hpp"
#include "sphmol/rhs/kernel_pass_variable_h.hpp"

template <int D>
struct PairTermFixture {
  sphmol::Particles<D> P;
  sphmol::Domain<D> domain;
  sphmol::Workspace<D> w;
  std::array<std::vector<double>, D> dxdt, dvdt;
  std::vector<double> drho, de, dh;
  double h = 0.0;

  void finish(double h_, bool variable_h = false, const char* kernel = "cubic_spline") {
    h = h_;
    const std::size_t n = P.size();
    w.n = w.n_fluid = n;
    w.particles = &P;
    w.domain = &domain;
    w.h = h;
    auto pass = variable_h ? sphmol::make_variable_h_kernel_pass<D>(kernel) : sphmol::make_kernel_pass<D>(kernel);
    w.W0 = pass->value_at_zero(h);
    for (int d = 0; d < D; ++d) {
      w.x[d] = P.x[d];
      w.v[d] = P.v[d];
      dxdt[d].assign(n, 0.0);
      dvdt[d].assign(n, 0.0);
      w.dxdt[d] = dxdt[d].data();
      w.dvdt[d] = dvdt[d].data();
    }
    w.rho = P.rho;
    w.p.assign(n, 0.0);
    w.c.assign(n, 1.0);
    w.e.assign(n, 1.0);
    if (w.hs.size() != n) w.hs.assign(n, h);
    drho.assign(n, 0.0);
    de.assign(n, 0.0);
    dh.assign(n, 0.0);
    w.drhodt = drho.data();
    w.dedt = de.data();
    w.dhdt = dh.data();
    sphmol::PairList all;
    all.offset.assign(1, 0);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j)
        if (j != i) all.j.push_back(static_cast<std::uint32_t>(j));
      all.offset.push_back(static_cast<std::uint32_t>(all.j.size()));
    }
    pass->apply(all, w);
  }
};
