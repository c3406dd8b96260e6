#pragma once
// A 3D particle set with its workspace ready for RHS terms (tests of the terms in 3D): fluid on the
// cubic lattice ((i + 1/2) dx, (j + 1/2) dx, (k + 1/2) dx) filling [0, 1)^3 with n points per axis,
// periodic on the chosen axes, optionally jittered, with the lattice-consistent mass of the cubic
// spline at h = 1.3 dx (summation density gives rho0 on the perfect periodic lattice), and optional
// wall layers below z = 0 (normal +z, depth below the plane z = 0, for the Morris wall model).
// Every rate block (dx/dt, dv/dt, drho/dt, de/dt) points into arrays of the fixture.
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "sphmol/kernels/cubic_spline.hpp"
#include "sphmol/scenes/lattice_mass.hpp"
#include "workspace_pairs.hpp"

struct LatticeWorkspace3 {
  sphmol::Particles<3> P;
  sphmol::Domain<3> dom;
  sphmol::Workspace<3> w;
  sphmol::PairList verlet;
  std::array<std::vector<double>, 3> dxdt, dvdt;
  std::vector<double> drhodt, dedt, drhodt_wall;
  int n = 0, floor_layers = 0;
  double dx = 0.0, h = 0.0, rho0 = 1000.0, mass = 0.0;

  LatticeWorkspace3(int per_axis, std::array<bool, 3> periodic, double jitter = 0.0, int wall_layers = 0,
                    unsigned seed = 7)
      : n(per_axis), floor_layers(wall_layers) {
    using sphmol::Kind;
    dx = 1.0 / n;
    h = 1.3 * dx;
    mass = sphmol::lattice_particle_mass<3>("cubic_spline", rho0, dx, h);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-jitter * dx, jitter * dx);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          P.add(Kind::Fluid, {(i + 0.5) * dx + u(rng), (j + 0.5) * dx + u(rng), (k + 0.5) * dx + u(rng)}, {0, 0, 0},
                mass, rho0);
    for (int l = 0; l < wall_layers; ++l)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          P.add(Kind::Wall, {(i + 0.5) * dx, (j + 0.5) * dx, -(l + 0.5) * dx}, {0, 0, 0}, mass, rho0, {0.0, 0.0, 1.0},
                (l + 0.5) * dx);
    dom.lo = {0.0, 0.0, -wall_layers * dx};
    dom.hi = {1.0, 1.0, 1.0};
    dom.periodic = {periodic[0], periodic[1], periodic[2] && wall_layers == 0};
    load_workspace(w, P, dom, h);
    w.W0 = sphmol::CubicSpline<3>::W(0.0, h);
    for (auto& s : w.strain) s.assign(w.n, 0.0);
    clear_rates();
  }

  // Pairs within the support, found with a skin (the kernel pass must drop the extra pairs).
  void pairs() { build_workspace_pairs<3, sphmol::CubicSpline<3>>(w, P, dom, 2.0 * h * 1.2, verlet); }

  void clear_rates() {
    for (int d = 0; d < 3; ++d) {
      dxdt[d].assign(P.n_fluid, 0.0);
      dvdt[d].assign(P.n_fluid, 0.0);
      w.dxdt[d] = dxdt[d].data();
      w.dvdt[d] = dvdt[d].data();
    }
    drhodt.assign(P.n_fluid, 0.0);
    dedt.assign(P.n_fluid, 0.0);
    drhodt_wall.assign(P.size() - P.n_fluid, 0.0);
    w.drhodt = drhodt.data();
    w.dedt = dedt.data();
    w.drhodt_wall = drhodt_wall.data();
    w.n_wall_density = drhodt_wall.size();
  }

  // The fluid particle at lattice site (i, j, k).
  std::size_t site(int i, int j, int k) const { return static_cast<std::size_t>((k * n + j) * n + i); }
  // True when site (i, j, k) lies at least `margin` lattice spacings from every face of [0, 1)^3.
  bool interior(std::size_t p, int margin) const {
    const int i = static_cast<int>(p % n), j = static_cast<int>(p / n % n), k = static_cast<int>(p / n / n);
    for (const int c : {i, j, k})
      if (c < margin || c >= n - margin) return false;
    return true;
  }
};
