// `sph-mol kernels`: the kernel catalogue (support, numerically integrated normalisation,
// moments M0..M4 and M'0..M'4 per dimension, Vukčević 2012, eqs 64/69), discrete particle-consistency
// sums (Vukčević 2012, eqs 90-91) on three particle sets, and with `--analysis hydrostatic` the computed
// analogue of Potapov & Reshetnikova 2021's Table 1 (eqs 17-22) on the triangular lattice.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <iostream>
#include <numbers>
#include <string>

#include "sphmol/analysis/hydrostatic_error.hpp"
#include "sphmol/analysis/kernel_moments.hpp"
#include "sphmol/analysis/corrected_consistency.hpp"
#include "sphmol/analysis/particle_consistency.hpp"
#include "sphmol/analysis/particle_sets.hpp"
#include "sphmol/io/atomic_file.hpp"
#include "sphmol/kernels/registry.hpp"
#include "study_common.hpp"
#include "number_checks.hpp"
#include "subcommand.hpp"

namespace {

struct Options {
  int dimension = 0;  // 0: all
  std::string analysis;
  std::string output;
  std::string kernel;
  std::string correction = "none";
  double eps = 0.01;
  const CLI::Option* eps_option = nullptr;         // given: only the hydrostatic analysis reads it
  const CLI::Option* correction_option = nullptr;  // given: only the catalogue reads it
} opt;

template <int D>
void print_catalogue() {
  std::printf("== %dD kernels (normalisation = integral of W over R^%d by GSL quadrature; M_k in h^k, "
              "M'_k in h^(k-1), M''_k in h^(k-2); Vukčević 2012, eqs 64, 69, 76; odd moments vanish by parity) ==\n", D, D);
  std::printf("%-22s %7s %15s %10s %10s %10s %10s | %9s %9s %9s %9s | %9s %9s %9s\n", "kernel", "support",
              "normalisation", "M1", "M2", "M3", "M4", "M'0", "M'1", "M'2", "M'3", "M''0", "M''2", "M''4");
  for (const auto& e : sphmol::kernel_catalogue<D>()) {
    if (!opt.kernel.empty() && e.name != opt.kernel) continue;
    if (!e.available) {
      std::printf("%-22s unavailable: %s\n", std::string(e.name).c_str(), std::string(e.unavailable_reason).c_str());
      continue;
    }
    const auto m = sphmol::analysis::kernel_moments(e.info);
    std::printf("%-22s %7.3g %15.12f %10.2e %10.6f %10.2e %10.6f | %9.2e %9.6f %9.2e %9.6f | %9.2e %9.6f %9.5f%s\n",
                std::string(e.name).c_str(), e.info.support, m.M[0], m.M[1], m.M[2], m.M[3], m.M[4], m.dM[0], m.dM[1],
                m.dM[2], m.dM[3], m.d2M[0], m.d2M[2], m.d2M[4],
                e.info.derivative_is_exact ? "" : "  (derivative: separate function)");
  }
}

template <int D>
void print_consistency() {
  using namespace sphmol::analysis;
  const double d = 1.0, h = 1.3 * d;  // h/d = 1.3, a common choice
  const int n = 6;                      // lattice half-width in d: covers support 3h
  std::printf("== %dD discrete consistency at the origin particle, d = 1, h = 1.3 d (Vukčević 2012, eqs 90-91: "
              "S0 -> 1, S1 -> 0; gradient sums G0 -> 0, G1 -> I) ==\n", D);
  std::printf("%-22s %-15s %4s %14s %12s %12s %14s %12s\n", "kernel", "set", "N", "S0-1", "|S1|", "|G0|",
              "max|G1-I|", "");
  const ParticleSet<D> sets[3] = {regular_lattice<D>(n, d), perturbed_lattice<D>(n, d, 0.2, 20211979),
                                  wall_lattice<D>(n, d)};
  const char* names[6] = {"regular", "perturbed", "wall", "regular+rkpm", "perturbed+rkpm", "wall+rkpm"};
  std::array<double, D> x{};
  for (const auto& e : sphmol::kernel_catalogue<D>()) {
    if (!e.available || (!opt.kernel.empty() && e.name != opt.kernel)) continue;
    for (int s = 0; s < 6; ++s) {
      const bool corrected = s >= 3;
      if (corrected && opt.correction != "rkpm") break;
      ConsistencySums<D> c;
      if (!corrected) c = consistency_sums<D>(sets[s], x, h, e.info, h / d);
      else if (!rkpm_consistency_sums<D>(sets[s - 3], x, h, e.info, h / d, c)) {
        std::printf("%-22s %-15s  singular moment matrix\n", std::string(e.name).c_str(), names[s]);
        continue;
      }
      double s1 = 0, g0 = 0, g1 = 0;
      for (int a = 0; a < D; ++a) {
        s1 += c.S1[a] * c.S1[a];
        g0 += c.G0[a] * c.G0[a];
        for (int b = 0; b < D; ++b) g1 = std::max(g1, std::abs(c.G1[a][b] - (a == b ? 1.0 : 0.0)));
      }
      std::printf("%-22s %-15s %4d %14.6e %12.4e %12.4e %14.6e\n", std::string(e.name).c_str(), names[s],
                  c.neighbours, c.S0 - 1.0, std::sqrt(s1), std::sqrt(g0), g1);
    }
  }
}

std::string roots_text(const std::vector<sphmol::analysis::HydrostaticRoot>& roots) {
  if (roots.empty()) return "-";
  std::string s;
  char buf[64];
  for (const auto& r : roots) {
    std::snprintf(buf, sizeof buf, "%s%.5f(%+.5f)", s.empty() ? "" : " ", r.k, r.other);
    s += buf;
  }
  return s;
}

bool write_output(const std::string& path, const std::string& text) {
  try {
    sphmol::write_file_atomically(path, text);
    return true;
  } catch (const std::exception& ex) {
    std::cerr << "sph-mol kernels: cannot write " << path << ": " << ex.what() << "\n";
    return false;
  }
}

int run_hydrostatic() {
  using namespace sphmol::analysis;
  const double aps[3] = {std::sqrt(3.0) / 2.0, std::numbers::pi / 4.0, 1.0};
  const char* ap_names[3] = {"sqrt3/2", "pi/4", "1"};
  const char* ap_columns[3] = {"sqrt3_2", "pi_4", "1"};  // in CSV column names
  // Each file is assembled in memory and written whole through a fresh temporary (never through a
  // link planted at its name).
  const bool write = !opt.output.empty();
  // One row per kernel and a_p, and the roots in their own table, one per row (a variable number of
  // them would not fit fixed columns).
  std::ostringstream table, roots;
  if (write) {
    std::error_code ec;
    std::filesystem::create_directories(opt.output, ec);
    table << "kernel,a_p [-],eps_rho_roots [-],eps_gradp_roots [-],condition22,best_k [-],best_max_abs_error [-]\n";
    roots << "kernel,a_p [-],root_of,k [-],other_error [-]\n";
    table.precision(10);
    roots.precision(10);
  }
  std::printf("Hydrostatic kernel analysis, Potapov & Reshetnikova 2021, eqs 17-22: 2D triangular lattice edge d, h = k d, "
              "k in [0.75, 1.25], eps = %g\n", opt.eps);
  std::printf("roots of eps_rho: k(eps_gradP there); roots of eps_gradP: k(eps_rho there); "
              "best k minimises max(|eps_rho|, |eps_gradP|); condition 22 holds iff that max <= eps\n");
  std::printf("%-22s %-8s %-40s %-40s %-6s %8s %10s\n", "kernel", "a_p", "eps_rho roots", "eps_gradP roots", "cond22",
              "best k", "max|eps|");
  for (const auto& e : sphmol::kernel_catalogue<2>()) {
    if (!e.available || (!opt.kernel.empty() && e.name != opt.kernel)) continue;
    if (write) {
      std::ostringstream curves;
      curves.precision(12);
      curves << "k [-]";
      for (auto n : ap_columns) curves << ",eps_rho_ap_" << n << " [-],eps_gradp_ap_" << n << " [-]";
      curves << "\n";
      for (int i = 0; i <= 500; ++i) {
        const double k = 0.75 + 0.5 * i / 500;
        curves << k;
        for (double ap : aps) {
          const auto err = hydrostatic_errors(e.info, k, ap);
          curves << "," << err.eps_rho << "," << err.eps_gradp;
        }
        curves << "\n";
      }
      if (!write_output(opt.output + "/hydrostatic_curves_" + std::string(e.name) + ".csv", curves.str())) return 1;
    }
    for (int a = 0; a < 3; ++a) {
      const auto row = hydrostatic_row(e.info, aps[a], opt.eps);
      std::printf("%-22s %-8s %-40s %-40s %-6s %8.5f %10.5f\n", std::string(e.name).c_str(), ap_names[a],
                  roots_text(row.rho_roots).c_str(), roots_text(row.gradp_roots).c_str(),
                  row.passes ? "pass" : "FAIL", row.best_k, row.best_err);
      if (write) {
        table << e.name << "," << aps[a] << "," << row.rho_roots.size() << "," << row.gradp_roots.size() << ","
              << (row.passes ? "pass" : "fail") << "," << row.best_k << "," << row.best_err << "\n";
        for (const auto& r : row.rho_roots) roots << e.name << "," << aps[a] << ",eps_rho," << r.k << "," << r.other << "\n";
        for (const auto& r : row.gradp_roots) roots << e.name << "," << aps[a] << ",eps_gradp," << r.k << "," << r.other << "\n";
      }
    }
  }
  if (write) {
    if (!write_output(opt.output + "/hydrostatic_table.csv", table.str())) return 1;
    if (!write_output(opt.output + "/hydrostatic_roots.csv", roots.str())) return 1;
    std::printf("wrote %s/hydrostatic_table.csv, hydrostatic_roots.csv and hydrostatic_curves_<kernel>.csv\n", opt.output.c_str());
  }
  return 0;
}

template <int D>
bool kernel_known(const std::string& name) {
  for (auto n : sphmol::kernel_names<D>())
    if (n == name) return true;
  return false;
}

int run() {
  if (opt.dimension != 0 && (opt.dimension < 1 || opt.dimension > 3)) {
    std::cerr << "sph-mol kernels: --dimension must be 1, 2 or 3 (got " << opt.dimension << ")\n";
    return 2;
  }
  if (!opt.kernel.empty() && !kernel_known<2>(opt.kernel)) {
    std::string known;
    for (auto n : sphmol::kernel_names<2>()) known += (known.empty() ? "" : ", ") + std::string(n);
    std::cerr << "sph-mol kernels: unknown kernel '" << opt.kernel << "' (known: " << known << ")\n";
    return 2;
  }
  if (opt.analysis == "hydrostatic") {
    if (opt.correction_option->count() > 0) {
      std::cerr << "sph-mol kernels: --correction is only used by the catalogue (without --analysis hydrostatic)\n";
      return 2;
    }
    if (opt.dimension != 0 && opt.dimension != 2) {
      std::cerr << "sph-mol kernels: the hydrostatic analysis is 2D (Potapov & Reshetnikova 2021, triangular lattice); "
                   "--dimension " << opt.dimension << " is not supported\n";
      return 2;
    }
    if (!opt.kernel.empty()) {
      try {
        sphmol::kernel_info<2>(opt.kernel);
      } catch (const std::exception& ex) {
        std::cerr << "sph-mol kernels: " << ex.what() << "\n";
        return 2;
      }
    }
    // Empty: the tables are printed only. A named folder gets the other commands' checks (a link).
    if (!opt.output.empty() && !sphmol::app::output_option_ok("kernels", opt.output)) return 2;
    return run_hydrostatic();
  }
  if (!opt.analysis.empty() && opt.analysis != "catalogue") {
    std::cerr << "sph-mol kernels: unknown analysis '" << opt.analysis << "' (known: catalogue, hydrostatic)\n";
    return 2;
  }
  if (!opt.output.empty()) {
    std::cerr << "sph-mol kernels: --output is only used with --analysis hydrostatic\n";
    return 2;
  }
  if (opt.eps_option->count() > 0) {
    std::cerr << "sph-mol kernels: --eps is only used with --analysis hydrostatic\n";
    return 2;
  }
  if (opt.dimension == 0 || opt.dimension == 1) { print_catalogue<1>(); print_consistency<1>(); }
  if (opt.dimension == 0 || opt.dimension == 2) { print_catalogue<2>(); print_consistency<2>(); }
  if (opt.dimension == 0 || opt.dimension == 3) { print_catalogue<3>(); print_consistency<3>(); }
  return 0;
}

const sphmol::app::RegisterSubcommand reg{sphmol::app::Subcommand{
    "kernels", "List SPH kernels with normalisation, moments and consistency sums; --analysis hydrostatic",
    [](CLI::App& sub) {
      sub.add_option("--dimension,-d", opt.dimension, "Restrict to dimension D (1, 2 or 3)");
      sub.add_option("--analysis,-a", opt.analysis, "catalogue (default) or hydrostatic (Potapov & Reshetnikova 2021, Table 1)");
      sub.add_option("--output,-o", opt.output, "Directory for hydrostatic_table.csv, hydrostatic_roots.csv and hydrostatic_curves_<kernel>.csv");
      sub.add_option("--kernel,-k", opt.kernel, "Restrict to one kernel");
      opt.eps_option = sub.add_option("--eps", opt.eps, "Tolerance of condition 22 (default 0.01; --analysis hydrostatic)")
                           ->check(sphmol::app::positive_number());
      opt.correction_option = sub.add_option("--correction", opt.correction,
                     "none (default) or rkpm: also print the consistency sums with the RKPM / moment-matrix "
                     "correction (Vukčević 2012, eqs 92-99), which restores linear consistency at the wall")
          ->check(CLI::IsMember({"none", "rkpm"}));
    },
    run}};

}  // namespace
