#pragma once
// The per-instruction-set loops of vector_exp.cpp. Each lives in a file of its own, compiled
// for its instruction set (plugins/method/CMakeLists.txt) and called only on CPUs that have
// it; those files include nothing but <cstddef>, the intrinsics and SLEEF, so that no inline
// function compiled for a wider set can stand in for the portable one elsewhere.

#include <cstddef>

namespace antipode::detail {

void exp_avx(double* x, std::size_t n);     // vector_exp_avx.cpp, -mavx
void exp_avx512(double* x, std::size_t n);  // vector_exp_avx512.cpp, -mavx512f

}  // namespace antipode::detail
