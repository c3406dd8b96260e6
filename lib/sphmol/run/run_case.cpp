#include "sphmol/run/run_case.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include "sphmol/run/conservation.hpp"
#include "sphmol/run/health_check.hpp"
#include "sphmol/run/last_good_state.hpp"
#include "sphmol/run/timed_output_files.hpp"
#include "sphmol/run/outflow.hpp"
#include <stdexcept>

#include "sphmol/config/position_correction.hpp"
#include "sphmol/core/version.hpp"
#include "sphmol/io/atomic_file.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/run/checkpoint.hpp"
#include "sphmol/run/observers.hpp"
#include "sphmol/run/output_folder.hpp"
#include "sphmol/run/partitioned_run.hpp"
#include "sphmol/run/plots.hpp"
#include "sphmol/run/progress.hpp"
#include "sphmol/run/restart_check.hpp"
#include "sphmol/run/signals.hpp"
#include "sphmol/run/start_piece.hpp"
#include "sphmol/time/integrator.hpp"

namespace sphmol {
namespace {

void log_line(std::ostream& log, const nlohmann::json& m, long steps, double wall) {
  // The output time as in the files' names (six significant digits): the stream's precision is left
  // at 2 by the wall time below, which printed 0.1125 as 0.11 from the second line on.
  log << "t = " << std::setw(10) << output_time_text(m["t"].get<double>()) << " s";
  for (const auto& [key, value] : m.items())
    if (key != "t" && value.is_number()) log << "   " << key << " = " << std::scientific << std::setprecision(3) << value.get<double>() << std::defaultfloat;
  log << "   steps = " << steps << "   wall = " << std::fixed << std::setprecision(2) << wall << " s" << std::defaultfloat << '\n';
}

template <int D>
nlohmann::json run_with(Case<D>& c, const Config& config, const RunOptions& opt, const OutputSink& out,
                        std::optional<OutputFolder>& folder) {
  const auto start = std::chrono::steady_clock::now();
  // Over ranks every rank builds only the particles it starts with when the case can
  // (Case::build_share), and no rank holds the whole scene at any time; otherwise every rank builds
  // the whole scene and the root keeps it (the case measures it there). The set-up's sums and gathers
  // over the scene go through each rank's particles as the run starts (run/start_piece.hpp).
  const bool root = !opt.partitioner || opt.partitioner->root();
  const SceneShare share = opt.partitioner ? opt.partitioner->share() : SceneShare{};
  const PieceCollectives ranks = opt.partitioner ? opt.partitioner->collectives() : one_rank_collectives();
  auto sys = opt.partitioner && c.builds_shares() ? c.build_share(config, share) : c.build(config);
  std::vector<double> y = sys->initial_state();
  auto integrator = make_integrator(config.time);
  auto observers = make_observers<D>(config, start_piece(*sys, y.data(), share, ranks));
  // Over several ranks (run/partitioned_run.hpp) the integrator advances this rank's part of the
  // state, and `y` holds the whole state only after a gather (checkpoints, the end, output times for
  // an observer that reads it); the case measures from each rank's own particles, and the root rank
  // writes, with the whole system `sys`.
  std::unique_ptr<PartitionedRun<D>> part;

  // Restart: the checkpoint's state, time, integrator state and measurements so far.
  double t = 0.0;
  nlohmann::json errors = nlohmann::json::array();
  long rhs_before = 0;
  double wall_before = 0.0, rhs_before_s = 0.0, search_before_s = 0.0;
  std::optional<Checkpoint> restart;
  if (!opt.restart_from.empty()) {
    restart = read_checkpoint(opt.restart_from);
    const std::size_t whole_size = sys->whole_layout().size();
    if (restart->case_name != config.case_name || restart->dimension != D || restart->y.size() != whole_size ||
        restart->integrator != integrator->name())
      throw CheckpointError(opt.restart_from + ": checkpoint (case " + restart->case_name + ", " +
                            std::to_string(restart->y.size()) + " state values, integrator " + restart->integrator +
                            ") does not match the config (case " + config.case_name + ", " +
                            std::to_string(whole_size) + " state values, integrator " + integrator->name() + ")");
    check_restart(*restart, config, opt.restart_from, opt.force_physics_change);
    // The checkpoint's copy is not needed again; a share keeps its own part.
    y = sys->is_share() ? sys->share_of(restart->y) : std::move(restart->y);
    std::vector<double>().swap(restart->y);
    t = restart->t;
    errors = restart->errors;
    rhs_before = restart->rhs_evals;
    wall_before = restart->wall_seconds;
    rhs_before_s = restart->rhs_seconds;
    search_before_s = restart->search_seconds;
  }
  // The particles this rank starts with, at the state the run starts from (collectives: every rank;
  // its lists are dropped once the log has its first record).
  std::optional<OwnedPiece<D>> starting = start_piece(*sys, y.data(), share, ranks);
  // Fluid that has left the domain is out of the run (run/outflow.hpp); a restarted run finds the
  // particles an earlier part took out where they left, outside the domain, and takes them out
  // again before its first evaluation (over ranks each rank from the particles it holds, before the
  // partition, which carries their kind to the ranks' particles).
  Outflow<D> outflow(fluid_totals(*starting).mass, config.health.max_outflow_fraction);
  outflow.take_out_at_start(*sys, y.data(), *starting, t);
  // The conservation log starts from the state the run starts from (no evaluation needed).
  ConservationLog<D> conservation(*starting, t);
  // The health limits' sums of that state (run/health_limits.hpp; the elastic energy follows the
  // first evaluation).
  HealthSums start_sums = health_sums(*starting);
  starting.reset();
  // Partitioned from the state the run starts from (a checkpoint holds the whole state, whatever
  // rank count wrote it). Once a rank has taken its slice of the scene it drops what it built and
  // its state y, before the partition's searches and its first evaluation, keeping its own particles
  // alone (in its local systems) and the scene's counts; the root keeps a whole scene it had to
  // build (a case without shares measures it), and gathers the whole state into y where it writes
  // it (checkpoints, the end, the last good state).
  if (opt.partitioner)
    part = opt.partitioner->partition(config, *sys, y, t, [&] {
      if (root && !sys->is_share()) return;
      sys->release_particles();
      std::vector<double>().swap(y);
    });
  OdeSystem& ode = part ? part->system() : static_cast<OdeSystem&>(*sys);
  double* const y_step = part ? part->state().data() : y.data();  // what the integrator advances
  integrator->initialize(ode, t, y_step);
  // A fixed time.dt runs as set even beyond the CFL bound (the stability studies rely on it), but a
  // step beyond the widest stable CFL step at the start is said: refining a file that fixes dt
  // keeps the old step, and the blow-up the health checks report later would not say why.
  std::vector<std::string> warnings;
  if (config.time.dt) {
    const double bound = ode.widest_stable_step();  // of the initialising evaluation (over ranks: global)
    if (bound > 0.0 && std::isfinite(bound) && *config.time.dt > bound) {
      std::ostringstream w;
      w << "time.dt = " << *config.time.dt << " s is " << *config.time.dt / bound << " times the largest stable step at t = "
        << t << " (" << bound << " s: the CFL bound with the coefficients at the top of their stable ranges, acoustic "
        << CflConfig::kMaxAcoustic << ", force " << CflConfig::kMaxForce;
      // The IMEX integrators' bound has no viscous limit (the viscous term is implicit).
      if (!config.time.implicit_viscosity()) w << ", viscous " << CflConfig::kMaxViscous;
      w << "); the run is likely to blow up: set a smaller time.dt, or remove it to step at the CFL bound";
      warnings.push_back(w.str());
      if (opt.log) *opt.log << "warning: " << warnings.back() << '\n';
    }
  }
  // Blow-up detection after every accepted step (run/health_check.hpp; over ranks, the partition's
  // own checks), and conservation diagnostics.
  std::optional<HealthCheck<D>> health;
  // Over ranks, SIGINT/SIGTERM as the ranks agree at the last step's check: the largest signal any
  // rank has received, the same on every rank, so that all stop at the same step (run/signals.hpp).
  int agreed_signal = 0;
  // The physical bounds from the whole scene's sums at t and the elastic energy of the evaluation at
  // t that the integrator's initialisation made: serially of the whole system; over ranks of the
  // ranks' own particles, summed exactly over the ranks, so that no rank evaluates (or holds the
  // neighbour list of) the whole scene for them and every rank count has the serial limits.
  const HealthLimits limits = [&] {
    const HealthLimits::Elastic elastic = elastic_energy(config);
    start_sums.el0 = part ? part->elastic_energy(elastic) : elastic_energy_total(elastic, *sys);
    return health_limits<D>(config, c.velocity_scale(config), c.free_surface(), start_sums);
  }();
  if (part) {
    part->start_health_check(t, limits);
    integrator->set_step_hook([&part, &agreed_signal](double tt, const double*, double hh) {
      agreed_signal = part->check(tt, hh, pending_signal());
    });
  } else {
    health.emplace(*sys, y.data(), t, limits);
    integrator->set_step_hook([&health](double tt, const double* yy, double hh) { (*health)(tt, yy, hh); });
  }
  if (restart) {
    // A malformed integrator or observer state is bad input (exit 2), like any other checkpoint field.
    try {
      integrator->restore_state(part ? part->local_integrator_state(restart->integrator_state) : restart->integrator_state);
      for (std::size_t k = 0; k < observers.size() && k < restart->observers.size(); ++k)
        observers[k]->restore_state(restart->observers[k], out);
    } catch (const std::exception& e) {
      throw CheckpointError(opt.restart_from + ": integrator_state / observers: " + e.what());
    }
    if (!restart->case_state.is_null()) {
      try {
        c.restore_state(restart->case_state);
      } catch (const std::exception& e) {
        throw CheckpointError(opt.restart_from + ": case_state: " + e.what());
      }
    } else if (!c.save_state().empty() && !restart->errors.empty()) {
      // A checkpoint written before cases carried their series. Refusing it would throw away the run
      // so far; the run continues and says what is missing. (The case as built saves nothing only
      // when it carries nothing; without earlier measurements nothing is lost.)
      std::ostringstream w;
      w << opt.restart_from << " has no case_state (written by an earlier sph-mol): the case's series files "
        << "(CSVs) and the summary values computed from them (decay rates, running maxima) "
        << "miss the output times up to t = " << t << " s, which the summary's errors still list; rerun from "
        << "t = 0 for complete series";
      warnings.push_back(w.str());
      if (opt.log && root) *opt.log << "warning: " << warnings.back() << '\n';
    }
    if (!(t < config.time.t_end) && opt.log && root)
      *opt.log << "the checkpoint is at time.t_end = " << config.time.t_end << " s: nothing to integrate; the run's end "
               << "(summary, plots) is done again (raise time.t_end with --set to continue the run)\n";
  }
  // Everything that can reject the input (scene, first RHS evaluation, checkpoint) has run: only
  // now does the output directory appear, locked for this run (run/output_folder.hpp).
  if (out.enabled) {
    folder.emplace(out.directory, OutputFolder::Options{opt.overwrite, opt.continuing});
    // A restart into its own folder carries on the list of files the run has written.
    if (restart && opt.continuing)
      for (const auto& f : restart->files) out.record(f);
  }
  // Over ranks every rank writes its own VTK pieces into the folder rank 0 has just made.
  if (part) part->barrier();
  const OutputSink own = root ? out : OutputSink{out.directory, opt.write_files};
  const double t_first = t;
  std::vector<double> scratch;
  // The per-particle fields (density, pressure, ...) of the whole state y at t, of this very state
  // and not of the integrator's last stage: the case's measurement and the observers read them.
  // Serially an evaluation; over ranks (collective) the fields of each rank's own particles,
  // gathered on the root: no rank evaluates the whole scene or builds its neighbour list.
  const auto whole_fields = [&] {
    if (part)
      part->whole_fields(t, *sys);
    else
      sys->refresh_fields(t, y.data(), scratch);
  };

  const auto wall_now = [&] {
    return wall_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  std::vector<std::string> written = restart ? restart->written : std::vector<std::string>{};  // pruning: run/checkpoint.hpp
  const auto checkpoint = [&] {
    // Over ranks every rank takes part in gathering the whole state and the integrator's state in
    // the serial layout on rank 0, which writes them.
    nlohmann::json integrator_state;
    if (part) {
      part->gather(y);
      integrator_state = part->whole_integrator_state(integrator->save_state());
      part->combine_monitors();  // for the summary of an interrupted run
    }
    if (!out.enabled) return;
    Checkpoint cp;
    cp.case_name = config.case_name;
    cp.dimension = D;
    cp.t = t;
    cp.y = y;
    cp.integrator = integrator->name();
    cp.integrator_state = part ? integrator_state : integrator->save_state();
    cp.errors = errors;
    cp.case_state = c.save_state();
    for (const auto& o : observers) cp.observers.push_back(o->save_state());
    cp.rhs_evals = rhs_before + ode.rhs_evaluations();
    cp.wall_seconds = wall_now();
    cp.rhs_seconds = rhs_before_s + (part ? part->rhs_seconds() : sys->rhs_seconds());
    cp.search_seconds = search_before_s + (part ? part->search_seconds() : sys->search_seconds());
    out.record(checkpoint_name(t));
    cp.files = out.written();
    write_checkpoint(out.directory, cp, to_yaml(config), written);
  };

  // Stop at every output time and every multiple of checkpoint_every; step by step in between.
  const auto& times = config.output.times;
  std::size_t next_out = 0;
  while (next_out < times.size() && times[next_out] <= t) ++next_out;
  const double every = config.output.checkpoint_every;
  const double inf = std::numeric_limits<double>::infinity();
  // k * every rounds off (3 x 0.025 = 0.07500000000000001): a checkpoint meant to fall on an output
  // time or on t_end (always an output time) does, rather than being missed or forcing a 1e-17 s step.
  const auto checkpoint_time = [&](long k) {
    const double tc = static_cast<double>(k) * every;
    for (const double to : times)
      if (std::abs(tc - to) <= 1e-9 * every) return to;
    return tc;
  };
  long k_cp = every > 0 ? static_cast<long>(t / every) : 0;
  while (every > 0 && checkpoint_time(k_cp) <= t) ++k_cp;
  double next_cp = every > 0 ? checkpoint_time(k_cp) : inf;

  std::optional<SignalGuard> guard;
  if (opt.handle_signals) guard.emplace();
  const auto signal_seen = [&] { return part ? agreed_signal : pending_signal(); };
  ProgressLine progress(opt.progress, t_first, config.time.t_end);
  int signal = 0;
  nlohmann::json blow_up;
  // Inside a step: a BlowUp from there (the health check, the integrator's step-size collapse) is
  // thrown on every rank alike over ranks, one from a root-only measurement on the root only.
  bool stepping = false;
  // Observers with their own sampling times (probes with `every`): the loop stops there as well.
  const auto next_observer_time = [&] {
    double tn = inf;
    for (const auto& o : observers) tn = std::min(tn, o->next_time());
    return tn;
  };
  // Over ranks: this rank's own particles at t, made once per stop for the case's measurement, the
  // conservation sums, the probes and the VTK pieces (collective: every rank makes it alike).
  std::optional<OwnedPiece<D>> stop_piece;
  const auto own_piece = [&]() -> const OwnedPiece<D>& {
    if (!stop_piece) stop_piece = part->owned_piece(t);
    return *stop_piece;
  };
  const auto observe_own_times = [&] {
    bool refreshed = false;
    for (auto& o : observers)
      if (o->next_time() <= t) {
        if (part && o->samples_pieces()) {  // the same on every rank
          o->at_time_pieces(*sys, own_piece(), t, out);
          continue;
        }
        if (!refreshed) {
          if (part) part->gather(y);  // collective: every rank has the same observers; the root receives
          whole_fields();
        }
        refreshed = true;
        if (root)
          o->at_time(*sys, y.data(), t, out);
        else
          o->pass_time(t);
      }
  };
  // Observers with per-rank files (VTK pieces): every rank writes its own particles' part.
  const auto write_pieces = [&] {
    if (!part || !own.enabled) return;  // the same on every rank
    if (std::none_of(observers.begin(), observers.end(), [](const auto& o) { return o->writes_pieces(); })) return;
    for (auto& o : observers)
      if (o->writes_pieces()) o->at_output_pieces(*sys, own_piece(), t, own);
  };
  // Over ranks those observers write their pieces, or sample from the pieces, instead.
  const auto on_root = [&](const std::unique_ptr<OutputObserver<D>>& o) {
    return !part || !(o->writes_pieces() || o->samples_output_pieces());
  };
  // Observers that sample the output times from pieces (probes without `every`): over ranks every
  // rank sends rank 0 its own particles' part of the samples (collective, the same on every rank).
  const auto sample_output_pieces = [&] {
    if (!part) return;
    for (auto& o : observers)
      if (o->samples_output_pieces() && o->samples_outputs()) o->at_output_time_pieces(*sys, own_piece(), t, out);
  };
  // Over ranks the whole state is gathered on rank 0 at an output time only for a case that
  // measures the whole system or an observer that reads it there; a case that measures from pieces,
  // the conservation sums and the observers that sample from pieces reduce over the ranks' own
  // particles (run/piece_reduction.hpp, probes/probe_observer.hpp).
  const bool observers_read_whole =
      std::any_of(observers.begin(), observers.end(), [&](const auto& o) { return on_root(o) && o->samples_outputs(); });
  const bool output_gathers = !part || !c.measures_pieces() || observers_read_whole;
  try {
  // The initial state: the observers (VTK files, probes) write t = 0 too; the case measures from the
  // first output time on. A restart continues from its checkpoint, which has them already.
  if (!restart) {
    if (!part || observers_read_whole) whole_fields();
    if (root && (!part || observers_read_whole)) {
      for (auto& o : observers)
        if (on_root(o)) o->at_output(*sys, y.data(), t, out);
    }
    sample_output_pieces();
    write_pieces();
    observe_own_times();
  }
  while (next_out < times.size()) {
    const double stop = std::min({times[next_out], next_cp, next_observer_time()});
    stop_piece.reset();  // the state moves on (and over ranks the share may change)
    while (t < stop && !(signal = signal_seen())) {
      stepping = true;
      t = integrator->step_toward(stop);
      // Fluid that left the domain in this step is taken out, and the integrator starts again from
      // the changed system at (t, y) (run/outflow.hpp). Over the limit: a BlowUp. Over ranks every
      // rank has the leavers' ids from the check: each takes its own and its halo copies out, and
      // all take them out of the whole system, and restart, at the same step.
      if (health && health->exits() && outflow.take_out(*sys, y.data(), t)) integrator->restart(ode, t, y_step);
      if (part && !part->leavers().empty()) {
        const std::vector<std::size_t> gone = part->leavers();
        part->take_out(gone);
        // The rank's state now: a repartition (rebalance below) resizes it, so not y_step.
        if (outflow.take_out(*sys, gone, part->leaver_masses(), t)) integrator->restart(ode, t, part->state().data());
      }
      stepping = false;
      // Not after the last step: nothing would run on the new share.
      if (part && t < times.back()) part->rebalance(*integrator, t);
      if (opt.after_step) opt.after_step(t);
      progress.update(t, integrator->stats().last_step, integrator->stats().steps);
    }
    // An output or checkpoint time that was reached is handled even if a signal came in meanwhile,
    // so the interrupt checkpoint never misses a measurement at its own time.
    if (t >= times[next_out]) {
      // Over ranks the case's monitors have watched each rank's own particles (the fields' evaluation
      // at this state included, as the serial run's refresh is watched): combined for its measurement.
      if (output_gathers) {
        if (part) part->gather(y);
        whole_fields();
      }
      // The ranks' evaluation of their own particles at this state, before the monitors combine.
      if (part) own_piece();
      if (part) part->combine_monitors();
      nlohmann::json m;
      if (part && c.measures_pieces())
        m = c.measure_pieces(*sys, own_piece(), t, out);  // collective, on every rank
      else if (root)
        m = c.measure(*sys, y.data(), t, out);
      if (part) conservation.record(own_piece(), t);  // collective
      sample_output_pieces();
      if (root) {
        if (output_gathers)
          for (auto& o : observers)
            if (on_root(o)) o->at_output(*sys, y.data(), t, out);
        progress.clear();
        if (opt.log) log_line(*opt.log, m, integrator->stats().steps, wall_now());
        errors.push_back(std::move(m));
        if (!part) conservation.record(*sys, y.data(), t);
      }
      write_pieces();
      ++next_out;
    }
    observe_own_times();
    if (t >= next_cp) {
      checkpoint();
      next_cp = checkpoint_time(++k_cp);
    }
    if (signal) break;
  }
  } catch (const BlowUp& b) {
    // End cleanly: report the cause and keep the last state that passed the checks.
    progress.clear();
    blow_up = {{"t", b.t}, {"cause", b.cause}, {"message", b.what()},
               {"last_good_t", part ? part->last_good_time() : health->last_good_time()}};
    if (b.particle >= 0) blow_up["particle"] = b.particle;
    // Over ranks the last good state is gathered from every rank when all of them are here, having
    // thrown the same BlowUp in the same step, and the root writes it.
    std::vector<double> last_good;
    if (part && own.enabled && stepping) part->gather_last_good(last_good);
    if (part && stepping) part->combine_monitors();
    const std::vector<double>* good = part ? &last_good : health ? &health->last_good_state() : nullptr;
    if (out.enabled && good && !good->empty()) {
      write_last_good_state<D>(*sys, good->data(), out.path("last_good_state.csv"));
      out.record("last_good_state.csv");
      blow_up["state_file"] = "last_good_state.csv";
    }
    if (opt.log && root) *opt.log << "sph-mol: " << b.what() << '\n';
  }
  progress.clear();
  if (signal) {
    checkpoint();
    if (opt.log) *opt.log << "interrupted by signal " << signal << " at t = " << t << " s; checkpoint written\n";
  } else if (blow_up.is_null()) {
    if (part) {
      part->gather(y);
      part->combine_monitors();
    }
    if (opt.final_state) *opt.final_state = y;
  }
  // Completed, interrupted or blown up: the probes' rows sampled since their last write (they write
  // at most once a second between output times).
  if (root)
    for (auto& o : observers) o->at_stop(out);
  const double wall = wall_now();
  const IntegratorStats st = integrator->stats();
  // The scene's counts (over ranks the particles are released on every rank but the root); the
  // walls include the ghost images of the last evaluation (serially; the whole system of a run over
  // ranks is never evaluated).
  const std::size_t n_fluid = sys->layout().n, n_wall = sys->base_particles() + sys->generated_particles() - n_fluid;

  nlohmann::json j;
  j["case"] = config.case_name;
  j["dimension"] = D;
  j["particles"] = {{"fluid", n_fluid}, {"wall", n_wall}};

  j["integrator"] = integrator->describe();
  j["outflow"] = outflow.to_json();
  if (const std::string w = outflow.warning(); !w.empty()) warnings.push_back(w);
  // Always present, empty when nothing was said or drawn, so readers need not test for them.
  j["warnings"] = nlohmann::json::array();
  j["plots"] = nlohmann::json::array();
  for (const auto& w : warnings) j["warnings"].push_back(w);  // main prints them, even with --quiet
  j["t_end"] = config.time.t_end;
  j["steps"] = st.steps;
  j["rejected_steps"] = st.rejected_steps;
  j["rhs_evals"] = rhs_before + ode.rhs_evaluations();
  j["neighbor_rebuilds"] = part ? part->neighbor_rebuilds() : sys->pair_list().rebuilds();
  j["wall_seconds"] = wall;
  {
    // Where the wall time went: the neighbour list (staleness test, rebuilds), the rest of the RHS
    // (particle sums, EOS, CFL limit), and everything else (set-up, integrator updates, output).
    const double rhs_s = rhs_before_s + (part ? part->rhs_seconds() : sys->rhs_seconds());
    const double search_s = search_before_s + (part ? part->search_seconds() : sys->search_seconds());
    j["wall_seconds_breakdown"] = {{"neighbour_search", search_s}, {"rhs_without_search", rhs_s - search_s},
                                   {"setup_integrator_output", wall - rhs_s}};
    // Fused pair passes only: each thread's time on pair rows in this process (not carried over a
    // restart, whose thread count may differ).
    if (!part && !sys->pair_thread_seconds().empty()) j["wall_seconds_breakdown"]["pair_rows_per_thread"] = sys->pair_thread_seconds();
  }
  j["threads"] = omp_get_max_threads();
  j["active_terms"] = sys->active_terms();
  j["state_fields"] = sys->layout().field_names();
  j["errors"] = errors;
  j["final_errors"] = c.final_errors(errors);
  j["primary_error"] = c.primary_error();
  j["primary_error_kind"] = c.has_exact_reference() ? "exact_reference" : "quantity";
  j["conservation"] = conservation.to_json(*sys);
  j["reference"] = c.reference();
  // Collective: on every rank, before the summary's entries that read it.
  const nlohmann::json parallel = part ? part->describe() : nlohmann::json();
  // The Verlet pairs: of the whole list serially, of the ranks' own rows over ranks (the whole
  // system builds no list there).
  std::uint64_t verlet_pairs = sys->pair_list().pairs().pairs();
  if (part) {
    verlet_pairs = 0;
    for (const auto& p : parallel["verlet_pairs_owned_rows"]) verlet_pairs += p.get<std::uint64_t>();
  }
  j["discretization"] = {{"kernel", std::string(sys->kernel_name())},
                         {"smoothing_length", sys->smoothing_length()},
                         {"neighbor_search", std::string(sys->pair_list().search_name())},
                         {"pair_list_radius", sys->pair_list().list_radius()},
                         {"verlet_pairs", verlet_pairs},
                         {"pair_passes", sys->pair_passes().empty() ? nlohmann::json("stored") : nlohmann::json(sys->pair_passes())}};
  j["wall_seconds_per_step_per_particle"] = st.steps > 0 ? wall / (static_cast<double>(st.steps) * n_fluid) : 0.0;
  c.annotate(j);
  for (const auto& o : observers) o->annotate(j);
  if (blow_up.contains("state_file"))
    j["csv_files"]["last_good_state.csv"] = "the fluid particles' positions and velocities at the last state that passed the health "
                                            "checks (t = blow_up.last_good_t)";
  if (part) j["parallel"] = parallel;
  if (restart) j["restarted_from"] = {{"checkpoint", opt.restart_from}, {"t", t_first}};
  // A signal that arrives after the last step (final observers, plots) is not lost either: gnuplot is
  // stopped, and the run ends as interrupted at t_end with a checkpoint (its data files complete; the
  // plot scripts stay for gnuplot). Over ranks they agree here too (a collective, on every rank).
  const auto signal_after_end = [&] {
    if (signal || !opt.handle_signals || !blow_up.is_null()) return;
    signal = part ? part->largest_signal(pending_signal()) : pending_signal();
    if (!signal) return;
    checkpoint();
    if (opt.log) *opt.log << "interrupted by signal " << signal << " after t = " << t << " s; checkpoint written\n";
  };
  signal_after_end();
  if (!signal && blow_up.is_null() && config.output.plots) {
    if (out.enabled) {  // over ranks, rank 0 plots while the others wait for it in signal_after_end
      const auto interrupted = [&] { return opt.handle_signals && pending_signal() != 0; };
      std::vector<PlotScript> scripts = c.plots(out);
      for (const auto& o : observers)
        for (auto& p : o->plots(out)) scripts.push_back(std::move(p));
      const PlotResult plots = make_plots(scripts, out, interrupted);
      j["plots"] = plots.written;
      for (const auto& w : plots.warnings) j["warnings"].push_back(w);  // main prints them, even with --quiet
    }
    signal_after_end();
  }
  j["status"] = signal ? "interrupted" : blow_up.is_null() ? "completed" : "blown_up";
  if (!blow_up.is_null()) j["blow_up"] = blow_up;
  if (signal) {
    j["signal"] = signal;
    j["t_reached"] = t;
  }
  return j;
}

template <int D>
nlohmann::json run_dimension(const Config& config, const RunOptions& opt, const OutputSink& out,
                             std::optional<OutputFolder>& folder) {
  auto c = make_case<D>(config);
  return run_with<D>(*c, config, opt, out, folder);
}

// The run's output folder: --output, else (restart) the folder the checkpoint lives in, else
// output.directory.
std::string output_directory(const Config& config, const RunOptions& options) {
  if (!options.output_dir.empty()) return options.output_dir;
  if (!options.restart_from.empty()) {
    const std::string parent = std::filesystem::path(options.restart_from).lexically_normal().parent_path().string();
    return parent.empty() ? "." : parent;
  }
  return config.output.directory;
}

}  // namespace

nlohmann::json run_case(const Config& config, const RunOptions& options) {
  if (!find_case_module(config.case_name)) throw std::invalid_argument("case: unknown case '" + config.case_name + "'");
  const bool root = !options.partitioner || options.partitioner->root();
  OutputSink out{output_directory(config, options), options.write_files && root};
  // The resolved config records the folder the run really writes to, as an absolute path, so a
  // restart from one of its checkpoints continues there whatever the current folder.
  Config resolved = config;
  if (out.enabled) resolved.output.directory = std::filesystem::absolute(out.directory).lexically_normal().string();
  RunOptions opt = options;
  // A restart into the folder its checkpoint lives in continues that run (its summary is its own).
  if (!options.restart_from.empty() && out.enabled) {
    const auto here = std::filesystem::weakly_canonical(out.directory);
    const auto home = std::filesystem::weakly_canonical(std::filesystem::path(options.restart_from).lexically_normal().parent_path());
    opt.continuing = here == home;
  }
  // A restart without --output continues in its checkpoint's folder whatever output.directory says;
  // a different one (edited in config.yaml, given with --set, or a run folder moved since) is not
  // used, and the run says so.
  std::string folder_notice;
  if (!options.restart_from.empty() && options.output_dir.empty() && out.enabled) {
    std::error_code ec1, ec2;
    const auto wanted = std::filesystem::weakly_canonical(config.output.directory, ec1);
    const auto here = std::filesystem::weakly_canonical(out.directory, ec2);
    if (ec1 || ec2 || wanted != here)
      folder_notice = "output.directory " + config.output.directory + " is not used: a restart without --output " +
                      "continues in the folder of its checkpoint, " + out.directory + "; give --output " +
                      config.output.directory + " to write there";
    if (!folder_notice.empty() && opt.log) *opt.log << "warning: " << folder_notice << '\n';
  }
  // Claimed by run_with before its first step (so before any file is written) and held until the
  // summary is written.
  std::optional<OutputFolder> folder;
  nlohmann::json summary;
  switch (config.dimension) {
    case 1: summary = run_dimension<1>(resolved, opt, out, folder); break;
    case 2: summary = run_dimension<2>(resolved, opt, out, folder); break;
    case 3: summary = run_dimension<3>(resolved, opt, out, folder); break;
    default: throw std::invalid_argument("dimension: must be 1, 2 or 3");
  }
  summary["config_file"] = config.source;
  if (!folder_notice.empty()) summary["warnings"].push_back(folder_notice);
  if (const auto& pc = config.discretization.position_correction; !pc.setting.empty()) {
    // discretization.position_correction: what ran, and for auto why (config/position_correction.hpp).
    nlohmann::json j{{"setting", pc.setting}, {"chosen", pc.chosen}};
    if (!pc.reason.empty()) j["reason"] = pc.reason;
    if (pc.cell_reynolds >= 0.0) {
      j["cell_reynolds_number"] = std::isfinite(pc.cell_reynolds) ? nlohmann::json(pc.cell_reynolds) : nlohmann::json("inf");
      j["cell_reynolds_threshold"] = kPositionCorrectionCellReynolds;
    }
    summary["position_correction"] = j;
  }
  summary["version"] = version();
  summary["git_commit"] = git_commit();
  if (out.enabled) {
    out.write("config.yaml", to_yaml(resolved));
    out.record("summary.json");
    summary["output_directory"] = out.directory;
    // What is in the folder now (pruned checkpoints are gone), plus the summary about to be written.
    nlohmann::json files = nlohmann::json::array();
    for (const auto& f : out.written())
      if (f == "summary.json" || std::filesystem::exists(std::filesystem::symlink_status(out.path(f)))) files.push_back(f);
    summary["files"] = files;
    write_file_atomically(out.path("summary.json"), summary.dump(2) + "\n");
  }
  return summary;
}

int interrupted_exit_code(const nlohmann::json& summary) {
  return summary.value("status", "") == "interrupted" ? 128 + summary.value("signal", 0) : 0;
}

}  // namespace sphmol
