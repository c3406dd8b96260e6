#include "sphmol/reference/data_directory.hpp"

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace sphmol {

std::vector<std::string> reference_data_dirs(const std::string& exe) {
  namespace fs = std::filesystem;
  std::vector<std::string> dirs;
  if (!exe.empty()) dirs.push_back((fs::path(exe).parent_path().parent_path() / "share" / "sph-mol").string());
  dirs.push_back(std::string(SPHMOL_SOURCE_DIR) + "/verification");
  dirs.push_back(std::string(SPHMOL_DATA_DIR));
  return dirs;
}

std::string reference_data_file(const std::string& name) {
  namespace fs = std::filesystem;
  std::error_code ec;
  // The kernel's link to this process's executable; not a path a user can plant.
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  const auto dirs = reference_data_dirs(ec ? std::string() : exe.string());
  std::string searched;
  for (const auto& d : dirs) {
    const fs::path p = fs::path(d) / name;
    if (fs::is_regular_file(p, ec)) return p.string();
    searched += (searched.empty() ? "" : ", ") + d;
  }
  throw std::runtime_error("reference data file " + name + " not found (searched " + searched + ")");
}

}  // namespace sphmol
