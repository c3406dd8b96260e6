#include "sphmol/io/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace sphmol {

std::string format_bytes(std::uintmax_t bytes) {
  if (bytes >= (std::uintmax_t{1} << 30) && bytes % (std::uintmax_t{1} << 30) == 0)
    return std::to_string(bytes >> 30) + " GiB";
  if (bytes >= (std::uintmax_t{1} << 20) && bytes % (std::uintmax_t{1} << 20) == 0)
    return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

std::string read_input_file(const std::string& path, std::uintmax_t max_bytes, const std::string& what,
                            InputLinks links) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused below anyway.
  const int nofollow = links == InputLinks::refuse ? O_NOFOLLOW : 0;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | nofollow);
  if (fd < 0) {
    const int err = errno;
    struct stat lst {};
    // O_NOFOLLOW fails with ELOOP on a link: say so rather than "too many levels of symbolic links".
    if (nofollow && err == ELOOP && ::lstat(path.c_str(), &lst) == 0 && S_ISLNK(lst.st_mode))
      throw InputFileError(path + ": a symbolic link; a " + what + " is never read through a link");
    throw InputFileError(path + ": cannot open " + what + ": " + std::strerror(err));
  }
  struct FdCloser {
    int fd;
    ~FdCloser() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw InputFileError(path + ": cannot stat " + what + ": " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw InputFileError(path + ": is a directory, not a " + what);
  if (!S_ISREG(st.st_mode)) throw InputFileError(path + ": not a regular file (a device, FIFO or socket cannot be a " + what + ")");
  const auto too_large = [&] {
    return InputFileError(path + ": " + what + " is larger than the limit of " + format_bytes(max_bytes));
  };
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes) throw too_large();
  std::string content;
  content.reserve(static_cast<std::size_t>(st.st_size));
  char buf[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw InputFileError(path + ": cannot read " + what + ": " + std::strerror(errno));
    }
    if (n == 0) break;
    // The file may grow while it is read (another process appending): the limit still holds.
    if (content.size() + static_cast<std::size_t>(n) > max_bytes) throw too_large();
    content.append(buf, static_cast<std::size_t>(n));
  }
  return content;
}

}  // namespace sphmol
