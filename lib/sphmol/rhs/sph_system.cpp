#include "sphmol/rhs/sph_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <omp.h>
#include <stdexcept>

#include "sphmol/core/polynomial_step.hpp"
#include "sphmol/neighbors/particle_reorder.hpp"
#include "sphmol/rhs/pair_pass_plan.hpp"

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
  // e and h are the scene's (initial_state() and a run over ranks read them before any evaluation);
  // the evaluation's own arrays are allocated by its first evaluation (allocate_workspace).
  ws_.e.assign(ws_.n, 0.0);
  ws_.hs.assign(ws_.n, h);
  support_ = kernel_->support();
  moving_walls_ = std::any_of(particles_.motion.begin(), particles_.motion.end(), [](std::int32_t k) { return k >= 0; });
  if (particles_.has_turning_walls())
    for (int d = 0; d < D; ++d) normal_now_[d] = particles_.wall_normal[d];
  // Fluid already taken out of the run (a rank's local system over MPI ranks, made from particles
  // that carry their kind): retired from the start, as retire() would.
  for (std::size_t i = 0; i < particles_.n_fluid; ++i)
    if (particles_.kind[i] == Kind::Out) retired_.push_back(i);
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
  // The references of a variable h only (h(0) for the state's h and for h from the density).
  if (fields.smoothing_length != SmoothingLengthMode::constant) h_ref_ = ws_.hs;
  if (fields.smoothing_length == SmoothingLengthMode::density) rho_ref_ = particles_.rho;
}

template <int D>
void SphSystem<D>::allocate_fields() {
  if (released_) throw std::logic_error("SphSystem: the particles were released (release_particles)");
  if (!ws_.rho.empty()) return;
  ws_.rho = particles_.rho;  // walls keep their rest density
  ws_.p.assign(n_base_, 0.0);
  ws_.c.assign(n_base_, 0.0);
}

template <int D>
void SphSystem<D>::allocate_workspace() {
  if (workspace_allocated_) return;
  allocate_fields();
  for (int d = 0; d < D; ++d) {
    ws_.x[d].assign(n_base_, 0.0);
    ws_.v[d] = particles_.v[d];  // wall velocities stay as prescribed; fluid entries are overwritten
  }
  for (auto& s : ws_.strain) s.assign(n_base_, 0.0);
  workspace_allocated_ = true;
}

template <int D>
void SphSystem<D>::set_initial_smoothing_lengths(const std::vector<double>& h0) {
  if (h0.size() != n_base_) throw std::invalid_argument("set_initial_smoothing_lengths: needs one h per particle");
  std::copy(h0.begin(), h0.end(), ws_.hs.begin());
  h_ref_ = ws_.hs;
}

template <int D>
std::vector<double> SphSystem<D>::initial_state() const {
  std::vector<double> y(layout_.size());
  const std::size_t n = layout_.n;
  // Energy and h(0) live in workspace order (reordering); back to state order.
  std::vector<double> e_tmp, h_tmp;
  const auto& e0 = state_order(ws_.e, e_tmp);
  const auto& h0 = layout_.has_smoothing_length ? state_order(h_ref_, h_tmp) : h_tmp;
  for (int d = 0; d < D; ++d)
    for (std::size_t i = 0; i < n; ++i) {
      y[layout_.position(d) + i] = particles_.x[d][i];
      y[layout_.velocity(d) + i] = particles_.v[d][i];
    }
  for (std::size_t i = 0; i < n; ++i) {
    if (layout_.has_density) y[layout_.density() + i] = particles_.rho[i];
    if (layout_.has_energy) y[layout_.energy() + i] = e0[i];
    if (layout_.has_smoothing_length) y[layout_.smoothing_length() + i] = h0[i];
  }
  for (std::size_t k = 0; k < layout_.n_wall_density; ++k) y[layout_.wall_density() + k] = particles_.rho[n + k];
  return y;
}

template <int D>
std::vector<std::string> SphSystem<D>::active_terms() const {
  std::vector<std::string> names;
  for (const auto& t : terms_) {
    if (const auto* f = dynamic_cast<const FusedPairPass<D>*>(t.get()))
      for (const auto& m : f->terms()) names.emplace_back(m->name());
    else
      names.emplace_back(t->name());
  }
  return names;
}

template <int D>
void SphSystem<D>::append_term(std::unique_ptr<Term<D>> t) {
  if (!stored_pairs_ && t->reads_stored_pairs())
    throw std::logic_error("SphSystem::append_term: '" + std::string(t->name()) + "' reads the stored pair list, "
                           "which fused pair passes do not build");
  terms_.push_back(std::move(t));
}

template <int D>
std::vector<std::string> SphSystem<D>::terms_needing_stored_pairs() const {
  std::vector<std::string> names;
  for (const auto& t : terms_)
    if (!can_run_fused(*t)) names.emplace_back(t->name());
  return names;
}

template <int D>
std::size_t SphSystem<D>::fused_pass_count() const {
  return sphmol::fused_pass_count(terms_);
}

template <int D>
void SphSystem<D>::fuse_pair_passes() {
  if (rhs_evals_ > 0) throw std::logic_error("SphSystem::fuse_pair_passes: must be set before the first evaluation");
  if (!stored_pairs_) return;
  terms_ = fuse_pair_terms(std::move(terms_), kernel_.get());
  stored_pairs_ = false;
  ws_.pairs.clear(0);  // never filled: a term reading it by mistake sees no pairs
}

template <int D>
std::vector<bool> SphSystem<D>::pair_passes_keep_skin_pairs() const {
  std::vector<bool> keep;
  for (const auto& t : terms_)
    if (const auto* f = dynamic_cast<const FusedPairPass<D>*>(t.get()))
      keep.push_back(!f->compacts_fluid_rows() && !f->compacts_wall_rows());
  return keep;
}

template <int D>
void SphSystem<D>::set_symmetric_pairs(bool on) {
  for (auto& t : terms_)
    if (auto* f = dynamic_cast<FusedPairPass<D>*>(t.get())) f->set_symmetric(on);
}

template <int D>
long SphSystem<D>::symmetric_evaluations() const {
  long most = 0;
  for (const auto& t : terms_)
    if (const auto* f = dynamic_cast<const FusedPairPass<D>*>(t.get())) most = std::max(most, f->symmetric_evaluations());
  return most;
}

template <int D>
std::vector<std::vector<std::string>> SphSystem<D>::pair_passes() const {
  std::vector<std::vector<std::string>> passes;
  for (const auto& t : terms_)
    if (const auto* f = dynamic_cast<const FusedPairPass<D>*>(t.get())) {
      passes.emplace_back();
      for (const auto& m : f->terms()) passes.back().emplace_back(m->name());
    }
  return passes;
}

template <int D>
std::size_t SphSystem<D>::active_pairs() const {
  if (stored_pairs_ || rhs_evals_ == 0) return ws_.pairs.pairs();
  return kernel_->count_active(pairs_->pairs(), ws_);
}

template <int D>
void SphSystem<D>::rhs(double t, const double* y, double* ydot) {
  if (released_) throw std::logic_error("SphSystem::rhs: the particles were released (release_particles)");
  ++rhs_evals_;
  ++rhs_calls_;
  allocate_workspace();
  const double t_start = omp_get_wtime();
  ws_.t = t;
  const std::size_t nf = layout_.n, nb = n_base_;
  const std::uint32_t* ord = perm_.empty() ? nullptr : perm_.data();  // workspace -> state index
  const Particles<D>& P = *ws_.particles;
  const bool turning = !normal_now_[0].empty();
  if (moving_walls_) {
    // Walls that follow a motion (core/wall_motion.hpp): position, velocity and, when the body
    // turns, normal at t, once per evaluation, so the pair loops read plain arrays. The trigonometry
    // of each body's frame is evaluated once here, not per particle.
    frames_.clear();
    for (const auto& m : P.motions) frames_.push_back(m.frame(t));
  }
  // Optional fields: per-scene branches outside every loop.
  const double* const rho_s = layout_.has_density ? y + layout_.density() : nullptr;
  const double* const e_s = layout_.has_energy ? y + layout_.energy() : nullptr;
  const double* const h_s = layout_.has_smoothing_length ? y + layout_.smoothing_length() : nullptr;
  const std::size_t nw = layout_.n_wall_density;
  // A split state (rhs_split): row i of a block from the owned rows of y or from the other rows.
  const bool split = splitting_;
  const double* const other = split_other_;
  const std::uint32_t* const fsrc = split_.fluid_source.data();
  const std::size_t no = split_.owned.n, width = split_.width;
  StateLayout<D> unit = layout_;  // block offsets in units of n: a block's index in a row
  unit.n = 1;
  const auto from_split = [&](std::size_t offset, std::size_t block, std::uint32_t s) {
    return s < no ? y[offset + s] : other[(s - no) * width + block];
  };
  const bool h_from_density = fields_.smoothing_length == SmoothingLengthMode::density;
  // The neighbour list's displacement test runs in the same region, after the gathers, when nothing
  // between them and the search changes the particles or the support (no generated particles,
  // constant h): one region fewer per evaluation.
  SearchInput<D> in;
  for (int d = 0; d < D; ++d) in.x[d] = ws_.x[d].data();
  in.kind = P.kind.data();
  in.n = ws_.n;
  in.domain = &domain_;
  const bool check_in_gather = !generator_ && fields_.smoothing_length == SmoothingLengthMode::constant;
  if (check_in_gather) pairs_->begin_check(in);
  // Every gather in one parallel region: each loop writes arrays of its own, so none waits for
  // another (nowait; the region's end is the one barrier). Loops over the same range with
  // schedule(static) give particle i to the same thread, so h from the density reads the density
  // its own thread gathered.
#pragma omp parallel
  {
    for (int d = 0; d < D; ++d) {
      const double* xs = y + layout_.position(d);
      const double* vs = y + layout_.velocity(d);
      double* const wx = ws_.x[d].data();
      double* const wv = ws_.v[d].data();
      if (split) {
        const std::size_t xo = split_.owned.position(d), vo = split_.owned.velocity(d);
        const std::size_t xb = static_cast<std::size_t>(d), vb = static_cast<std::size_t>(D + d);
#pragma omp for schedule(static) nowait
        for (std::size_t i = 0; i < nf; ++i) {
          const std::uint32_t s = fsrc[i];
          wx[i] = domain_.wrap(d, from_split(xo, xb, s));
          wv[i] = from_split(vo, vb, s);
        }
      } else if (!ord && !domain_.periodic[d]) {
        // In storage order and not wrapped: plain copies, which vectorise (wrap is the identity).
#pragma omp for schedule(static) nowait
        for (std::size_t i = 0; i < nf; ++i) {
          wx[i] = xs[i];
          wv[i] = vs[i];
        }
      } else {
#pragma omp for schedule(static) nowait
        for (std::size_t i = 0; i < nf; ++i) {
          const std::size_t k = ord ? ord[i] : i;
          wx[i] = domain_.wrap(d, xs[k]);
          wv[i] = vs[k];
        }
      }
    }
    if (moving_walls_) {
#pragma omp for schedule(static) nowait
      for (std::size_t i = nf; i < nb; ++i) {
        const auto s = P.wall_state(i, frames_, t);
        for (int d = 0; d < D; ++d) {
          ws_.x[d][i] = domain_.wrap(d, s.x[d]);
          ws_.v[d][i] = s.v[d];
          if (turning) normal_now_[d][i] = s.n[d];
        }
      }
    } else {
      for (int d = 0; d < D; ++d) {
#pragma omp for schedule(static) nowait
        for (std::size_t i = nf; i < nb; ++i) ws_.x[d][i] = domain_.wrap(d, P.wall_position(d, i, t));
      }
    }
    auto gather = [&](const double* from, std::size_t block, std::vector<double>& to) {
      double* dst = to.data();
      if (split) {
        const std::size_t offset = block * no;  // the block in the owned rows
#pragma omp for schedule(static) nowait
        for (std::size_t i = 0; i < nf; ++i) dst[i] = from_split(offset, block, fsrc[i]);
        return;
      }
#pragma omp for schedule(static) nowait
      for (std::size_t i = 0; i < nf; ++i) dst[i] = from[ord ? ord[i] : i];
    };
    if (rho_s) gather(rho_s, unit.density(), ws_.rho);
    if (e_s) gather(e_s, unit.energy(), ws_.e);
    if (h_s) gather(h_s, unit.smoothing_length(), ws_.hs);
    if (nw > 0) {
      // Wall densities (dynamic boundary particles), state index k = wall nf + k; floored at rho0
      // (smoothly: state_fields.hpp).
      const double* rw = y + layout_.wall_density();
      const double floor = fields_.wall_density_floor, width_floor = fields_.wall_density_floor_width;
      if (split) {
        const std::uint32_t* const wsrc = split_.wall_source.data();
        const std::size_t nwo = split_.owned.n_wall_density, wo = split_.owned.wall_density();
#pragma omp for schedule(static) nowait
        for (std::size_t k = 0; k < nw; ++k) {
          const std::uint32_t s = wsrc[k];
          const double r = s < nwo ? y[wo + s] : other[(s - nwo) * width];
          ws_.rho[nf + k] = floor + smooth_max0(r - floor, width_floor);
        }
      } else {
#pragma omp for schedule(static) nowait
        for (std::size_t k = 0; k < nw; ++k)
          ws_.rho[nf + k] = floor + smooth_max0(rw[ord ? ord[nf + k] - nf : k] - floor, width_floor);
      }
    } else {
      // Walls without a density in the state start every evaluation from their own density: a term
      // that overwrites it (the extrapolated wall pressure) leaves walls without fluid alone, and
      // they must not keep a value from an earlier evaluation (the output reads them).
      // (P is in workspace order: reordering permutes it with the workspace.)
      const double* rw = P.rho.data();
#pragma omp for schedule(static) nowait
      for (std::size_t i = nf; i < nb; ++i) ws_.rho[i] = rw[i];
    }
    if (h_from_density) {  // Niedoba 2012, eq 2.67
#pragma omp for schedule(static) nowait
      for (std::size_t i = 0; i < nf; ++i) ws_.hs[i] = h_ref_[i] * std::pow(rho_ref_[i] / ws_.rho[i], 1.0 / D);
    }
    if (check_in_gather) {
#pragma omp barrier
      pairs_->check_in_team(in);  // reads every position
    }
  }
  // Generated (ghost) particles are appended here, from the fluid state just gathered (positions,
  // velocities, density, energy, h), so that the neighbour update and every term see them like
  // ordinary wall particles.
  if (generator_ && generator_->generate(nb, particles_, ws_)) pairs_->invalidate();
  if (fields_.smoothing_length != SmoothingLengthMode::constant) {
    // Pairs are found with h_ij = (h_i + h_j)/2 <= max h: the list radius follows the largest h.
    const double hmax = *std::max_element(ws_.hs.begin(), ws_.hs.end());
    pairs_->set_support(support_ * hmax);
  }

  for (int d = 0; d < D; ++d) in.x[d] = ws_.x[d].data();  // a generator may have added particles
  in.kind = P.kind.data();
  in.n = ws_.n;
  const double t_search = omp_get_wtime();
  if (reorder_ && pairs_->stale(in)) {
    reorder_workspace();  // permutes in place: `in` stays valid
    ord = perm_.data();
    pairs_->invalidate();
  }
  pairs_->update(in);
  search_seconds_ += omp_get_wtime() - t_search;
  ws_.verlet = &pairs_->pairs();
  ws_.verlet_rebuilds = pairs_->rebuilds();
  if (stored_pairs_) kernel_->apply(pairs_->pairs(), ws_);
  // Rows of the implicit operator never hold more entries than the Verlet list's rows.
  if (record_) record_->begin(nf, D, pairs_->pairs().offset.data(), ord);
  ws_.implicit = record_;

  // Derivatives are written in workspace order: straight into ydot, or into out_ and scattered below
  // (reordered, or only the owned rows of a split state).
  if (ord || split) out_.resize(layout_.size());
  double* const out = ord || split ? out_.data() : ydot;
  for (int d = 0; d < D; ++d) {
    ws_.dxdt[d] = out + layout_.position(d);
    ws_.dvdt[d] = out + layout_.velocity(d);
  }
  ws_.drhodt = layout_.has_density ? out + layout_.density() : nullptr;
  ws_.dedt = layout_.has_energy ? out + layout_.energy() : nullptr;
  ws_.dhdt = layout_.has_smoothing_length ? out + layout_.smoothing_length() : nullptr;
  ws_.drhodt_wall = layout_.n_wall_density > 0 ? out + layout_.wall_density() : nullptr;
  for (int d = 0; d < D; ++d) ws_.wall_normal[d] = normal_now_[d].empty() ? nullptr : normal_now_[d].data();
  // The terms, the scatter to state order and the CFL limit in one parallel region per evaluation
  // when every term runs in a team (Term::runs_in_team): each region's start and end is a
  // synchronisation, and one thread descheduled by another process stalls all of them. A term that
  // opens its own regions is called between two such regions.
  const std::size_t nw_rates = layout_.n_wall_density;
  const std::size_t blocks = ord && nf > 0 ? (layout_.size() - nw_rates) / nf : 0;
  const std::uint32_t* at = inv_.data();  // state -> workspace index
  // Acoustic limit per particle with its own h and sound speed (the EOS sets c_i; an EOS that does
  // not falls back to the configured c), so compressible runs use the largest local c / h.
  double amax2 = 0.0, acoustic = std::numeric_limits<double>::infinity(), hmin = ws_.h;
  // Row i's part of those extremes, into a reduction's copies (passed in: a capture would reach
  // the shared variables, not each thread's).
  const auto cfl_row = [this](std::size_t i, double& amax2_i, double& acoustic_i, double& hmin_i) {
    double v2 = 0.0, a2 = 0.0;
    for (int d = 0; d < D; ++d) {
      v2 += ws_.v[d][i] * ws_.v[d][i];
      a2 += ws_.dvdt[d][i] * ws_.dvdt[d][i];
    }
    amax2_i = std::max(amax2_i, a2);
    const double speed = std::max(cfl_.sound_speed, ws_.c[i]) + std::sqrt(v2);
    if (speed > 0.0) acoustic_i = std::min(acoustic_i, ws_.hs[i] / speed);
    hmin_i = std::min(hmin_i, ws_.hs[i]);
  };
  for (std::size_t k = 0;;) {
    std::size_t e = k;  // terms [k, e) run in a team
    while (e < terms_.size() && terms_[e]->runs_in_team()) ++e;
    const bool first = k == 0, last = e == terms_.size();
    // Between two terms that open their own regions there is nothing to run: no team is started.
#pragma omp parallel if (first || last || e > k)
    {
      if (first) {
        // dx/dt = v, every other rate 0, before the terms add to them.
#pragma omp for schedule(static) nowait
        for (std::size_t i = 0; i < nf; ++i) {
          for (int d = 0; d < D; ++d) {
            ws_.dxdt[d][i] = ws_.v[d][i];
            ws_.dvdt[d][i] = 0.0;
          }
          if (ws_.drhodt) ws_.drhodt[i] = 0.0;
          if (ws_.dedt) ws_.dedt[i] = 0.0;
          if (ws_.dhdt) ws_.dhdt[i] = 0.0;
        }
        if (ws_.drhodt_wall) {
#pragma omp for schedule(static) nowait
          for (std::size_t q = 0; q < nw_rates; ++q) ws_.drhodt_wall[q] = 0.0;
        }
#pragma omp barrier
      }
      for (std::size_t q = k; q < e; ++q) terms_[q]->apply(ws_);  // each ends with a barrier
      if (last) {
        if (!retired_.empty()) {
          // Particles taken out (retire()): every rate zero, before the scatter and the CFL extremes
          // read them (the body force and the self terms would otherwise move them). A uniform
          // branch: every thread meets the loop's closing barrier.
          const std::size_t* const gone = retired_.data();
#pragma omp for schedule(static)
          for (std::size_t r = 0; r < retired_.size(); ++r) {
            const std::size_t i = ord ? at[gone[r]] : gone[r];
            for (int d = 0; d < D; ++d) {
              ws_.dxdt[d][i] = 0.0;
              ws_.dvdt[d][i] = 0.0;
            }
            if (ws_.drhodt) ws_.drhodt[i] = 0.0;
            if (ws_.dedt) ws_.dedt[i] = 0.0;
            if (ws_.dhdt) ws_.dhdt[i] = 0.0;
          }
        }
        if (split) {
          // The owned rows' rates and their CFL extremes in one pass; the other rows' rates are
          // not wanted. Wall densities first (few), then the owned fluid rows.
          const std::size_t wb = layout_.wall_density(), wbo = split_.owned.wall_density();
          const std::uint32_t* const wrow = split_.wall_rate_row.data();
#pragma omp for schedule(static) nowait
          for (std::size_t q = 0; q < split_.owned.n_wall_density; ++q) ydot[wbo + q] = out_[wb + wrow[q]];
          const std::size_t fluid_blocks = 2 * D + layout_.extra_blocks();
          const std::uint32_t* const frow = split_.fluid_rate_row.data();
#pragma omp for schedule(static) nowait reduction(max : amax2) reduction(min : acoustic, hmin)
          for (std::size_t o = 0; o < no; ++o) {
            const std::size_t i = frow[o];
            for (std::size_t b = 0; b < fluid_blocks; ++b) ydot[b * no + o] = out_[b * nf + i];
            cfl_row(i, amax2, acoustic, hmin);
          }
        } else if (blocks > 0) {
          // Per-fluid blocks first, then the wall-density block (walls are ordered among
          // themselves). The loop runs over the state index, so each thread writes its own
          // contiguous part of ydot, the part the integrator's loops give it
          // (time/particle_split.hpp); over the workspace index, the two threads' writes
          // interleaved within cache lines once the flow had mixed the particles.
          for (std::size_t b = 0; b < blocks; ++b) {
            double* const to = ydot + b * nf;
            const double* const from = out_.data() + b * nf;
#pragma omp for schedule(static) nowait
            for (std::size_t q = 0; q < nf; ++q) to[q] = from[at[q]];
          }
          const std::size_t wb = layout_.wall_density();
#pragma omp for schedule(static) nowait
          for (std::size_t q = 0; q < nw_rates; ++q) ydot[wb + q] = out_[wb + at[nf + q] - nf];
        }
        if (!split) {
#pragma omp for schedule(static) nowait reduction(max : amax2) reduction(min : acoustic, hmin)
        for (std::size_t i = 0; i < nf; ++i) cfl_row(i, amax2, acoustic, hmin);
        }
      }
    }  // the region's end: every reduction combined, every rate written
    if (last) break;
    terms_[e]->apply(ws_);
    k = e + 1;
  }
  ws_.implicit = nullptr;
  if (record_) record_->end();
  extremes_ = {acoustic, amax2, hmin};
  // The viscous limit binds an explicit viscous term only: not the explicit part of an IMEX split.
  stable_step_ = cfl_step(cfl_, acoustic, amax2, hmin, !record_);
  widest_step_ = cfl_step(cfl_.widest(), acoustic, amax2, hmin, !record_);
  rhs_seconds_ += omp_get_wtime() - t_start;
}

namespace {

// A member set for the length of a call, and set back however the call ends.
template <class T>
class SetDuring {
 public:
  SetDuring(T& slot, T value) : slot_(slot), old_(slot) { slot_ = value; }
  ~SetDuring() { slot_ = old_; }
  SetDuring(const SetDuring&) = delete;
  SetDuring& operator=(const SetDuring&) = delete;

 private:
  T& slot_;
  T old_;
};

}  // namespace

template <int D>
void SphSystem<D>::set_fields(const ParticleFieldValues& f) {
  const std::size_t nb = n_base_;
  for (const auto* a : {&f.density, &f.pressure, &f.sound_speed, &f.energy, &f.smoothing_length})
    if (a->size() != nb) throw std::invalid_argument("SphSystem::set_fields: needs one value per particle of the scene");
  // Workspace index k holds particle perm_[k] when reordered.
  allocate_fields();
  const auto put = [&](const std::vector<double>& from, std::vector<double>& to) {
    for (std::size_t k = 0; k < nb; ++k) to[k] = from[perm_.empty() ? k : perm_[k]];
  };
  put(f.density, ws_.rho);
  put(f.pressure, ws_.p);
  put(f.sound_speed, ws_.c);
  put(f.energy, ws_.e);
  put(f.smoothing_length, ws_.hs);
  if (fields_.smoothing_length != SmoothingLengthMode::constant)
    if (nb > 0) pairs_->set_support(support_ * *std::max_element(ws_.hs.begin(), ws_.hs.begin() + static_cast<std::ptrdiff_t>(nb)));
}

template <int D>
void SphSystem<D>::rhs_explicit(double t, const double* y, double* fe, ViscousOperator& op) {
  if (generator_) throw std::logic_error("SphSystem::rhs_explicit: generated particles have no implicit operator");
  const SetDuring<ViscousOperator*> recording(record_, &op);
  rhs(t, y, fe);
}

template <int D>
void SphSystem<D>::set_split_state(SplitState<D> split) {
  if (reorder_) throw std::logic_error("SphSystem::set_split_state: not with reordering");
  const StateLayout<D>& o = split.owned;
  if (o.has_density != layout_.has_density || o.has_energy != layout_.has_energy ||
      o.has_smoothing_length != layout_.has_smoothing_length || (o.n_wall_density > 0) != (layout_.n_wall_density > 0) ||
      split.fluid_source.size() != layout_.n || split.wall_source.size() != layout_.n_wall_density ||
      split.fluid_rate_row.size() != o.n || split.wall_rate_row.size() != o.n_wall_density ||
      split.width < 2 * D + layout_.extra_blocks())
    throw std::invalid_argument("SphSystem::set_split_state: the split does not fit the system's state");
  split_ = std::move(split);
}

template <int D>
void SphSystem<D>::rhs_split(double t, const double* y, const double* other, double* ydot) {
  if (split_.width == 0) throw std::logic_error("SphSystem::rhs_split: no split state set");
  const SetDuring<bool> splitting(splitting_, true);
  split_other_ = other;
  rhs(t, y, ydot);
}

template <int D>
void SphSystem<D>::rhs_explicit_split(double t, const double* y, const double* other, double* fe, ViscousOperator& op) {
  if (generator_) throw std::logic_error("SphSystem::rhs_explicit: generated particles have no implicit operator");
  const SetDuring<ViscousOperator*> recording(record_, &op);
  rhs_split(t, y, other, fe);
}

template <int D>
std::vector<std::string> SphSystem<D>::implicit_terms() const {
  std::vector<std::string> names;
  auto add = [&names](const Term<D>& t) {
    if (t.implicit()) names.emplace_back(t.name());
  };
  for (const auto& t : terms_) {
    if (const auto* f = dynamic_cast<const FusedPairPass<D>*>(t.get()))
      for (const auto& m : f->terms()) add(*m);
    else
      add(*t);
  }
  return names;
}

template <int D>
void SphSystem<D>::release_particles() {
  if (rhs_calls_ > 0 || workspace_allocated_) throw std::logic_error("SphSystem::release_particles: the system was evaluated");
  const auto drop = [](auto& v) { std::decay_t<decltype(v)>().swap(v); };
  // Reordering keeps a copy of the particles for its workspace (set_reorder), in the initial order.
  if (reorder_) {
    for (int d = 0; d < D; ++d) {
      drop(wp_.x[d]);
      drop(wp_.v[d]);
      drop(wp_.x_ref[d]);
      drop(wp_.wall_normal[d]);
    }
    for (auto* v : {&wp_.mass, &wp_.rho, &wp_.wall_depth, &wp_.rest_density, &wp_.viscosity}) drop(*v);
    drop(wp_.kind);
    drop(wp_.stationary);
    drop(wp_.body);
    drop(wp_.motion);
  }
  for (int d = 0; d < D; ++d) {
    drop(particles_.x[d]);
    drop(particles_.v[d]);
    drop(particles_.x_ref[d]);
    drop(particles_.wall_normal[d]);
    drop(x_out_[d]);
    drop(normal_now_[d]);
  }
  drop(particles_.mass);
  drop(particles_.rho);
  drop(particles_.kind);
  drop(particles_.wall_depth);
  drop(particles_.stationary);
  drop(particles_.body);
  drop(particles_.rest_density);
  drop(particles_.viscosity);
  drop(particles_.motion);
  drop(h_ref_);
  drop(rho_ref_);
  drop(rho_out_);
  drop(p_out_);
  drop(c_out_);
  drop(e_out_);
  drop(hs_out_);
  // The scene's e and h(0), and any fields set on it (the evaluation's arrays were never made).
  drop(ws_.e);
  drop(ws_.hs);
  drop(ws_.rho);
  drop(ws_.p);
  drop(ws_.c);
  // What the case's monitors keep per particle of the whole scene (their local systems' terms read
  // it from the rows they watch).
  for (const auto& m : monitors_) m->release_whole();
  released_ = true;
  if (share_) {
    // From here on the system stands for the whole scene, as a released whole system does.
    for (auto& i : retired_) i += whole_.first;
    layout_.n = whole_.fluid;
    n_base_ = whole_.size;
    layout_.n_wall_density = fields_.wall_density ? whole_.size - whole_.fluid : 0;
    ws_.n_wall_density = layout_.n_wall_density;
    share_ = false;
  }
}

template <int D>
void SphSystem<D>::set_whole_scene(const WholeScene& whole) {
  if (released_) throw std::logic_error("SphSystem::set_whole_scene: the particles were released");
  const std::size_t n = n_base_, nf = particles_.n_fluid;
  // Fluid first in the whole scene: the share's fluid is the whole scene's fluid in its range.
  if (whole.first + n > whole.size || whole.fluid > whole.size ||
      nf != std::clamp(whole.fluid, whole.first, whole.first + n) - whole.first)
    throw std::invalid_argument("SphSystem::set_whole_scene: particles [" + std::to_string(whole.first) + ", " +
                                std::to_string(whole.first + n) + ") with " + std::to_string(nf) +
                                " fluid are not a share of a scene of " + std::to_string(whole.size) + " particles, " +
                                std::to_string(whole.fluid) + " fluid");
  whole_ = whole;
  share_ = true;
}

template <int D>
typename SphSystem<D>::WholeScene SphSystem<D>::whole_scene() const {
  if (share_) return whole_;
  return {0, n_base_, layout_.n};
}

template <int D>
StateLayout<D> SphSystem<D>::whole_layout() const {
  StateLayout<D> w = layout_;
  if (!share_) return w;
  w.n = whole_.fluid;
  w.n_wall_density = fields_.wall_density ? whole_.size - whole_.fluid : 0;
  return w;
}

template <int D>
std::vector<double> SphSystem<D>::share_of(const std::vector<double>& whole) const {
  const StateLayout<D> W = whole_layout();
  if (whole.size() != W.size()) throw std::invalid_argument("SphSystem::share_of: not a state of the whole scene");
  if (!share_) return whole;
  const StateLayout<D>& L = layout_;
  std::vector<double> y(L.size());
  const std::size_t first = whole_.first, nf = L.n, blocks = 2 * D + L.extra_blocks();
  for (std::size_t b = 0; b < blocks; ++b)
    for (std::size_t i = 0; i < nf; ++i) y[b * nf + i] = whole[b * W.n + first + i];
  // Wall densities: the share's walls are the whole scene's [first + nf, ...), after its fluid.
  for (std::size_t k = 0; k < L.n_wall_density; ++k) y[L.wall_density() + k] = whole[W.wall_density() + (first + nf - W.n) + k];
  return y;
}

template <int D>
void SphSystem<D>::retire(const std::vector<std::size_t>& fluid) {
  if (released_) {  // the indices only (run/outflow.hpp keeps the count on every rank)
    for (const std::size_t i : fluid)
      if (i >= layout_.n) throw std::invalid_argument("SphSystem::retire: " + std::to_string(i) + " is not a fluid particle");
    retired_.insert(retired_.end(), fluid.begin(), fluid.end());
    return;
  }
  bool changed = false;
  for (const std::size_t i : fluid) {
    if (i >= layout_.n) throw std::invalid_argument("SphSystem::retire: " + std::to_string(i) + " is not a fluid particle");
    if (particles_.kind[i] == Kind::Out) continue;
    particles_.kind[i] = Kind::Out;
    // The workspace's copy of the particles (reordering) holds particle i at inv_[i].
    if (reorder_) wp_.kind[inv_[i]] = Kind::Out;
    retired_.push_back(i);
    changed = true;
  }
  if (changed) pairs_->invalidate();  // the next evaluation lists its pairs without them
}

template <int D>
void SphSystem<D>::set_generator(std::unique_ptr<ParticleGenerator<D>> g) {
  if (reorder_ && g) throw std::logic_error("SphSystem: reordering does not support generated particles");
  generator_ = std::move(g);
}

template <int D>
void SphSystem<D>::set_reorder(bool on) {
  if (rhs_evals_ > 0) throw std::logic_error("SphSystem::set_reorder: must be set before the first evaluation");
  if (on && generator_) throw std::logic_error("SphSystem: reordering does not support generated particles");
  if (on && split_.width > 0) throw std::logic_error("SphSystem::set_reorder: not with a split state");
  reorder_ = on;
  perm_.clear();
  inv_.clear();
  ws_.particles = &particles_;
  ws_.order = nullptr;
  if (!on) return;
  wp_ = particles_;
  perm_.resize(n_base_);
  std::iota(perm_.begin(), perm_.end(), 0u);
  inv_ = perm_;
  ws_.particles = &wp_;
  ws_.order = perm_.data();
}

// New Morton order of the fluid and of the walls (each within its own range, so fluid stays first
// and rows keep their fluid-then-wall structure), applied to every array indexed by workspace index.
template <int D>
void SphSystem<D>::reorder_workspace() {
  const std::size_t nf = layout_.n, nb = n_base_;
  std::array<const double*, D> xs;
  for (int d = 0; d < D; ++d) xs[d] = ws_.x[d].data();
  // Cells half the list radius wide: neighbours within a few cells, a few particles per cell. Those
  // in one cell by state index: the order is then a function of the positions alone, which a run
  // over ranks reproduces in its local systems from the global ids (parallel/distributed_system.hpp).
  const double cell = 0.5 * pairs_->list_radius();
  const auto fluid = morton_order<D>(xs, 0, nf, domain_, cell, perm_.data());
  const auto walls = morton_order<D>(xs, nf, nb, domain_, cell, perm_.data());
  std::vector<double> td;
  std::vector<std::uint32_t> tu;
  std::vector<std::uint8_t> tb;
  std::vector<std::int32_t> ti;
  std::vector<Kind> tk;
  auto both = [&](auto& v, auto& tmp) {
    permute_range(v, fluid, 0, tmp);
    permute_range(v, walls, nf, tmp);
  };
  for (int d = 0; d < D; ++d) {
    both(ws_.x[d], td);
    both(ws_.v[d], td);
    both(wp_.x[d], td);
    both(wp_.v[d], td);
    both(wp_.x_ref[d], td);
    both(wp_.wall_normal[d], td);
    if (!normal_now_[d].empty()) both(normal_now_[d], td);
  }
  for (auto* v : {&ws_.rho, &ws_.p, &ws_.c, &ws_.e, &ws_.hs, &wp_.mass, &wp_.rho, &wp_.wall_depth}) both(*v, td);
  if (!wp_.rest_density.empty()) both(wp_.rest_density, td);
  if (!wp_.viscosity.empty()) both(wp_.viscosity, td);
  for (auto& s : ws_.strain) both(s, td);
  if (!h_ref_.empty()) both(h_ref_, td);
  if (!rho_ref_.empty()) both(rho_ref_, td);
  both(wp_.stationary, tb);
  both(wp_.body, ti);
  both(wp_.motion, ti);
  both(wp_.kind, tk);
  both(perm_, tu);
  for (std::size_t i = 0; i < nb; ++i) inv_[perm_[i]] = static_cast<std::uint32_t>(i);
}

template <int D>
const std::vector<double>& SphSystem<D>::state_order(const std::vector<double>& w, std::vector<double>& out) const {
  if (perm_.empty()) return w;
  out = w;
  for (std::size_t k = 0; k < perm_.size(); ++k) out[perm_[k]] = w[k];
  return out;
}

template class SphSystem<1>;
template class SphSystem<2>;
template class SphSystem<3>;

}  // namespace sphmol
