// libFuzzer target for the triangle-mesh reader (geometry/triangle_mesh_shape.cpp): the first byte
// picks the format (STL, OFF, PLY, OBJ), the rest are the file's bytes. Every input must either give
// a closed surface, whose inside test and distance are finite, or be refused with
// std::invalid_argument (no other exception, crash, hang, huge allocation or sanitizer report).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "sphmol/geometry/triangle_mesh_shape.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kFormats[] = {"stl", "off", "ply", "obj"};
  const std::string format = kFormats[data[0] % 4];
  const std::string bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    const sphmol::geometry::TriangleMeshShape mesh(bytes, format, "fuzz." + format);
    const auto b = mesh.bounds();
    const sphmol::geometry::Vec<3> centre{0.5 * (b.lo[0] + b.hi[0]), 0.5 * (b.lo[1] + b.hi[1]), 0.5 * (b.lo[2] + b.hi[2])};
    if (std::isfinite(centre[0]) && std::isfinite(centre[1]) && std::isfinite(centre[2]) &&
        std::isnan(mesh.signed_distance(centre)))
      std::abort();
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
