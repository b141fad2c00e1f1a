// The SVM's exp at the CPU's vector width (plugins/method/src/vector_exp.hpp): every kernel the
// CPU runs gives the same bits, and they are exp's to within SLEEF's 1 ulp.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "src/vector_exp.hpp"

namespace antipode::detail {
namespace {

// What the Gaussian kernel takes the exponential of (-gamma |z - sv|^2: zero down to where
// exp underflows, and past it), in an odd count so that every kernel has a tail to finish
// one at a time.
std::vector<double> exponents() {
  std::vector<double> x = {0.0, -0.0, -1e-300, -1e-12, -0.5, -1.0, -708.0, -745.0, -746.0, -1e6};
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> spread(-60.0, 0.0);
  while (x.size() < 10'007) x.push_back(spread(random));
  return x;
}

std::uint64_t bits(double v) {
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

const ExpKernel kAll[] = {ExpKernel::kScalar, ExpKernel::kSse2, ExpKernel::kAvx,
                          ExpKernel::kAvx512};

TEST(VectorExp, EveryKernelTheCpuRunsGivesTheSameBits) {
  const std::vector<double> x = exponents();
  std::vector<double> reference = x;
  exp_in_place(reference.data(), reference.size(), ExpKernel::kScalar);
  std::string compared;  // printed: a CPU without AVX-512 cannot check that kernel
  for (const ExpKernel kernel : kAll) {
    if (!cpu_runs(kernel)) continue;
    SCOPED_TRACE(exp_kernel_name(kernel));
    // Every length up to 17 as well, so that each kernel's tail is checked.
    for (std::size_t n :
         {x.size(), std::size_t(1), std::size_t(7), std::size_t(9), std::size_t(17)}) {
      std::vector<double> y(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n));
      exp_in_place(y.data(), n, kernel);
      for (std::size_t i = 0; i < n; ++i)
        ASSERT_EQ(bits(y[i]), bits(reference[i])) << "exp(" << x[i] << ")";
    }
    compared += std::string(" ") + exp_kernel_name(kernel);
  }
  std::printf("compared exp kernels:%s (widest: %s)\n", compared.c_str(),
              exp_kernel_name(widest_exp_kernel()));
  EXPECT_NE(compared.find("sse2"), std::string::npos);  // every x86-64 CPU has it
}

TEST(VectorExp, ValuesAreExpWithinAnUlp) {
  std::vector<double> y = exponents();
  const std::vector<double> x = y;
  exp_in_place(y.data(), y.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double want = std::exp(x[i]);
    if (want < std::numeric_limits<double>::min()) {
      EXPECT_LE(y[i], std::numeric_limits<double>::min()) << "exp(" << x[i] << ")";
      continue;
    }
    EXPECT_NEAR(y[i], want, 2.0 * std::numeric_limits<double>::epsilon() * want)
        << "exp(" << x[i] << ")";
  }
  EXPECT_EQ(y[0], 1.0);
  EXPECT_EQ(y[9], 0.0);  // exp(-1e6) underflows to zero
}

}  // namespace
}  // namespace antipode::detail
