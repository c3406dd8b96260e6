#pragma once
// Doubles <-> hexadecimal text of their raw bytes, for checkpoints: exact (bit-identical restarts)
// and NaN/inf survive, which JSON numbers cannot carry. Little-endian byte order on all targets we
// build for; the codec does not convert.
#include <string>
#include <vector>

namespace sphmol {

std::string encode_doubles(const double* data, std::size_t n);
inline std::string encode_doubles(const std::vector<double>& v) { return encode_doubles(v.data(), v.size()); }
// Throws std::runtime_error on text that is not 16 hex digits per double.
std::vector<double> decode_doubles(const std::string& hex);

}  // namespace sphmol
