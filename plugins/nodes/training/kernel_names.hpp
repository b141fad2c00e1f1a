#pragma once
// The kernel families named in a training node's `kernels` port.

#include <string>
#include <vector>

#include "antipode/core/error.hpp"
#include "antipode/grasp/svm_model.hpp"

namespace antipode::training {

/// The kernels named ("poly", "rbf"), in order. An empty list or an unknown name is an
/// antipode::Error saying which names there are, for the node to report at its port.
inline std::vector<SvmKernelType> kernel_types(const std::vector<std::string>& names) {
  if (names.empty()) throw Error("no kernel named (use poly, rbf or both)");
  std::vector<SvmKernelType> types;
  for (const std::string& name : names) types.push_back(kernel_type(name));
  return types;
}

}  // namespace antipode::training
