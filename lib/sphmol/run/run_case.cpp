#include "sphmol/run/run_case.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "sphmol/io/atomic_file.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "sphmol/scenes/channel_reference.hpp"
#include "sphmol/scenes/channel_scene.hpp"
#include "sphmol/time/integrator.hpp"

namespace sphmol {
namespace {

std::string time_label(double t) {
  std::ostringstream s;
  s << std::setprecision(6) << t;
  return s.str();
}

void write_profile(const std::string& dir, const ChannelErrors& e) {
  std::ostringstream s;
  s << "# SPH velocity profile vs exact series at t = " << e.t << " s\ny,u_sph,u_exact\n" << std::setprecision(12);
  for (const auto& p : e.profile) s << p.y << ',' << p.u_sph << ',' << p.u_exact << '\n';
  write_file_atomically(dir + "/profile_t" + time_label(e.t) + ".csv", s.str());
}

nlohmann::json run_channel(const Config& config, const RunOptions& opt, const std::string& dir) {
  const auto start = std::chrono::steady_clock::now();
  ChannelScene scene = build_channel_scene(config);
  const ChannelReference ref = make_channel_reference(config);
  const std::size_t n_fluid = scene.particles.n_fluid, n_wall = scene.particles.n_wall();
  auto sys = assemble_system<2>(config, std::move(scene.particles), scene.domain, scene.spacing);
  std::vector<double> y = sys->initial_state();
  auto integrator = make_integrator(config.time);
  integrator->initialize(*sys, 0.0, y.data());

  nlohmann::json errors = nlohmann::json::array();
  ChannelErrors last;
  for (double t_out : config.output.times) {
    integrator->advance(t_out);
    last = channel_errors(*sys, y.data(), t_out, ref);
    errors.push_back({{"t", t_out}, {"e_rms", last.e_rms}, {"e_max", last.e_max}});
    if (opt.write_files && config.output.profiles) write_profile(dir, last);
    if (opt.log)
      *opt.log << "t = " << std::setw(10) << t_out << " s   e_rms = " << std::scientific << std::setprecision(3)
               << last.e_rms << "   e_max = " << last.e_max << std::defaultfloat << "   steps = "
               << integrator->stats().steps << '\n';
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const IntegratorStats st = integrator->stats();

  nlohmann::json j;
  j["case"] = config.case_name;
  j["dimension"] = 2;
  j["particles"] = {{"fluid", n_fluid}, {"wall", n_wall}};
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
  j["final_errors"] = {{"e_rms", last.e_rms}, {"e_max", last.e_max}};
  j["reference"] = ref.name;
  j["v0"] = ref.v0;
  j["discretization"] = {{"kernel", std::string(sys->kernel_name())},
                         {"spacing", scene.spacing},
                         {"smoothing_length", sys->smoothing_length()},
                         {"wall_layers", scene.wall_layers},
                         {"neighbor_search", std::string(sys->pair_list().search_name())},
                         {"pair_list_radius", sys->pair_list().list_radius()},
                         {"pairs", sys->pair_list().pairs().pairs()}};
  j["wall_seconds_per_step_per_particle"] = st.steps > 0 ? wall / (static_cast<double>(st.steps) * n_fluid) : 0.0;
  return j;
}

}  // namespace

nlohmann::json run_case(const Config& config, const RunOptions& options) {
  const std::string dir = options.output_dir.empty() ? config.output.directory : options.output_dir;
  if (options.write_files) std::filesystem::create_directories(dir);
  nlohmann::json summary;
  if (config.case_name == "couette" || config.case_name == "poiseuille") {
    if (config.dimension != 2) throw std::invalid_argument("dimension: the channel cases are two-dimensional");
    summary = run_channel(config, options, dir);
  } else {
    throw std::invalid_argument("case: unknown case '" + config.case_name + "'");
  }
  summary["config_file"] = config.source;
  if (options.write_files) {
    write_file_atomically(dir + "/config.yaml", to_yaml(config));
    write_file_atomically(dir + "/summary.json", summary.dump(2) + "\n");
  }
  return summary;
}

}  // namespace sphmol
