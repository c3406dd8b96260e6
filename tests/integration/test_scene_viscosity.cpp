// Fluid bodies of their own viscosity through the sph-mol binary: a plane Couette flow of two layers,
// the lower four times less viscous, between a resting mirror floor and a mirror lid moving along
// itself (periodic in x). At steady state the shear stress is the same in both layers, so the
// profile is piecewise linear with slopes in the ratio 4 : 1 and the interface at
// u_i = U mu_2 h_1 / (mu_1 h_2 + mu_2 h_1) = 0.8 U.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_helpers.hpp"

using namespace run_helpers;

TEST_CASE("scene viscosity: a two-layer Couette flow has the piecewise linear profile", "[integration][scene]") {
  const double U = 0.01, H = 0.01, nu1 = 1e-4, nu2 = 4e-4;
  const fs::path dir = scratch("two-layer-couette");
  std::ofstream(dir / "layers.yaml") << R"yaml(case: scene
dimension: 2
fluid:
  density: 1000.0
  kinematic_viscosity: 1.0e-4
  eos: {type: linear_relative, sound_speed: 0.1}
scene:
  domain: {lo: [0, 0], hi: [0.005, 0.01], boundaries: [periodic, wall]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [0.005, 0.005]}
    - shape: {type: box, lo: [0, 0.005], hi: [0.005, 0.01]}
      kinematic_viscosity: 4.0e-4
  walls:
    - name: lid
      shape: {type: plane, point: [0, 0.01], normal: [0, -1]}
      velocity: [0.01, 0]
discretization:
  spacing: 0.0005
  boundary: ghost
  viscosity: morris
  density: continuity
time:
  t_end: 3.0
  integrator: leapfrog
output:
  times: [3.0]
  plots: false
  profiles: false
probes:
  - name: u
    type: line
    from: [0.0025, 0.00025]
    to: [0.0025, 0.00975]
    points: 20
    fields: [velocity]
)yaml";
  const auto r = sph_mol("-q --threads 1 --config '" + (dir / "layers.yaml").string() + "' --output '" + (dir / "out").string() + "'",
                         dir / "err.log");
  INFO(r.err);
  REQUIRE(r.code == 0);
  // The profile at t = 3 s (12 viscous times of the lower layer, 48 of the upper).
  std::ifstream csv(dir / "out" / "probe_u.csv");
  std::string line;
  std::getline(csv, line);  // header
  std::vector<double> y, u;
  while (std::getline(csv, line)) {
    std::istringstream s(line);
    std::string t, x, yy, uu;
    std::getline(s, t, ',');
    std::getline(s, x, ',');
    std::getline(s, yy, ',');
    std::getline(s, uu, ',');
    if (std::stod(t) != 3.0) continue;
    y.push_back(std::stod(yy));
    u.push_back(std::stod(uu));
  }
  REQUIRE(y.size() == 20u);
  const double h1 = 0.5 * H, mu1 = nu1, mu2 = nu2, ui = U * mu2 * h1 / (mu1 * (H - h1) + mu2 * h1);
  CHECK(ui == Approx(0.8 * U));
  // Away from the walls and the interface by more than the kernel support (1.3 mm; the probe's
  // Shepard interpolation smooths the kink within it): measured within 1e-4 U; the arithmetic mean
  // of the two viscosities across the interface gave up to 0.017 U.
  const double support = 2.0 * 1.3 * 0.0005;
  int checked = 0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    if (y[k] < support || y[k] > H - support || std::abs(y[k] - h1) < support) continue;
    const double exact = y[k] < h1 ? ui * y[k] / h1 : ui + (U - ui) * (y[k] - h1) / (H - h1);
    INFO("y = " << y[k] << ": u = " << u[k] << ", exact " << exact);
    CHECK(std::abs(u[k] - exact) < 2e-3 * U);
    ++checked;
  }
  CHECK(checked == 8);  // y = 1.75-3.25 mm and 6.75-8.25 mm
  fs::remove_all(dir);
}
