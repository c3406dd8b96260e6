#pragma once
// Write a whole file or nothing: content goes to a uniquely named temporary file in the same
// directory (created with O_EXCL, so a file or symbolic link planted there is never opened), is
// flushed to disk, then renamed over the target. A killed run, a full disk or a file size limit never
// leaves a truncated file under the final name, and a link at the final name is replaced, not followed.
#include <string>

namespace sphmol {

void write_file_atomically(const std::string& path, const std::string& content);

// Creates `.NAME.XXXXXX` next to `path` with O_CREAT | O_EXCL (mode 0644) and returns its open
// descriptor; `tmp_path` receives its name. For writers that stream into the file themselves and then
// rename it over `path`. Throws std::runtime_error.
int create_unique_temporary(const std::string& path, std::string& tmp_path);

// fsync on a directory, so a rename into it survives a crash (best effort).
void fsync_directory(const std::string& dir);

}  // namespace sphmol
