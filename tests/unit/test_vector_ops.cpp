// The compiled N_VLinearSum and N_VScale (time/vector_ops.hpp) give SUNDIALS' serial results to
// the bit, for every coefficient form its N_VLinearSum_Serial treats apart and every aliasing.
#include <catch2/catch.hpp>

#include <nvector/nvector_serial.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "sphmol/time/vector_ops.hpp"

using namespace sphmol;

namespace {

struct Vectors {
  explicit Vectors(SUNContext ctx, sunindextype n) : x(N_VNew_Serial(n, ctx)), y(N_VNew_Serial(n, ctx)) {}
  ~Vectors() {
    N_VDestroy(x);
    N_VDestroy(y);
  }
  N_Vector x, y;
};

void fill(N_Vector v, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> e(-30, 30);
  double* d = NV_DATA_S(v);
  for (sunindextype i = 0; i < NV_LENGTH_S(v); ++i) d[i] = std::ldexp(u(rng), e(rng));
  d[0] = 0.0;
  d[1] = -0.0;
}

bool same_bits(N_Vector a, N_Vector b) {
  return std::memcmp(NV_DATA_S(a), NV_DATA_S(b), static_cast<std::size_t>(NV_LENGTH_S(a)) * sizeof(double)) == 0;
}

}  // namespace

TEST_CASE("compiled N_VLinearSum and N_VScale give SUNDIALS' serial results to the bit", "[time][vector_ops]") {
  SUNContext ctx = nullptr;
  REQUIRE(SUNContext_Create(nullptr, &ctx) == 0);
  const sunindextype n = 1031;
  std::mt19937_64 rng(5);
  const std::vector<double> coefficients{1.0, -1.0, 0.0, 0.3, -0.3, 2.5, 1.0 / 3.0, -7.25};
  int cases = 0;
  for (const double a : coefficients)
    for (const double b : coefficients)
      for (int alias = 0; alias < 3; ++alias) {  // z apart, z = x, z = y
        Vectors ref(ctx, n), mine(ctx, n);
        fill(ref.x, rng);
        fill(ref.y, rng);
        N_VScale_Serial(1.0, ref.x, mine.x);
        N_VScale_Serial(1.0, ref.y, mine.y);
        use_compiled_linear_ops(mine.x);
        N_Vector zr = N_VClone(ref.x), zm = N_VClone(mine.x);
        N_Vector out_r = alias == 0 ? zr : alias == 1 ? ref.x : ref.y;
        N_Vector out_m = alias == 0 ? zm : alias == 1 ? mine.x : mine.y;
        N_VLinearSum_Serial(a, ref.x, b, ref.y, out_r);
        N_VLinearSum(a, mine.x, b, mine.y, out_m);  // dispatches through mine.x's operations
        INFO("a " << a << ", b " << b << ", alias " << alias);
        CHECK(same_bits(out_r, out_m));
        N_VScale_Serial(a, ref.y, zr);
        N_VScale(a, mine.y, zm);
        CHECK(same_bits(zr, zm));
        N_VScale_Serial(b, ref.x, ref.x);
        N_VScale(b, mine.x, mine.x);
        CHECK(same_bits(ref.x, mine.x));
        N_VDestroy(zr);
        N_VDestroy(zm);
        ++cases;
      }
  CHECK(cases == 192);
  // Clones carry the operations.
  Vectors v(ctx, n);
  use_compiled_linear_ops(v.x);
  N_Vector c = N_VClone(v.x);
  CHECK(c->ops->nvlinearsum == v.x->ops->nvlinearsum);
  CHECK(c->ops->nvlinearsum != v.y->ops->nvlinearsum);
  N_VDestroy(c);
  SUNContext_Free(&ctx);
}
