#include "sphmol/io/gnuplot.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "sphmol/io/atomic_file.hpp"

namespace sphmol {

namespace {

bool is_alnum(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); }

std::string quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

// A complete PNG: the 8-byte signature first and the IEND chunk (length 0, type, CRC) last.
bool complete_png(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  char head[8] = {};
  f.read(head, 8);
  if (!f || std::memcmp(head, "\x89PNG\r\n\x1a\n", 8) != 0) return false;
  f.seekg(-12, std::ios::end);
  char tail[12] = {};
  f.read(tail, 12);
  return f && std::memcmp(tail, "\0\0\0\0IEND\xae\x42\x60\x82", 12) == 0;
}

std::string log_name_of(const std::string& script_name) {
  const std::string stem =
      script_name.size() > 3 && script_name.ends_with(".gp") ? script_name.substr(0, script_name.size() - 3) : script_name;
  return stem + ".gnuplot.log";
}

bool write_all(int fd, const std::string& text) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t w = ::write(fd, p, left);
    if (w < 0 && errno == EINTR) continue;
    if (w < 0) return false;
    p += w;
    left -= static_cast<std::size_t>(w);
  }
  return true;
}

// Removes a temporary on every path out of run_gnuplot unless released.
struct TemporaryFile {
  std::string path;
  ~TemporaryFile() {
    if (!path.empty()) ::unlink(path.c_str());
  }
};

GnuplotOutcome draw(const std::string& gnuplot, const std::string& dir, const std::string& prefix, const std::string& script_name,
                    const std::string& script, const std::string& png, std::size_t at, const std::string& output_line,
                    const std::function<bool()>& interrupted) {
  GnuplotOutcome r;
  write_file_atomically(prefix + script_name, script);

  // The PNG's temporary (mkostemp appends [A-Za-z0-9] only, so the name stays plain inside quotes),
  // the script gnuplot actually runs (the kept one with the temporary as output), and the log.
  TemporaryFile tmp_png, run_script, tmp_log;
  ::close(create_unique_temporary(prefix + png, tmp_png.path));
  std::string run_text = script;
  run_text.replace(at, output_line.size(),
                   "set output " + quoted(tmp_png.path.substr(prefix.size())) + "\n");
  {
    const int fd = create_unique_temporary(prefix + script_name, run_script.path);
    const bool written = write_all(fd, run_text);
    if (::close(fd) != 0 || !written) {
      r.problem = "cannot write the gnuplot script for " + png + " in " + dir + ": " + std::strerror(errno);
      return r;
    }
  }
  const std::string log_name = log_name_of(script_name);
  const int log_fd = create_unique_temporary(prefix + log_name, tmp_log.path);
  const int null_fd = ::open("/dev/null", O_RDWR | O_CLOEXEC);
  // Everything the child needs is prepared before fork: it only calls async-signal-safe functions.
  const std::string run_arg = run_script.path.substr(prefix.size());
  std::vector<char*> argv{const_cast<char*>("gnuplot"), const_cast<char*>(run_arg.c_str()), nullptr};
  const pid_t pid = null_fd < 0 ? -1 : ::fork();
  if (pid == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    ::dup2(null_fd, STDIN_FILENO);
    ::dup2(null_fd, STDOUT_FILENO);
    ::dup2(log_fd, STDERR_FILENO);
    ::execv(gnuplot.c_str(), argv.data());
    ::_exit(127);
  }
  const int fork_errno = errno;
  if (null_fd >= 0) ::close(null_fd);
  ::close(log_fd);
  const auto keep_log = [&] {
    if (std::rename(tmp_log.path.c_str(), (prefix + log_name).c_str()) == 0) tmp_log.path.clear();
  };
  if (pid < 0) {
    r.problem = std::string("cannot start gnuplot: ") + std::strerror(fork_errno);
    return r;
  }
  int status = 0;
  for (;;) {
    const pid_t w = ::waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (w < 0 && errno != EINTR) {
      r.problem = std::string("lost the gnuplot process: ") + std::strerror(errno);
      return r;
    }
    if (interrupted && interrupted()) {
      ::kill(pid, SIGTERM);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      keep_log();
      r.interrupted = true;
      r.problem = "interrupted while gnuplot was drawing " + png;
      return r;
    }
    const timespec pause{0, 10'000'000};  // 10 ms
    ::nanosleep(&pause, nullptr);
  }
  keep_log();
  const bool exited_ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (!exited_ok) {
    r.problem = WIFEXITED(status) && WEXITSTATUS(status) == 127 ? "cannot run " + gnuplot
                : WIFEXITED(status) ? "gnuplot failed (exit status " + std::to_string(WEXITSTATUS(status)) + "), see " + prefix + log_name
                                    : "gnuplot was killed by signal " + std::to_string(WTERMSIG(status)) + ", see " + prefix + log_name;
    return r;
  }
  if (!complete_png(tmp_png.path)) {
    r.problem = "gnuplot wrote no complete " + png + " (disk full?), see " + prefix + log_name;
    return r;
  }
  if (std::rename(tmp_png.path.c_str(), (prefix + png).c_str()) != 0) {
    r.problem = "cannot rename the drawn plot to " + prefix + png + ": " + std::strerror(errno);
    return r;
  }
  tmp_png.path.clear();
  fsync_directory(dir);
  r.ok = true;
  return r;
}

}  // namespace

bool plain_file_name(std::string_view name) {
  if (name.empty() || !is_alnum(name.front()) || name.find("..") != std::string_view::npos) return false;
  for (char c : name)
    if (!is_alnum(c) && c != '_' && c != '.' && c != '+' && c != '-') return false;
  return true;
}

std::string gnuplot_file(std::string_view name) {
  if (!plain_file_name(name)) throw std::logic_error("gnuplot: '" + std::string(name) + "' is not a plain file name");
  return quoted(name);
}

std::string gnuplot_text(std::string_view text) {
  static constexpr std::string_view kAllowed = " _.,:;=+-*/()[]{}^%#";
  std::string s;
  for (char c : text) s += is_alnum(c) || kAllowed.find(c) != std::string_view::npos ? c : '_';
  return quoted(s);
}

std::string gnuplot_output_line(std::string_view png) { return "set output " + gnuplot_file(png) + "\n"; }

std::string find_gnuplot() {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty() || dir.front() != '/') continue;  // "" and relative entries mean the current directory
    const std::string candidate = dir + "/gnuplot";
    struct stat st {};
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

GnuplotOutcome run_gnuplot(const std::string& gnuplot, const std::string& dir, const std::string& script_name,
                           const std::string& script, const std::string& png, const std::function<bool()>& interrupted) {
  if (!plain_file_name(script_name)) throw std::logic_error("gnuplot: '" + script_name + "' is not a plain file name");
  const std::string output_line = gnuplot_output_line(png);
  const std::size_t at = script.find(output_line);
  if (at == std::string::npos || script.find(output_line, at + 1) != std::string::npos)
    throw std::logic_error("gnuplot: the script for " + png + " must name it once with " + output_line);
  const std::string prefix = dir + "/";
  GnuplotOutcome r = draw(gnuplot, dir, prefix, script_name, script, png, at, output_line, interrupted);
  // No PNG of an earlier run stays under the name of one that failed: it would not show these data.
  if (!r.ok) ::unlink((prefix + png).c_str());
  return r;
}


}  // namespace sphmol
