#include "sphmol/parallel/mpi_run.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "sphmol/boundary/ghost_particles.hpp"
#include "sphmol/parallel/communicator_reduction.hpp"
#include "sphmol/parallel/distributed_health_check.hpp"
#include "sphmol/parallel/distributed_system.hpp"
#include "sphmol/parallel/piece_collectives.hpp"
#include "sphmol/parallel/whole_fields.hpp"
#include "sphmol/io/double_codec.hpp"

namespace sphmol::parallel {

namespace {

// Integrator checkpoint arrays of the positions' length (D values per fluid particle): the leapfrogs'
// position correction c, and leapfrog_imex's previous velocities and its f_I = L v + b.
constexpr const char* kPositionLength[] = {"c", "v_previous", "f_implicit"};

template <int D>
class MpiRun final : public PartitionedRun<D> {
 public:
  MpiRun(const Communicator& comm, const Config& config, const SphSystem<D>& whole, const std::vector<double>& y0,
         double t0, double tolerance, double rebalance_threshold, const std::function<void()>& scene_read)
      : comm_(comm),
        sys_(comm, config, whole, y0, t0, tolerance, rebalance_threshold, scene_read),
        y_(sys_.take_initial_state()),
        t0_(t0),
        whole_(&whole), whole_terms_(whole.active_terms()) {}

  OdeSystem& system() override { return sys_; }
  std::vector<double>& state() override { return y_; }
  void gather(std::vector<double>& whole) override {
    ++whole_state_gathers_;
    sys_.gather(y_.data(), whole);
  }
  double elastic_energy(const HealthLimits::Elastic& elastic) override {
    return DistributedHealthCheck<D>::elastic_energy(comm_, sys_, elastic);
  }
  int check(double t, double, int signal) override {
    if (!health_) throw std::logic_error("MpiRun::check before start_health_check");
    return (*health_)(t, y_.data(), signal);
  }
  const std::vector<std::size_t>& leavers() const override {
    static const std::vector<std::size_t> none;
    return health_ ? health_->leavers() : none;
  }
  const std::vector<double>& leaver_masses() const override {
    static const std::vector<double> none;
    return health_ ? health_->leaver_masses() : none;
  }
  void take_out(const std::vector<std::size_t>& gone) override { sys_.take_out(gone, y_.data()); }
  void start_health_check(double t0, const HealthLimits& limits) override { health_.emplace(comm_, sys_, y_, t0, limits); }
  void gather_last_good(std::vector<double>& whole) override {
    if (health_) sys_.gather(health_->last_good_state().data(), whole);
  }
  int largest_signal(int signal) override { return comm_.max(signal); }
  void whole_fields(double t, SphSystem<D>& whole) override {
    ++whole_field_gathers_;
    refresh(t);
    gather_whole_fields(comm_, sys_, comm_.rank() == 0 ? &whole : nullptr);
  }
  OwnedPiece<D> owned_piece(double t) override {
    ++owned_pieces_;
    refresh(t);
    OwnedPiece<D> p;
    p.system = &sys_.local_system();
    p.y = sys_.local_state().data();
    // Owned fluid comes first among the owned particles; the local rows are in global-id order, so
    // sorting the rows sorts the ids too.
    const auto& rows = sys_.owned_rows();
    const auto& gid = sys_.gid();
    const std::size_t nfo = sys_.owned().n_fluid;
    std::vector<std::pair<std::size_t, std::int64_t>> fluid, walls;
    for (std::size_t o = 0; o < rows.size(); ++o) (o < nfo ? fluid : walls).emplace_back(rows[o], static_cast<std::int64_t>(gid[o]));
    std::sort(fluid.begin(), fluid.end());
    std::sort(walls.begin(), walls.end());
    for (const auto& [row, id] : fluid) {
      p.fluid_rows.push_back(row);
      p.fluid_ids.push_back(id);
    }
    for (const auto& [row, id] : walls) {
      p.wall_rows.push_back(row);
      p.wall_ids.push_back(id);
    }
    // Ghost walls: the images of owned sources (the generator's sources are local fluid rows).
    if (const auto* ghosts = dynamic_cast<const GhostGenerator<D>*>(p.system->generator())) {
      std::vector<bool> owned_fluid(p.system->particles().n_fluid, false);
      for (const std::size_t row : p.fluid_rows) owned_fluid[row] = true;
      const auto& sources = ghosts->sources();
      for (std::size_t g = 0; g < sources.size(); ++g)
        if (sources[g] < owned_fluid.size() && owned_fluid[sources[g]]) p.ghost_rows.push_back(ghosts->base() + g);
    }
    p.row_ids.assign(sys_.local_gid().begin(), sys_.local_gid().end());
    static_cast<PieceCollectives&>(p) = piece_collectives(comm_);
    return p;
  }
  void barrier() override { comm_.barrier(); }
  void combine_monitors() override {
    const CommunicatorReduction ranks(comm_);
    for (const auto& m : sys_.monitors()) m->combine(ranks);
  }
  void rebalance(Integrator& integrator, double t) override {
    if (!sys_.imbalanced()) return;
    // The leapfrogs carry, beyond y, their last evaluation f (the state's length) and the XSPH
    // correction c (the positions' length), leapfrog_imex also its previous velocities and
    // f_I = L v + b of the operator recorded at the step's own (predicted) state (both of the
    // positions' length): all travel through the integrator's checkpoint state, which is restored
    // after the integrator is started on the new share (its first evaluation there, and the operator
    // recorded by it, are replaced by the restored arrays: the steps go on bit for bit).
    nlohmann::json js = integrator.save_state();
    // ARKODE and CVODE keep their step history (error controller, Adams history, interpolation
    // history) inside SUNDIALS, in vectors cloned from the state vector: the repartition moves them
    // all with the particles (vector_family.hpp), and the integrator goes on with them
    // (Integrator::resize); starting it again on the new share would change the steps from the
    // serial run's. arkode_imex records its frozen viscous operator again on the new share, at the
    // state where the serial run recorded it: an evaluation the serial run does not make, which the
    // case's monitors do not watch. (ERKStep also resizes its vectors itself.)
    if (!js.contains("f")) {
      if (!integrator.can_resize())
        throw std::logic_error("MpiRun::rebalance: integrator '" + integrator.name() + "' cannot move with the particles");
      sys_.repartition(t, y_, {}, {});
      sys_.watch_evaluations(false);
      integrator.resize(sys_, t, y_.data());
      sys_.watch_evaluations(true);
      if (health_) health_->moved(y_);
      return;
    }
    std::vector<double> f = decode_doubles(js.at("f").get<std::string>());
    std::vector<std::vector<double>> carried;
    std::vector<const char*> carried_keys;
    for (const char* key : kPositionLength)
      if (js.contains(key)) {
        carried.push_back(decode_doubles(js.at(key).get<std::string>()));
        carried_keys.push_back(key);
      }
    std::vector<std::vector<double>*> positions;
    for (auto& a : carried) positions.push_back(&a);
    sys_.repartition(t, y_, {&f}, positions);
    js["f"] = encode_doubles(f);
    for (std::size_t i = 0; i < carried.size(); ++i) js[carried_keys[i]] = encode_doubles(carried[i]);
    // That start evaluates the state the step ended in, which the serial drift-kick-drift leapfrog
    // never evaluates: the case's monitors do not watch it.
    sys_.watch_evaluations(false);
    integrator.initialize(sys_, t, y_.data());
    sys_.watch_evaluations(true);
    integrator.restore_state(js);
    if (health_) health_->moved(y_);  // the last good state, which y_ is (between steps), in the new share
  }
  // The leapfrogs' per-particle arrays: f of the state's length, and those of kPositionLength (carried
  // in the position blocks of a state-length array).
  nlohmann::json whole_integrator_state(const nlohmann::json& state) override {
    nlohmann::json js = state;
    if (!js.contains("f")) return js;  // ARKODE, CVODE: no per-particle arrays (a step size, counters)
    // Gathered on the root, which writes the checkpoint; the other ranks take part and keep theirs.
    std::vector<double> whole;
    const bool root = sys_.gather(decode_doubles(js.at("f").get<std::string>()).data(), whole);
    if (root) js["f"] = encode_doubles(whole);
    for (const char* key : kPositionLength) {
      if (!js.contains(key)) continue;
      std::vector<double> c = decode_doubles(js.at(key).get<std::string>());
      c.resize(sys_.size(), 0.0);
      if (!sys_.gather(c.data(), whole)) continue;
      whole.resize(D * sys_.whole_layout().n);
      js[key] = encode_doubles(whole);
    }
    return js;
  }
  nlohmann::json local_integrator_state(const nlohmann::json& whole) override {
    nlohmann::json js = whole;
    if (!js.contains("f")) return js;  // restore_state() names what is missing
    js["f"] = encode_doubles(sys_.local_part(decode_doubles(js.at("f").get<std::string>())));
    for (const char* key : kPositionLength) {
      if (!js.contains(key)) continue;
      std::vector<double> c = decode_doubles(js.at(key).get<std::string>());
      c.resize(sys_.whole_layout().size(), 0.0);
      std::vector<double> mine = sys_.local_part(c);
      mine.resize(D * sys_.layout().n);
      js[key] = encode_doubles(mine);
    }
    return js;
  }
  double last_good_time() const override { return health_ ? health_->last_good_time() : t0_; }
  double rhs_seconds() const override { return sys_.stats().rhs_seconds; }
  double search_seconds() const override { return sys_.stats().search_seconds; }
  long neighbor_rebuilds() const override { return sys_.stats().rebuilds; }

  // The local system's fields at (t, y_): once per output time, for the whole system's fields and
  // the VTK pieces alike. The state is the same while the evaluations and the share are.
  void refresh(double t) {
    const auto key = std::make_tuple(t, sys_.rhs_evaluations(), sys_.stats().repartitions, sys_.stats().plans);
    if (refreshed_ && *refreshed_ == key) return;
    sys_.refresh_local(t, y_.data());
    refreshed_ = std::make_tuple(t, sys_.rhs_evaluations(), sys_.stats().repartitions, sys_.stats().plans);
  }

  nlohmann::json describe() const override {
    const auto s = sys_.stats();
    const auto owned = comm_.all_gather(static_cast<std::uint64_t>(sys_.owned().size()));
    const auto fluid = comm_.all_gather(static_cast<std::uint64_t>(sys_.owned().n_fluid));
    const auto halo = comm_.all_gather(static_cast<std::uint64_t>(s.halo_max));
    const auto exchange = comm_.all_gather(s.exchange_seconds);
    const auto rhs = comm_.all_gather(s.rhs_seconds);
    const auto [own_pairs, halo_pairs] = sys_.pair_work();
    const auto pairs = comm_.all_gather(own_pairs);
    const auto redundant = comm_.all_gather(halo_pairs);
    // Terms appended to the whole system other than by add_monitor (no shipped case does) are not in
    // the local systems, and the whole system is not evaluated: they do not run over ranks.
    const auto local = sys_.active_terms();
    std::vector<std::string> output_only;
    for (const auto& t : whole_terms_)
      if (std::find(local.begin(), local.end(), t) == local.end()) output_only.push_back(t);
    // The whole system is never evaluated over ranks (its fields at output times are the ranks'):
    // both counts are 0, summed over the ranks.
    const auto whole_evaluations = comm_.sum(static_cast<std::uint64_t>(whole_->evaluations_including_refreshes()));
    const auto whole_rebuilds = comm_.sum(static_cast<std::uint64_t>(whole_->pair_list().rebuilds()));
    // The whole scene's particles each rank still holds: rank 0's alone, after the set-up.
    const auto held = comm_.all_gather(static_cast<std::uint64_t>(whole_->particles_released() ? 0 : whole_->base_particles()));
    // The particles each rank built of the scene: rank 0 the whole scene; the others their share
    // when the case builds shares (Case::build_share), else the whole scene too.
    const auto built = comm_.all_gather(static_cast<std::uint64_t>(sys_.scene_particles_built()));
    return {{"terms_not_run", output_only},
            {"scene_particles_built", built},
            {"whole_scene_particles_held", held},
            {"whole_scene_evaluations", whole_evaluations},
            {"whole_scene_neighbour_rebuilds", whole_rebuilds},
            {"ranks", comm_.size()},
            {"decomposition", "recursive coordinate bisection by pair count (Zoltan)"},
            {"load_imbalance", s.imbalance},
            {"load_imbalance_last_plan", s.imbalance_seen},
            {"repartitions", s.repartitions},
            {"halo_depth_list_radii", s.depth},
            {"halo_plans", s.plans},
            {"ghost_mirror_margin_max", s.mirror_margin_max},
            {"reorder_serial_list_rebuilds", s.serial_sorts},
            {"owned_particles", owned},
            {"owned_fluid", fluid},
            {"halo_particles_max", halo},
            {"verlet_pairs_owned_rows", pairs},
            {"verlet_pairs_halo_rows", redundant},
            {"exchange_seconds", exchange},
            {"rhs_seconds", rhs},
            {"whole_state_gathers", whole_state_gathers_},
            {"whole_field_gathers", whole_field_gathers_},
            {"owned_pieces", owned_pieces_},
            {"output", "each rank writes its own particles' VTK pieces; probes sample at their own times and at the "
                       "output times from each rank's own particles, rank 0 adding the ranks' terms in the serial order; "
                       "the case measures from each rank's own particles, its sums and the conservation sums reduced "
                       "exactly over the ranks; checkpoints and the end gather the whole state on rank 0, which writes "
                       "every other file"}};
  }

 private:
  Communicator comm_;
  DistributedSystem<D> sys_;
  std::vector<double> y_;
  double t0_;
  std::optional<DistributedHealthCheck<D>> health_;  // from start_health_check()
  const SphSystem<D>* whole_;  // the scene as every rank builds it (never evaluated here; released but on rank 0)
  std::vector<std::string> whole_terms_;
  // Collective calls (the same on every rank): whole states and whole fields gathered on rank 0,
  // and pieces made (VTK outputs, probe samples).
  long whole_state_gathers_ = 0, whole_field_gathers_ = 0, owned_pieces_ = 0;
  std::optional<std::tuple<double, long, long, long>> refreshed_;  // refresh(): (t, evaluations, repartitions, plans)
};

// What the distributed system does not support yet: a ConfigError naming the keys, on every rank.
template <int D>
void refuse_unsupported(const Config& config, const SphSystem<D>& whole) {
  std::vector<std::string> why;
  const std::string& integrator = config.time.integrator;
  if (integrator != "leapfrog" && integrator != "leapfrog_kdk" && integrator != "leapfrog_imex" && integrator != "arkode_erk" &&
      integrator != "cvode_adams" && integrator != "arkode_imex")
    why.push_back("time.integrator: '" + integrator +
                  "' (leapfrog, leapfrog_kdk, leapfrog_imex, arkode_erk, arkode_imex and cvode_adams run over ranks)");
  // Every discretization.boundary runs over ranks, and so do repulsive wall bodies: the repulsive
  // force (boundary/repulsive_force.hpp) sums over each fluid row's wall neighbours in the stored pair
  // list, which the halo holds as for any other term, and the per-body laws are among the tables every
  // rank keeps whole (parallel/particle_columns.hpp). Reordering runs too: the local systems keep
  // their particles in the serial workspace's order (parallel/distributed_system.hpp).
  // Ghost walls are the one generated set the local systems rebuild (distributed_system.hpp).
  if (whole.has_generator() && !dynamic_cast<const GhostGenerator<D>*>(whole.generator()))
    why.push_back("generated particles other than ghost walls");
  if (why.empty()) return;
  std::string text;
  for (const auto& w : why) text += (text.empty() ? "" : "; ") + w;
  throw ConfigError("not available in a run over several MPI ranks yet: " + text);
}

}  // namespace

MpiRunPartitioner::MpiRunPartitioner(const Communicator& comm, double imbalance_tolerance, double rebalance_threshold)
    : comm_(comm), tolerance_(imbalance_tolerance), rebalance_threshold_(rebalance_threshold) {
  if (!(imbalance_tolerance > 1.0)) throw std::invalid_argument("the load imbalance tolerance must be > 1");
  if (!(rebalance_threshold >= 1.0)) throw std::invalid_argument("the rebalance threshold must be >= 1");
}

SceneShare MpiRunPartitioner::share() const {
  return {static_cast<std::size_t>(comm_.rank()), static_cast<std::size_t>(comm_.size())};
}

PieceCollectives MpiRunPartitioner::collectives() const { return piece_collectives(comm_); }

template <int D>
std::unique_ptr<PartitionedRun<D>> MpiRunPartitioner::make(const Config& config, const SphSystem<D>& whole,
                                                           const std::vector<double>& y0, double t0,
                                                           const std::function<void()>& scene_read) const {
  refuse_unsupported(config, whole);
  return std::make_unique<MpiRun<D>>(comm_, config, whole, y0, t0, tolerance_, rebalance_threshold_, scene_read);
}

std::unique_ptr<PartitionedRun<1>> MpiRunPartitioner::partition(const Config& c, const SphSystem<1>& w,
                                                                 const std::vector<double>& y0, double t0,
                                                                 const std::function<void()>& scene_read) const {
  return make<1>(c, w, y0, t0, scene_read);
}
std::unique_ptr<PartitionedRun<2>> MpiRunPartitioner::partition(const Config& c, const SphSystem<2>& w,
                                                                 const std::vector<double>& y0, double t0,
                                                                 const std::function<void()>& scene_read) const {
  return make<2>(c, w, y0, t0, scene_read);
}
std::unique_ptr<PartitionedRun<3>> MpiRunPartitioner::partition(const Config& c, const SphSystem<3>& w,
                                                                 const std::vector<double>& y0, double t0,
                                                                 const std::function<void()>& scene_read) const {
  return make<3>(c, w, y0, t0, scene_read);
}

}  // namespace sphmol::parallel
