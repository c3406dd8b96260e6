#include "sphmol/reference/duct_series.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_erf.h>
#include <gsl/gsl_sf_zeta.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sphmol {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double tail_tol = 1e-16;   // of g c^2/nu, c = min(a, b)
constexpr long max_terms = 20000000;  // the steady remainder within ~1e-6 c of a corner needs this many
constexpr int max_modes = 40001;      // per direction in the transient double series

double scale(const DuctSeries& d) {
  const double c = std::min(d.a, d.b);
  return std::abs(d.g) * c * c / d.nu;
}

void check_params(const DuctSeries& d) {
  if (!(d.a > 0.0) || !(d.b > 0.0) || !(d.nu > 0.0) || !std::isfinite(d.a) || !std::isfinite(d.b) ||
      !std::isfinite(d.nu) || !std::isfinite(d.g))
    throw std::domain_error("DuctSeries: a, b and nu must be positive and finite, g finite");
}

void check_point(const DuctSeries& d, double y, double z) {
  check_params(d);
  if (!(std::abs(y) <= d.a) || !(std::abs(z) <= d.b)) throw std::domain_error("DuctSeries: (y, z) outside the duct");
}

void check_time(double t) {
  if (!(t >= 0.0) || !std::isfinite(t)) throw std::domain_error("DuctSeries: t must be finite and >= 0");
}

// (-1)^{(i-1)/2} for odd i.
double odd_sign(long i) { return ((i - 1) / 2) % 2 == 0 ? 1.0 : -1.0; }

// The remainder R of White 2006, eq 3-48 after the closed-form channel part (see the header), with the
// cosine series in y (half-width p) and the hyperbolic factor in z (half-width q):
//   u_s = g (p^2 - y^2)/(2 nu) - R,  R = 16 p^2 g/(nu pi^3) sum_{i odd} (-1)^{(i-1)/2} h_i cos(i pi y/2p)/i^3,
//   h_i = cosh(i pi z/2p)/cosh(i pi q/2p).
double steady_oriented(double p, double q, double y, double z, double nu, double g, double tol) {
  const double k = 16.0 * p * p * g / (nu * pi * pi * pi);
  const double dz = q - std::abs(z);
  const double r = std::exp(-pi * dz / (2.0 * p));  // h_i <= min(1, 2 r^i)
  double sum = 0.0;
  for (long i = 1; i <= max_terms; i += 2) {
    const double x = i * pi / (2.0 * p);
    // cosh(x|z|)/cosh(xq) written without overflow.
    const double h = std::exp(-x * dz) * (1.0 + std::exp(-2.0 * x * std::abs(z))) / (1.0 + std::exp(-2.0 * x * q));
    const double di = static_cast<double>(i);
    sum += odd_sign(i) * h * std::cos(x * y) / (di * di * di);
    // Remaining odd i' >= M = i + 2: sum h/i'^3 <= min(1/M^3 + 1/(4 M^2), 2 r^M/(M^3 (1 - r^2))), the first
    // from h <= 1 and the integral test with spacing 2, the second a geometric series.
    const double m = di + 2.0;
    const double algebraic = 1.0 / (m * m * m) + 1.0 / (4.0 * m * m);
    const double geometric = r < 1.0 ? 2.0 * std::pow(r, m) / (m * m * m * -std::expm1(2.0 * std::log(r))) : algebraic;
    if (std::abs(k) * std::min(algebraic, geometric) < tol) return g / (2.0 * nu) * (p * p - y * y) - k * sum;
  }
  throw std::runtime_error("DuctSeries: the steady series did not converge (a point within ~1e-6 of a corner)");
}

// sum_{odd m >= M} e^{-alpha m^2}/m^2 <= e^{-alpha M^2}/(M^2 (1 - e^{-4 alpha M})), since m^2 >= M^2 + 4 M j
// for m = M + 2j.
double gaussian_tail(double alpha, double m) {
  return std::exp(-alpha * m * m) / (m * m * -std::expm1(-4.0 * alpha * m));
}

}  // namespace

double DuctSeries::steady_velocity(double y, double z) const {
  check_point(*this, y, z);
  if (std::abs(y) == a || std::abs(z) == b || g == 0.0) return 0.0;
  const double tol = tail_tol * scale(*this);
  // The remainder converges like r^i with r = e^{-pi (b - |z|)/2a} in the first orientation and
  // e^{-pi (a - |y|)/2b} in the exchanged one: sum the faster.
  if ((b - std::abs(z)) / a >= (a - std::abs(y)) / b) return steady_oriented(a, b, y, z, nu, g, tol);
  return steady_oriented(b, a, z, y, nu, g, tol);
}

double DuctSeries::centre_velocity() const { return steady_velocity(0.0, 0.0); }

double DuctSeries::mean_velocity() const {
  check_params(*this);
  // White 2006, eq 3-49 is symmetric in (a, b); with p = min, q = max the correction factor 192 p/(pi^5 q)
  // stays <= 0.63. sum_{i odd} tanh(i pi q/2p)/i^5 = (1 - 2^-5) zeta(5) - sum_{i odd} (1 - tanh x_i)/i^5, and
  // 1 - tanh x = 2 e^{-2x}/(1 + e^{-2x}) decays geometrically (GSL's zeta gives the first sum exactly).
  const double p = std::min(a, b);
  const double q = std::max(a, b);
  const double odd_zeta5 = (1.0 - 1.0 / 32.0) * gsl_sf_zeta_int(5);
  const double r = std::exp(-pi * q / p);  // e^{-2 x_1}; 1 - tanh x_i <= 2 r^i
  double defect = 0.0;
  for (int i = 1; i <= max_modes; i += 2) {
    const double e = std::exp(-i * pi * q / p);
    const double di = i;
    defect += 2.0 * e / (1.0 + e) / (di * di * di * di * di);
    const double m = di + 2.0;
    if (2.0 * std::pow(r, m) / (std::pow(m, 5) * -std::expm1(2.0 * std::log(r))) < 1e-17) break;
  }
  return g * p * p / (3.0 * nu) * (1.0 - 192.0 * p / (std::pow(pi, 5) * q) * (odd_zeta5 - defect));
}

double DuctSeries::velocity_fourier(double y, double z, double t) const {
  check_point(*this, y, z);
  check_time(t);
  if (!(t > 0.0)) throw std::domain_error("DuctSeries::velocity_fourier: t must be > 0");
  if (std::abs(y) == a || std::abs(z) == b || g == 0.0) return 0.0;
  const double tol = tail_tol * scale(*this);
  // Decaying part D = sum C_mn e^{-nu lambda_mn t} cos cos (header). With lambda_mn >= 2 sqrt(lambda_m
  // lambda_n) = m n pi^2/(2ab): |term| <= K e^{-alpha m^2}/m^2 e^{-beta n^2}/n^2, K = 32 g a b/(pi^4 nu),
  // so the terms outside m < M, n < N sum to at most K pi^2/8 (T_alpha(M) + T_beta(N)).
  const double alpha = nu * t * pi * pi / (4.0 * a * a);
  const double beta = nu * t * pi * pi / (4.0 * b * b);
  const double k = 32.0 * std::abs(g) * a * b / (std::pow(pi, 4) * nu) * pi * pi / 8.0;
  auto modes = [&](double rate) {
    int m = 1;
    while (k * gaussian_tail(rate, m) >= tol / 2.0) {
      m += 2;
      if (m > max_modes)
        throw std::runtime_error("DuctSeries::velocity_fourier: too many modes at t = " + std::to_string(t) +
                                 " (use velocity() or velocity_duhamel() at short times)");
    }
    return m;
  };
  const int mm = modes(alpha);
  const int nn = modes(beta);
  double sum = 0.0;
  for (int m = 1; m < mm; m += 2) {
    const double km = m * pi / (2.0 * a);
    const double cy = odd_sign(m) * std::cos(km * y) / m;
    double row = 0.0;
    for (int n = 1; n < nn; n += 2) {
      const double kn = n * pi / (2.0 * b);
      const double lambda = km * km + kn * kn;
      row += odd_sign(n) * std::cos(kn * z) / n * std::exp(-nu * lambda * t) / lambda;
    }
    sum += cy * row;
  }
  return steady_velocity(y, z) - 16.0 * g / (pi * pi * nu) * sum;
}

double DuctSeries::heat_factor(double x, double half, double s) const {
  if (!(half > 0.0) || !(std::abs(x) <= half)) throw std::domain_error("DuctSeries::heat_factor: x outside (-half, half)");
  check_time(s);
  if (std::abs(x) == half) return 0.0;
  if (s == 0.0) return 1.0;
  // Images: theta = 1 - sum_{k>=0} (-1)^k [erfc(((2k+1)h - x)/sigma) + erfc(((2k+1)h + x)/sigma)],
  // sigma = 2 sqrt(nu s). Each erfc solves the heat equation; the sum telescopes to 1 on x = +-h, and all
  // arguments are positive inside, so theta -> 1 as s -> 0+. Both arguments of term k are >= 2kh/sigma:
  // |term k| <= 2 e^{-q k^2}, q = (2h/sigma)^2, tail from m: <= 2 e^{-q m^2}/(1 - e^{-2 q m}).
  const double sigma = 2.0 * std::sqrt(nu * s);
  const double q = (2.0 * half / sigma) * (2.0 * half / sigma);
  double sum = 0.0;
  for (int k = 0; k <= max_modes; ++k) {
    const double c = (2.0 * k + 1.0) * half;
    sum += (k % 2 == 0 ? 1.0 : -1.0) * (gsl_sf_erfc((c - x) / sigma) + gsl_sf_erfc((c + x) / sigma));
    const double m = k + 1.0;
    if (2.0 * std::exp(-q * m * m) / -std::expm1(-2.0 * q * m) < 1e-17) return 1.0 - sum;
  }
  throw std::runtime_error("DuctSeries::heat_factor: image series did not converge (s too large)");
}

double DuctSeries::velocity_duhamel(double y, double z, double t) const {
  check_point(*this, y, z);
  check_time(t);
  if (!(t > 0.0)) throw std::domain_error("DuctSeries::velocity_duhamel: t must be > 0");
  if (std::abs(y) == a || std::abs(z) == b) return 0.0;
  // Duhamel: the forced problem is the time integral of the free decay of the uniform state g, and the
  // rectangle's free decay from 1 is theta_a(y, s) theta_b(z, s).
  struct Params {
    const DuctSeries* d;
    double y, z;
  } params{this, y, z};
  gsl_function f;
  f.function = [](double s, void* vp) {
    const auto* p = static_cast<const Params*>(vp);
    return p->d->heat_factor(p->y, p->d->a, s) * p->d->heat_factor(p->z, p->d->b, s);
  };
  f.params = &params;
  gsl_integration_workspace* ws = gsl_integration_workspace_alloc(1000);
  if (ws == nullptr) throw std::bad_alloc();
  // GSL's default handler aborts; its status is checked here instead (as in analysis/kernel_moments.cpp).
  gsl_error_handler_t* old_handler = gsl_set_error_handler_off();
  double result = 0.0, err = 0.0;
  const double c = std::min(a, b);
  const int status = gsl_integration_qag(&f, 0.0, t, 1e-14 * c * c / nu, 1e-13, 1000, GSL_INTEG_GAUSS21, ws, &result, &err);
  gsl_set_error_handler(old_handler);
  gsl_integration_workspace_free(ws);
  if (status != GSL_SUCCESS && err > 1e-12 * c * c / nu)
    throw std::runtime_error(std::string("DuctSeries::velocity_duhamel: quadrature failed: ") + gsl_strerror(status));
  return g * result;
}

double DuctSeries::velocity(double y, double z, double t) const {
  check_point(*this, y, z);
  check_time(t);
  if (t == 0.0) return 0.0;
  const double c = std::min(a, b);
  if (nu * t / (c * c) >= switch_tau) return velocity_fourier(y, z, t);
  return velocity_duhamel(y, z, t);
}

}  // namespace sphmol
