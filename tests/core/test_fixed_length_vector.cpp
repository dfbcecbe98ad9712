// The time paths' state vectors (core/src/fixed_length_vector.hpp, private to core): every
// fixed-length kernel gives the serial N_Vector's result to the bit, for the body contact's 2
// (4 braking), the δ-only path's 3 entries and the extended path's 7, including the serial kernels' special cases and the
// aliasing the integrators use (z = x_0 in place, z among the summed vectors).
#include <sundials/sundials_context.h>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "fixed_length_vector.hpp"

namespace {

using covopt::internal::MakeFixedLengthVector;

/// Owns a SUNContext and two families of vectors of one length: fixed-length kernels and the
/// plain serial ones, filled with the same values.
class Pair {
 public:
  explicit Pair(int length) : length_(length) {
    SUNContext_Create(nullptr, &context_);
    fixed_template_ = MakeFixedLengthVector(length, context_);
    serial_template_ = N_VNew_Serial(length, context_);
    N_VEnableFusedOps_Serial(serial_template_, SUNTRUE);
  }
  ~Pair() {
    for (N_Vector v : owned_) N_VDestroy(v);
    N_VDestroy(fixed_template_);
    N_VDestroy(serial_template_);
    SUNContext_Free(&context_);
  }
  Pair(const Pair&) = delete;
  Pair& operator=(const Pair&) = delete;

  bool made() const { return fixed_template_ != nullptr; }
  /// A fixed-length vector and a serial one holding the same random values (a zero at entry
  /// `zero_at` if >= 0).
  std::pair<N_Vector, N_Vector> Vectors(int zero_at = -1) {
    N_Vector f = N_VClone(fixed_template_);
    N_Vector s = N_VClone(serial_template_);
    owned_.push_back(f);
    owned_.push_back(s);
    std::uniform_real_distribution<double> value(-3.0, 3.0);
    for (int i = 0; i < length_; ++i) {
      const double x = i == zero_at ? 0.0 : value(random_);
      NV_Ith_S(f, i) = x;
      NV_Ith_S(s, i) = x;
    }
    return {f, s};
  }

 private:
  int length_;
  SUNContext context_ = nullptr;
  N_Vector fixed_template_ = nullptr;
  N_Vector serial_template_ = nullptr;
  std::vector<N_Vector> owned_;
  std::mt19937_64 random_{20261123};
};

bool SameBits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

void CheckSame(N_Vector fixed, N_Vector serial) {
  const sunindextype n = N_VGetLength(serial);
  REQUIRE(N_VGetLength(fixed) == n);
  for (sunindextype i = 0; i < n; ++i) {
    CAPTURE(i, NV_Ith_S(fixed, i), NV_Ith_S(serial, i));
    CHECK(SameBits(NV_Ith_S(fixed, i), NV_Ith_S(serial, i)));
  }
}

}  // namespace

TEST_CASE("Only the time paths' lengths have fixed-length vectors", "[time][vector]") {
  SUNContext context = nullptr;
  SUNContext_Create(nullptr, &context);
  for (const int length : {1, 5, 8}) CHECK(MakeFixedLengthVector(length, context) == nullptr);
  N_Vector v = MakeFixedLengthVector(7, context);
  REQUIRE(v != nullptr);
  CHECK(N_VGetLength(v) == 7);
  CHECK(N_VGetVectorID(v) == SUNDIALS_NVEC_SERIAL);
  N_VDestroy(v);
  SUNContext_Free(&context);
}

TEST_CASE("Fixed-length kernels equal the serial ones to the bit", "[time][vector]") {
  const int length = GENERATE(2, 3, 4, 7);
  CAPTURE(length);
  Pair pair(length);
  REQUIRE(pair.made());

  SECTION("element-wise operations") {
    auto [xf, xs] = pair.Vectors();
    auto [yf, ys] = pair.Vectors(1);  // a zero for the division and the inverse test
    auto [zf, zs] = pair.Vectors();
    // N_VLinearSum's special forms: a, b = ±1, a = b, a = -b, and the general case.
    for (const auto& [a, b] : {std::pair{1.0, 1.0}, {1.0, -1.0}, {-1.0, 1.0}, {-1.0, -1.0},
                              {0.37, 0.37}, {0.37, -0.37}, {1.0, 0.45}, {0.45, 1.0}, {-1.0, 0.45},
                              {0.45, -1.0}, {0.3, 0.71}}) {
      CAPTURE(a, b);
      N_VLinearSum(a, xf, b, yf, zf);
      N_VLinearSum(a, xs, b, ys, zs);
      CheckSame(zf, zs);
    }
    for (const double c : {1.0, -1.0, 0.3}) {
      N_VScale(c, xf, zf);
      N_VScale(c, xs, zs);
      CheckSame(zf, zs);
    }
    N_VConst(0.25, zf);
    N_VConst(0.25, zs);
    CheckSame(zf, zs);
    N_VProd(xf, yf, zf);
    N_VProd(xs, ys, zs);
    CheckSame(zf, zs);
    N_VDiv(xf, xf, zf);
    N_VDiv(xs, xs, zs);
    CheckSame(zf, zs);
    N_VAbs(xf, zf);
    N_VAbs(xs, zs);
    CheckSame(zf, zs);
    N_VInv(xf, zf);
    N_VInv(xs, zs);
    CheckSame(zf, zs);
    N_VAddConst(xf, -0.7, zf);
    N_VAddConst(xs, -0.7, zs);
    CheckSame(zf, zs);
    N_VCompare(1.1, xf, zf);
    N_VCompare(1.1, xs, zs);
    CheckSame(zf, zs);
    CHECK(N_VInvTest(yf, zf) == N_VInvTest(ys, zs));
    CHECK(N_VInvTest(yf, zf) == SUNFALSE);
    CheckSame(zf, zs);
  }

  SECTION("reductions") {
    auto [xf, xs] = pair.Vectors();
    auto [wf, ws] = pair.Vectors();
    N_VAbs(wf, wf);
    N_VAbs(ws, ws);
    CHECK(SameBits(N_VDotProd(xf, wf), N_VDotProd(xs, ws)));
    CHECK(SameBits(N_VMaxNorm(xf), N_VMaxNorm(xs)));
    CHECK(SameBits(N_VWrmsNorm(xf, wf), N_VWrmsNorm(xs, ws)));
    CHECK(SameBits(N_VMin(xf), N_VMin(xs)));
    CHECK(SameBits(N_VWSqrSumLocal(xf, wf), N_VWSqrSumLocal(xs, ws)));
  }

  SECTION("fused operations, with the aliasing the integrators use") {
    // The Runge-Kutta stage sums and the Adams history: up to 14 vectors (Fehlberg 13
    // stages), and more than the kernel's 16 cached ones.
    const int count = GENERATE(1, 2, 3, 7, 14, 17);
    const int alias = GENERATE(0, 1, 2, 3);  // none, z = X_0 (c_0 = 1), z = X_0 (c_0 != 1), z = X_last
    CAPTURE(count, alias);
    std::vector<N_Vector> fixed, serial;
    std::vector<double> c;
    for (int k = 0; k < count; ++k) {
      auto [f, s] = pair.Vectors();
      fixed.push_back(f);
      serial.push_back(s);
      c.push_back(0.1 + 0.37 * k - 0.05 * k * k);
    }
    auto [zf, zs] = pair.Vectors();
    if (alias == 1 || alias == 2) {
      zf = fixed[0];
      zs = serial[0];
      c[0] = alias == 1 ? 1.0 : 0.8;
    } else if (alias == 3) {
      zf = fixed.back();
      zs = serial.back();
    }
    REQUIRE(N_VLinearCombination(count, c.data(), fixed.data(), zf) == 0);
    REQUIRE(N_VLinearCombination(count, c.data(), serial.data(), zs) == 0);
    CheckSame(zf, zs);

    auto [xf, xs] = pair.Vectors();
    std::vector<N_Vector> out_fixed, out_serial;
    for (int k = 0; k < count; ++k) {
      auto [f, s] = pair.Vectors();
      out_fixed.push_back(f);
      out_serial.push_back(s);
    }
    // Z_k = a_k x + Y_k, into separate vectors and in place (Y == Z).
    REQUIRE(N_VScaleAddMulti(count, c.data(), xf, fixed.data(), out_fixed.data()) == 0);
    REQUIRE(N_VScaleAddMulti(count, c.data(), xs, serial.data(), out_serial.data()) == 0);
    for (int k = 0; k < count; ++k) CheckSame(out_fixed[k], out_serial[k]);
    REQUIRE(N_VScaleAddMulti(count, c.data(), xf, fixed.data(), fixed.data()) == 0);
    REQUIRE(N_VScaleAddMulti(count, c.data(), xs, serial.data(), serial.data()) == 0);
    for (int k = 0; k < count; ++k) CheckSame(fixed[k], serial[k]);

    std::vector<double> products_fixed(static_cast<std::size_t>(count));
    std::vector<double> products_serial(static_cast<std::size_t>(count));
    REQUIRE(N_VDotProdMulti(count, xf, fixed.data(), products_fixed.data()) == 0);
    REQUIRE(N_VDotProdMulti(count, xs, serial.data(), products_serial.data()) == 0);
    for (int k = 0; k < count; ++k) CHECK(SameBits(products_fixed[k], products_serial[k]));
  }
}
