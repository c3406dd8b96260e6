#pragma once
// Exact solution of the Riemann problem for the 1D Euler equations of an ideal gas (Toro, "Riemann
// Solvers and Numerical Methods for Fluid Dynamics", 3rd ed., ch. 4). Reference for the Niedoba
// 2012, §3 shock tube (rho 1/0.25, p 1/0.1795, gamma 1.4).
// Star pressure: root of Toro eq 4.5, f(p) = f_L(p) + f_R(p) + u_R - u_L, by GSL Brent; f is monotone
// increasing and f(0) < 0 unless a vacuum is generated, so [0, p_hi] with f(p_hi) > 0 brackets it.

namespace sphmol {

struct EulerState {
  double rho;  // density
  double u;    // velocity
  double p;    // pressure
};

struct RiemannSample {
  double rho, u, p;
  double e;  // specific internal energy p / ((gamma - 1) rho)
};

// Positions (or speeds) of the waves. For a shock head == tail == the shock. Left wave: head is the
// leftmost edge, tail the rightmost; right wave: tail is the leftmost edge, head the rightmost.
struct RiemannWaves {
  bool left_is_shock, right_is_shock;
  double left_head, left_tail, contact, right_tail, right_head;
};

class ExactRiemannSolver {
 public:
  // Throws std::invalid_argument for non-positive density/pressure or gamma <= 1, std::domain_error
  // when the data generate a vacuum (Toro eq 4.40 violated: 2 (a_L + a_R)/(gamma - 1) <= u_R - u_L).
  ExactRiemannSolver(EulerState left, EulerState right, double gamma);

  double p_star() const { return p_star_; }
  double u_star() const { return u_star_; }
  double rho_star_left() const { return rho_star_l_; }
  double rho_star_right() const { return rho_star_r_; }
  double gamma() const { return gamma_; }
  const EulerState& left() const { return left_; }
  const EulerState& right() const { return right_; }

  // Solution at similarity coordinate xi = (x - x0)/t (Toro §4.5).
  RiemannSample sample(double xi) const;
  // Solution at (x, t) with the diaphragm at x0; t = 0 returns the initial data (right state at x = x0).
  RiemannSample sample(double x, double t, double x0) const;
  // Wave speeds, and positions at time t for a diaphragm at x0.
  RiemannWaves wave_speeds() const;
  RiemannWaves waves(double t, double x0) const;

 private:
  double f_side(double p, const EulerState& s, double a) const;  // Toro eqs 4.6, 4.7
  EulerState left_, right_;
  double gamma_, a_l_, a_r_;
  double p_star_ = 0, u_star_ = 0, rho_star_l_ = 0, rho_star_r_ = 0;
};

}  // namespace sphmol
