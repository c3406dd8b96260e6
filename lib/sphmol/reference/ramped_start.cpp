#include "sphmol/reference/ramped_start.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sphmol {
namespace {

struct Integrand {
  const std::function<double(double)>* u_step;
  double t, ramp;
};

double integrand(double tau, void* p) {
  const auto* q = static_cast<const Integrand*>(p);
  const double w = std::numbers::pi / q->ramp;
  return 0.5 * w * std::sin(w * tau) * (*q->u_step)(std::max(q->t - tau, 0.0));
}

}  // namespace

double ramped_start(const std::function<double(double)>& u_step, double t, double ramp, double abs_tol) {
  if (!(t >= 0.0) || !std::isfinite(t)) throw std::domain_error("ramped_start: t must be finite and >= 0");
  if (!(ramp > 0.0)) return u_step(t);
  if (t == 0.0) return 0.0;
  Integrand q{&u_step, t, ramp};
  gsl_function f;
  f.function = &integrand;
  f.params = &q;
  const std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> ws(
      gsl_integration_workspace_alloc(1000), &gsl_integration_workspace_free);
  double result = 0.0, err = 0.0;
  gsl_error_handler_t* old_handler = gsl_set_error_handler_off();
  const int status = gsl_integration_qag(&f, 0.0, std::min(t, ramp), abs_tol, 1e-13, 1000, GSL_INTEG_GAUSS21, ws.get(), &result, &err);
  gsl_set_error_handler(old_handler);
  if (status != GSL_SUCCESS) throw std::runtime_error(std::string("ramped_start: quadrature failed: ") + gsl_strerror(status));
  return result;
}

}  // namespace sphmol
