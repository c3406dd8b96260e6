#pragma once
// Runs a program with an argument vector (fork/exec, no shell), so tests can pass arguments that
// hold quotes, spaces, `$(...)`, `;`, backticks, `|`, `<` or newlines exactly as a user would.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace test_support {

struct ProcessResult {
  int code = -1;        // exit status, or 128 + signal if the child was killed
  std::string err;      // captured standard error
};

// Runs `program args...` in `cwd` (empty: the current directory) with standard output discarded and
// standard error captured through `err_file`. `env` entries ("NAME=value") are added to the
// environment of the child; `file_size_limit` (bytes) is its `ulimit -f`.
inline ProcessResult run_process(const std::string& program, const std::vector<std::string>& args,
                                 const std::string& err_file, const std::string& cwd = {},
                                 const std::vector<std::string>& env = {}, rlim_t file_size_limit = RLIM_INFINITY) {
  const pid_t pid = ::fork();
  if (pid < 0) return {};
  if (pid == 0) {
    if (!cwd.empty() && ::chdir(cwd.c_str()) != 0) ::_exit(127);
    const int devnull = ::open("/dev/null", O_RDWR);
    const int err = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (devnull < 0 || err < 0) ::_exit(127);
    ::dup2(devnull, STDIN_FILENO);
    ::dup2(devnull, STDOUT_FILENO);
    ::dup2(err, STDERR_FILENO);
    for (const auto& e : env) ::putenv(const_cast<char*>(e.c_str()));
    if (file_size_limit != RLIM_INFINITY) {
      const rlimit lim{file_size_limit, file_size_limit};
      ::setrlimit(RLIMIT_FSIZE, &lim);
    }
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(program.c_str()));
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return {};
  ProcessResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
  std::ifstream in(err_file);
  std::ostringstream s;
  s << in.rdbuf();
  r.err = s.str();
  return r;
}

}  // namespace test_support
