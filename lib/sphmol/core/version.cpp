#include "sphmol/core/version.hpp"
namespace sphmol {
const char* version() { return "0.1.0"; }
}
