#include "sphmol/io/links.hpp"

#include <filesystem>

namespace sphmol {

namespace fs = std::filesystem;

std::optional<std::string> final_link_message(const std::string& path) {
  if (path.empty()) return std::nullopt;
  // "link/" and "link/." name the link too, and the system follows it there: fold them to "link".
  fs::path p = fs::path(path).lexically_normal();
  if (!p.has_filename() && p.has_relative_path()) p = p.parent_path();
  std::error_code ec;
  if (fs::symlink_status(p, ec).type() != fs::file_type::symlink) return std::nullopt;
  fs::path target = fs::read_symlink(p, ec);
  // A relative target counts from the link's folder: name the folder the user can pass as it is.
  if (!ec && target.is_relative()) target = (p.parent_path() / target).lexically_normal();
  const std::string why = "; links are not followed (one planted under that name would redirect the files): give ";
  if (ec) return path + " is a symbolic link" + why + "the folder it points to itself";
  return path + " is a symbolic link to " + target.string() + why + target.string() + " itself";
}

}  // namespace sphmol
