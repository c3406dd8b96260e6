#include "sphmol/reference/poiseuille_series.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sphmol/reference/repeated_erfc.hpp"

namespace sphmol {
namespace {

constexpr double tail_tol = 1e-17;  // relative to peak_velocity()
constexpr int max_terms = 100000;

void check_args(const PoiseuilleSeries& p, double y, double t) {
  if (!(p.l > 0.0) || !(p.nu > 0.0)) throw std::domain_error("PoiseuilleSeries: l and nu must be positive");
  if (!(y >= 0.0 && y <= p.l)) throw std::domain_error("PoiseuilleSeries: y outside [0, l]");
  if (!(t >= 0.0) || !std::isfinite(t)) throw std::domain_error("PoiseuilleSeries: t must be finite and >= 0");
}

}  // namespace

double PoiseuilleSeries::steady_velocity(double y) const { return F / (2.0 * nu) * y * (l - y); }
double PoiseuilleSeries::peak_velocity() const { return F * l * l / (8.0 * nu); }

double PoiseuilleSeries::velocity_fourier(double y, double t) const {
  check_args(*this, y, t);
  if (!(t > 0.0)) throw std::domain_error("PoiseuilleSeries::velocity_fourier: t must be > 0");
  // Corrected Vukčević et al. 2012, eq 19 (see header). Work in units of peak = F l^2/(8 nu):
  // coefficient 4 F l^2/(nu pi^3 n^3) = peak * 32/(pi^3 n^3).
  const double pi = std::numbers::pi;
  const double a = pi * pi * nu * t / (l * l);
  const double c = 32.0 / (pi * pi * pi);
  double sum = 0.0;
  for (int j = 0; j <= max_terms; ++j) {
    const double n = 2.0 * j + 1.0;
    sum += c / (n * n * n) * std::sin(n * pi * y / l) * std::exp(-a * n * n);
    // Remaining odd n' = m + 2i, m = n + 2, i >= 0: n'^2 >= m^2 + 4 m i, so
    // tail <= c/m^3 e^{-a m^2} / (1 - e^{-4 a m}).
    const double m = n + 2.0;
    const double tail = c / (m * m * m) * std::exp(-a * m * m) / (-std::expm1(-4.0 * a * m));
    if (tail < tail_tol) return peak_velocity() * (4.0 * y * (l - y) / (l * l) - sum);
  }
  throw std::runtime_error("PoiseuilleSeries::velocity_fourier: series did not converge (t too small)");
}

double PoiseuilleSeries::velocity_images(double y, double t) const {
  check_args(*this, y, t);
  if (!(t > 0.0)) throw std::domain_error("PoiseuilleSeries::velocity_images: t must be > 0");
  // Derived here: w = u - F t solves w_t = nu w_yy, w(y,0) = 0, w = -F t on both plates. For one wall,
  // the solution with boundary data t^{n/2} is Gamma(n/2+1) (4t)^{n/2} i^n erfc(y/s) (Carslaw & Jaeger
  // 2.5), s = 2 sqrt(nu t); n = 2 gives G(x) = -4 F t i2erfc(x/s), G(0) = -F t. Alternating images
  //   w = sum_{k>=0} (-1)^k [G(y + k l) + G((k+1) l - y)]
  // reduce to G(0) at y = 0 and at y = l (the k >= 1 terms cancel pairwise), and vanish as t -> 0+.
  // So u = F t - 4 F t sum_k (-1)^k [i2erfc((y + k l)/s) + i2erfc(((k+1) l - y)/s)].
  const double s = 2.0 * std::sqrt(nu * t);
  double sum = 0.0;
  for (int k = 0; k <= max_terms; ++k) {
    const double sign = (k % 2 == 0) ? 1.0 : -1.0;
    sum += sign * (i2erfc((y + k * l) / s) + i2erfc(((k + 1) * l - y) / s));
    // i2erfc(x) <= e^{-x^2}/4 for x >= 0 (substitute t = x + u in its integral form), both arguments of
    // term j are >= j l/s, so |term j| <= e^{-q j^2}/2 with q = (l/s)^2; times 4 F t = peak * 32 nu t/l^2.
    // Tail from m = k+1: <= 32 tau e^{-q m^2} / (2 (1 - e^{-2 q m})).
    const double q = (l / s) * (l / s);
    const double tau = nu * t / (l * l);
    const double m = k + 1.0;
    const double tail = 32.0 * tau * std::exp(-q * m * m) / (2.0 * -std::expm1(-2.0 * q * m));
    if (tail < tail_tol) return F * t * (1.0 - 4.0 * sum);
  }
  throw std::runtime_error("PoiseuilleSeries::velocity_images: series did not converge (t too large)");
}

double PoiseuilleSeries::velocity(double y, double t) const {
  check_args(*this, y, t);
  if (t == 0.0) return 0.0;
  if (nu * t / (l * l) >= switch_tau) return velocity_fourier(y, t);
  return velocity_images(y, t);
}

}  // namespace sphmol
