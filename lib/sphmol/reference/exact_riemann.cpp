#include "sphmol/reference/exact_riemann.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sphmol {

ExactRiemannSolver::ExactRiemannSolver(EulerState left, EulerState right, double gamma)
    : left_(left), right_(right), gamma_(gamma) {
  if (!(gamma > 1.0)) throw std::invalid_argument("ExactRiemannSolver: gamma must be > 1");
  for (const EulerState* s : {&left_, &right_}) {
    if (!(s->rho > 0.0) || !(s->p > 0.0) || !std::isfinite(s->u) || !std::isfinite(s->rho) || !std::isfinite(s->p))
      throw std::invalid_argument("ExactRiemannSolver: initial states need finite u and positive rho, p (vacuum in data is not supported)");
  }
  a_l_ = std::sqrt(gamma * left_.p / left_.rho);
  a_r_ = std::sqrt(gamma * right_.p / right_.rho);
  const double du = right_.u - left_.u;
  // Pressure positivity condition, Toro eq 4.40: otherwise the two rarefactions leave a vacuum between them.
  if (2.0 / (gamma - 1.0) * (a_l_ + a_r_) <= du)
    throw std::domain_error("ExactRiemannSolver: initial data generate a vacuum (2(aL+aR)/(gamma-1) <= uR-uL = " +
                            std::to_string(du) + ")");

  struct Ctx { const ExactRiemannSolver* self; double du; } ctx{this, du};
  auto f = [](double p, void* vp) {
    auto* c = static_cast<Ctx*>(vp);
    return c->self->f_side(p, c->self->left_, c->self->a_l_) + c->self->f_side(p, c->self->right_, c->self->a_r_) + c->du;
  };
  // f is increasing and concave (Toro §4.3.1), f(0) = du - 2(aL+aR)/(gamma-1) < 0 by the check above;
  // grow the upper end until f changes sign (f grows like sqrt(p), so doubling terminates).
  double lo = 0.0, hi = std::max(left_.p, right_.p);
  int grow = 0;
  while (f(hi, &ctx) < 0.0) {
    lo = hi;
    hi *= 2.0;
    if (++grow > 2000) throw std::runtime_error("ExactRiemannSolver: could not bracket the star pressure");
  }
  if (f(hi, &ctx) == 0.0) {
    p_star_ = hi;
  } else {
    gsl_function F{f, &ctx};
    gsl_root_fsolver* solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    gsl_root_fsolver_set(solver, &F, lo, hi);
    int status = GSL_CONTINUE;
    for (int it = 0; it < 500 && status == GSL_CONTINUE; ++it) {
      if (gsl_root_fsolver_iterate(solver) != GSL_SUCCESS) break;
      status = gsl_root_test_interval(gsl_root_fsolver_x_lower(solver), gsl_root_fsolver_x_upper(solver), 0.0,
                                      4.0 * DBL_EPSILON);
    }
    p_star_ = gsl_root_fsolver_root(solver);
    gsl_root_fsolver_free(solver);
    if (status != GSL_SUCCESS) throw std::runtime_error("ExactRiemannSolver: Brent did not converge");
  }
  // Toro eq 4.9.
  u_star_ = 0.5 * (left_.u + right_.u) + 0.5 * (f_side(p_star_, right_, a_r_) - f_side(p_star_, left_, a_l_));
  const double g = gamma_, gm = (g - 1.0) / (g + 1.0);
  auto rho_star = [&](const EulerState& s) {
    const double r = p_star_ / s.p;
    return r > 1.0 ? s.rho * (r + gm) / (gm * r + 1.0)  // shock, Toro eq 4.19
                   : s.rho * std::pow(r, 1.0 / g);      // rarefaction (isentropic), Toro eq 4.23
  };
  rho_star_l_ = rho_star(left_);
  rho_star_r_ = rho_star(right_);
}

double ExactRiemannSolver::f_side(double p, const EulerState& s, double a) const {
  const double g = gamma_;
  if (p > s.p) {  // shock, Toro eq 4.6
    const double A = 2.0 / ((g + 1.0) * s.rho), B = (g - 1.0) / (g + 1.0) * s.p;
    return (p - s.p) * std::sqrt(A / (p + B));
  }
  // rarefaction, Toro eq 4.7
  return 2.0 * a / (g - 1.0) * (std::pow(p / s.p, (g - 1.0) / (2.0 * g)) - 1.0);
}

RiemannWaves ExactRiemannSolver::wave_speeds() const {
  const double g = gamma_;
  RiemannWaves w{};
  w.contact = u_star_;
  if (p_star_ > left_.p) {  // Toro eq 4.52
    w.left_is_shock = true;
    w.left_head = w.left_tail =
        left_.u - a_l_ * std::sqrt((g + 1.0) / (2.0 * g) * p_star_ / left_.p + (g - 1.0) / (2.0 * g));
  } else {  // Toro eqs 4.55, 4.54
    w.left_is_shock = false;
    w.left_head = left_.u - a_l_;
    w.left_tail = u_star_ - a_l_ * std::pow(p_star_ / left_.p, (g - 1.0) / (2.0 * g));
  }
  if (p_star_ > right_.p) {  // Toro eq 4.59
    w.right_is_shock = true;
    w.right_head = w.right_tail =
        right_.u + a_r_ * std::sqrt((g + 1.0) / (2.0 * g) * p_star_ / right_.p + (g - 1.0) / (2.0 * g));
  } else {  // Toro eqs 4.62, 4.61
    w.right_is_shock = false;
    w.right_head = right_.u + a_r_;
    w.right_tail = u_star_ + a_r_ * std::pow(p_star_ / right_.p, (g - 1.0) / (2.0 * g));
  }
  return w;
}

RiemannWaves ExactRiemannSolver::waves(double t, double x0) const {
  if (!(t >= 0.0)) throw std::domain_error("ExactRiemannSolver::waves: t must be >= 0");
  RiemannWaves w = wave_speeds();
  for (double* v : {&w.left_head, &w.left_tail, &w.contact, &w.right_tail, &w.right_head}) *v = x0 + *v * t;
  return w;
}

RiemannSample ExactRiemannSolver::sample(double xi) const {
  const double g = gamma_;
  const RiemannWaves w = wave_speeds();
  auto make = [g](double rho, double u, double p) { return RiemannSample{rho, u, p, p / ((g - 1.0) * rho)}; };
  if (xi <= u_star_) {
    if (xi <= w.left_head) return make(left_.rho, left_.u, left_.p);
    if (w.left_is_shock || xi >= w.left_tail) return make(rho_star_l_, u_star_, p_star_);
    // Inside the left fan, Toro eq 4.56.
    const double c = 2.0 / (g + 1.0) + (g - 1.0) / ((g + 1.0) * a_l_) * (left_.u - xi);
    return make(left_.rho * std::pow(c, 2.0 / (g - 1.0)), 2.0 / (g + 1.0) * (a_l_ + 0.5 * (g - 1.0) * left_.u + xi),
                left_.p * std::pow(c, 2.0 * g / (g - 1.0)));
  }
  if (xi >= w.right_head) return make(right_.rho, right_.u, right_.p);
  if (w.right_is_shock || xi <= w.right_tail) return make(rho_star_r_, u_star_, p_star_);
  // Inside the right fan, Toro eq 4.63.
  const double c = 2.0 / (g + 1.0) - (g - 1.0) / ((g + 1.0) * a_r_) * (right_.u - xi);
  return make(right_.rho * std::pow(c, 2.0 / (g - 1.0)), 2.0 / (g + 1.0) * (-a_r_ + 0.5 * (g - 1.0) * right_.u + xi),
              right_.p * std::pow(c, 2.0 * g / (g - 1.0)));
}

RiemannSample ExactRiemannSolver::sample(double x, double t, double x0) const {
  if (!(t >= 0.0)) throw std::domain_error("ExactRiemannSolver::sample: t must be >= 0");
  if (t == 0.0) {
    const EulerState& s = x < x0 ? left_ : right_;
    return RiemannSample{s.rho, s.u, s.p, s.p / ((gamma_ - 1.0) * s.rho)};
  }
  return sample((x - x0) / t);
}

}  // namespace sphmol
