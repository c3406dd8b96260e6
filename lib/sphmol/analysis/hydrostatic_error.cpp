#include "sphmol/analysis/hydrostatic_error.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "sphmol/analysis/hexagonal_lattice.hpp"

namespace sphmol::analysis {

HydrostaticErrors hydrostatic_errors(const KernelInfo<2>& kernel, double k, double a_p) {
  const double h = k;  // d = 1
  HydrostaticErrors e;
  double sw = 0.0, sg = 0.0;
  for (const auto& p : hexagonal_lattice_points(1.0, kernel.support * h)) {
    const double r = std::hypot(p[0], p[1]);
    sw += kernel.W(r, h);
    if (r > 0.0) sg += kernel.dWdr_k(r, h, k) * p[1] * p[1] / r;
  }
  e.eps_rho = a_p * sw - 1.0;
  e.eps_gradp = -a_p * sg - 1.0;
  return e;
}

HydrostaticErrors hydrostatic_errors_block(const KernelInfo<2>& kernel, double k, double a_p, double d,
                                           double rho0, double g, double depth) {
  const double h = k * d, m = a_p * d * d * rho0, V = m / rho0;
  const double s3 = std::sqrt(3.0) / 2.0;
  // Rows of the block reach two rows beyond the support; the centre particle is at (0, depth).
  const int nrow = int(std::ceil(kernel.support * h / (s3 * d))) + 2;
  const int ncol = int(std::ceil(kernel.support * h / d)) + 2;
  const double xi = 0.0, yi = depth, Pi = rho0 * g * yi;
  double rho = 0.0, dPdy = 0.0;
  for (int b = -nrow; b <= nrow; ++b)
    for (int a = -ncol; a <= ncol; ++a) {
      const double xj = (a + 0.5 * (b & 1)) * d, yj = depth + b * s3 * d;
      const double r = std::hypot(xi - xj, yi - yj);
      rho += m * kernel.W(r, h);  // eq 3
      if (r > 0.0) dPdy += V * (Pi + rho0 * g * yj) * kernel.dWdr_k(r, h, k) * (yi - yj) / r;  // eq 4
    }
  return {rho / rho0 - 1.0, dPdy / (rho0 * g) - 1.0};
}

namespace {

std::vector<HydrostaticRoot> find_roots(const std::function<double(double)>& f,
                                        const std::function<double(double)>& other, double lo, double hi,
                                        int scan) {
  std::vector<HydrostaticRoot> roots;
  gsl_function gf;
  gf.function = [](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); };
  gf.params = const_cast<std::function<double(double)>*>(&f);
  gsl_root_fsolver* s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  double a = lo, fa = f(a);
  for (int i = 1; i <= scan; ++i) {
    const double b = lo + (hi - lo) * i / scan, fb = f(b);
    double root = std::nan("");
    if (fa == 0.0) root = a;
    else if (fa * fb < 0.0) {
      gsl_root_fsolver_set(s, &gf, a, b);
      for (int it = 0; it < 200; ++it) {
        gsl_root_fsolver_iterate(s);
        const double xl = gsl_root_fsolver_x_lower(s), xu = gsl_root_fsolver_x_upper(s);
        if (gsl_root_test_interval(xl, xu, 1e-15, 1e-14) == GSL_SUCCESS) break;
      }
      root = gsl_root_fsolver_root(s);
    }
    if (!std::isnan(root) && std::abs(f(root)) < 1e-9) roots.push_back({root, other(root)});
    a = b;
    fa = fb;
  }
  gsl_root_fsolver_free(s);
  return roots;
}

}  // namespace

HydrostaticRow hydrostatic_row(const KernelInfo<2>& kernel, double a_p, double eps, double k_min, double k_max,
                               int scan) {
  gsl_error_handler_t* old_handler = gsl_set_error_handler_off();
  HydrostaticRow row;
  row.kernel = std::string(kernel.name);
  row.a_p = a_p;
  auto rho = [&](double k) { return hydrostatic_errors(kernel, k, a_p).eps_rho; };
  auto gradp = [&](double k) { return hydrostatic_errors(kernel, k, a_p).eps_gradp; };
  row.rho_roots = find_roots(rho, gradp, k_min, k_max, scan);
  row.gradp_roots = find_roots(gradp, rho, k_min, k_max, scan);

  // Condition 22 asks for one k with both errors small: minimise the larger of the two, first on
  // the scan grid, then by golden section on the grid cell pair around the best node.
  std::function<double(double)> worst = [&](double k) {
    const auto e = hydrostatic_errors(kernel, k, a_p);
    return std::max(std::abs(e.eps_rho), std::abs(e.eps_gradp));
  };
  int best = 0;
  double fbest = worst(k_min);
  for (int i = 1; i <= scan; ++i) {
    const double f = worst(k_min + (k_max - k_min) * i / scan);
    if (f < fbest) { fbest = f; best = i; }
  }
  row.best_k = k_min + (k_max - k_min) * best / scan;
  row.best_err = fbest;
  if (best > 0 && best < scan) {
    const double lo = k_min + (k_max - k_min) * (best - 1) / scan, hi = k_min + (k_max - k_min) * (best + 1) / scan;
    gsl_function gf;
    gf.function = [](double x, void* p) { return (*static_cast<std::function<double(double)>*>(p))(x); };
    gf.params = &worst;
    gsl_min_fminimizer* m = gsl_min_fminimizer_alloc(gsl_min_fminimizer_goldensection);
    if (gsl_min_fminimizer_set(m, &gf, row.best_k, lo, hi) == GSL_SUCCESS) {
      for (int it = 0; it < 200; ++it) {
        gsl_min_fminimizer_iterate(m);
        if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(m), gsl_min_fminimizer_x_upper(m), 1e-13, 0.0) ==
            GSL_SUCCESS)
          break;
      }
      const double k = gsl_min_fminimizer_x_minimum(m), f = worst(k);
      if (f < row.best_err) { row.best_k = k; row.best_err = f; }
    }
    gsl_min_fminimizer_free(m);
  }
  row.passes = row.best_err <= eps;
  gsl_set_error_handler(old_handler);
  return row;
}

}  // namespace sphmol::analysis
