#pragma once
// Surge-front position of a collapsing water column of width a and height H = 2a (n^2 = H/a = 2) on a
// dry horizontal bed. Three references, in the dimensionless variables of Martin & Moyce,
// Z = x_front / a against T = t sqrt(2 g / a):
//   - Ritter's shallow-water solution for a dam break, front speed 2 sqrt(g H): Z = 1 + 2 sqrt(gH) t / a.
//     Shallow water neglects vertical accelerations; the real front starts slower and stays behind it,
//     so it is an upper bound.
//   - Martin & Moyce 1952 (Phil. Trans. R. Soc. Lond. A 244:312-324), experiment n^2 = 2, a = 2.25 in
//     (their Fig. 3), and Koshizuka & Oka 1996 (Nucl. Sci. Eng. 123:421-434), experiment with
//     a = 0.146 m, H = 0.292 m. Points as digitised in PySPH, pysph/examples/db_exp_data.py
//     (github.com/pypr/pysph), which names these figures as its source.
#include <cmath>
#include <optional>
#include <span>

namespace sphmol {

struct FrontPoint {
  double T, Z;  // t sqrt(2 g / a), x_front / a
};

std::span<const FrontPoint> martin_moyce_1952_n2_2();
std::span<const FrontPoint> koshizuka_oka_1996();

// Z at T by linear interpolation between the points; empty outside their range.
std::optional<double> interpolate_front(std::span<const FrontPoint> data, double T);

// Whether a column of width a and height H is the experiments' H = 2a, to a relative 1e-6 (lengths
// given as whole numbers of a spacing that does not divide them exactly). Other columns have no
// experimental front here: the experiments are for n^2 = H/a = 2 only.
inline bool experiments_apply(double a, double H) { return std::abs(H / a - 2.0) <= 2e-6; }

// Ritter front x_front(t) = a + 2 sqrt(g H) t.
inline double ritter_front(double a, double g, double H, double t) { return a + 2.0 * std::sqrt(g * H) * t; }

}  // namespace sphmol

