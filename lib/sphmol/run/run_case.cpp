#include "sphmol/run/run_case.hpp"

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <stdexcept>

#include "sphmol/io/atomic_file.hpp"
#include "sphmol/run/case_registry.hpp"
#include "sphmol/run/conservation.hpp"
#include "sphmol/run/health_check.hpp"
#include "sphmol/run/last_good_state.hpp"
#include "sphmol/run/observers.hpp"
#include "sphmol/time/integrator.hpp"

namespace sphmol {
namespace {

void log_line(std::ostream& log, const nlohmann::json& m, long steps) {
  log << "t = " << std::setw(10) << m["t"].get<double>() << " s";
  for (const auto& [key, value] : m.items())
    if (key != "t" && value.is_number()) log << "   " << key << " = " << std::scientific << std::setprecision(3) << value.get<double>() << std::defaultfloat;
  log << "   steps = " << steps << '\n';
}

template <int D>
nlohmann::json run_with(Case<D>& c, const Config& config, const RunOptions& opt, const OutputSink& out) {
  const auto start = std::chrono::steady_clock::now();
  auto sys = c.build(config);
  std::vector<double> y = sys->initial_state();
  auto integrator = make_integrator(config.time);
  auto observers = make_observers<D>(config);
  integrator->initialize(*sys, 0.0, y.data());
  HealthCheck<D> health(*sys, y.data(), 0.0);
  integrator->set_step_hook([&health](double t, const double* yy, double h) { health(t, yy, h); });
  ConservationLog<D> conservation;
  conservation.record(*sys, y.data(), 0.0);

  nlohmann::json errors = nlohmann::json::array();
  nlohmann::json blow_up;
  try {
    for (double t_out : config.output.times) {
      integrator->advance(t_out);
      nlohmann::json m = c.measure(*sys, y.data(), t_out, out);
      for (auto& o : observers) o->at_output(*sys, y.data(), t_out, out);
      if (opt.log) log_line(*opt.log, m, integrator->stats().steps);
      errors.push_back(std::move(m));
      conservation.record(*sys, y.data(), t_out);
    }
    for (auto& o : observers) o->at_end(*sys, y.data(), config.time.t_end, out);
    if (opt.final_state) *opt.final_state = y;
  } catch (const BlowUp& b) {
    // End cleanly: report the cause and keep the last state that passed the checks.
    blow_up = {{"t", b.t}, {"cause", b.cause}, {"message", b.what()}, {"last_good_t", health.last_good_time()}};
    if (b.particle >= 0) blow_up["particle"] = b.particle;
    if (out.enabled) {
      write_last_good_state<D>(*sys, health.last_good_state().data(), out.path("last_good_state.csv"));
      blow_up["state_file"] = "last_good_state.csv";
    }
    if (opt.log) *opt.log << "sph-mol: " << b.what() << '\n';
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const IntegratorStats st = integrator->stats();
  const auto& P = sys->particles();

  nlohmann::json j;
  j["case"] = config.case_name;
  j["dimension"] = D;
  j["particles"] = {{"fluid", P.n_fluid}, {"wall", P.n_wall()}};
  j["status"] = blow_up.is_null() ? "completed" : "blown_up";
  if (!blow_up.is_null()) j["blow_up"] = blow_up;
  j["integrator"] = integrator->describe();
  j["t_end"] = config.time.t_end;
  j["steps"] = st.steps;
  j["rejected_steps"] = st.rejected_steps;
  j["rhs_evals"] = sys->rhs_evaluations();
  j["neighbor_rebuilds"] = sys->pair_list().rebuilds();
  j["wall_seconds"] = wall;
  j["threads"] = 1;
  j["active_terms"] = sys->active_terms();
  j["state_fields"] = sys->layout().field_names();
  j["errors"] = errors;
  j["final_errors"] = c.final_errors(errors);
  j["primary_error"] = c.primary_error();
  j["conservation"] = conservation.to_json(*sys);
  j["reference"] = c.reference();
  j["discretization"] = {{"kernel", std::string(sys->kernel_name())},
                         {"smoothing_length", sys->smoothing_length()},
                         {"neighbor_search", std::string(sys->pair_list().search_name())},
                         {"pair_list_radius", sys->pair_list().list_radius()},
                         {"verlet_pairs", sys->pair_list().pairs().pairs()}};
  j["wall_seconds_per_step_per_particle"] = st.steps > 0 ? wall / (static_cast<double>(st.steps) * P.n_fluid) : 0.0;
  c.annotate(j);
  return j;
}

template <int D>
nlohmann::json run_dimension(const std::function<std::unique_ptr<Case<D>>()>& factory, const std::string& note,
                             const Config& config, const RunOptions& opt, const OutputSink& out) {
  if (!factory)
    throw std::invalid_argument("dimension: case '" + config.case_name + "' is " + note + ", not " + std::to_string(D) + "D");
  auto c = factory();
  return run_with<D>(*c, config, opt, out);
}

}  // namespace

nlohmann::json run_case(const Config& config, const RunOptions& options) {
  const auto& registry = case_registry();
  const auto it = registry.find(config.case_name);
  if (it == registry.end()) throw std::invalid_argument("case: unknown case '" + config.case_name + "'");
  OutputSink out{options.output_dir.empty() ? config.output.directory : options.output_dir, options.write_files};
  if (out.enabled) std::filesystem::create_directories(out.directory);
  const CaseFactory& f = it->second;
  nlohmann::json summary;
  switch (config.dimension) {
    case 1: summary = run_dimension<1>(f.d1, f.dimensions_note, config, options, out); break;
    case 2: summary = run_dimension<2>(f.d2, f.dimensions_note, config, options, out); break;
    case 3: summary = run_dimension<3>(f.d3, f.dimensions_note, config, options, out); break;
    default: throw std::invalid_argument("dimension: must be 1, 2 or 3");
  }
  summary["config_file"] = config.source;
  if (out.enabled) {
    write_file_atomically(out.path("config.yaml"), to_yaml(config));
    write_file_atomically(out.path("summary.json"), summary.dump(2) + "\n");
  }
  return summary;
}

}  // namespace sphmol
