#pragma once
namespace sphmol {
const char* version();
}
