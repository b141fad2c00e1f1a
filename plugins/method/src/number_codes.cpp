#include "number_codes.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

namespace antipode::detail {
namespace {

constexpr int kCodeMax = 127;
constexpr int kMinExponent = -60;  // an all-zero run gets this exponent
constexpr int kMaxExponent = 121;  // 127 * 2^121 is below the largest float

// The code of a finite `value` in a run of exponent `exponent`.
int code_of(float value, int exponent) {
  const float code = std::nearbyint(std::ldexp(value, -exponent));
  return static_cast<int>(
      std::clamp(code, static_cast<float>(-kCodeMax), static_cast<float>(kCodeMax)));
}

}  // namespace

float round_to_half(float value) { return static_cast<float>(Eigen::half(value)); }

std::uint16_t half_bits(float value) {
  return Eigen::numext::bit_cast<std::uint16_t>(Eigen::half(value));
}

float from_half_bits(std::uint16_t bits) {
  return static_cast<float>(Eigen::numext::bit_cast<Eigen::half>(bits));
}

int code_exponent(const NumberRun& run) {
  float largest = 0.0f;
  for (std::size_t i = 0; i < run.count; ++i) largest = std::max(largest, std::abs(run[i]));
  if (largest == 0.0f) return kMinExponent;
  const auto limit = [](int e) { return std::ldexp(static_cast<float>(kCodeMax), e); };
  int e = std::clamp(std::ilogb(largest) - 6, kMinExponent, kMaxExponent);  // near the answer
  while (e < kMaxExponent && largest > limit(e)) ++e;
  while (e > kMinExponent && largest <= limit(e - 1)) --e;
  return e;
}

void round_to_codes(float* first, std::size_t count, std::size_t stride) {
  const int e = code_exponent({first, count, stride});
  for (std::size_t i = 0; i < count; ++i) {
    float& v = first[i * stride];
    v = std::ldexp(static_cast<float>(code_of(v, e)), e);
  }
}

std::int8_t append_codes(const NumberRun& run, std::vector<std::int8_t>& codes) {
  const int e = code_exponent(run);
  for (std::size_t i = 0; i < run.count; ++i) {
    codes.push_back(static_cast<std::int8_t>(code_of(run[i], e)));
  }
  return static_cast<std::int8_t>(e);
}

void decode_codes(const std::int8_t* codes, std::size_t count, int exponent, float* values,
                  std::size_t stride) {
  // code * 2^exponent is exact as a product: |code| <= 127 fits the significand and every
  // allowed exponent keeps the result a normal float. One multiplication per number instead
  // of an ldexp call made reading models/hog_svm.model about 3 times faster.
  const float scale = std::ldexp(1.0f, exponent);
  for (std::size_t i = 0; i < count; ++i) values[i * stride] = static_cast<float>(codes[i]) * scale;
}

std::string codes_problem(const std::vector<std::int8_t>& exponents,
                          const std::vector<std::int8_t>& codes) {
  for (const std::int8_t e : exponents) {
    if (e < kMinExponent || e > kMaxExponent) return "code exponent " + std::to_string(e);
  }
  if (std::any_of(codes.begin(), codes.end(), [](std::int8_t c) { return c < -kCodeMax; })) {
    return "code -128";
  }
  return "";
}

}  // namespace antipode::detail
