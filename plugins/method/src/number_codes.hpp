#pragma once
// Compact numbers for model files (svm_model.cpp, format 4): half precision (IEEE binary16,
// 2 bytes, 11 significant bits) and 8-bit codes. A run of numbers - a basis row, a support
// vector component - is coded with one exponent e: each number becomes an integer c in
// [-127, 127] standing for c * 2^e, e the smallest exponent with every |number| <=
// 127 * 2^e. The step being a power of two makes each coded number an exact float and lets
// e be found again from coded numbers, so coding twice changes nothing and a file gives back
// exactly the numbers it was written from. Libraries compress blocks of bytes, not matrices
// whose numbers a model can round, hence these few functions.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace antipode::detail {

float round_to_half(float value);
std::uint16_t half_bits(float value);
float from_half_bits(std::uint16_t bits);

// The run of `count` numbers `stride` apart from `first`: a matrix row (stride 1) or column.
struct NumberRun {
  const float* first;
  std::size_t count;
  std::size_t stride;
  float operator[](std::size_t i) const { return first[i * stride]; }
};

// e of a run of finite numbers.
int code_exponent(const NumberRun& run);
// Rounds a run of finite numbers in place to what its codes stand for.
void round_to_codes(float* first, std::size_t count, std::size_t stride);
// Appends the codes of a run of finite numbers to `codes`; returns their exponent.
std::int8_t append_codes(const NumberRun& run, std::vector<std::int8_t>& codes);
// values[i * stride] = codes[i] * 2^exponent for i < count.
void decode_codes(const std::int8_t* codes, std::size_t count, int exponent, float* values,
                  std::size_t stride);
// "" when exponents and codes read from a file are in range, else what is wrong.
std::string codes_problem(const std::vector<std::int8_t>& exponents,
                          const std::vector<std::int8_t>& codes);

}  // namespace antipode::detail
