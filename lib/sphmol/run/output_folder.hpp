#pragma once
// A run's claim on its output folder, held for the run's lifetime:
// - an exclusive lock (flock on DIR/.sph-mol.lock), so a second run into the same folder stops with a
//   clear error instead of overwriting the first one's files;
// - a folder that holds another run's summary.json is refused unless `overwrite`, which first deletes
//   exactly the files that run listed in its summary (nothing else in the folder is touched);
// - `continuing` (a restart into its own run folder) accepts the summary the interrupted run left;
// - `lock_only` (a study) takes the lock and leaves the folder's contents alone, but refuses a folder
//   that holds a run's summary.json;
// - a folder whose own name is a symbolic link is refused (io/links.hpp), and so is a summary.json
//   that is a link, a FIFO, a device or larger than a summary can be;
// - folders it created are removed again when it is destroyed by an exception while they hold
//   nothing but the lock file: a run or study that fails before writing leaves no empty folder.
#include <stdexcept>
#include <string>
#include <vector>

namespace sphmol {

struct OutputFolderError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class OutputFolder {
 public:
  struct Options {
    bool overwrite = false;
    bool continuing = false;
    // Only the lock: a study (compare, converge, stability) rewrites its own fixed file names, and a
    // second study into the same folder while the first runs is what must be stopped; a run's folder
    // is refused.
    bool lock_only = false;
  };
  // Creates the folder if needed (and its parents), locks it and checks it. Throws OutputFolderError.
  OutputFolder(const std::string& directory, Options options);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::string& directory() const { return directory_; }

 private:
  std::string directory_;
  int lock_fd_ = -1;
  // The folders create_directories made, innermost first, and the exceptions in flight at the start.
  std::vector<std::string> created_;
  int uncaught_ = 0;
};

// The name of the lock file inside an output folder.
inline constexpr const char* kOutputLockFile = ".sph-mol.lock";

}  // namespace sphmol
