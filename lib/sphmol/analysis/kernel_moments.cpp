#include "sphmol/analysis/kernel_moments.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sphmol::analysis {

double angular_factor(int D, int k) {
  if (k % 2 != 0) return 0.0;
  constexpr double pi = std::numbers::pi;
  switch (D) {
    case 1: return 2.0;
    case 2: {  // int_0^{2pi} cos^k = 2 pi (k-1)!!/k!!
      double f = 2.0 * pi;
      for (int j = 2; j <= k; j += 2) f *= double(j - 1) / double(j);
      return f;
    }
    case 3: return 4.0 * pi / (k + 1);  // 2 pi int_{-1}^{1} mu^k dmu
    default: throw std::invalid_argument("angular_factor: dimension must be 1, 2 or 3");
  }
}

double radial_integral(int D, double support, double h, int p, double (*g)(double, double)) {
  return radial_integral(D, support, h, p, [g, h](double r) { return g(r, h); });
}

double radial_integral(int D, double support, double h, int p, const std::function<double(double)>& g) {
  struct Params { int power; const std::function<double(double)>* g; } prm{D - 1 + p, &g};
  gsl_function f;
  f.function = [](double r, void* vp) {
    auto* q = static_cast<Params*>(vp);
    return (*q->g)(r) * std::pow(r, q->power);
  };
  f.params = &prm;
  gsl_integration_workspace* ws = gsl_integration_workspace_alloc(200);
  // A polynomial piece is integrated exactly at once, but its error estimate may stay above
  // the tolerance; qag then returns its best result with an error code, which we accept.
  gsl_error_handler_t* old_handler = gsl_set_error_handler_off();
  // Integrate piece by piece between integer multiples of h: every kernel's knots lie there,
  // so each piece is smooth and 61-point Gauss-Kronrod is exact for the polynomial ones.
  double total = 0.0;
  const double end = support * h;
  for (double a = 0.0; a < end - 1e-15 * end;) {
    const double b = std::min(end, (std::floor(a / h + 1e-12) + 1.0) * h);
    double result = 0.0, err = 0.0;
    gsl_integration_qag(&f, a, b, 0.0, 1e-13, 200, GSL_INTEG_GAUSS61, ws, &result, &err);
    total += result;
    a = b;
  }
  gsl_integration_workspace_free(ws);
  gsl_set_error_handler(old_handler);
  return total;
}

KernelMoments kernel_moments(int D, double support, double (*W)(double, double),
                             double (*dWdr)(double, double), double h) {
  KernelMoments m;
  for (int k = 0; k <= 4; ++k) {
    m.M[k] = k % 2 ? 0.0 : angular_factor(D, k) * radial_integral(D, support, h, k, W) / std::pow(h, k);
    // -int s_1^k d_1 W dV = -int n_1^(k+1) r^k W'(r) dV.
    m.dM[k] = (k + 1) % 2 ? 0.0
                          : -angular_factor(D, k + 1) * radial_integral(D, support, h, k, dWdr) / std::pow(h, k - 1);
  }
  // W'' by a central difference of W' with a step far below the distance of any Gauss-Kronrod
  // node from its piece's ends (~3e-4 of the piece), so it never straddles a knot.
  const double step = 1e-6 * h;
  auto d2 = [&](double r) {
    const double a = std::max(0.0, r - step), b = r + step;
    return (dWdr(b, h) - dWdr(a, h)) / (b - a);
  };
  for (int k = 0; k <= 4; ++k) {
    if (k % 2) continue;
    double v = angular_factor(D, k + 2) * radial_integral(D, support, h, k, d2);
    if (D > 1) v += (angular_factor(D, k) - angular_factor(D, k + 2)) * radial_integral(D, support, h, k - 1, dWdr);
    m.d2M[k] = v / std::pow(h, k - 2);
  }
  return m;
}

}  // namespace sphmol::analysis
