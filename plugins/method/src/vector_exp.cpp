#include "vector_exp.hpp"

#include <stdexcept>
#include <string>

#include <emmintrin.h>
#include <sleef.h>

#include "vector_exp_kernels.hpp"

namespace antipode::detail {
namespace {

void exp_scalar(double* x, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) x[i] = Sleef_cinz_expd1_u10purec(x[i]);
}

void exp_sse2(double* x, std::size_t n) {
  std::size_t i = 0;
  for (; i + 2 <= n; i += 2) _mm_storeu_pd(x + i, Sleef_cinz_expd2_u10sse2(_mm_loadu_pd(x + i)));
  exp_scalar(x + i, n - i);
}

void run(double* x, std::size_t n, ExpKernel kernel) {
  switch (kernel) {
    case ExpKernel::kScalar:
      return exp_scalar(x, n);
    case ExpKernel::kSse2:
      return exp_sse2(x, n);
    case ExpKernel::kAvx:
      return exp_avx(x, n);
    case ExpKernel::kAvx512:
      return exp_avx512(x, n);
  }
}

}  // namespace

bool cpu_runs(ExpKernel kernel) {
  switch (kernel) {
    case ExpKernel::kScalar:
    case ExpKernel::kSse2:  // part of x86-64
      return true;
    case ExpKernel::kAvx:
      return __builtin_cpu_supports("avx");
    case ExpKernel::kAvx512:
      return __builtin_cpu_supports("avx512f");
  }
  return false;
}

ExpKernel widest_exp_kernel() {
  static const ExpKernel widest = [] {
    for (const ExpKernel k : {ExpKernel::kAvx512, ExpKernel::kAvx})
      if (cpu_runs(k)) return k;
    return ExpKernel::kSse2;
  }();
  return widest;
}

const char* exp_kernel_name(ExpKernel kernel) {
  switch (kernel) {
    case ExpKernel::kScalar:
      return "scalar";
    case ExpKernel::kSse2:
      return "sse2";
    case ExpKernel::kAvx:
      return "avx";
    case ExpKernel::kAvx512:
      return "avx512";
  }
  return "?";
}

void exp_in_place(double* x, std::size_t n, ExpKernel kernel) {
  if (!cpu_runs(kernel))
    throw std::invalid_argument(std::string("exp_in_place: this CPU has no ") +
                                exp_kernel_name(kernel));
  run(x, n, kernel);
}

void exp_in_place(double* x, std::size_t n) { run(x, n, widest_exp_kernel()); }

}  // namespace antipode::detail
