#include "sphmol/run/output_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>

#include "sphmol/io/input_file.hpp"
#include "sphmol/io/links.hpp"

namespace sphmol {

namespace fs = std::filesystem;

namespace {

// A name a summary may list for deletion: one plain entry of this folder, never a path out of it.
bool plain_name(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos &&
         name.find('\0') == std::string::npos && name != kOutputLockFile;
}

// A run's summary lists its files and measurements: megabytes at most. The cap keeps a planted
// /dev/zero-like or huge file from exhausting memory.
constexpr std::uintmax_t kMaxSummaryBytes = std::uintmax_t{64} << 20;

// The files of the run whose summary.json is in `dir` (the summary lists them under "files"; it and
// the resolved config.yaml are always that run's). The summary is read as an input file: a FIFO
// would block for ever with the folder locked, and a link is refused (a run writes a plain file).
// Throws InputFileError.
std::set<std::string> files_of_previous_run(const fs::path& summary) {
  std::set<std::string> names{"summary.json", "config.yaml"};
  const std::string text = read_input_file(summary.string(), kMaxSummaryBytes, "run summary", InputLinks::refuse);
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_object() && j.contains("files") && j["files"].is_array())
    for (const auto& f : j["files"])
      if (f.is_string() && plain_name(f.get<std::string>())) names.insert(f.get<std::string>());
  return names;
}

}  // namespace

OutputFolder::OutputFolder(const std::string& directory, Options options)
    : directory_(directory), uncaught_(std::uncaught_exceptions()) {
  // Before anything is created: a link under the folder's name would receive every file.
  if (const auto link = final_link_message(directory)) throw OutputFolderError("output directory " + *link);
  std::error_code ec;
  fs::path top = fs::path(directory).lexically_normal();
  if (!top.has_filename()) top = top.parent_path();  // "a/b/" names the folder a/b
  for (fs::path p = top; !p.empty() && !fs::exists(fs::symlink_status(p, ec)); p = p.parent_path()) {
    created_.push_back(p.string());
    if (p == p.parent_path()) break;
  }
  fs::create_directories(directory, ec);
  if (ec || !fs::is_directory(directory))
    throw OutputFolderError("output directory " + directory + ": cannot create it" + (ec ? ": " + ec.message() : std::string()));
  const std::string lock = (fs::path(directory) / kOutputLockFile).string();
  // O_NOFOLLOW: a link planted under the lock file's name is refused, never opened.
  lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (lock_fd_ < 0)
    throw OutputFolderError("output directory " + directory + ": cannot open its lock file " + kOutputLockFile + ": " +
                            std::strerror(errno));
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(lock_fd_);
    lock_fd_ = -1;
    throw OutputFolderError(err == EWOULDBLOCK ? "output directory " + directory +
                                                     ": another sph-mol run is writing there (choose another --output)"
                                               : "output directory " + directory + ": cannot lock it: " + std::strerror(err));
  }
  const auto refuse = [this](const std::string& message) {
    ::close(lock_fd_);
    lock_fd_ = -1;
    return OutputFolderError(message);
  };
  const fs::path summary = fs::path(directory) / "summary.json";
  if (options.continuing || !fs::exists(fs::symlink_status(summary))) return;
  // A study's files beside a run's would be neither in that run's file list (its --overwrite leaves
  // them) nor told apart from it.
  if (options.lock_only)
    throw refuse("output directory " + directory + " holds the results of a run (summary.json); a study does not write "
                 "into a run's folder: choose another --output");
  if (!options.overwrite)
    throw refuse("output directory " + directory +
                 " holds the results of another run (summary.json); choose another --output, or give "
                 "--overwrite to delete that run's files first");
  std::set<std::string> previous;
  try {
    previous = files_of_previous_run(summary);
  } catch (const InputFileError& e) {
    throw refuse("output directory " + directory + ": --overwrite reads the earlier run's summary.json to know its files: " +
                 e.what() + "; remove it or choose another --output");
  }
  for (const std::string& name : previous) {
    const fs::path p = fs::path(directory) / name;
    // remove_all deletes a link itself, never what it points to.
    fs::remove_all(p, ec);
    if (ec) throw refuse("output directory " + directory + ": --overwrite cannot delete " + name + ": " + ec.message());
  }
}

OutputFolder::~OutputFolder() {
  // A folder this claim made, left by a failure with nothing in it but the lock file, is removed (the
  // lock is unlinked while still held; a run that opens the folder meanwhile makes it non-empty, and
  // then it stays). Otherwise the lock file stays: deleting it would let a run that opened it
  // meanwhile lock a dead file.
  if (lock_fd_ >= 0 && !created_.empty() && std::uncaught_exceptions() > uncaught_) {
    std::error_code ec;
    bool only_lock = true;
    for (const auto& e : fs::directory_iterator(directory_, ec)) only_lock = only_lock && e.path().filename() == kOutputLockFile;
    if (!ec && only_lock) {
      fs::remove(fs::path(directory_) / kOutputLockFile, ec);
      // fs::remove on a folder is rmdir: it fails, and leaves the folder, unless it is empty.
      for (const auto& d : created_)
        if (!fs::remove(d, ec)) break;
    }
  }
  if (lock_fd_ >= 0) ::close(lock_fd_);
}

}  // namespace sphmol
