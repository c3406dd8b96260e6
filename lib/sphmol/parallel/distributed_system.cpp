#include "sphmol/parallel/distributed_system.hpp"

#include <mpi.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>

#include "sphmol/core/scene_share.hpp"
#include "sphmol/kernels/registry.hpp"
#include "sphmol/neighbors/neighbor_search.hpp"
#include "sphmol/neighbors/particle_reorder.hpp"
#include "sphmol/parallel/halo_particles.hpp"
#include "sphmol/parallel/migration.hpp"
#include "sphmol/parallel/particle_selection.hpp"
#include "sphmol/parallel/rcb_partition.hpp"
#include "sphmol/parallel/region_bounds.hpp"
#include "sphmol/rhs/assemble.hpp"

namespace sphmol::parallel {

namespace {

// One particle's state as it is gathered: a fluid particle's value in each block of the state (x,
// v, then density, energy and smoothing length when the scene has them), a wall's integrated
// density in the first entry.
template <int D>
inline constexpr std::size_t most_blocks = 2 * D + 3;

template <int D>
struct GatherRow {
  std::uint64_t gid;
  std::array<double, most_blocks<D>> value;
};

}  // namespace

template <int D>
DistributedSystem<D>::DistributedSystem(const Communicator& comm, const Config& config, const SphSystem<D>& whole,
                                        const std::vector<double>& y0, double t0, double imbalance_tolerance,
                                        double rebalance_threshold, const std::function<void()>& scene_read)
    : comm_(comm),
      config_(config),
      rcb_(std::make_unique<RcbPartitioner<D>>(comm, imbalance_tolerance)),
      rebalance_threshold_(rebalance_threshold),
      domain_(whole.domain()),
      whole_layout_(whole.whole_layout()),
      implicit_terms_(whole.implicit_terms()),
      cfl_(whole.cfl_limits()),
      monitors_(whole.monitors()) {
  if (whole.rhs_evaluations() > 0) throw std::logic_error("DistributedSystem: the whole system must not be evaluated yet");
  // Reordering: the local systems keep their particles in the serial workspace's order instead of
  // reordering a workspace of their own (the header), so they are assembled without it.
  reorder_ = whole.reorder();
  config_.discretization.reorder = false;
  // The most viscous liquid of the whole scene, whatever part of it `whole` holds (max is exact).
  cfl_.kinematic_viscosity = comm.max(cfl_.kinematic_viscosity);
  // Ghost (mirror) walls: every local system is assembled with the whole system's mirrors (the header).
  if (whole.has_generator()) {
    const auto* ghosts = dynamic_cast<const GhostGenerator<D>*>(whole.generator());
    if (!ghosts) throw std::invalid_argument("DistributedSystem: generated particles other than ghost walls are not supported");
    ghost_walls_ = ghosts->walls();
    ghost_planes_ = ghosts->planes();
  }
  // `whole` holds the whole scene or this rank's share of it (SphSystem::is_share): its particles are
  // the scene's [first, first + P.size()).
  const Particles<D>& P = whole.particles();
  const auto scene = whole.whole_scene();
  const std::size_t n = scene.size, first = scene.first;
  n_fluid_global_ = scene.fluid;
  scene_particles_built_ = P.size();
  variable_h_ = config.discretization.smoothing_length != "constant";
  support_ = kernel_info<D>(config.discretization.kernel).support;
  // The local systems are assembled with the scene's own spacing: h = smoothing_ratio * spacing and
  // the terms' length scales (particle shifting's W(dx)) are then the whole system's to the bit.
  const double h = whole.smoothing_length(), ratio = config.discretization.smoothing_ratio;
  spacing_ = whole.spacing();
  if (ratio * spacing_ != h) throw std::logic_error("DistributedSystem: the whole system's spacing does not give its smoothing length");
  // Halo depth: one list radius per dependent pair pass (the top of the header); a term that sums
  // over the stored pair list without a row form counts as a pass of its own.
  const std::size_t passes = (whole.pair_passes().empty() ? whole.fused_pass_count() : whole.pair_passes().size()) +
                             whole.terms_needing_stored_pairs().size();
  stats_.depth = static_cast<int>(std::max<std::size_t>(1, passes));
  range_ = stats_.depth * whole.pair_list().list_radius();
  skin_ = config.discretization.skin * h;

  const StateLayout<D>& Y = whole.layout();  // y0's
  if (y0.size() != Y.size()) throw std::invalid_argument("DistributedSystem: y0 is not a state of the scene's particles");
  // Each rank starts from an equal slice of the global ids (core/scene_share.hpp), which RCB cuts by
  // particle count.
  const SceneShare share{static_cast<std::size_t>(comm.rank()), static_cast<std::size_t>(comm.size())};
  const std::size_t lo = share.begin(n), hi = share.end(n);
  if (lo < first || hi > first + P.size() || (whole.is_share() && (lo != first || hi != first + P.size())))
    throw std::invalid_argument("DistributedSystem: the system holds particles [" + std::to_string(first) + ", " +
                                std::to_string(first + P.size()) + ") of the scene, not this rank's share [" +
                                std::to_string(lo) + ", " + std::to_string(hi) + ")");
  std::array<std::vector<double>, D> xw;
  for (int d = 0; d < D; ++d) {
    xw[d].resize(hi - lo);
    for (std::size_t i = lo; i < hi; ++i)
      xw[d][i - lo] = domain_.wrap(d, i < n_fluid_global_ ? y0[Y.position(d) + (i - first)] : P.wall_position(d, i - first, t0));
  }
  // The cut by count, of the slices.
  std::vector<std::uint64_t> slice(hi - lo);
  std::iota(slice.begin(), slice.end(), static_cast<std::uint64_t>(lo));
  std::array<const double*, D> xs;
  for (int d = 0; d < D; ++d) xs[d] = xw[d].data();
  std::vector<double> count(hi - lo, 1.0);
  const RcbResult<D> cut = rcb_->partition(xs, count.data(), slice.data(), slice.size());
  for (auto& c : xw) std::vector<double>().swap(c);
  // Every rank holds the whole scene (a case that builds it whole): each takes its own particles from
  // it by the cut's destinations, which every rank learns (4 bytes per particle), instead of receiving
  // their data from the slices' ranks; the same particles in migrate()'s order (ascending global id:
  // fluid first), so the same start as the migration's. A share (or one rank) takes its slice and
  // migrates it.
  const bool take_own = !whole.is_share() && comm.size() > 1;
  std::vector<std::uint32_t> rows;
  if (take_own) {
    const std::vector<int> destination = comm.all_gather_v(cut.destination);  // in global-id order
    for (std::size_t g = 0; g < destination.size(); ++g)
      if (destination[g] == comm.rank()) rows.push_back(static_cast<std::uint32_t>(g - first));
  } else {
    rows.resize(hi - lo);
    std::iota(rows.begin(), rows.end(), static_cast<std::uint32_t>(lo - first));
  }
  take_particles(whole, rows, first);
  // The owned part of the start state moves with the particles from here on, and neither the scene
  // nor y0 is read again: the caller may drop them now (scene_read), before the migration and the
  // searches of the partition by pair count.
  std::vector<double> y = local_part(y0, Y, first);
  if (scene_read) scene_read();
  if (!take_own) migrate_state(cut.destination, y, {});
  balance_by_pairs(t0, y);
  initial_state_ = std::move(y);
}

template <int D>
void DistributedSystem<D>::take_particles(const SphSystem<D>& whole, const std::vector<std::uint32_t>& rows, std::size_t first) {
  // Rows of `whole`, whose particles are the scene's [first, ...); fluid ids come before walls'.
  const Particles<D>& P = whole.particles();
  gid_.resize(rows.size());
  std::size_t fluid = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    gid_[k] = first + rows[k];
    fluid += gid_[k] < n_fluid_global_ ? 1 : 0;
  }
  owned_ = select_particles(P, rows, fluid);
  if (reorder_)
    for (auto& c : x_sorted_) c.assign(rows.size(), 0.0);
  // Walls keep the energy the scene gave them (the state holds the fluid's only), and with a variable
  // h every particle keeps its h(0) (the walls' h; with h from the density the fluid's reference):
  // per owned particle, moving with it (extras()), and sent with the halo (plan()).
  if (whole_layout_.has_energy) {
    const std::vector<double>& e = whole.energy();
    e_own_.resize(rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) e_own_[k] = e[rows[k]];
  }
  if (variable_h_) {
    const std::vector<double>& h0 = whole.smoothing_lengths();
    h0_own_.resize(rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) h0_own_[k] = h0[rows[k]];
  }
  set_layout();
}

template <int D>
void DistributedSystem<D>::migrate_state(const std::vector<int>& destination, std::vector<double>& y,
                                         std::vector<std::vector<double>*> more) {
  std::vector<std::vector<double>> columns;
  to_columns(y, state_blocks(), columns);
  std::vector<std::vector<double>*> extra;
  for (auto& c : columns) extra.push_back(&c);
  extra.insert(extra.end(), more.begin(), more.end());
  migrate(comm_, owned_, gid_, destination, extras(extra));
  set_layout();
  from_columns(columns, state_blocks(), y);
}

template <int D>
void DistributedSystem<D>::balance_by_pairs(double t0, std::vector<double>& y) {
  // Work per particle: its row of the neighbour list (support + skin) plus one, as imbalanced()
  // counts it, from a search over each rank's own particles and its halo at (t0, y) (the halo of the
  // count partition's plan, with the positions of the state): no rank searches the whole scene.
  // Then RCB cuts again by that work.
  const Stats before = stats_;
  owned_positions(t0, y.data());
  if (variable_h_) hmax_ = largest_h(y.data());
  if (ghost_walls_) margin_ = mirror_margin();
  plan();
  const std::size_t no = owned_.size();
  std::array<std::vector<double>, D> x;
  SearchInput<D> in;
  for (int d = 0; d < D; ++d) {
    x[d] = x_now_[d];
    const std::vector<double> xh = halo_->exchange(comm_, x_now_[d]);
    x[d].insert(x[d].end(), xh.begin(), xh.end());
    in.x[d] = x[d].data();
  }
  std::vector<Kind> kind = owned_.kind;
  const std::vector<Kind> kh = halo_->exchange(comm_, owned_.kind);
  kind.insert(kind.end(), kh.begin(), kh.end());
  in.kind = kind.data();
  in.n = kind.size();
  in.domain = &domain_;
  in.radius = range_ / stats_.depth;  // the list radius
  // The rows' lengths alone: the pairs themselves are not needed (NeighborSearch::row_lengths).
  const std::vector<std::uint32_t> rows = make_neighbor_search<D>(config_.discretization.neighbor_search)->row_lengths(in);
  weight_.resize(no);
  for (std::size_t o = 0; o < no; ++o) weight_[o] = 1.0 + rows[o];
  std::array<const double*, D> xs;
  for (int d = 0; d < D; ++d) xs[d] = x_now_[d].data();
  const RcbResult<D> cut = rcb_->partition(xs, weight_.data(), gid_.data(), gid_.size());
  migrate_state(cut.destination, y, {&weight_});
  local_.reset();
  halo_.reset();
  velocity_halo_.reset();
  stats_ = before;
  stats_.imbalance = stats_.imbalance_seen = load_imbalance(comm_, std::accumulate(weight_.begin(), weight_.end(), 0.0));
  plan_due_ = true;
  replanned_ = false;
}

template <int D>
DistributedSystem<D>::~DistributedSystem() = default;

template <int D>
std::vector<std::vector<double>*> DistributedSystem<D>::extras(std::vector<std::vector<double>*> arrays) {
  if (whole_layout_.has_energy) arrays.push_back(&e_own_);
  if (variable_h_) arrays.push_back(&h0_own_);
  if (reorder_)
    for (auto& c : x_sorted_) arrays.push_back(&c);
  return arrays;
}

template <int D>
void DistributedSystem<D>::set_layout() {
  nfo_ = owned_.n_fluid;
  layout_.n = nfo_;
  layout_.has_density = whole_layout_.has_density;
  layout_.has_energy = whole_layout_.has_energy;
  layout_.has_smoothing_length = whole_layout_.has_smoothing_length;
  layout_.n_wall_density = whole_layout_.n_wall_density > 0 ? owned_.n_wall() : 0;
  for (int d = 0; d < D; ++d) x_now_[d].resize(owned_.size());
}

template <int D>
bool DistributedSystem<D>::imbalanced() {
  if (!replanned_) return false;  // the same on every rank: plans are collective
  replanned_ = false;
  const PairList& rows = local_->pair_list().pairs();
  weight_.resize(owned_.size());
  for (std::size_t o = 0; o < owned_.size(); ++o) {
    const std::size_t k = owned_at_[o];
    weight_[o] = 1.0 + (rows.offset[k + 1] - rows.offset[k]);
  }
  stats_.imbalance_seen = load_imbalance(comm_, std::accumulate(weight_.begin(), weight_.end(), 0.0));
  return stats_.imbalance_seen > rebalance_threshold_;
}

template <int D>
void DistributedSystem<D>::to_columns(const std::vector<double>& array, std::size_t blocks,
                                      std::vector<std::vector<double>>& columns) const {
  const std::size_t no = owned_.size();
  // Arrays of the state's length hold the wall densities too, when the scene has them: a column on
  // every rank alike (migrate() moves the same arrays everywhere), whatever walls a rank owns.
  const bool walls = blocks > D && whole_layout_.n_wall_density > 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    columns.emplace_back(no, 0.0);
    for (std::size_t o = 0; o < nfo_; ++o) columns.back()[o] = array[b * nfo_ + o];
  }
  if (walls) {
    columns.emplace_back(no, 0.0);
    for (std::size_t o = nfo_; o < no; ++o) columns.back()[o] = array[layout_.wall_density() + (o - nfo_)];
  }
}

template <int D>
void DistributedSystem<D>::from_columns(const std::vector<std::vector<double>>& columns, std::size_t blocks,
                                        std::vector<double>& array) const {
  const std::size_t no = owned_.size();
  const bool walls = blocks > D && whole_layout_.n_wall_density > 0;
  array.assign(blocks * nfo_ + (walls ? layout_.n_wall_density : 0), 0.0);
  for (std::size_t b = 0; b < blocks; ++b)
    for (std::size_t o = 0; o < nfo_; ++o) array[b * nfo_ + o] = columns[b][o];
  if (walls)
    for (std::size_t o = nfo_; o < no; ++o) array[layout_.wall_density() + (o - nfo_)] = columns[blocks][o];
}

template <int D>
void DistributedSystem<D>::repartition(double t, std::vector<double>& y, const std::vector<std::vector<double>*>& state,
                                       const std::vector<std::vector<double>*>& positions) {
  owned_positions(t, y.data());
  std::array<const double*, D> xs;
  for (int d = 0; d < D; ++d) xs[d] = x_now_[d].data();
  const RcbResult<D> cut = rcb_->partition(xs, weight_.data(), gid_.data(), gid_.size());
  // The vectors of the integrators that wrap y (wrap_state) and their clones move as y does
  // (vector_family.hpp): SUNDIALS' integrators find their history in the new share.
  std::vector<std::shared_ptr<VectorFamily>> families;
  for (const auto& f : families_)
    if (auto live = f.lock()) families.push_back(std::move(live));
  FamilyMove vectors(families, y.data(), y.size());
  std::vector<std::vector<double>*> moving = state;
  for (auto* a : vectors.arrays()) moving.push_back(a);
  // migrate() moves the same columns on every rank.
  const auto count = static_cast<double>(moving.size());
  if (comm_.min(count) != comm_.max(count))
    throw std::logic_error("DistributedSystem::repartition: the ranks move different numbers of arrays");
  // Every array as per-particle columns, which migrate() moves with the particles.
  const std::size_t state_blocks = this->state_blocks();
  std::vector<std::vector<double>> columns;
  std::vector<const std::vector<double>*> arrays{&y};
  for (const auto* a : moving) arrays.push_back(a);
  for (const auto* a : arrays) {
    if (a->size() != layout_.size()) throw std::invalid_argument("DistributedSystem::repartition: an array is not of the state's length");
    to_columns(*a, state_blocks, columns);
  }
  for (const auto* a : positions) {
    if (a->size() != D * nfo_) throw std::invalid_argument("DistributedSystem::repartition: an array is not of the positions' length");
    to_columns(*a, D, columns);
  }
  std::vector<std::vector<double>*> extra;
  for (auto& c : columns) extra.push_back(&c);
  extra.push_back(&weight_);
  const bool walls = whole_layout_.n_wall_density > 0;
  migrate(comm_, owned_, gid_, cut.destination, extras(extra));
  set_layout();
  // Back from columns, in the order they were made.
  std::size_t at = 0;
  const std::size_t per_state = state_blocks + (walls ? 1 : 0);
  const auto take = [&](std::size_t count) {
    std::vector<std::vector<double>> c(columns.begin() + static_cast<long>(at), columns.begin() + static_cast<long>(at + count));
    at += count;
    return c;
  };
  from_columns(take(per_state), state_blocks, y);
  for (auto* a : moving) from_columns(take(per_state), state_blocks, *a);
  for (auto* a : positions) from_columns(take(D), D, *a);
  vectors.finish(y.data(), y.size());
  stats_.imbalance = load_imbalance(comm_, std::accumulate(weight_.begin(), weight_.end(), 0.0));
  ++stats_.repartitions;
  plan_due_ = true;
}

template <int D>
void DistributedSystem<D>::owned_positions(double t, const double* y) {
  const std::size_t no = owned_.size();
  for (int d = 0; d < D; ++d) {
    double* x = x_now_[d].data();
    const double* yx = y + layout_.position(d);
    for (std::size_t o = 0; o < nfo_; ++o) x[o] = domain_.wrap(d, yx[o]);
    for (std::size_t o = nfo_; o < no; ++o) x[o] = domain_.wrap(d, owned_.wall_position(d, o, t));
  }
}

template <int D>
double DistributedSystem<D>::largest_h(const double* y) {
  // As the serial evaluation sets h: from the state, or from the density (Niedoba 2012, eq 2.67);
  // walls keep h(0).
  const StateLayout<D>& L = layout_;
  double hmax = 0.0, hmax_fluid = 0.0;
  for (std::size_t o = 0; o < owned_.size(); ++o) {
    double h = h0_own_[o];
    if (o < nfo_ && L.has_smoothing_length) h = y[L.smoothing_length() + o];
    else if (o < nfo_) h *= std::pow(owned_.rho[o] / y[L.density() + o], 1.0 / D);
    hmax = std::max(hmax, h);
    if (o < nfo_) hmax_fluid = std::max(hmax_fluid, h);
  }
  // The serial ghost generator makes images within kappa times the fluid's largest h (and the
  // scene's h): every rank's local generator gets the largest over all ranks.
  if (ghost_walls_) hmax_fluid_ = comm_.max(hmax_fluid);
  return comm_.max(hmax);
}

template <int D>
double DistributedSystem<D>::mirror_margin() const {
  // A fluid particle p behind a mirror (a wall it has crossed) is nearer to the images of the
  // particles in front than to those particles: along each mirror normal of an image the two
  // distances differ by at most 2 p, so an image within the support comes from a source within the
  // support plus 2 D times the deepest crossing. Particles in front of every mirror: 0.
  double behind = 0.0;
  const auto crossed = [&](const GhostPlane<D>& m, std::size_t o) {
    double s = -m.offset;
    for (int d = 0; d < D; ++d) s += m.normal[d] * x_now_[d][o];
    behind = std::max(behind, -s);
  };
  for (std::size_t o = 0; o < nfo_; ++o) {
    for (int d = 0; d < D; ++d)
      for (int side = 0; side < 2; ++side)
        if ((*ghost_walls_)[d][side].present) crossed(face_plane(d, side, (*ghost_walls_)[d][side]), o);
    for (const auto& m : ghost_planes_) crossed(m, o);
  }
  return 2.0 * D * comm_.max(behind);
}

template <int D>
bool DistributedSystem<D>::serial_list_stale() {
  // The serial Verlet list's test (neighbors/verlet_list.hpp) on the whole scene, with the same
  // operations: its support (the largest h over all ranks with a variable h), the room its growth
  // since the rebuild leaves in the skin, and every particle's displacement since the rebuild,
  // reduced over the ranks. The positions are owned_positions()', those of the serial workspace.
  const double support = variable_h_ ? support_ * hmax_ : support_ * (config_.discretization.smoothing_ratio * spacing_);
  bool stale = !sorted_once_;
  if (!stale) {
    const double room = skin_ - std::max(0.0, support - sorted_support_);
    if (room <= 0.0) {
      stale = true;
    } else {
      const double limit2 = 0.25 * room * room;
      bool far = false;
      for (std::size_t o = 0; o < owned_.size(); ++o) {
        double r2 = 0.0;
        for (int d = 0; d < D; ++d) {
          const double dx = domain_.min_image(d, x_now_[d][o] - x_sorted_[d][o]);
          r2 += dx * dx;
        }
        far |= r2 > limit2;
      }
      stale = !comm_.all(!far);
    }
  }
  if (!stale) return false;
  x_sorted_ = x_now_;
  sorted_support_ = support;
  sorted_cell_ = 0.5 * (support + skin_);  // SphSystem: half the list radius
  sorted_once_ = true;
  ++stats_.serial_sorts;
  return true;
}

template <int D>
bool DistributedSystem<D>::moved_too_far(double t, const double* y) const {
  // A support grown since the plan eats into the skin (the Verlet list's rule, neighbors/verlet_list.hpp);
  // hmax_ is the same on every rank, so this decision is too. The ghost margin's growth does not:
  // a mirror image moves exactly as far as its source (a reflection is an isometry), so a pair of a
  // row and an image within the support now was within the support plus the skin at the plan, and
  // its source within that plus the margin of the plan's positions (mirror_margin()).
  const double room = skin_ - std::max(0.0, support_ * (hmax_ - hmax_plan_));
  if (!(room > 0.0)) return true;
  const double limit2 = 0.25 * room * room;
  // From y without storing the positions (the test runs at every evaluation, a plan rarely). The
  // fluid's loop in the neighbour list's arithmetic (VerletList::check_in_team): the minimum image
  // of the displacement from the state's position needs no wrap first; the box's constants in
  // locals and the test ORed into an integer, without an exit per particle, so that it vectorises.
  std::array<double, D> period, inv_period;
  std::array<const double*, D> xs, x0;
  for (int d = 0; d < D; ++d) {
    period[d] = domain_.period(d);
    inv_period[d] = domain_.inv_period(d);
    xs[d] = y + layout_.position(d);
    x0[d] = x_plan_[d].data();
  }
  std::int64_t far = 0;
  for (std::size_t o = 0; o < nfo_; ++o) {
    double r2 = 0.0;
    for (int d = 0; d < D; ++d) {
      const double dx = xs[d][o] - x0[d][o];
      const double m = dx - period[d] * std::nearbyint(dx * inv_period[d]);
      r2 += m * m;
    }
    far |= static_cast<std::int64_t>(r2 > limit2);
  }
  for (std::size_t o = nfo_; o < owned_.size(); ++o) {
    double r2 = 0.0;
    for (int d = 0; d < D; ++d) {
      const double dx = domain_.min_image(d, domain_.wrap(d, owned_.wall_position(d, o, t)) - x_plan_[d][o]);
      r2 += dx * dx;
    }
    far |= static_cast<std::int64_t>(r2 > limit2);
  }
  return !comm_.all(far == 0);
}

template <int D>
void DistributedSystem<D>::plan() {
  const std::size_t no = owned_.size();
  std::array<const double*, D> xs;
  for (int d = 0; d < D; ++d) xs[d] = x_now_[d].data();
  // Variable h: P list radii of the largest h now (the local systems' pair lists follow their own largest h).
  hmax_plan_ = hmax_;
  margin_plan_ = margin_;
  const double range = (variable_h_ ? stats_.depth * (support_ * hmax_plan_ + skin_) : range_) + stats_.depth * margin_plan_;
  // A new plan object: operators recorded with the old one keep it (velocity_halo.hpp).
  auto halo = std::make_shared<Halo<D>>();
  halo->plan(comm_, domain_, gather_owned_bounds<D>(comm_, xs, no), xs, no, range);
  halo_ = halo;
  velocity_halo_ = std::make_shared<const VelocityHalo<D>>(comm_, halo_, n_fluid_global_, static_cast<std::uint64_t>(stats_.repartitions));
  const std::vector<std::uint64_t> hgid = halo_->exchange(comm_, gid_);
  Particles<D> all = owned_;
  append_particles(all, exchange_halo_particles(comm_, *halo_, owned_));
  // The local set in global-id order: the serial order of these particles, fluid first.
  const std::size_t nh = hgid.size();
  const auto gid_of = [&](std::uint32_t k) { return k < no ? gid_[k] : hgid[k - no]; };
  std::vector<std::uint32_t> order(no + nh);
  std::iota(order.begin(), order.end(), 0u);
  if (reorder_ && sorted_once_) {
    // The serial workspace's order (SphSystem::reorder_workspace): fluid first, each part by the
    // Morton code of the positions at the serial list's latest rebuild, on the serial grid, and
    // within a cell by global id (the serial state index).
    std::array<std::vector<double>, D> xs_all;
    std::array<const double*, D> xk;
    for (int d = 0; d < D; ++d) {
      xs_all[d] = x_sorted_[d];
      const std::vector<double> xh = halo_->exchange(comm_, x_sorted_[d]);
      xs_all[d].insert(xs_all[d].end(), xh.begin(), xh.end());
      xk[d] = xs_all[d].data();
    }
    const MortonGrid<D> grid(domain_, sorted_cell_);
    std::vector<std::uint64_t> code(no + nh);
    for (std::size_t k = 0; k < no + nh; ++k) code[k] = grid.code(xk, k);
    const auto key = [&](std::uint32_t k) { return std::make_tuple(gid_of(k) >= n_fluid_global_, code[k], gid_of(k)); };
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
  } else {
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return gid_of(a) < gid_of(b); });
  }
  nf_local_ = static_cast<std::size_t>(std::count_if(order.begin(), order.end(), [&](std::uint32_t k) { return gid_of(k) < n_fluid_global_; }));
  owned_at_.resize(no);
  halo_at_.resize(nh);
  for (std::size_t k = 0; k < order.size(); ++k)
    (order[k] < no ? owned_at_[order[k]] : halo_at_[order[k] - no]) = static_cast<std::uint32_t>(k);
  local_gid_.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) local_gid_[k] = gid_of(order[k]);
  // The viscous operator's rows and columns of the local fluid particles: owned fluid o is row and
  // column o, halo particle q column nfo + q (velocity_halo.hpp).
  local_row_.assign(nf_local_, ViscousOperator::kNoRow);
  local_column_.assign(nf_local_, ViscousOperator::kNoRow);
  for (std::size_t o = 0; o < nfo_; ++o) local_row_[owned_at_[o]] = local_column_[owned_at_[o]] = static_cast<std::uint32_t>(o);
  for (std::size_t q = 0; q < nh; ++q)
    if (halo_at_[q] < nf_local_) local_column_[halo_at_[q]] = static_cast<std::uint32_t>(nfo_ + q);
  if (local_) {  // the counters of the system it replaces
    stats_.search_seconds += local_->search_seconds();
    stats_.rebuilds += local_->pair_list().rebuilds();
  }
  // Per local row: a value of the owned particles or of the halo's copies (exchanged with them).
  const auto local_values = [&](const std::vector<double>& own) {
    const std::vector<double> halo_values = halo_->exchange(comm_, own);
    std::vector<double> v(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) v[k] = order[k] < no ? own[order[k]] : halo_values[order[k] - no];
    return v;
  };
  std::vector<double> energy;
  if (whole_layout_.has_energy) {
    // The fluid's e comes from the state at every evaluation; the walls keep theirs.
    energy = local_values(e_own_);
    std::fill(energy.begin(), energy.begin() + static_cast<long>(nf_local_), 0.0);
  }
  local_ = assemble_system<D>(config_, select_particles(all, order, nf_local_), domain_, spacing_,
                              ghost_walls_ ? &*ghost_walls_ : nullptr, std::move(energy), ghost_planes_);
  // Fluid taken out of the run arrives as Kind::Out (the owners' kind), which the new local system
  // starts with retired (SphSystem's constructor): no pair, zero rates.
  if (variable_h_) local_->set_initial_smoothing_lengths(local_values(h0_own_));
  // Its pair list is built at this plan's positions, and moved_too_far() plans again (with a new
  // local system) once any particle of any rank, halo particles' owners included, has moved half the
  // skin since: the list's own test could never be the first to find it stale. With a variable h
  // the local support follows the local largest h, which the plan's test does not watch, and
  // generated images (ghost walls) rebuild the list anyway: there the list keeps its test.
  if (!variable_h_ && !ghost_walls_) local_->keep_pair_list_until_replaced();
  if (!monitors_.empty()) {
    // The monitors watch the owned fluid rows, by global id (the halo's are their owners' to watch).
    WatchedRows rows;
    rows.id.resize(nf_local_);
    rows.owned.resize(nf_local_);
    rows.start.resize(D * nf_local_);
    for (std::size_t k = 0; k < nf_local_; ++k) {
      rows.id[k] = gid_of(order[k]);
      rows.owned[k] = order[k] < no ? 1 : 0;
      // The particles' positions as the scene built them (owned_.x, moved with them; the state
      // holds where they are now).
      for (int d = 0; d < D; ++d) rows.start[D * k + static_cast<std::size_t>(d)] = all.x[d][order[k]];
    }
    rows.watching = watching_;
    for (const auto& m : monitors_) local_->append_term(m->watch(rows));
  }
  // The local system reads the owned rows from the rank's state and the halo rows from the
  // exchange's buffer, and writes the owned rows' rates alone (rhs/split_state.hpp): halo particle
  // q is row q of the buffer, an owned wall's density row its index among the owned walls.
  SplitState<D> split;
  split.owned = layout_;
  split.width = state_blocks();
  const std::size_t nwl = local_->layout().n_wall_density, nwo = layout_.n_wall_density;
  split.fluid_source.resize(nf_local_);
  split.wall_source.resize(nwl);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::uint32_t j = order[k];
    const std::size_t source = j < no ? (k < nf_local_ ? j : j - nfo_) : (k < nf_local_ ? nfo_ : nwo) + (j - no);
    if (k < nf_local_) split.fluid_source[k] = static_cast<std::uint32_t>(source);
    else if (k - nf_local_ < nwl) split.wall_source[k - nf_local_] = static_cast<std::uint32_t>(source);
  }
  split.fluid_rate_row.assign(owned_at_.begin(), owned_at_.begin() + static_cast<long>(nfo_));
  split.wall_rate_row.resize(nwo);
  for (std::size_t w = 0; w < nwo; ++w) split.wall_rate_row[w] = static_cast<std::uint32_t>(owned_at_[nfo_ + w] - nf_local_);
  local_->set_split_state(std::move(split));
  y_local_.clear();  // made by refresh_local() only
  x_plan_ = x_now_;
  replanned_ = true;
  plan_due_ = false;
  ++stats_.plans;
  stats_.halo = nh;
  stats_.halo_max = std::max(stats_.halo_max, nh);
}

template <int D>
void DistributedSystem<D>::take_out(const std::vector<std::size_t>& gone, double* y) {
  const auto leaving = [&](std::uint64_t id) { return std::binary_search(gone.begin(), gone.end(), static_cast<std::size_t>(id)); };
  // The serial system rebuilds its list (and sorts its workspace) at the next evaluation after
  // fluid has left (SphSystem::retire).
  if (!gone.empty()) sorted_once_ = false;
  for (std::size_t o = 0; o < nfo_; ++o)
    if (leaving(gid_[o])) {
      owned_.kind[o] = Kind::Out;
      for (int d = 0; d < D; ++d) y[layout_.velocity(d) + o] = 0.0;
    }
  if (!local_) return;
  std::vector<std::size_t> rows;
  for (std::size_t k = 0; k < nf_local_; ++k)
    if (leaving(local_gid_[k])) rows.push_back(k);
  local_->retire(rows);
}

template <int D>
void DistributedSystem<D>::exchange_into_local(const double* y) {
  // The halo rows as an evaluation receives them, then the owned and halo state into one local
  // state (output times only: an evaluation reads both where they are).
  exchange_halo(y);
  const std::size_t no = owned_.size(), width = state_blocks();
  const StateLayout<D>& L = layout_;
  const StateLayout<D>& LL = local_->layout();
  y_local_.resize(local_->size());
  for (std::size_t b = 0; b < width; ++b)
    for (std::size_t o = 0; o < nfo_; ++o) y_local_[b * nf_local_ + owned_at_[o]] = y[b * nfo_ + o];
  if (L.n_wall_density > 0 && LL.n_wall_density > 0)
    for (std::size_t o = nfo_; o < no; ++o) y_local_[LL.wall_density() + (owned_at_[o] - nf_local_)] = y[L.wall_density() + (o - nfo_)];
  for (std::size_t q = 0; q < halo_->size(); ++q) {
    const std::size_t k = halo_at_[q];
    const double* r = halo_rows_.data() + q * width;
    if (k < nf_local_) {
      for (std::size_t b = 0; b < width; ++b) y_local_[b * nf_local_ + k] = r[b];
    } else if (LL.n_wall_density > 0) {
      y_local_[LL.wall_density() + (k - nf_local_)] = r[0];
    }
  }
}

template <int D>
void DistributedSystem<D>::exchange_halo(const double* y) {
  // The owned state to the ranks whose halo holds it, as rows (exchange_into_local's rows), into
  // halo_rows_, which the local system reads in place (rhs_split).
  const std::size_t width = state_blocks();
  const StateLayout<D>& L = layout_;
  const bool wall_density = L.n_wall_density > 0;
  const auto pack = [&](std::uint32_t o, double* row) {
    if (o < nfo_) {
      for (std::size_t b = 0; b < width; ++b) row[b] = y[b * nfo_ + o];
    } else {
      std::fill(row, row + width, 0.0);
      if (wall_density) row[0] = y[L.wall_density() + (o - nfo_)];
    }
  };
  halo_rows_.resize(halo_->size() * width);
  halo_->exchange_rows(comm_, width, pack, halo_rows_.data(), [] {});
}

template <int D>
void DistributedSystem<D>::prepare_local(double t, const double* y) {
  // The owned positions are stored when something reads them: the ghost margin or a plan.
  const bool due = stats_.plans == 0 || plan_due_;  // the same on every rank
  bool stored = false;
  if (ghost_walls_ || due) {
    owned_positions(t, y);
    stored = true;
  }
  if (variable_h_) hmax_ = largest_h(y);
  if (ghost_walls_) {
    margin_ = mirror_margin();
    stats_.mirror_margin_max = std::max(stats_.mirror_margin_max, margin_);
  }
  // Reordering: where the serial run rebuilds its list and sorts its workspace, the local system is
  // made again in the new order. Not at an evaluation the serial run does not make (an integrator
  // starting again on a new share): the serial list is not tested there.
  bool sorted = false;
  if (reorder_ && *watching_) {
    if (!stored) owned_positions(t, y);
    stored = true;
    sorted = serial_list_stale();
  }
  if (due || sorted || moved_too_far(t, y)) {
    if (!stored) owned_positions(t, y);
    plan();
  }
  if (variable_h_ && ghost_walls_)
    if (auto* g = dynamic_cast<GhostGenerator<D>*>(local_->generator())) g->set_reach_h(hmax_fluid_);
}

template <int D>
void DistributedSystem<D>::refresh_local(double t, const double* y) {
  // As an evaluation prepares the local system (a halo plan when one is due), then its fields as
  // SphSystem::refresh_fields sets them: no evaluation is counted and the step limit stays.
  prepare_local(t, y);
  exchange_into_local(y);
  std::vector<double> scratch;
  local_->refresh_fields(t, y_local_.data(), scratch);
}

template <int D>
void DistributedSystem<D>::rhs(double t, const double* y, double* ydot) {
  evaluate(t, y, ydot, nullptr);
}

template <int D>
void DistributedSystem<D>::rhs_explicit(double t, const double* y, double* fe, ViscousOperator& op) {
  evaluate(t, y, fe, &op);
}

template <int D>
void DistributedSystem<D>::evaluate(double t, const double* y, double* ydot, ViscousOperator* op) {
  ++rhs_evals_;
  const double t_start = omp_get_wtime();
  prepare_local(t, y);
  const double t_planned = omp_get_wtime();
  exchange_halo(y);
  stats_.exchange_seconds += omp_get_wtime() - t_planned;

  // The local system reads the owned rows from y and the halo rows from the exchange's buffer, and
  // writes the owned rows' rates into ydot with their CFL extremes (SphSystem::rhs_split).
  if (op) {
    local_->rhs_explicit_split(t, y, halo_rows_.data(), ydot, local_op_);
    op->owned_rows(local_op_, local_row_, local_column_, nfo_, velocity_halo_);
  } else {
    local_->rhs_split(t, y, halo_rows_.data(), ydot);
  }

  // The CFL extremes reduced over ranks: one reduction for the three, max |a|^2 as the minimum of
  // its negative (min and max are exact).
  const double t_reduce = omp_get_wtime();
  const auto& e = local_->cfl_extremes();
  const double mine[3] = {e.acoustic, -e.amax2, e.hmin};
  double all[3];
  MPI_Allreduce(mine, all, 3, MPI_DOUBLE, MPI_MIN, comm_.handle());
  // As SphSystem: no viscous limit for the explicit part of an IMEX split.
  const CflLimits& cfl = cfl_;
  stable_step_ = cfl_step(cfl, all[0], -all[1], all[2], op == nullptr);
  widest_step_ = cfl_step(cfl.widest(), all[0], -all[1], all[2], op == nullptr);
  if (rhs_evals_ == 1) first_stable_step_ = stable_step_;
  const double t_end = omp_get_wtime();
  stats_.exchange_seconds += t_end - t_reduce;
  stats_.rhs_seconds += t_end - t_start;
  stats_.search_seconds += t_planned - t_start;  // the displacement test and the plan
}

template <int D>
void DistributedSystem<D>::minimum_everywhere(double* values, std::size_t count) const {
  MPI_Allreduce(MPI_IN_PLACE, values, static_cast<int>(count), MPI_DOUBLE, MPI_MIN, comm_.handle());
}

template <int D>
N_Vector DistributedSystem<D>::wrap_state(double* data, std::size_t length, SUNContext ctx) const {
  if (length != layout_.size()) throw std::invalid_argument("DistributedSystem::wrap_state: not this rank's state length");
  std::uint64_t mine = length, whole = 0;
  MPI_Allreduce(&mine, &whole, 1, MPI_UINT64_T, MPI_SUM, comm_.handle());
  N_Vector v = make_fixed_point_norm_vector(comm_.handle(), data, length, static_cast<std::size_t>(whole), ctx);
  // repartition() moves it and its clones; families whose vectors are all destroyed are forgotten.
  families_.erase(std::remove_if(families_.begin(), families_.end(), [](const auto& f) { return f.expired(); }), families_.end());
  families_.push_back(family_of(v));
  return v;
}

template <int D>
typename DistributedSystem<D>::Stats DistributedSystem<D>::stats() const {
  Stats s = stats_;
  if (local_) {
    s.search_seconds += local_->search_seconds();
    s.rebuilds += local_->pair_list().rebuilds();
  }
  return s;
}

template <int D>
std::pair<std::uint64_t, std::uint64_t> DistributedSystem<D>::pair_work() const {
  if (!local_) return {0, 0};
  const PairList& rows = local_->pair_list().pairs();
  std::uint64_t owned = 0;
  for (const std::uint32_t k : owned_at_) owned += rows.offset[k + 1] - rows.offset[k];
  return {owned, rows.pairs() - owned};
}

template <int D>
double DistributedSystem<D>::owned_density(std::size_t o) const {
  return local_ ? local_->density()[owned_at_[o]] : owned_.rho[o];
}

template <int D>
std::vector<double> DistributedSystem<D>::local_part(const std::vector<double>& whole) const {
  return local_part(whole, whole_layout_, 0);
}

template <int D>
std::vector<double> DistributedSystem<D>::local_part(const std::vector<double>& source, const StateLayout<D>& W,
                                                     std::size_t first) const {
  if (source.size() != W.size()) throw std::invalid_argument("DistributedSystem::local_part: not a state of that layout");
  const StateLayout<D>& L = layout_;
  const std::size_t blocks = state_blocks();
  std::vector<double> y(L.size());
  // Fluid id g is the source's fluid row g - first; wall id g its wall (g - first) - W.n.
  for (std::size_t o = 0; o < nfo_; ++o)
    for (std::size_t b = 0; b < blocks; ++b) y[b * nfo_ + o] = source[b * W.n + (gid_[o] - first)];
  if (L.n_wall_density > 0)
    for (std::size_t o = nfo_; o < owned_.size(); ++o)
      y[L.wall_density() + (o - nfo_)] = source[W.wall_density() + (gid_[o] - first - W.n)];
  return y;
}

template <int D>
bool DistributedSystem<D>::gather(const double* y, std::vector<double>& whole) const {
  const StateLayout<D>& L = layout_;
  const StateLayout<D>& W = whole_layout_;
  const std::size_t blocks = state_blocks();
  std::vector<GatherRow<D>> mine(owned_.size());
  if (blocks > most_blocks<D>) throw std::logic_error("DistributedSystem::gather: more state blocks than a row holds");
  for (std::size_t o = 0; o < owned_.size(); ++o) {
    mine[o].gid = gid_[o];
    mine[o].value.fill(0.0);
    if (o < nfo_)
      for (std::size_t b = 0; b < blocks; ++b) mine[o].value[b] = y[b * nfo_ + o];
    else if (L.n_wall_density > 0)
      mine[o].value[0] = y[L.wall_density() + (o - nfo_)];
  }
  const std::vector<GatherRow<D>> rows = comm_.gather_v(mine);
  if (comm_.rank() != 0) return false;
  whole.assign(W.size(), 0.0);
  for (const auto& r : rows) {
    if (r.gid < W.n)
      for (std::size_t b = 0; b < blocks; ++b) whole[b * W.n + r.gid] = r.value[b];
    else if (W.n_wall_density > 0)
      whole[W.wall_density() + (r.gid - W.n)] = r.value[0];
  }
  return true;
}

template class DistributedSystem<1>;
template class DistributedSystem<2>;
template class DistributedSystem<3>;

}  // namespace sphmol::parallel
