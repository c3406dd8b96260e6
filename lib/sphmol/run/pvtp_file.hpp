#pragma once
// The VTK parallel PolyData file (.pvtp) of a run over several ranks: it declares the point arrays
// that every piece holds (names, types, components, as in the pieces) and names each rank's piece
// file, a .vtp beside it; ParaView and VisIt read the pieces through it as one data set.
// Piece names: `<stem>_r<rank>.vtp` beside `<stem>.pvtp` (fluid_0003.pvtp: fluid_0003_r0.vtp,
// fluid_0003_r1.vtp, ...), plain names in the output folder, like every file a run writes.
#include <string>
#include <vector>

namespace sphmol {

// One DataArray as a .vtp declares it.
struct VtkArrayInfo {
  std::string type, name;
  int components = 1;
};

// The arrays of a .vtp piece: its point data and its points.
struct VtkArrayLayout {
  std::vector<VtkArrayInfo> point_data;
  VtkArrayInfo points;
};

// The name of rank `rank`'s piece of `<stem>.pvtp`.
std::string vtp_piece_name(const std::string& stem, int rank);

// The .pvtp text: GhostLevel 0 (no piece holds another's particles), the arrays of `layout`, and
// one <Piece Source=...> per name in `sources` (paths relative to the .pvtp), in rank order.
std::string pvtp_file(const VtkArrayLayout& layout, const std::vector<std::string>& sources);

}  // namespace sphmol
