// sph-bench, end to end in 3D: a dam break in a box, built here from the geometry kit and
// assemble_system with the formulation of verification/dam_break.yaml (Wendland C2, h = 1.414 dp,
// continuity + delta-SPH 0.1, Monaghan artificial viscosity alpha = 0.02, Tait EOS with c0 = 20
// sqrt(g H), one layer of dynamic boundary particles, leapfrog with one RHS evaluation per step): a
// water column 0.4 x 0.67 x 0.3 m at the x = 0 end of a tank 1.6 x 0.67 x 0.4 m with an open top,
// dp = 0.01 m (80,400 fluid and 29,498 wall particles). "us/particle-step" = wall time / (steps x all
// particles), as DamBreakStep reports it for the 2D dam break.
//   sph-bench --benchmark_filter=DamBreak3DStep   single steps on 1 and 2 threads
// On a shared machine set OMP_WAIT_POLICY=passive (bench_dam_break.cpp).
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "sphmol/config/config.hpp"
#include "sphmol/geometry/box_shape.hpp"
#include "sphmol/geometry/lattice.hpp"
#include "sphmol/geometry/wall_layers.hpp"
#include "sphmol/physics/eos_tait.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "sphmol/time/integrator.hpp"

namespace {

struct DamBreak3D {
  std::unique_ptr<sphmol::SphSystem<3>> sys;
  std::vector<double> y;  // the state the integrator advances in place (declared first: outlives it)
  std::unique_ptr<sphmol::Integrator> integrator;
};

DamBreak3D build_dam_break_3d(double dp) {
  namespace geo = sphmol::geometry;
  const double g = 9.81, rho0 = 1000.0;
  const geo::Vec<3> column{0.4, 0.67, 0.3}, tank{1.6, 0.67, 0.4};
  // The 2D dam break's discretisation and time stepping; gravity along -z, and the sound speed scaled
  // to this column (DualSPHysics' coefsound 20, as the 2D case).
  sphmol::Config c = sphmol::load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml");
  c.dimension = 3;
  c.fluid.body_force = {0.0, 0.0, -g};
  c.fluid.eos.sound_speed = 20.0 * std::sqrt(g * column[2]);
  c.discretization.spacing = dp;
  const sphmol::TaitLaw law(c.fluid.eos.sound_speed, rho0, c.fluid.eos.gamma);
  const auto hydrostatic = [&](double z) { return law.density(rho0 * g * std::max(0.0, column[2] - z)); };

  geo::Lattice<3> lattice;
  lattice.spacing = dp;
  const double m = rho0 * lattice.cell_volume();
  sphmol::Particles<3> particles;
  for (const auto& x : geo::fill(geo::BoxShape<3>({0, 0, 0}, column), lattice))
    particles.add(sphmol::Kind::Fluid, x, {0, 0, 0}, m, hydrostatic(x[2]));
  const int layers = c.discretization.wall_layers > 0 ? c.discretization.wall_layers : 1;
  // Wall densities: hydrostatic under the column, as the 2D scene sets them, rho0 elsewhere.
  for (const auto& w : geo::box_container_walls<3>({0, 0, 0}, tank, {false, false, false, false, false, true}, lattice,
                                                   layers * dp)) {
    const double rho = w.x[0] < column[0] ? hydrostatic(w.x[2]) : rho0;
    particles.add(sphmol::Kind::Wall, w.x, {0, 0, 0}, m, rho, w.normal, w.depth);
  }
  sphmol::Domain<3> domain;
  const double margin = layers * dp + 2.0 * 2.0 * c.discretization.smoothing_ratio * dp;  // walls + two supports
  domain.lo = {-margin, -margin, -margin};
  domain.hi = {tank[0] + margin, tank[1] + margin, std::max(tank[2], 2.0 * column[2]) + margin};

  DamBreak3D run;
  run.sys = sphmol::assemble_system<3>(c, std::move(particles), domain, dp);
  run.y = run.sys->initial_state();
  run.integrator = sphmol::make_integrator(c.time);
  run.integrator->initialize(*run.sys, 0.0, run.y.data());
  return run;
}

// One benchmark iteration is one time step. Argument: threads. The column first collapses for 100
// steps, so that the neighbour list has been rebuilt as in a running case.
void DamBreak3DStep(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  omp_set_num_threads(threads);
  DamBreak3D run = build_dam_break_3d(0.01);
  const double never = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 100; ++k) run.integrator->step_toward(never);
  for (auto _ : state) {
    run.integrator->step_toward(never);
    benchmark::DoNotOptimize(run.y.data());
  }
  const double particles = static_cast<double>(run.sys->particles().size());
  state.counters["us/particle-step"] = benchmark::Counter(
      particles * 1e-6, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["particles"] = particles;
  state.counters["fluid"] = static_cast<double>(run.sys->particles().n_fluid);
  state.counters["pairs/particle"] = static_cast<double>(run.sys->active_pairs()) / particles;
  omp_set_num_threads(1);
}
BENCHMARK(DamBreak3DStep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

}  // namespace
