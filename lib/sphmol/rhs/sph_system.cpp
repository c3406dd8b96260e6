#include "sphmol/rhs/sph_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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
  for (auto& s : ws_.strain) s.assign(ws_.n, 0.0);
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
  // Generated (ghost) particles are appended here, from the fluid state just gathered, so that the
  // neighbour update and every term see them like ordinary wall particles.
  if (generator_ && generator_->generate(nb, particles_, ws_)) pairs_->invalidate();
  const std::size_t n = ws_.n;

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
  for (const auto& term : terms_) term->apply(ws_);

  double vmax2 = 0.0, amax2 = 0.0;
#pragma omp parallel for schedule(static) reduction(max : vmax2, amax2)
  for (std::size_t i = 0; i < nf; ++i) {
    double v2 = 0.0, a2 = 0.0;
    for (int d = 0; d < D; ++d) {
      v2 += ws_.v[d][i] * ws_.v[d][i];
      a2 += ws_.dvdt[d][i] * ws_.dvdt[d][i];
    }
    vmax2 = std::max(vmax2, v2);
    amax2 = std::max(amax2, a2);
  }
  const double h = ws_.h;
  double dt = std::numeric_limits<double>::infinity();
  if (cfl_.sound_speed + std::sqrt(vmax2) > 0.0) dt = std::min(dt, cfl_.acoustic * h / (cfl_.sound_speed + std::sqrt(vmax2)));
  if (amax2 > 0.0) dt = std::min(dt, cfl_.force * std::sqrt(h / std::sqrt(amax2)));
  if (cfl_.kinematic_viscosity > 0.0) dt = std::min(dt, cfl_.viscous * h * h / cfl_.kinematic_viscosity);
  stable_step_ = dt;
}

template class SphSystem<1>;
template class SphSystem<2>;
template class SphSystem<3>;

}  // namespace sphmol
