#pragma once
// exp() over arrays of doubles at the widest vector width the CPU has, chosen at run time,
// with the same bits on every CPU.
//
// The Gaussian kernel of an SVM decision takes one exponential per hand and support vector
// (9 million for table_mug.pcd's 476 screened hands). Eigen's vectorized exp is compiled for
// the build's instruction set (SSE2, two doubles at a time, on a portable x86-64 build), and
// a build for a wider set would give other bits, hence other scores, on other CPUs. SLEEF's
// deterministic exp (the `cinz` functions: 1-ulp, no fused multiply-add) computes the same
// bits with SSE2, AVX or AVX-512, so the kernel is picked by the CPU the program runs on
// and the exponentials add nothing to what differs between CPUs (docs/classification.md:
// the matrix products' last bits; the grasps stay the same). On an AVX-512 CPU this took the SVM
// stage of table_mug.pcd's detection from 82 to 62 ms (classification_bench
// BM_FileToClassifiedGrasps, old and new builds side by side; docs/classification.md, speed
// and size). x86-64 only (its intrinsics and CPU checks).

#include <cstddef>

namespace antipode::detail {

/// The instruction sets exp_in_place can use, narrowest first.
enum class ExpKernel { kScalar, kSse2, kAvx, kAvx512 };

/// The widest kernel this CPU runs: kSse2 at least.
ExpKernel widest_exp_kernel();

/// Whether this CPU runs `kernel`.
bool cpu_runs(ExpKernel kernel);

/// "scalar", "sse2", "avx" or "avx512".
const char* exp_kernel_name(ExpKernel kernel);

/// x[i] = exp(x[i]) for i in [0, n), with the widest kernel. Thread-safe (no shared state
/// but the kernel chosen once).
void exp_in_place(double* x, std::size_t n);

/// The same with a given kernel, which the CPU must run (cpu_runs), else std::invalid_argument:
/// every kernel gives the same bits.
void exp_in_place(double* x, std::size_t n, ExpKernel kernel);

}  // namespace antipode::detail
