#include "sphmol/reference/dam_break_front.hpp"

#include <array>

namespace sphmol {

namespace {
// Martin & Moyce 1952, Fig. 3, n^2 = 2, a = 2.25 in (via PySPH db_exp_data.py, see the header).
constexpr std::array<FrontPoint, 15> kMartinMoyce{{{0.832, 1.217}, {1.219, 1.474}, {1.997, 2.292}, {2.547, 2.995},
                                                   {3.345, 4.134}, {4.034, 4.944}, {4.418, 5.881}, {5.091, 6.980},
                                                   {5.685, 7.945}, {6.306, 8.966}, {6.822, 9.986}, {7.439, 10.963},
                                                   {8.031, 11.977}, {8.633, 13.005}, {9.237, 13.970}}};
// Koshizuka & Oka 1996 experiment (via PySPH db_exp_data.py).
constexpr std::array<FrontPoint, 9> kKoshizukaOka{{{0.0, 1.000}, {0.381, 1.111}, {0.769, 1.252}, {1.153, 1.505},
                                                   {1.537, 1.892}, {1.935, 2.241}, {2.323, 2.615}, {2.719, 3.003},
                                                   {3.096, 3.624}}};
}  // namespace

std::span<const FrontPoint> martin_moyce_1952_n2_2() { return kMartinMoyce; }
std::span<const FrontPoint> koshizuka_oka_1996() { return kKoshizukaOka; }

std::optional<double> interpolate_front(std::span<const FrontPoint> data, double T) {
  if (data.empty() || T < data.front().T || T > data.back().T) return std::nullopt;
  for (std::size_t k = 1; k < data.size(); ++k)
    if (T <= data[k].T) {
      const double s = (T - data[k - 1].T) / (data[k].T - data[k - 1].T);
      return data[k - 1].Z + s * (data[k].Z - data[k - 1].Z);
    }
  return data.back().Z;
}

}  // namespace sphmol
