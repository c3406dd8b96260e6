#include "sphmol/rhs/sph_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sphmol {

template <int D>
SphSystem<D>::SphSystem(Particles<D> particles, Domain<D> domain, double h, std::unique_ptr<KernelPass<D>> kernel,
                        std::vector<std::unique_ptr<Term<D>>> terms, std::unique_ptr<VerletList<D>> pairs,
                        CflLimits cfl)
    : particles_(std::move(particles)),
      domain_(domain),
      kernel_(std::move(kernel)),
      terms_(std::move(terms)),
      pairs_(std::move(pairs)),
      cfl_(cfl) {
  layout_.n = particles_.n_fluid;
  ws_.n = particles_.size();
  n_base_ = ws_.n;
  ws_.n_fluid = particles_.n_fluid;
  ws_.particles = &particles_;
  ws_.domain = &domain_;
  ws_.h = h;
  ws_.W0 = kernel_->value_at_zero(h);
  for (int d = 0; d < D; ++d) {
    ws_.x[d].assign(ws_.n, 0.0);
    ws_.v[d] = particles_.v[d];  // wall velocities stay as prescribed; fluid entries are overwritten
  }
  ws_.rho = particles_.rho;  // walls keep their rest density
  ws_.p.assign(ws_.n, 0.0);
  ws_.c.assign(ws_.n, 0.0);
  ws_.e.assign(ws_.n, 0.0);
  ws_.hs.assign(ws_.n, h);
  support_ = kernel_->support();
  for (auto& s : ws_.strain) s.assign(ws_.n, 0.0);
}

template <int D>
void SphSystem<D>::configure_fields(const StateFields& fields, std::vector<double> energy) {
  fields_ = fields;
  layout_.has_density = fields.density;
  layout_.has_energy = fields.energy;
  layout_.has_smoothing_length = fields.smoothing_length == SmoothingLengthMode::ode;
  if (fields.energy) {
    if (energy.size() != ws_.n) throw std::invalid_argument("configure_fields: energy needs one value per particle");
    ws_.e = std::move(energy);
  }
  if (fields.wall_density) layout_.n_wall_density = n_base_ - particles_.n_fluid;
  ws_.n_wall_density = layout_.n_wall_density;
  h_ref_ = ws_.hs;
  rho_ref_ = particles_.rho;
}

template <int D>
std::vector<double> SphSystem<D>::initial_state() const {
  std::vector<double> y(layout_.size());
  const std::size_t n = layout_.n;
  for (int d = 0; d < D; ++d)
    for (std::size_t i = 0; i < n; ++i) {
      y[layout_.position(d) + i] = particles_.x[d][i];
      y[layout_.velocity(d) + i] = particles_.v[d][i];
    }
  for (std::size_t i = 0; i < n; ++i) {
    if (layout_.has_density) y[layout_.density() + i] = particles_.rho[i];
    if (layout_.has_energy) y[layout_.energy() + i] = ws_.e[i];
    if (layout_.has_smoothing_length) y[layout_.smoothing_length() + i] = h_ref_[i];
  }
  for (std::size_t k = 0; k < layout_.n_wall_density; ++k) y[layout_.wall_density() + k] = particles_.rho[n + k];
  return y;
}

template <int D>
std::vector<std::string> SphSystem<D>::active_terms() const {
  std::vector<std::string> names;
  for (const auto& t : terms_) names.emplace_back(t->name());
  return names;
}

template <int D>
void SphSystem<D>::rhs(double t, const double* y, double* ydot) {
  ++rhs_evals_;
  ws_.t = t;
  const std::size_t nf = layout_.n, nb = n_base_;
  for (int d = 0; d < D; ++d) {
    const double* xs = y + layout_.position(d);
    const double* vs = y + layout_.velocity(d);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < nf; ++i) {
      ws_.x[d][i] = domain_.wrap(d, xs[i]);
      ws_.v[d][i] = vs[i];
    }
    for (std::size_t i = nf; i < nb; ++i)
      ws_.x[d][i] = domain_.wrap(d, particles_.x_ref[d][i] + (particles_.stationary[i] ? 0.0 : particles_.v[d][i] * t));
  }
  // Optional fields: per-scene branches outside every pair loop.
  if (layout_.has_density) std::copy(y + layout_.density(), y + layout_.density() + nf, ws_.rho.begin());
  if (layout_.has_energy) std::copy(y + layout_.energy(), y + layout_.energy() + nf, ws_.e.begin());
  if (layout_.has_smoothing_length)
    std::copy(y + layout_.smoothing_length(), y + layout_.smoothing_length() + nf, ws_.hs.begin());
  if (const std::size_t nw = layout_.n_wall_density; nw > 0) {
    const double* rw = y + layout_.wall_density();
    const double floor = fields_.wall_density_floor;
    for (std::size_t k = 0; k < nw; ++k) ws_.rho[nf + k] = std::max(floor, rw[k]);
  }
  if (fields_.smoothing_length == SmoothingLengthMode::density)  // seed 003 eq 2.67
    for (std::size_t i = 0; i < nf; ++i) ws_.hs[i] = h_ref_[i] * std::pow(rho_ref_[i] / ws_.rho[i], 1.0 / D);
  // Generated (ghost) particles are appended here, from the fluid state just gathered (positions,
  // velocities, density, energy, h), so that the neighbour update and every term see them like
  // ordinary wall particles.
  if (generator_ && generator_->generate(nb, particles_, ws_)) pairs_->invalidate();
  const std::size_t n = ws_.n;
  if (fields_.smoothing_length != SmoothingLengthMode::constant) {
    // Pairs are found with h_ij = (h_i + h_j)/2 <= max h: the list radius follows the largest h.
    const double hmax = *std::max_element(ws_.hs.begin(), ws_.hs.end());
    pairs_->set_support(support_ * hmax);
  }

  SearchInput<D> in;
  for (int d = 0; d < D; ++d) in.x[d] = ws_.x[d].data();
  in.kind = particles_.kind.data();
  in.n = n;
  in.domain = &domain_;
  pairs_->update(in);
  kernel_->apply(pairs_->pairs(), ws_);

  for (int d = 0; d < D; ++d) {
    ws_.dxdt[d] = ydot + layout_.position(d);
    ws_.dvdt[d] = ydot + layout_.velocity(d);
    std::copy(ws_.v[d].begin(), ws_.v[d].begin() + nf, ws_.dxdt[d]);
    std::fill(ws_.dvdt[d], ws_.dvdt[d] + nf, 0.0);
  }
  ws_.drhodt = layout_.has_density ? ydot + layout_.density() : nullptr;
  ws_.dedt = layout_.has_energy ? ydot + layout_.energy() : nullptr;
  ws_.dhdt = layout_.has_smoothing_length ? ydot + layout_.smoothing_length() : nullptr;
  if (ws_.drhodt) std::fill(ws_.drhodt, ws_.drhodt + nf, 0.0);
  if (ws_.dedt) std::fill(ws_.dedt, ws_.dedt + nf, 0.0);
  if (ws_.dhdt) std::fill(ws_.dhdt, ws_.dhdt + nf, 0.0);
  ws_.drhodt_wall = layout_.n_wall_density > 0 ? ydot + layout_.wall_density() : nullptr;
  if (ws_.drhodt_wall) std::fill(ws_.drhodt_wall, ws_.drhodt_wall + layout_.n_wall_density, 0.0);
  for (const auto& term : terms_) term->apply(ws_);

  // Acoustic limit per particle with its own h and sound speed (the EOS sets c_i; an EOS that does
  // not falls back to the configured c), so compressible runs use the largest local c / h.
  double amax2 = 0.0, acoustic = std::numeric_limits<double>::infinity(), hmin = ws_.h;
#pragma omp parallel for schedule(static) reduction(max : amax2) reduction(min : acoustic, hmin)
  for (std::size_t i = 0; i < nf; ++i) {
    double v2 = 0.0, a2 = 0.0;
    for (int d = 0; d < D; ++d) {
      v2 += ws_.v[d][i] * ws_.v[d][i];
      a2 += ws_.dvdt[d][i] * ws_.dvdt[d][i];
    }
    amax2 = std::max(amax2, a2);
    const double speed = std::max(cfl_.sound_speed, ws_.c[i]) + std::sqrt(v2);
    if (speed > 0.0) acoustic = std::min(acoustic, ws_.hs[i] / speed);
    hmin = std::min(hmin, ws_.hs[i]);
  }
  double dt = std::numeric_limits<double>::infinity();
  if (std::isfinite(acoustic)) dt = std::min(dt, cfl_.acoustic * acoustic);
  if (amax2 > 0.0) dt = std::min(dt, cfl_.force * std::sqrt(hmin / std::sqrt(amax2)));
  if (cfl_.kinematic_viscosity > 0.0) dt = std::min(dt, cfl_.viscous * hmin * hmin / cfl_.kinematic_viscosity);
  stable_step_ = dt;
}

template class SphSystem<1>;
template class SphSystem<2>;
template class SphSystem<3>;

}  // namespace sphmol
