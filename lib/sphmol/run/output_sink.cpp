#include <algorithm>

#include "sphmol/io/atomic_file.hpp"
#include "sphmol/run/case.hpp"

namespace sphmol {

void OutputSink::write(const std::string& file, const std::string& content) const {
  write_file_atomically(path(file), content);
  record(file);
}

void OutputSink::record(const std::string& file) const {
  if (std::find(files->begin(), files->end(), file) == files->end()) files->push_back(file);
}

}  // namespace sphmol
