#include "sphmol/reference/couette_series.hpp"

#include <gsl/gsl_sf_erf.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sphmol {
namespace {

// Tail target relative to v0: two orders below the 1e-14 accuracy target leaves room for round-off.
constexpr double tail_tol = 1e-17;
constexpr int max_terms = 100000;

void check_args(const CouetteSeries& c, double y, double t) {
  if (!(c.l > 0.0) || !(c.nu > 0.0)) throw std::domain_error("CouetteSeries: l and nu must be positive");
  if (!(y >= 0.0 && y <= c.l)) throw std::domain_error("CouetteSeries: y outside [0, l]");
  if (!(t >= 0.0) || !std::isfinite(t)) throw std::domain_error("CouetteSeries: t must be finite and >= 0");
}

}  // namespace

double CouetteSeries::steady_velocity(double y) const { return v0 * y / l; }

double CouetteSeries::velocity_fourier(double y, double t) const {
  check_args(*this, y, t);
  if (!(t > 0.0)) throw std::domain_error("CouetteSeries::velocity_fourier: t must be > 0");
  // Vukčević et al. 2012, eq 23: u = v0 y/l + sum_{n>=1} 2 v0/(n pi) (-1)^n sin(n pi y/l) exp(-nu
  // n^2 pi^2 t/l^2). (Checked: at t = 0 the sum is minus the sine series of y/l, so u(y,0) = 0.)
  const double pi = std::numbers::pi;
  const double a = pi * pi * nu * t / (l * l);  // exponent per n^2
  double sum = 0.0;
  for (int n = 1; n <= max_terms; ++n) {
    const double sign = (n % 2 == 0) ? 1.0 : -1.0;
    sum += 2.0 / (n * pi) * sign * std::sin(n * pi * y / l) * std::exp(-a * n * n);
    // Tail after n, with m = n+1: sum_{k>=m} 2/(k pi) e^{-a k^2} <= 2/(m pi) e^{-a m^2} / (1 - e^{-2 a m}),
    // because k^2 - m^2 >= 2 m (k - m).
    const double m = n + 1.0;
    const double tail = 2.0 / (m * pi) * std::exp(-a * m * m) / (-std::expm1(-2.0 * a * m));
    if (tail < tail_tol) return v0 * (y / l + sum);
  }
  throw std::runtime_error("CouetteSeries::velocity_fourier: series did not converge (t too small)");
}

double CouetteSeries::velocity_images(double y, double t) const {
  check_args(*this, y, t);
  if (!(t > 0.0)) throw std::domain_error("CouetteSeries::velocity_images: t must be > 0");
  // Method of images (derived here, not in Vukčević et al. 2012): each erfc((c -+ y)/(2 sqrt(nu
  // t))) solves u_t = nu u_yy; the pair cancels at y = 0 and the sum telescopes to erfc(0) = 1 at y
  // = l; all arguments are positive inside the channel, so u -> 0 as t -> 0+.
  // u = v0 sum_{k>=0} [erfc(((2k+1) l - y)/s) - erfc(((2k+1) l + y)/s)], s = 2 sqrt(nu t).
  const double s = 2.0 * std::sqrt(nu * t);
  double sum = 0.0;
  for (int k = 0; k <= max_terms; ++k) {
    const double c = (2.0 * k + 1.0) * l;
    sum += gsl_sf_erfc((c - y) / s) - gsl_sf_erfc((c + y) / s);
    // Term j is bounded by erfc(2 j l/s) <= exp(-(2 j l/s)^2); with q = 2 l/s and m = k+1 the tail
    // sum_{j>=m} e^{-q^2 j^2} <= e^{-q^2 m^2} / (1 - e^{-2 q^2 m}).
    const double q2 = (2.0 * l / s) * (2.0 * l / s);
    const double m = k + 1.0;
    const double tail = std::exp(-q2 * m * m) / (-std::expm1(-2.0 * q2 * m));
    if (tail < tail_tol) return v0 * sum;
  }
  throw std::runtime_error("CouetteSeries::velocity_images: series did not converge (t too large)");
}

double CouetteSeries::velocity(double y, double t) const {
  check_args(*this, y, t);
  if (t == 0.0) return y == l ? v0 : 0.0;
  if (nu * t / (l * l) >= switch_tau) return velocity_fourier(y, t);
  return velocity_images(y, t);
}

}  // namespace sphmol
