#pragma once
// Where the reference tables shipped with sph-mol (the Ghia centre lines, verification/ghia1982_*.csv)
// are found at run time. A binary run from its build tree reads them from the source tree; an
// installed one (cmake --install ... --prefix P) from P/share/sph-mol, located from the executable's
// own path, so the prefix chosen at install time need not be the one configured.
#include <string>
#include <vector>

namespace sphmol {

// The directories searched, in order: <dir of exe>/../share/sph-mol (the data installed beside this
// binary), the source tree's verification/ (compiled in), and the configured install data directory
// (compiled in). `exe` empty: the first is left out.
std::vector<std::string> reference_data_dirs(const std::string& exe);

// Path of `name` in the first directory of reference_data_dirs(<this process's executable>) that
// holds it; std::runtime_error naming every directory searched when none does.
std::string reference_data_file(const std::string& name);

}  // namespace sphmol
