#pragma once
// Convergence studies (sph-mol converge).
//  time:  spatial discretisation fixed; fixed step dt0 / 2^k, k = 0..levels-1 (dt0 = --dt0, else
//         time.dt of the config, else the case's CFL step at t = 0: the built system's stable_step
//         after one RHS evaluation of the initial state). Error of level k = rms over all fluid
//         velocity components at t_end of (v_k - v_ref) divided by max |v_ref|, where v_ref is a
//         reference run of the same discretisation with ARKODE Verner 8_5_6 (order 6) at step
//         dt_finest / 8. Expected order: 2 for the leapfrogs, the table's q for ERK.
//  space: discretization.particles_across n0 * 2^k, or discretization.spacing dx0 / 2^k, with h/dx
//         fixed (discretization.smoothing_ratio); the configured integrator (or --integrators) with
//         its accuracy settings: rtol as configured, a fixed time.dt halved with dx (constant Courant
//         number), CFL steps as they come; error = the case's primary final error against its
//         reference, plotted against the spacing the scene used.
//         arkode_imex levels solve their stages at time.rtol 1e-14, time.atol 1e-14 max|v_ref| unless
//         the config gives them (at the defaults the solves' error hides the step's).
// Observed order per pair of consecutive clean levels (completed, finite error above arkode_imex's
// stage-solve tolerance): log(e_k / e_{k+1}) / log 2; overall: least-squares slope of log e vs
// log(dt) (or log dx) over the longest run of consecutive clean levels. Each level has a status
// (completed / blown_up). Writes convergence.csv, convergence.json and convergence.png.
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/studies/integrator_spec.hpp"

namespace sphmol {

struct ConvergeOptions {
  std::string refine = "time";  // time | space
  int levels = 4;
  std::vector<IntegratorSpec> integrators;  // empty: defaults (see default_time_integrators)
  std::optional<double> dt0;
  std::string output_dir;
  std::ostream* log = nullptr;
};

// leapfrog, leapfrog_kdk, Heun-Euler (2), Bogacki-Shampine (3), Zonneveld (4).
std::vector<IntegratorSpec> default_time_integrators();

// Observed orders between consecutive levels (refinement ratio 2) and the least-squares slope.
std::vector<double> pairwise_orders(const std::vector<double>& errors);
double least_squares_order(const std::vector<double>& errors);

nlohmann::json run_converge(const Config& base, const ConvergeOptions& opt);

}  // namespace sphmol
