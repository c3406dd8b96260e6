#include "sphmol/io/double_codec.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace sphmol {

std::string encode_doubles(const double* data, std::size_t n) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string out(16 * n, '0');
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t bits;
    std::memcpy(&bits, &data[i], sizeof bits);
    for (int k = 15; k >= 0; --k, bits >>= 4) out[16 * i + static_cast<std::size_t>(k)] = digits[bits & 0xf];
  }
  return out;
}

std::vector<double> decode_doubles(const std::string& hex) {
  if (hex.size() % 16 != 0) throw std::runtime_error("checkpoint: hex data length is not a multiple of 16");
  std::vector<double> out(hex.size() / 16);
  for (std::size_t i = 0; i < out.size(); ++i) {
    std::uint64_t bits = 0;
    for (std::size_t k = 0; k < 16; ++k) {
      const char c = hex[16 * i + k];
      int d;
      if (c >= '0' && c <= '9') d = c - '0';
      else if (c >= 'a' && c <= 'f') d = c - 'a' + 10;
      else throw std::runtime_error("checkpoint: invalid hex digit in data");
      bits = (bits << 4) | static_cast<std::uint64_t>(d);
    }
    std::memcpy(&out[i], &bits, sizeof bits);
  }
  return out;
}

}  // namespace sphmol
