#pragma once
// Where the benchmarks find the shared clouds.

#include <string>

namespace antipode::bench {

/// Path of a cloud in the shared data folder.
inline std::string shared_cloud(const std::string& name) {
  return std::string(ANTIPODE_BENCH_DATA_DIR) + "/clouds/" + name;
}

}  // namespace antipode::bench
