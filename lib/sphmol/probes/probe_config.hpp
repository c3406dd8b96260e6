#pragma once
// The `probes` section: named sampling points, lines, planes, free-surface gauges and wall-body
// forces, each written to its own CSV (probes/probe_observer.hpp). Read by the loader through
// read_probes(), written back by probes_to_yaml(); config/README.md documents the keys.
#include <optional>
#include <string>
#include <vector>

namespace sphmol {

// config.hpp holds a list of ProbeConfig and yaml_reader.hpp includes config.hpp: declared only.
class MapReader;

struct ProbeConfig {
  std::string name;  // [A-Za-z0-9_-]+, unique: the file is probe_<name>.csv
  std::string type;  // point | line | plane | height_gauge | force
  // point: `at`; line: `from`, `to`, `points` (>= 2); plane (3D): `origin`, `edge_1`, `edge_2`,
  // `points` = {n1, n2} (each >= 2); height_gauge: `at` (the D - 1 horizontal coordinates) and the
  // scanned vertical `range` (empty: the vertical extent of all particles); force: `body`.
  std::vector<double> at, from, to, origin, edge_1, edge_2, range;
  std::vector<int> points;
  // point, line, plane: any of "p", "rho", "velocity" (in that column order); default all three.
  std::vector<std::string> fields;
  std::string body;     // force: the wall body's name
  int body_index = -1;  // force: its index in the scene's body list (Particles::body)
  std::optional<double> every;  // sample every `every` s (from t = 0); absent: at the output times
  // "FILE:LINE: probes[i].KEY" of the key that places the probe (at / from / origin / body), for the
  // checks that need the built scene (a point outside the particles' bounds): a ConfigError there.
  std::string where;

  // The sample points of a point, line or plane probe, in CSV row order (plane: edge_1 fastest).
  std::vector<std::vector<double>> sample_points() const;
};

struct Config;

// Reads `probes` from the top-level map. `config`: the run's settings read so far (dimension,
// time.t_end, discretization); `bodies`: the names of the scene's wall bodies (index =
// Particles::body), empty for scenes without named bodies. Throws ConfigError through the reader
// (FILE:LINE: probes[i].key: message).
// `notices` receives what is accepted but worth saying (an `every` past t_end).
std::vector<ProbeConfig> read_probes(MapReader& top, const Config& config, const std::vector<std::string>& bodies,
                                     std::vector<std::string>* notices = nullptr);

// The resolved `probes` section as YAML (top-level key at column 0); "" when there are none.
std::string probes_to_yaml(const std::vector<ProbeConfig>& probes);

}  // namespace sphmol
