#pragma once
namespace sphmol {
const char* version();
// The git commit the program was built from ("-dirty" appended when tracked files had changes),
// or "unknown" when it was not built from a git checkout.
const char* git_commit();
}
