#pragma once
// The prescribed rigid motion of a wall body. Every wall particle of the body follows it from its
// reference position x_ref and reference normal n_ref (both as built, at t = 0):
//   translation:  x = x_ref + V t,                              v = V
//   rotation:     x = c + R(omega t) (x_ref - c),               v = omega k x (x + depth n - c)
//   oscillation:  x = x_ref + A sin(2 pi f t + phase),          v = 2 pi f A cos(2 pi f t + phase)
//   pitching:     x = c + R(theta(t)) (x_ref - c), theta(t) = theta0 sin(2 pi f t + phase),
//                 v = theta'(t) k x (x + depth n - c)
// R(theta) turns by theta about the axis k through the centre c (2D: the z axis; 3D: `axis`,
// Rodrigues' formula); normals turn with the body, n = R n_ref.
// The velocity a wall particle carries is the body's at the particle's surface point x + depth n
// (the foot of its normal), as a cavity lid's particles all carry the lid's speed: the Morris wall
// model (Morris, Fox & Zhu 1997, §3.2) extrapolates from the wall particle's velocity as the
// velocity of the wall surface, and a turning particle's own omega (r - depth) is short of the
// surface's omega r by omega depth (measured on Taylor-Couette flow, 10 spacings of inner radius:
// the fluid lagged the exact profile by 5.5 % of omega R1 next to the inner cylinder). x_ref is the mean position of an
// oscillation, so a nonzero phase starts the wall displaced by A sin(phase).
// stationary: the particles stay at x_ref with their reference normals and only carry the velocity
// the motion gives them there (a belt such as a cavity lid, or a spinning cylinder whose surface
// moves while its shape stays where it is: v = omega k x (x_ref + depth n_ref - c)).
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sphmol {

enum class WallMotionKind : std::uint8_t { translation = 0, rotation = 1, oscillation = 2, pitching = 3 };

template <int D>
struct WallMotion {
  WallMotionKind kind = WallMotionKind::translation;
  bool stationary = false;
  std::array<double, D> velocity{};   // translation: V [m/s]
  std::array<double, D> centre{};     // rotation, pitching: c [m], a point on the axis
  std::array<double, 3> axis{0.0, 0.0, 1.0};  // rotation, pitching in 3D: k (normalised by validated()); 2D: z
  double omega = 0.0;                 // rotation: angular velocity [rad/s], positive counter-clockwise about k
  std::array<double, D> amplitude{};  // oscillation: A [m]
  double angle_amplitude = 0.0;       // pitching: theta0 [rad]
  double frequency = 0.0;             // oscillation, pitching: f [Hz], > 0
  double phase = 0.0;                 // oscillation, pitching [rad]

  bool rotates() const { return kind == WallMotionKind::rotation || kind == WallMotionKind::pitching; }

  // The motion with a unit axis, or std::invalid_argument naming what is wrong.
  WallMotion validated() const {
    WallMotion m = *this;
    const auto finite = [](double x) { return std::isfinite(x); };
    bool ok = finite(omega) && finite(angle_amplitude) && finite(frequency) && finite(phase);
    for (int d = 0; d < D; ++d) ok = ok && finite(velocity[d]) && finite(centre[d]) && finite(amplitude[d]);
    if (!ok) throw std::invalid_argument("wall motion: every value must be finite");
    if (rotates() && D == 1) throw std::invalid_argument("wall motion: a one-dimensional wall cannot rotate");
    if ((kind == WallMotionKind::oscillation || kind == WallMotionKind::pitching) && !(frequency > 0.0))
      throw std::invalid_argument("wall motion: an oscillation needs a frequency > 0");
    if (rotates() && D == 3) {
      const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
      if (!std::isfinite(n) || !(n > 0.0)) throw std::invalid_argument("wall motion: the rotation axis must be a nonzero vector");
      for (double& a : m.axis) a /= n;
    }
    if (D == 2) m.axis = {0.0, 0.0, 1.0};
    return m;
  }

  // What the motion is at one time, shared by every particle of the body: the rotation (cos, sin of
  // the angle and the angular rate) or the displacement and velocity of a translation.
  struct Frame {
    double cos = 1.0, sin = 0.0, rate = 0.0;
    double rate_change = 0.0;  // the angular acceleration theta'' (pitching)
    std::array<double, D> shift{}, velocity{}, acceleration{};
  };
  Frame frame(double t) const {
    Frame f;
    const double w = 2.0 * std::numbers::pi * frequency;
    switch (kind) {
      case WallMotionKind::translation:
        for (int d = 0; d < D; ++d) {
          f.shift[d] = velocity[d] * t;
          f.velocity[d] = velocity[d];
        }
        break;
      case WallMotionKind::oscillation: {
        const double s = std::sin(w * t + phase), c = std::cos(w * t + phase);
        for (int d = 0; d < D; ++d) {
          f.shift[d] = amplitude[d] * s;
          f.velocity[d] = amplitude[d] * w * c;
          f.acceleration[d] = -amplitude[d] * w * w * s;
        }
        break;
      }
      case WallMotionKind::rotation:
        f.cos = std::cos(omega * t);
        f.sin = std::sin(omega * t);
        f.rate = omega;
        break;
      case WallMotionKind::pitching: {
        const double theta = angle_amplitude * std::sin(w * t + phase);
        f.cos = std::cos(theta);
        f.sin = std::sin(theta);
        f.rate = angle_amplitude * w * std::cos(w * t + phase);
        f.rate_change = -angle_amplitude * w * w * std::sin(w * t + phase);
        break;
      }
    }
    return f;
  }

  // Position x, velocity v and normal n at the frame's time of the particle at x_ref with normal n_ref.
  void apply(const Frame& f, const std::array<double, D>& x_ref, const std::array<double, D>& n_ref, double depth,
             std::array<double, D>& x, std::array<double, D>& v, std::array<double, D>& n) const {
    if (!rotates()) {
      for (int d = 0; d < D; ++d) {
        x[d] = stationary ? x_ref[d] : x_ref[d] + f.shift[d];
        v[d] = f.velocity[d];
        n[d] = n_ref[d];
      }
      return;
    }
    if constexpr (D >= 2) {
      std::array<double, D> r{};
      for (int d = 0; d < D; ++d) r[d] = x_ref[d] - centre[d];
      if (stationary) {
        x = x_ref;
        n = n_ref;
      } else {
        r = turn(f, r);
        n = turn(f, n_ref);
        for (int d = 0; d < D; ++d) x[d] = centre[d] + r[d];
      }
      for (int d = 0; d < D; ++d) r[d] += depth * n[d];  // the surface point
      v = cross_axis(r);
      for (int d = 0; d < D; ++d) v[d] *= f.rate;
    }
  }

  // The acceleration of the wall's material at a particle with position x, normal n, depth `depth` and
  // velocity v at the frame's time (as apply() gives them). Exact, from the motion's derivatives, so
  // that no difference step sets a frequency beyond which it is wrong. A translation: its A''; a
  // rotation: theta'' k x r + theta' k x v, r from the axis to the surface point x + depth n (the
  // tangential and centripetal parts). For a stationary body, the material acceleration
  // dv/dt + (v . grad) v of the velocity field the fixed particles carry, which is the same expression.
  std::array<double, D> acceleration(const Frame& f, const std::array<double, D>& x, const std::array<double, D>& n,
                                     double depth, const std::array<double, D>& v) const {
    if (!rotates()) return f.acceleration;
    std::array<double, D> r{};
    for (int d = 0; d < D; ++d) r[d] = x[d] + depth * n[d] - centre[d];
    const auto tangential = cross_axis(r), centripetal = cross_axis(v);
    std::array<double, D> a{};
    for (int d = 0; d < D; ++d) a[d] = f.rate_change * tangential[d] + f.rate * centripetal[d];
    return a;
  }

  // The largest speed a particle at x_ref (normal n_ref, depth `depth`) carries over time (for energy bounds).
  double max_speed(const std::array<double, D>& x_ref, const std::array<double, D>& n_ref = {}, double depth = 0.0) const {
    const double w = 2.0 * std::numbers::pi * frequency;
    double s2 = 0.0;
    switch (kind) {
      case WallMotionKind::translation:
        for (int d = 0; d < D; ++d) s2 += velocity[d] * velocity[d];
        return std::sqrt(s2);
      case WallMotionKind::oscillation:
        for (int d = 0; d < D; ++d) s2 += amplitude[d] * amplitude[d];
        return w * std::sqrt(s2);
      case WallMotionKind::rotation:
      case WallMotionKind::pitching: {
        if constexpr (D == 1) return 0.0;
        std::array<double, D> r{};
        for (int d = 0; d < D; ++d) r[d] = x_ref[d] + depth * n_ref[d] - centre[d];
        const auto c = cross_axis(r);  // |k x r|: the surface point's distance from the axis
        for (int d = 0; d < D; ++d) s2 += c[d] * c[d];
        const double rate = kind == WallMotionKind::rotation ? std::abs(omega) : std::abs(angle_amplitude) * w;
        return rate * std::sqrt(s2);
      }
    }
    return 0.0;
  }

 private:
  // k x r (2D: k = z, so (-r_y, r_x)).
  std::array<double, D> cross_axis(const std::array<double, D>& r) const {
    std::array<double, D> c{};
    if constexpr (D == 2) {
      c[0] = -r[1];
      c[1] = r[0];
    } else if constexpr (D == 3) {
      c[0] = axis[1] * r[2] - axis[2] * r[1];
      c[1] = axis[2] * r[0] - axis[0] * r[2];
      c[2] = axis[0] * r[1] - axis[1] * r[0];
    }
    return c;
  }
  // R(theta) r: in 2D the plane rotation, in 3D Rodrigues' formula
  // R r = r cos + (k x r) sin + k (k . r)(1 - cos).
  std::array<double, D> turn(const Frame& f, const std::array<double, D>& r) const {
    std::array<double, D> out{};
    if constexpr (D == 2) {
      out[0] = f.cos * r[0] - f.sin * r[1];
      out[1] = f.sin * r[0] + f.cos * r[1];
    } else if constexpr (D == 3) {
      const auto c = cross_axis(r);
      const double kr = axis[0] * r[0] + axis[1] * r[1] + axis[2] * r[2];
      for (int d = 0; d < 3; ++d) out[d] = r[d] * f.cos + c[d] * f.sin + axis[d] * kr * (1.0 - f.cos);
    }
    return out;
  }
};

}  // namespace sphmol
