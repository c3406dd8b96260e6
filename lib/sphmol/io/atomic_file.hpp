#pragma once
// Write a whole file or nothing: content goes to a temporary file in the same directory, is
// flushed to disk, then renamed over the target. A killed run never leaves a truncated result.
#include <string>

namespace sphmol {

void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace sphmol
