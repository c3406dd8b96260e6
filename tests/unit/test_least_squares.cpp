// The least-squares slope shared by the convergence studies and the decaying cases' rate fits.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "sphmol/core/least_squares.hpp"

using namespace sphmol;

TEST_CASE("least-squares slope: exact on a line, the mean slope through scatter, NaN below two points", "[core]") {
  CHECK(least_squares_slope({0.0, 1.0, 2.0, 3.0}, {1.0, 3.0, 5.0, 7.0}) == Approx(2.0));
  CHECK(least_squares_slope({-1.0, 2.5}, {4.0, -3.0}) == Approx(-2.0));
  // Scatter of +-0.5 about y = 6x on alternate points: the fit finds 6 within the scatter's pull.
  const std::vector<double> x{0.0, 1.0, 2.0, 3.0, 4.0, 5.0};
  std::vector<double> y;
  for (std::size_t k = 0; k < x.size(); ++k) y.push_back(6.0 * x[k] + (k % 2 == 0 ? 0.5 : -0.5));
  CHECK(least_squares_slope(x, y) == Approx(6.0 - 3.0 / 35.0));
  CHECK(std::isnan(least_squares_slope({1.0}, {2.0})));
  CHECK(std::isnan(least_squares_slope({}, {})));
}
