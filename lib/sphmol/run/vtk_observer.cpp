#include "sphmol/run/vtk_observer.hpp"

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "sphmol/io/atomic_file.hpp"

namespace sphmol {

namespace {

void put(std::ostringstream& s, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  s << buf;
}

template <class Get>
void data_array(std::ostringstream& s, const char* type, const std::string& name, int components, std::size_t n,
                Get get) {
  s << "        <DataArray type=\"" << type << "\"";
  if (!name.empty()) s << " Name=\"" << name << "\"";
  s << " NumberOfComponents=\"" << components << "\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < n; ++i) {
    s << "          ";
    for (int c = 0; c < components; ++c) {
      if (c) s << ' ';
      put(s, get(i, c));
    }
    s << '\n';
  }
  s << "        </DataArray>\n";
}

std::string pvd_text(const std::vector<std::pair<double, std::string>>& files) {
  std::ostringstream s;
  s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "  <Collection>\n";
  for (const auto& [t, f] : files) {
    s << "    <DataSet timestep=\"";
    put(s, t);
    s << "\" group=\"\" part=\"0\" file=\"" << f << "\"/>\n";
  }
  s << "  </Collection>\n</VTKFile>\n";
  return s.str();
}

}  // namespace

template <int D>
std::string vtp_text(const SphSystem<D>& sys, const double* y, double t, bool walls, bool ghosts) {
  const auto& P = sys.particles();
  const auto& L = sys.layout();
  const auto& dom = sys.domain();
  // Written: fluid [0, nf), then walls [nf, nb) if asked, then ghosts [nb, nb + ng) if asked.
  const std::size_t nf = P.n_fluid, nb = sys.base_particles(), ng = ghosts ? sys.generated_particles() : 0;
  const std::size_t nw = walls ? nb - nf : 0, n = nf + nw + ng;
  const auto index = [&](std::size_t k) { return k < nf + nw ? k : nb + (k - nf - nw); };  // row -> particle
  const auto position = [&](std::size_t k, int d) {
    if (d >= D) return 0.0;
    const std::size_t i = index(k);
    // Fluid from the state; walls move rigidly, x = x_ref + v t; ghosts as generated. Wrapped into
    // the periodic box.
    if (i >= nb) return dom.wrap(d, sys.positions()[d][i]);
    return dom.wrap(d, i < nf ? y[L.position(d) + i] : P.x_ref[d][i] + P.v[d][i] * t);
  };
  const auto velocity = [&](std::size_t k, int d) {
    if (d >= D) return 0.0;
    const std::size_t i = index(k);
    if (i >= nb) return sys.velocities()[d][i];
    return i < nf ? y[L.velocity(d) + i] : P.v[d][i];
  };
  const std::vector<double>& rho = sys.density();
  const std::vector<double>& p = sys.pressure();
  const auto kind = [&](std::size_t k) {
    const std::size_t i = index(k);
    return i >= nb ? 2.0 : static_cast<double>(P.kind[i]);
  };

  // Further state blocks after the velocities, one scalar per fluid particle each (walls: 0).
  // (Wall densities of dynamic boundary particles, last in the state, are in "density" already.)
  const std::size_t extra = nf > 0 ? L.extra_blocks() : 0;
  std::vector<std::string> names = L.field_names();
  std::vector<std::string> extra_names;
  for (std::size_t k = 0; k < extra; ++k)
    extra_names.push_back(names.size() >= 2 + extra ? names[2 + k] : "state_block_" + std::to_string(k));

  std::ostringstream s;
  s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
    << "  <PolyData>\n    <FieldData>\n"
    << "      <DataArray type=\"Float64\" Name=\"TIME\" NumberOfTuples=\"1\" format=\"ascii\">";
  put(s, t);
  s << "</DataArray>\n    </FieldData>\n"
    << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
    << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
    << "      <PointData Scalars=\"density\" Vectors=\"velocity\">\n";
  data_array(s, "Float64", "velocity", 3, n, velocity);
  data_array(s, "Float64", "density", 1, n, [&](std::size_t k, int) {
    const std::size_t i = index(k);
    return i < rho.size() ? rho[i] : 0.0;
  });
  data_array(s, "Float64", "pressure", 1, n, [&](std::size_t k, int) {
    const std::size_t i = index(k);
    return i < p.size() ? p[i] : 0.0;
  });
  data_array(s, "UInt8", "kind", 1, n, [&](std::size_t k, int) { return kind(k); });
  for (std::size_t k = 0; k < extra; ++k)
    data_array(s, "Float64", extra_names[k], 1, n,
               [&](std::size_t i, int) { return i < nf ? y[L.velocities_end() + k * nf + i] : 0.0; });
  s << "      </PointData>\n      <Points>\n";
  data_array(s, "Float64", "", 3, n, position);
  s << "      </Points>\n      <Verts>\n";
  // One vertex cell per particle, so ParaView draws the points without a glyph filter.
  data_array(s, "Int64", "connectivity", 1, n, [](std::size_t i, int) { return static_cast<double>(i); });
  data_array(s, "Int64", "offsets", 1, n, [](std::size_t i, int) { return static_cast<double>(i + 1); });
  s << "      </Verts>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  return s.str();
}

template <int D>
void VtkObserver<D>::at_output(const SphSystem<D>& sys, const double* y, double t, const OutputSink& out) {
  if (!out.enabled) return;
  char name[32];
  std::snprintf(name, sizeof name, "particles_%04zu.vtp", written_.size());
  out.write(name, vtp_text(sys, y, t, walls_, ghosts_));
  written_.emplace_back(t, name);
  // Rewritten every time, so an interrupted run still leaves a complete collection.
  out.write("particles.pvd", pvd_text(written_));
}

template <int D>
nlohmann::json VtkObserver<D>::save_state() const {
  nlohmann::json files = nlohmann::json::array();
  for (const auto& [t, f] : written_) files.push_back({{"t", t}, {"file", f}});
  return {{"files", files}};
}

template <int D>
void VtkObserver<D>::restore_state(const nlohmann::json& state, const OutputSink& out) {
  // Continue the collection with the earlier files that are in this output directory (a restart
  // into another directory starts a new collection).
  written_.clear();
  if (!state.contains("files")) return;
  for (const auto& f : state["files"]) {
    const std::string file = f.at("file").get<std::string>();
    if (std::filesystem::exists(out.path(file))) written_.emplace_back(f.at("t").get<double>(), file);
  }
}

template class VtkObserver<1>;
template class VtkObserver<2>;
template class VtkObserver<3>;
template std::string vtp_text<1>(const SphSystem<1>&, const double*, double, bool, bool);
template std::string vtp_text<2>(const SphSystem<2>&, const double*, double, bool, bool);
template std::string vtp_text<3>(const SphSystem<3>&, const double*, double, bool, bool);

}  // namespace sphmol
