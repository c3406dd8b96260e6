#pragma once
// Reads a whole input file (config, checkpoint) with its limits checked before anything is read: it
// must be a regular file (not /dev/zero, a FIFO or a terminal, which never end or block) no larger
// than `max_bytes`, so a wrong path is a clear error instead of an exhausted memory or a hang.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace sphmol {

struct InputFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Config files: far above any scene description (the shipped ones are a few KiB).
inline constexpr std::uintmax_t kMaxConfigBytes = std::uintmax_t{16} << 20;  // 16 MiB

// Whether a symbolic link at `path` itself is read through (a config the user links to) or refused
// (a file the program wrote itself, such as a run's summary.json, is never a link).
enum class InputLinks { follow, refuse };

// The content of `path`; throws InputFileError "PATH: reason" (cannot open, a refused link, not a
// regular file, larger than the limit, read error). `what` names the kind of file in the message
// ("config file").
std::string read_input_file(const std::string& path, std::uintmax_t max_bytes, const std::string& what,
                            InputLinks links = InputLinks::follow);

// "16 MiB", "1 GiB", or the byte count.
std::string format_bytes(std::uintmax_t bytes);

}  // namespace sphmol
