#include "sphmol/io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace sphmol {

namespace {

std::string reason(int err) {
  // EFBIG: `ulimit -f` (SIGXFSZ is ignored by the program, so write() reports it instead of a kill).
  if (err == EFBIG) return std::string(std::strerror(err)) + " (the file size limit, ulimit -f, was reached)";
  return std::strerror(err);
}

// The directory a path lives in ("." for a bare file name).
std::string parent_of(const std::string& path) {
  const std::string parent = std::filesystem::path(path).parent_path().string();
  return parent.empty() ? "." : parent;
}

}  // namespace

void fsync_directory(const std::string& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;  // best effort: the rename itself is atomic
  ::fsync(fd);
  ::close(fd);
}

int create_unique_temporary(const std::string& path, std::string& tmp_path) {
  const std::filesystem::path p(path);
  std::string templ = (std::filesystem::path(parent_of(path)) / ("." + p.filename().string() + ".XXXXXX")).string();
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  // mkostemp creates the file with O_CREAT | O_EXCL: it never opens an existing file or a link.
  const int fd = ::mkostemp(buf.data(), O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("cannot create a temporary file for " + path + ": " + reason(errno));
  ::fchmod(fd, 0644);
  tmp_path.assign(buf.data());
  return fd;
}

void write_file_atomically(const std::string& path, const std::string& content) {
  std::string tmp;
  const int fd = create_unique_temporary(path, tmp);
  const auto fail = [&](const std::string& what, int err) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw std::runtime_error("cannot " + what + " " + path + ": " + reason(err));
  };
  const char* p = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t w = ::write(fd, p, left);
    if (w < 0) {
      if (errno == EINTR) continue;
      fail("write", errno);
    }
    p += w;
    left -= static_cast<std::size_t>(w);
  }
  if (::fsync(fd) != 0) fail("flush", errno);
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw std::runtime_error("cannot flush " + path + ": " + reason(err));
  }
  // rename() replaces a link at `path` by the file itself; it never writes through the link.
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw std::runtime_error("cannot rename a temporary file to " + path + ": " + reason(err));
  }
  fsync_directory(parent_of(path));
}

}  // namespace sphmol
