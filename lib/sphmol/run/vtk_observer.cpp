#include "sphmol/run/vtk_observer.hpp"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "sphmol/io/atomic_file.hpp"

namespace sphmol {

namespace {

const char* const kPartName[3] = {"fluid", "walls", "ghosts"};

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// One array of the appended section: its XML attributes and its little-endian bytes.
struct Array {
  std::string type, name;
  int components;
  std::string bytes;
};

template <class T>
void append_le(std::string& out, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if constexpr (std::endian::native == std::endian::big)
    for (std::size_t k = 0; k < sizeof(T) / 2; ++k) std::swap(b[k], b[sizeof(T) - 1 - k]);
  out.append(b, sizeof(T));
}

template <class T, class Get>
Array make_array(const char* type, std::string name, int components, std::size_t n, Get get) {
  Array a{type, std::move(name), components, {}};
  a.bytes.reserve(n * static_cast<std::size_t>(components) * sizeof(T));
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < components; ++c) append_le<T>(a.bytes, static_cast<T>(get(i, c)));
  return a;
}

void array_tag(std::ostringstream& s, const Array& a, std::uint64_t offset, const char* indent, bool tuples = false) {
  s << indent << "<DataArray type=\"" << a.type << "\" Name=\"" << a.name << "\" NumberOfComponents=\"" << a.components
    << "\"";
  if (tuples) s << " NumberOfTuples=\"1\"";
  s << " format=\"appended\" offset=\"" << offset << "\"/>\n";
}

// The rows of `part` as particle indices of the system: fluid [0, nf), walls [nf, nb), ghosts
// [nb, nb + ng) (positions and fields of all of them are indexed so).
template <int D>
std::pair<std::size_t, std::size_t> part_range(const SphSystem<D>& sys, VtkPart part) {
  const std::size_t nf = sys.layout().n, nb = sys.base_particles();  // counts only (the particles may be released)
  switch (part) {
    case VtkPart::fluid: return {0, nf};
    case VtkPart::walls: return {nf, nb};
    case VtkPart::ghosts: return {nb, nb + sys.generated_particles()};
  }
  return {0, 0};
}

}  // namespace

template <int D>
std::size_t vtk_part_size(const SphSystem<D>& sys, VtkPart part) {
  const auto [b, e] = part_range(sys, part);
  return e - b;
}

namespace {

// The arrays of one .vtp: its TimeValue, the point data, the points and the vertex cells.
struct VtpArrays {
  std::vector<Array> time, point, points, verts;
};

// The arrays of `rows` (particle indices of sys, all of `part`), written with the ids `ids`.
template <int D>
VtpArrays vtp_arrays(const SphSystem<D>& sys, const double* y, double t, VtkPart part,
                     const std::vector<std::size_t>& rows, const std::vector<std::int64_t>& ids, bool every_block) {
  const auto& P = sys.particles();
  const auto& L = sys.layout();
  const auto& dom = sys.domain();
  const std::size_t nf = P.n_fluid;
  const std::size_t n = rows.size();
  const std::vector<double>& rho = sys.density();
  const std::vector<double>& p = sys.pressure();

  // Fluid from the state; walls where the solver puts them; ghosts as generated (their positions
  // and velocities exist only in the workspace, whose order is the state order when a generator is
  // set: SphSystem does not reorder then). All wrapped into the periodic box.
  const auto position = [&](std::size_t k, int d) {
    if (d >= D) return 0.0;
    const std::size_t i = rows[k];
    if (part == VtkPart::fluid) return dom.wrap(d, y[L.position(d) + i]);
    if (part == VtkPart::walls) return dom.wrap(d, P.wall_position(d, i, t));
    return dom.wrap(d, sys.positions()[d][i]);
  };
  const auto velocity = [&](std::size_t k, int d) {
    if (d >= D) return 0.0;
    const std::size_t i = rows[k];
    if (part == VtkPart::fluid) return y[L.velocity(d) + i];
    if (part == VtkPart::walls) return P.wall_velocity(d, i, t);
    return sys.velocities()[d][i];
  };
  const auto field = [&](const std::vector<double>& f) {
    return [&f, &rows](std::size_t k, int) { return rows[k] < f.size() ? f[rows[k]] : 0.0; };
  };

  VtpArrays a;
  a.time.push_back(make_array<double>("Float64", "TimeValue", 1, 1, [&](std::size_t, int) { return t; }));
  a.point.push_back(make_array<std::int64_t>("Int64", "id", 1, n, [&](std::size_t k, int) { return ids[k]; }));
  a.point.push_back(make_array<double>("Float64", "mass", 1, n, field(P.mass)));
  a.point.push_back(make_array<double>("Float64", "velocity", 3, n, velocity));
  // With an integrated density the fluid's is the state's own (the same values the RHS gathered).
  if (part == VtkPart::fluid && L.has_density)
    a.point.push_back(make_array<double>("Float64", "density", 1, n,
                                         [&](std::size_t k, int) { return y[L.density() + rows[k]]; }));
  else
    a.point.push_back(make_array<double>("Float64", "density", 1, n, field(rho)));
  a.point.push_back(make_array<double>("Float64", "pressure", 1, n, field(p)));
  a.point.push_back(make_array<std::uint8_t>("UInt8", "kind", 1, n, [&](std::size_t, int) {
    return static_cast<std::uint8_t>(part);
  }));
  // every_block: a piece declares the state blocks even where its system has no fluid, as every
  // other piece and the .pvtp do.
  if (part == VtkPart::fluid && (nf > 0 || every_block)) {
    // Further state blocks after the velocities, one scalar per fluid particle each, except the
    // density, written above (one array per name: ParaView shows only one of two equal names). Wall
    // densities of dynamic boundary particles, last in the state, are in the walls' "density".
    const std::size_t extra = L.extra_blocks();
    const std::vector<std::string> names = L.field_names();
    for (std::size_t b = 0; b < extra; ++b) {
      const std::string name = names.size() >= 2 + extra ? names[2 + b] : "state_block_" + std::to_string(b);
      if (name == "density") continue;
      a.point.push_back(make_array<double>("Float64", name, 1, n, [&, b](std::size_t k, int) {
        return y[L.velocities_end() + b * nf + rows[k]];
      }));
    }
  }
  a.points.push_back(make_array<double>("Float64", "Points", 3, n, position));
  // One vertex cell per particle, so ParaView draws the points without a glyph filter.
  a.verts.push_back(make_array<std::int64_t>("Int64", "connectivity", 1, n, [](std::size_t k, int) { return k; }));
  a.verts.push_back(make_array<std::int64_t>("Int64", "offsets", 1, n, [](std::size_t k, int) { return k + 1; }));
  return a;
}

std::string vtp_text(const VtpArrays& a, std::size_t n) {
  std::ostringstream s;
  std::uint64_t offset = 0;
  const auto tags = [&](const std::vector<Array>& arrays, const char* indent, bool tuples = false) {
    for (const auto& x : arrays) {
      array_tag(s, x, offset, indent, tuples);
      offset += sizeof(std::uint64_t) + x.bytes.size();
    }
  };
  s << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
    << "  <PolyData>\n    <FieldData>\n";
  tags(a.time, "      ", true);
  s << "    </FieldData>\n"
    << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
    << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
    << "      <PointData Scalars=\"density\" Vectors=\"velocity\">\n";
  tags(a.point, "        ");
  s << "      </PointData>\n      <Points>\n";
  tags(a.points, "        ");
  s << "      </Points>\n      <Verts>\n";
  tags(a.verts, "        ");
  s << "      </Verts>\n    </Piece>\n  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";
  std::string text = s.str();
  text.reserve(text.size() + offset + 32);
  for (const auto* group : {&a.time, &a.point, &a.points, &a.verts})
    for (const auto& x : *group) {
      append_le<std::uint64_t>(text, x.bytes.size());
      text += x.bytes;
    }
  text += "\n  </AppendedData>\n</VTKFile>\n";
  return text;
}

std::vector<VtkArrayInfo> infos(const std::vector<Array>& arrays) {
  std::vector<VtkArrayInfo> out;
  for (const auto& a : arrays) out.push_back({a.type, a.name, a.components});
  return out;
}

}  // namespace

template <int D>
std::string vtp_file(const SphSystem<D>& sys, const double* y, double t, VtkPart part) {
  const auto [first, last] = part_range(sys, part);
  std::vector<std::size_t> rows;
  std::vector<std::int64_t> ids;
  rows.reserve(last - first);
  ids.reserve(last - first);
  for (std::size_t i = first; i < last; ++i) {
    // Fluid taken out of the run (run/outflow.hpp) is not written; the ids of the others stay theirs.
    if (part == VtkPart::fluid && sys.is_retired(i)) continue;
    rows.push_back(i);
    // Ghosts -1: they are made anew at every evaluation.
    ids.push_back(part == VtkPart::ghosts ? std::int64_t{-1} : static_cast<std::int64_t>(i));
  }
  return vtp_text(vtp_arrays(sys, y, t, part, rows, ids, false), rows.size());
}

template <int D>
std::string vtp_piece_file(const SphSystem<D>& sys, const double* y, double t, VtkPart part,
                           const std::vector<std::size_t>& rows, const std::vector<std::int64_t>& ids) {
  if (ids.size() != rows.size()) throw std::invalid_argument("vtp_piece_file: one id per row");
  const auto [first, last] = part_range(sys, part);
  for (const std::size_t i : rows)
    if (i < first || i >= last) throw std::invalid_argument("vtp_piece_file: a row outside its particle group");
  return vtp_text(vtp_arrays(sys, y, t, part, rows, ids, true), rows.size());
}

template <int D>
VtkArrayLayout vtk_array_layout(const SphSystem<D>& sys, VtkPart part) {
  // The arrays of an empty selection: the same names, types and components as any piece's.
  const VtpArrays a = vtp_arrays(sys, nullptr, 0.0, part, {}, {}, true);
  return {infos(a.point), infos(a.points).front()};
}

template <int D>
void VtkObserver<D>::at_output(const SphSystem<D>& sys, const double* y, double t, const OutputSink& out) {
  if (!out.enabled) return;
  std::vector<VtkPart> parts{VtkPart::fluid};
  if (walls_ && vtk_part_size(sys, VtkPart::walls) > 0) parts.push_back(VtkPart::walls);
  if (ghosts_ && vtk_part_size(sys, VtkPart::ghosts) > 0) parts.push_back(VtkPart::ghosts);
  for (const VtkPart part : parts) {
    char name[48];
    std::snprintf(name, sizeof name, "%s_%04zu.vtp", kPartName[static_cast<int>(part)], outputs_);
    out.write(name, vtp_file(sys, y, t, part));
    written_.push_back({t, static_cast<int>(part), name});
  }
  ++outputs_;
  write_collection(out);
}

template <int D>
void VtkObserver<D>::write_collection(const OutputSink& out) const {
  // Rewritten every time, so an interrupted run still leaves a complete collection.
  std::ostringstream s;
  s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "  <Collection>\n";
  for (const auto& e : written_)
    s << "    <DataSet timestep=\"" << number(e.t) << "\" group=\"\" part=\"" << e.part << "\" name=\""
      << kPartName[e.part] << "\" file=\"" << e.file << "\"/>\n";
  s << "  </Collection>\n</VTKFile>\n";
  out.write("particles.pvd", s.str());
}

template <int D>
void VtkObserver<D>::at_output_pieces(const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t, const OutputSink& out) {
  if (!out.enabled) return;  // the same on every rank
  // The groups of the serial output, decided on the whole scene (a rank may own no wall), and for
  // the ghosts on every rank's images of its own sources (the whole system is not evaluated here).
  std::vector<VtkPart> parts{VtkPart::fluid};
  if (walls_ && vtk_part_size(whole, VtkPart::walls) > 0) parts.push_back(VtkPart::walls);
  if (ghosts_ && piece.sum(piece.ghost_rows.size()) > 0) parts.push_back(VtkPart::ghosts);
  const auto stem = [&](VtkPart part) {
    char name[48];
    std::snprintf(name, sizeof name, "%s_%04zu", kPartName[static_cast<int>(part)], outputs_);
    return std::string(name);
  };
  // Ghosts are -1, as in the serial file: they are made anew at every evaluation.
  const std::vector<std::int64_t> ghost_ids(piece.ghost_rows.size(), -1);
  for (const VtkPart part : parts) {
    const bool fluid = part == VtkPart::fluid, ghosts = part == VtkPart::ghosts;
    out.write(vtp_piece_name(stem(part), piece.rank),
              vtp_piece_file(*piece.system, piece.y, t, part,
                             fluid ? piece.fluid_rows : ghosts ? piece.ghost_rows : piece.wall_rows,
                             fluid ? piece.fluid_ids : ghosts ? ghost_ids : piece.wall_ids));
  }
  // Every piece is on disk before a collection names it.
  piece.barrier();
  for (const VtkPart part : parts) {
    const std::string file = stem(part) + ".pvtp";
    if (piece.rank == 0) {
      std::vector<std::string> sources;
      for (int r = 0; r < piece.ranks; ++r) {
        sources.push_back(vtp_piece_name(stem(part), r));
        out.record(sources.back());  // written by rank r, listed in rank 0's summary
      }
      out.write(file, pvtp_file(vtk_array_layout(*piece.system, part), sources));
    }
    written_.push_back({t, static_cast<int>(part), file});
  }
  ++outputs_;
  if (piece.rank == 0) write_collection(out);
}

template <int D>
nlohmann::json VtkObserver<D>::save_state() const {
  nlohmann::json files = nlohmann::json::array();
  for (const auto& e : written_) files.push_back({{"t", e.t}, {"part", e.part}, {"file", e.file}});
  return {{"files", files}, {"outputs", outputs_}};
}

template <int D>
void VtkObserver<D>::restore_state(const nlohmann::json& state, const OutputSink& out) {
  // Continue the collection with the earlier files that are in this output directory (a restart
  // into another directory starts a new collection, numbered from 0).
  written_.clear();
  outputs_ = 0;
  if (!state.contains("files")) return;
  for (const auto& f : state["files"]) {
    const std::string file = f.at("file").get<std::string>();
    const int part = f.value("part", 0);
    if (part < 0 || part > 2) continue;
    if (std::filesystem::exists(out.path(file))) written_.push_back({f.at("t").get<double>(), part, file});
  }
  if (written_.empty()) return;
  if (state.contains("outputs")) {
    outputs_ = state["outputs"].get<std::size_t>();
  } else {  // a checkpoint without the count: one output time per distinct t
    for (std::size_t k = 0; k < written_.size(); ++k) outputs_ += k == 0 || written_[k].t != written_[k - 1].t;
  }
}

template class VtkObserver<1>;
template class VtkObserver<2>;
template class VtkObserver<3>;
template std::size_t vtk_part_size<1>(const SphSystem<1>&, VtkPart);
template std::size_t vtk_part_size<2>(const SphSystem<2>&, VtkPart);
template std::size_t vtk_part_size<3>(const SphSystem<3>&, VtkPart);
template std::string vtp_file<1>(const SphSystem<1>&, const double*, double, VtkPart);
template std::string vtp_file<2>(const SphSystem<2>&, const double*, double, VtkPart);
template std::string vtp_file<3>(const SphSystem<3>&, const double*, double, VtkPart);
template std::string vtp_piece_file<1>(const SphSystem<1>&, const double*, double, VtkPart, const std::vector<std::size_t>&,
                                       const std::vector<std::int64_t>&);
template std::string vtp_piece_file<2>(const SphSystem<2>&, const double*, double, VtkPart, const std::vector<std::size_t>&,
                                       const std::vector<std::int64_t>&);
template std::string vtp_piece_file<3>(const SphSystem<3>&, const double*, double, VtkPart, const std::vector<std::size_t>&,
                                       const std::vector<std::int64_t>&);
template VtkArrayLayout vtk_array_layout<1>(const SphSystem<1>&, VtkPart);
template VtkArrayLayout vtk_array_layout<2>(const SphSystem<2>&, VtkPart);
template VtkArrayLayout vtk_array_layout<3>(const SphSystem<3>&, VtkPart);

}  // namespace sphmol
