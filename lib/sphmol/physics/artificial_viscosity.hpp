#pragma once
// Monaghan artificial viscosity, Niedoba 2012, eqs 2.70-2.72:
//   Pi_ij = (beta theta_ij - alpha cbar_ij) theta_ij / rhobar_ij   if v_ij . x_ij < 0, else 0
//   theta_ij = h_ij v_ij . x_ij / (|x_ij|^2 + eta^2),  eta = eta_factor h_ij (Niedoba 2012: 0.1 h_ij)
//   dv_i/dt -= sum_j m_j Pi_ij grad_i W_ij                    (added to the pressure term, eq 2.71)
//   de_i/dt += 1/2 sum_j m_j Pi_ij v_ij . grad_i W_ij         (its work, eq 2.72; only with energy)
// Pi_ij is symmetric in i, j, so the pair forces are antisymmetric and momentum is conserved; the
// heating is >= 0. Sound speeds c_i come from the EOS (Workspace::c), h_ij = (h_i + h_j)/2.
//
// The signal-velocity form of Monaghan (1997, J. Comput. Phys. 136:298), as written by Price (2008,
// J. Comput. Phys. 227:10040) for shock tubes, replaces Pi_ij by
//   Pi_ij = -alpha v_sig w_ij / rhobar_ij,  v_sig = (c_i + c_j - beta w_ij)/2,  w_ij = v_ij . x_ij / |x_ij|
// for approaching pairs (w_ij < 0): linear in w_ij with a signal speed instead of the quadratic
// theta_ij of h_ij-scaled velocities, so it needs no eta and spreads a shock over fewer particles
// (Price 2008: alpha = 1, beta = 2). Force and heating are the same pair sums as above.
//
// The switch. Both forms act on approaching pairs only, through min(v_ij . x_ij, 0): a kink in f(t, y)
// where a pair turns, which caps every fixed-step integrator at order 2 (docs/verification.md, "Time-
// error floor"). With width > 0 it is the C^6 min of core/polynomial_step.hpp's step P,
//   min(vx, 0) -> vx P(offset - vx / delta),  delta = width cbar_ij h_ij,
// equal to min(vx, 0) outside the band [-(1 - offset) delta, offset delta] and of the sign of vx in it.
// C^6 lifts the cap to order 8, above Verner 8(5)6's 6, and P's derivatives stay small where those of
// the C-infinity step of core/smooth_step.hpp grow faster than k!, so Verner's order shows at a coarser
// step (docs/verification.md, "A polynomial step").
// offset = 0 (the default) puts the band on the approaching side: receding pairs still get nothing,
// Pi_ij >= 0 and the heating >= 0 as before, but pairs approaching slower than about delta / 3 get
// little viscosity. offset > 0 moves a part of the band to the receding side, where pairs slower than
// offset delta get Pi_ij < 0 (the heating m_j Pi_ij F_ij vx / 2 stays >= 0 while beta t_ij rhobar_ij
// < alpha cbar_ij, t_ij below: sw there is at most offset delta P(offset)), and the approaching pairs
// get more of Pi_ij; at offset = 0.3, P(0.3) = 0.062, a shock tube's expanding pairs get at most 6.2 %
// of the viscosity the same rate of compression would (docs/verification.md, "The shock tubes' switch").
// delta is a velocity (width cbar_ij) times a length (h_ij): the band is |v_ij| <~ width cbar_ij h_ij /
// |x_ij|, a fixed fraction of the sound speed at every resolution and velocity scale. width = 0 is the
// sharp switch exactly.
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "sphmol/core/polynomial_step.hpp"
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

// The switch's step, P of core/polynomial_step.hpp: the one function both the scalar switch below and
// the vectorised pair loops of physics/weakly_compressible_row.hpp call.
template <class V>
[[gnu::always_inline]] inline V switch_step_lanes(V t) {
  return polynomial_step_lanes(t);
}

// The switch of both Pi forms: min(vx, 0) for delta = 0, else the band [-(1 - offset) delta, offset delta]
// (above). For a double or (AVX2) four lanes, each lane the scalar's number bit for bit (the pair loops
// of physics/weakly_compressible_row.hpp). At delta = 0 and vx = 0, t = 0/0 is NaN, which P reads as
// t <= 0: sw = 0, min(vx, 0) with the sign of vx's zero.
template <class V>
[[gnu::always_inline]] inline V switched_vx_lanes(V vx, V delta, V offset) {
  return vx * switch_step_lanes(offset - vx / delta);
}
inline double switched_vx(double vx, double delta, double offset) { return switched_vx_lanes(vx, delta, offset); }

// Monaghan's Pi_ij for one pair from vx = v_ij . x_ij and r2 = |x_ij|^2. Receding pairs (vx >= 0, beyond
// the band's receding part) get no viscosity: theta = 0 through the switch (above), with no branch. One division: t = theta / rhobar.
struct MonaghanPi {
  double alpha, beta, eta;
  double width = 0.0;   // the switch's band in cbar_ij h_ij; 0 = min(vx, 0)
  double offset = 0.0;  // the band's receding part, a fraction of it in [0, 1/2]
  // The band delta in v_ij . x_ij; width h_ij first, which a row of equal h computes once.
  double band(double cbar, double hij) const { return width * hij * cbar; }
  // The switched v_ij . x_ij (above).
  double sw(double vx, double cbar, double hij) const { return switched_vx(vx, band(cbar, hij), offset); }
  // Pi_ij from the switched sw = sw(vx, cbar, hij) (of the sign of vx, <= 0 outside the band).
  double switched(double sw, double r2, double hij, double cbar, double rhobar) const {
    const double t = hij * sw / ((r2 + eta * eta * hij * hij) * rhobar);
    return (beta * t * rhobar - alpha * cbar) * t;
  }
  double operator()(double vx, double r2, double hij, double cbar, double rhobar) const {
    return switched(sw(vx, cbar, hij), r2, hij, cbar, rhobar);
  }
  // The same with the sharp switch min(vx, 0), which sw() is bit for bit at width 0 (above), without
  // the polynomial: for loops that choose the switch once per row.
  double sharp(double vx, double r2, double hij, double cbar, double rhobar) const {
    return switched(std::min(vx, 0.0), r2, hij, cbar, rhobar);
  }
};

// Monaghan (1997)'s Pi_ij for one pair, same arguments as MonaghanPi (h_ij sets the switch's band only). vx = 0 at r2 = 0
// (a particle's own row entry or coincident particles), where F = 0 too: no division by zero.
struct SignalVelocityPi {
  double alpha, beta;
  double width = 0.0;   // the switch's band in cbar_ij h_ij; 0 = min(vx, 0)
  double offset = 0.0;  // as MonaghanPi's
  double band(double cbar, double hij) const { return width * hij * cbar; }  // as MonaghanPi's
  double sw(double vx, double cbar, double hij) const { return switched_vx(vx, band(cbar, hij), offset); }
  double operator()(double vx, double r2, double hij, double cbar, double rhobar) const {
    return from_switched(r2 > 0.0 ? sw(vx, cbar, hij) : 0.0, r2, cbar, rhobar);
  }
  double sharp(double vx, double r2, double, double cbar, double rhobar) const {  // as MonaghanPi's
    return from_switched(r2 > 0.0 ? std::min(vx, 0.0) : 0.0, r2, cbar, rhobar);
  }

 private:
  double from_switched(double sw, double r2, double cbar, double rhobar) const {
    const double w = r2 > 0.0 ? sw / std::sqrt(r2) : 0.0;
    return -alpha * (cbar - 0.5 * beta * w) * w / rhobar;  // v_sig = (c_i + c_j - beta w)/2 = cbar - beta w/2
  }
};

template <int D, bool WithEnergy, class Pi = MonaghanPi>
class ArtificialViscosity final : public PairTermFor<D, ArtificialViscosity<D, WithEnergy, Pi>> {
 public:
  explicit ArtificialViscosity(Pi pi) : pi_(pi) {}
  ArtificialViscosity(double alpha, double beta, double eta_factor, double width = 0.0)
      : pi_{alpha, beta, eta_factor, width} {}
  std::string_view name() const override {
    if constexpr (std::is_same_v<Pi, SignalVelocityPi>)
      return WithEnergy ? "artificial_viscosity_signal_velocity+heating" : "artificial_viscosity_signal_velocity";
    return WithEnergy ? "artificial_viscosity+heating" : "artificial_viscosity";
  }
  // The switch is chosen once per row: the sharp one needs no polynomial (3.7x the pressure row's
  // instructions with it).
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    if (pi_.width == 0.0) row_with<false>(w, i, r);
    else row_with<true>(w, i, r);
  }

 private:
  template <bool Smooth>
  void row_with(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    {
      double a[D] = {}, de = 0.0;
      for (std::uint32_t k = 0; k < r.n; ++k) {
        const std::uint32_t j = r.j[k];
        double vx = 0.0, r2 = 0.0;
        for (int d = 0; d < D; ++d) {
          vx += (w.v[d][i] - w.v[d][j]) * r.dx[d][k];
          r2 += r.dx[d][k] * r.dx[d][k];
        }
        const double hij = 0.5 * (w.hs[i] + w.hs[j]), cbar = 0.5 * (w.c[i] + w.c[j]), rhobar = 0.5 * (w.rho[i] + w.rho[j]);
        const double pi = Smooth ? pi_(vx, r2, hij, cbar, rhobar) : pi_.sharp(vx, r2, hij, cbar, rhobar);
        const double s = m[j] * pi * r.F[k];
        for (int d = 0; d < D; ++d) a[d] -= s * r.dx[d][k];
        if constexpr (WithEnergy) de += 0.5 * s * vx;
      }
      for (int d = 0; d < D; ++d) w.dvdt[d][i] += a[d];
      if constexpr (WithEnergy) w.dedt[i] += de;
    }
  }

  Pi pi_;
};

}  // namespace sphmol
