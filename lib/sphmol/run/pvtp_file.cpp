#include "sphmol/run/pvtp_file.hpp"

#include <sstream>

namespace sphmol {

std::string vtp_piece_name(const std::string& stem, int rank) { return stem + "_r" + std::to_string(rank) + ".vtp"; }

std::string pvtp_file(const VtkArrayLayout& layout, const std::vector<std::string>& sources) {
  const auto declare = [](std::ostringstream& s, const VtkArrayInfo& a) {
    s << "      <PDataArray type=\"" << a.type << "\" Name=\"" << a.name << "\" NumberOfComponents=\"" << a.components
      << "\"/>\n";
  };
  std::ostringstream s;
  s << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
    << "  <PPolyData GhostLevel=\"0\">\n"
    << "    <PPointData Scalars=\"density\" Vectors=\"velocity\">\n";
  for (const auto& a : layout.point_data) declare(s, a);
  s << "    </PPointData>\n    <PPoints>\n";
  declare(s, layout.points);
  s << "    </PPoints>\n";
  for (const auto& source : sources) s << "    <Piece Source=\"" << source << "\"/>\n";
  s << "  </PPolyData>\n</VTKFile>\n";
  return s.str();
}

}  // namespace sphmol
