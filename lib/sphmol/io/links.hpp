#pragma once
// Folders the program writes into or reads a run from must not be symbolic links: a link planted
// under the name given would send checkpoints and results (or a restart) wherever it points. Only
// the last component is judged; links higher up (such as /home) are ordinary system layout.
#include <optional>
#include <string>

namespace sphmol {

// If the last component of `path` is a symbolic link (also when written "link/" or "link/.", which
// the system would follow): "PATH is a symbolic link to TARGET; ... give TARGET itself". Else nullopt.
std::optional<std::string> final_link_message(const std::string& path);

}  // namespace sphmol
