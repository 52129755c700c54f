// The packs' log1p and atan2 (core/base/simd_math.h) against glibc's libm, lane by lane, over the ranges the closed
// form uses them on: log1p of non-negative numbers from 1e-300 to 1e300 (and 0), atan2 in all four quadrants with
// ratios from 1e-12 to 1e12 and signed zeros. The bound is the header's: 2 ulp of the result.
#include "base/simd_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace somicage {
namespace {

#if SOMICAGE_SIMD_PACKS

// Evaluates f on the inputs a pack at a time and returns the largest |f - reference| / (ulp(reference) + floor).
template <typename F, typename R>
double worstError(const std::vector<double>& y, const std::vector<double>& x, F f, R reference, double floor) {
  double worst = 0;
  for (std::size_t i = 0; i + simd::kLanes <= x.size(); i += simd::kLanes) {
    simd::Pack py, px;
    for (int l = 0; l < simd::kLanes; ++l) py.v[l] = y[i + l], px.v[l] = x[i + l];
    const simd::Pack r = f(py, px);
    for (int l = 0; l < simd::kLanes; ++l) {
      const double expected = reference(y[i + l], x[i + l]);
      const double ulp = std::nextafter(std::abs(expected), INFINITY) - std::abs(expected);
      const double error = std::abs(r.v[l] - expected) / (ulp + floor);
      EXPECT_TRUE(std::isfinite(r.v[l])) << "at y " << y[i + l] << ", x " << x[i + l];
      worst = std::max(worst, error);
    }
  }
  return worst;
}

TEST(SimdMath, Log1pIsWithinTwoUlpOfLibm) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> exponent(-300, 300), unit(0, 1);
  std::vector<double> x = {0, 1e-300, 1e-17, 1.1e-16, 2.3e-16, 1, 0.41421356237309503, 0.4142135623730951, 1e300};
  for (int i = 0; i < 20000; ++i) x.push_back(std::pow(10.0, exponent(rng)));
  for (int i = 0; i < 20000; ++i) x.push_back(3 * unit(rng));  // around u = 2 and sqrt(2), where the reductions switch
  while (x.size() % simd::kLanes) x.push_back(0.5);
  const auto f = [](const simd::Pack&, const simd::Pack& a) { return simd::log1p(a); };
  const double worst = worstError(x, x, f, [](double, double a) { return ::log1p(a); }, 0);
  EXPECT_LE(worst, 2.0);
  RecordProperty("log1p_max_ulp", std::to_string(worst));
}

TEST(SimdMath, Atan2IsWithinTwoUlpOfLibmInEveryQuadrant) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> exponent(-12, 12), unit(-1, 1);
  std::vector<double> y = {0.0, -0.0, 1, -1, 0.0, -0.0, 1e-300, -1e300}, x = {1, 1, 0.0, 0.0, -1, -1, -1e300, 1e-300};
  for (int i = 0; i < 40000; ++i) {
    const double a = unit(rng), b = unit(rng) * std::pow(10.0, exponent(rng));
    y.push_back(a), x.push_back(b);
  }
  const auto f = [](const simd::Pack& a, const simd::Pack& b) { return simd::atan2(a, b); };
  const double worst = worstError(y, x, f, [](double a, double b) { return ::atan2(a, b); }, 0);
  EXPECT_LE(worst, 2.0);
  RecordProperty("atan2_max_ulp", std::to_string(worst));
  // The quadrants of the signed zeros, exactly.
  simd::Pack a, b;
  const double ys[4] = {0.0, -0.0, 0.0, -0.0}, xs[4] = {1, 1, -1, -1}, expected[4] = {0.0, -0.0, M_PI, -M_PI};
  for (int l = 0; l < simd::kLanes; ++l) a.v[l] = ys[l], b.v[l] = xs[l];
  const simd::Pack r = simd::atan2(a, b);
  for (int l = 0; l < simd::kLanes; ++l) {
    EXPECT_EQ(r.v[l], expected[l]) << "lane " << l;
    EXPECT_EQ(std::signbit(r.v[l]), std::signbit(expected[l])) << "lane " << l;
  }
}

#else

TEST(SimdMath, Log1pIsWithinTwoUlpOfLibm) { GTEST_SKIP() << "no SIMD packs on this architecture or compiler"; }

#endif

}  // namespace
}  // namespace somicage
