// Exact sums over a run's pieces (run/piece_reduction.hpp, time/fixed_point_norm.hpp): the same
// double for any order and any split of the terms over pieces (ranks, here threads that play them),
// the exact sum where an ordinary sum cancels to nothing, and NaN / infinities as documented.
#include <catch2/catch.hpp>

#include <algorithm>
#include <barrier>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <thread>
#include <vector>

#include "sphmol/run/piece_reduction.hpp"
#include "sphmol/time/fixed_point_norm.hpp"

using namespace sphmol;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Terms of many magnitudes and both signs.
std::vector<double> mixed_terms(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  std::vector<double> v(n);
  for (auto& x : v) x = std::ldexp(mantissa(rng), exponent(rng));
  return v;
}

// The sum, largest and smallest of `values` split over `parts` pieces, each reduced on its own thread
// with collectives over the threads (as MpiRun's over the ranks).
struct Reduced {
  double sum, largest, smallest;
};
Reduced reduce_in_parts(const std::vector<double>& values, int parts) {
  std::vector<std::vector<double>> max_in(parts);
  std::vector<std::vector<std::uint64_t>> sum_in(parts);
  std::barrier sync(parts);
  std::vector<Reduced> out(parts);
  const auto rank = [&](int r) {
    OwnedPiece<1> piece;
    piece.max_each = [&, r](const std::vector<double>& v) {
      max_in[r] = v;
      sync.arrive_and_wait();
      std::vector<double> all = max_in[0];
      for (int k = 1; k < parts; ++k)
        for (std::size_t i = 0; i < all.size(); ++i) all[i] = std::max(all[i], max_in[k][i]);
      sync.arrive_and_wait();
      return all;
    };
    piece.sum_each = [&, r](const std::vector<std::uint64_t>& v) {
      sum_in[r] = v;
      sync.arrive_and_wait();
      std::vector<std::uint64_t> all = sum_in[0];
      for (int k = 1; k < parts; ++k)
        for (std::size_t i = 0; i < all.size(); ++i) all[i] += sum_in[k][i];
      sync.arrive_and_wait();
      return all;
    };
    PieceReduction red;
    const auto s = red.sum(), hi = red.largest(), lo = red.smallest();
    // Piece r: every parts-th value from r (interleaved, so the pieces' order differs from the whole's).
    for (std::size_t i = static_cast<std::size_t>(r); i < values.size(); i += static_cast<std::size_t>(parts)) {
      red.add(s, values[i]);
      red.add(hi, values[i]);
      red.add(lo, values[i]);
    }
    red.reduce(piece);
    out[r] = {red.value(s), red.value(hi), red.value(lo)};
  };
  std::vector<std::thread> threads;
  for (int r = 1; r < parts; ++r) threads.emplace_back(rank, r);
  rank(0);
  for (auto& t : threads) t.join();
  for (int r = 1; r < parts; ++r) {
    REQUIRE(same_bits(out[r].sum, out[0].sum));
    REQUIRE(same_bits(out[r].largest, out[0].largest));
    REQUIRE(same_bits(out[r].smallest, out[0].smallest));
  }
  return out[0];
}

}  // namespace

TEST_CASE("fixed-point total: shuffled terms give the identical double, close to the exact sum", "[fixed_point][piece_reduction]") {
  std::vector<double> v = mixed_terms(5000, 7);
  const double first = fixed_point_total(v.data(), v.size());
  long double exact = 0.0L;
  for (const double x : v) exact += x;
  CHECK(std::abs(first - static_cast<double>(exact)) <= 1e-12 * std::abs(first));
  std::mt19937 rng(3);
  for (int k = 0; k < 5; ++k) {
    std::shuffle(v.begin(), v.end(), rng);
    CHECK(same_bits(fixed_point_total(v.data(), v.size()), first));
  }
  // An ordinary sum in another order differs in its last bits (what the fixed point is for).
  double forward = 0.0, backward = 0.0;
  for (const double x : v) forward += x;
  for (auto it = v.rbegin(); it != v.rend(); ++it) backward += *it;
  CHECK(!same_bits(forward, backward));
}

TEST_CASE("fixed-point total: cancellation keeps the small terms an ordinary sum loses", "[fixed_point][piece_reduction]") {
  const std::vector<double> v{1e16, 1.0, -1e16, 1.0};
  double plain = 0.0;
  for (const double x : v) plain += x;
  CHECK(plain == 1.0);  // 1e16 + 1 rounds to 1e16: one of the ones is lost
  CHECK(fixed_point_total(v.data(), v.size()) == 2.0);
  const std::vector<double> zero{0.1, -0.1, 0.3, -0.3};
  CHECK(fixed_point_total(zero.data(), zero.size()) == 0.0);
  // Terms below 2^-96 of the largest are dropped (the documented bound).
  const std::vector<double> tiny{1.0, 0x1p-100, -1.0};
  CHECK(fixed_point_total(tiny.data(), tiny.size()) == 0.0);
  const std::vector<double> nan{1.0, std::numeric_limits<double>::quiet_NaN()};
  CHECK(std::isnan(fixed_point_total(nan.data(), nan.size())));
}

TEST_CASE("piece reduction: any split over pieces gives the whole's sum, largest and smallest to the bit",
          "[piece_reduction]") {
  const std::vector<double> v = mixed_terms(3001, 11);
  const Reduced one = reduce_in_parts(v, 1);
  CHECK(same_bits(one.sum, fixed_point_total(v.data(), v.size())));
  CHECK(one.largest == *std::max_element(v.begin(), v.end()));
  CHECK(one.smallest == *std::min_element(v.begin(), v.end()));
  for (const int parts : {2, 3, 4, 7}) {
    INFO(parts << " pieces");
    const Reduced split = reduce_in_parts(v, parts);
    CHECK(same_bits(split.sum, one.sum));
    CHECK(same_bits(split.largest, one.largest));
    CHECK(same_bits(split.smallest, one.smallest));
  }
  // A piece with no values takes part too (more pieces than values).
  const std::vector<double> two{3.0, -1.5};
  const Reduced few = reduce_in_parts(two, 4);
  CHECK(few.sum == 1.5);
  CHECK(few.largest == 3.0);
  CHECK(few.smallest == -1.5);
}

TEST_CASE("piece reduction: NaN and infinite values", "[piece_reduction]") {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(reduce_in_parts({1.0, inf, 2.0}, 2).sum == inf);
  CHECK(reduce_in_parts({1.0, -inf, 2.0}, 3).sum == -inf);
  CHECK(std::isnan(reduce_in_parts({inf, 1.0, -inf}, 2).sum));
  const Reduced with_nan = reduce_in_parts({1.0, nan, 2.0}, 2);
  CHECK(std::isnan(with_nan.sum));
  CHECK(std::isnan(with_nan.largest));
  CHECK(std::isnan(with_nan.smallest));
  const Reduced none = reduce_in_parts({}, 2);
  CHECK(none.sum == 0.0);
  CHECK(none.largest == -inf);
  CHECK(none.smallest == inf);
}
