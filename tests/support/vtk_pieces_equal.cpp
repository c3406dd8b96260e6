// vtk-pieces-equal SERIAL.vtp PARALLEL.pvtp [PIECES]: exit 0 when the pieces of PARALLEL.pvtp
// (PIECES of them, if given) together hold the particles of SERIAL.vtp, with the same arrays and
// the same values to the bit (vtk_pieces.hpp); else 1 and what differs. For the CMake tests of
// sph-mol under mpirun.
#include <iostream>
#include <string>

#include "vtk_pieces.hpp"

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::cerr << "usage: vtk-pieces-equal SERIAL.vtp PARALLEL.pvtp [PIECES]\n";
    return 2;
  }
  try {
    const vtk_pieces::Particles serial = vtk_pieces::read_vtp(argv[1]);
    const vtk_pieces::Particles split = vtk_pieces::read_pvtp(argv[2]);
    if (argc == 4 && split.pieces != std::stoull(argv[3])) {
      std::cerr << argv[2] << ": " << split.pieces << " pieces, expected " << argv[3] << '\n';
      return 1;
    }
    const std::string why = vtk_pieces::difference(split, serial);
    if (!why.empty()) {
      std::cerr << argv[2] << " against " << argv[1] << ": " << why << '\n';
      return 1;
    }
  } catch (const std::exception& e) {
    std::cerr << e.what() << '\n';
    return 1;
  }
  return 0;
}
