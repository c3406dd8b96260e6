#pragma once
// A case module: one folder under cases/ that owns everything about one kind of run: its config
// sections (read, checked against the shared settings, written back by to_yaml), its scene builder,
// its reference check and its plots. The loader reads the shared sections (dimension, fluid,
// discretization, time, output) and hands the top-level keys the module names to the module; the
// run loop and the studies reach the case only through Case<D> (run/case.hpp) and this record.
// Adding a case: a folder cases/<name>/ with a function returning its CaseModule, and one line in
// cases/registry.cpp.
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/config/scene_checks.hpp"
#include "sphmol/config/yaml_reader.hpp"
#include "sphmol/run/case.hpp"

namespace sphmol {

// What a module's reader returns: the settings Config keeps, and the scene's size as the builder
// will make it (particle counts, spacing, periodic lengths), for the shared checks.
struct CaseRead {
  std::shared_ptr<const CaseSettings> settings;
  SceneSize size;
  // With CaseModule::spacing_from_scene and neither discretization.particles_across nor spacing
  // given: the loader takes size.spacing as discretization.spacing and reports this rule as a notice.
  std::string spacing_rule = {};
  // Said to the user with the loader's other notices (a setting that has no effect, ...).
  std::vector<std::string> notices = {};
  // Whether the domain has a face open to outflow (run/outflow.hpp): without one,
  // health.max_outflow_fraction has nothing to count.
  bool open_to_outflow = false;
  // Whether size.wall counts the scene's wall particles (a scene too large to count while loading
  // does not): a counted 0 means discretization.wall_layers has nothing to set.
  bool wall_count_known = true;
};

struct CaseModule {
  std::string name;
  std::string description;             // one line: the flow and its reference
  std::vector<int> dimensions;         // the dimensions the case is built in
  std::vector<std::string> sections;   // top-level keys the case owns (e.g. "geometry")
  bool uses_fluid_density = true;      // false: the case's own states give the densities
  bool provides_energy = false;        // the scene sets an initial internal energy (discretization.energy)
  bool position_noise = false;         // the scene applies discretization.position_noise
  bool lattice_mass = false;           // the scene's lattice masses follow discretization.particle_mass
  bool free_surface = false;           // the fluid has a free surface (no transport velocity there)
  // Case::velocity_scale reads the config alone (not the built scene), so the loader can derive
  // defaults from it before the scene exists: fluid.eos.sound_speed = 10 U, the shifting velocity.
  bool velocity_scale_from_config = false;
  // The case derives the particle spacing from its geometry when neither particles_across nor
  // spacing is given (its reader returns it in CaseRead::size.spacing with the rule it used).
  bool spacing_from_scene = false;
  // fluid.eos.sound_speed when it is not given, from the config alone (the case's settings read), with
  // the rule in words for the notice; used before the velocity-scale default c = 10 U. May be empty.
  std::function<std::pair<double, std::string>(const Config& c)> default_sound_speed;

  // Case-specific defaults of shared keys, applied before the shared sections are read. May be empty.
  std::function<void(Config&)> defaults;
  // Reads the case's own sections from r.top and checks them, and the shared settings the case
  // depends on, failing through the readers (key and line): everything the scene builder would
  // reject (lengths that are not whole numbers of the spacing, ...) is an error here.
  std::function<CaseRead(CaseReaders& r, const Config& c)> read;
  // Scales every sound speed of the scene by `factor` (stability maps) and returns the sound speed
  // to report; throws ConfigError when the scaled scene is not valid for the case. Empty:
  // fluid.eos.sound_speed is scaled.
  std::function<double(Config& c, double factor)> scale_sound_speed;

  // The case in each dimension it supports (empty in the others).
  std::function<std::unique_ptr<Case<1>>()> make1;
  std::function<std::unique_ptr<Case<2>>()> make2;
  std::function<std::unique_ptr<Case<3>>()> make3;

  bool supports(int dimension) const {
    for (int d : dimensions)
      if (d == dimension) return true;
    return false;
  }
  std::string dimensions_text() const;  // "2", "1 or 2", "2 or 3"
};

// Every registered case, in registration order (cases/registry.cpp).
const std::vector<CaseModule>& case_modules();
// The case named `name`, or nullptr.
const CaseModule* find_case_module(const std::string& name);
// The names of every registered case, for messages and documentation checks.
std::vector<std::string> case_names();
// The case config.case_name in dimension D; std::invalid_argument if it is unknown or not built in D.
template <int D>
std::unique_ptr<Case<D>> make_case(const Config& config);

}  // namespace sphmol
