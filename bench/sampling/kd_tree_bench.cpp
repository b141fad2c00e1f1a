// The KD-tree behind PointIndex: nanoflann against PCL's KdTreeFLANN, on the voxelised
// table_mug.pcd, for the two ball sizes the hand search queries (3 cm frames, 10 cm hand
// neighbourhoods), unsorted results, one thread.
#include <filesystem>

#include <benchmark/benchmark.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>

#include "antipode/geometry/point_index.hpp"
#include "antipode/geometry/preprocess.hpp"
#include "antipode/io/load_cloud.hpp"
#include "bench_data.hpp"

namespace antipode {
namespace {

const std::string kScene = bench::shared_cloud("table_mug.pcd");
constexpr std::size_t kQueries = 1000;

const Cloud* scene() {
  static const Cloud cloud = std::filesystem::exists(kScene)
                                 ? preprocess(load_cloud(kScene), PreprocessOptions{})
                                 : Cloud{};
  return cloud.empty() ? nullptr : &cloud;
}

void BM_RadiusSearchNanoflann(benchmark::State& state) {
  const Cloud* cloud = scene();
  if (cloud == nullptr) return state.SkipWithError("shared cloud not found");
  const float radius = static_cast<float>(state.range(0)) / 1000.0f;
  const PointIndex index(cloud->points_m);
  std::vector<std::int32_t> found;
  const std::size_t stride = cloud->size() / kQueries;
  for (auto _ : state) {
    std::size_t total = 0;
    for (std::size_t q = 0; q < kQueries; ++q) {
      index.radius_search(cloud->points_m[q * stride], radius, found);
      total += found.size();
    }
    benchmark::DoNotOptimize(total);
  }
}
BENCHMARK(BM_RadiusSearchNanoflann)->Arg(30)->Arg(100)->Unit(benchmark::kMillisecond);

void BM_RadiusSearchPclFlann(benchmark::State& state) {
  const Cloud* cloud = scene();
  if (cloud == nullptr) return state.SkipWithError("shared cloud not found");
  const float radius = static_cast<float>(state.range(0)) / 1000.0f;
  pcl::PointCloud<pcl::PointXYZ>::Ptr points(new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : cloud->points_m) points->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  pcl::KdTreeFLANN<pcl::PointXYZ> tree(false);  // unsorted results
  tree.setInputCloud(points);
  std::vector<int> found;
  std::vector<float> distances;
  const std::size_t stride = cloud->size() / kQueries;
  for (auto _ : state) {
    std::size_t total = 0;
    for (std::size_t q = 0; q < kQueries; ++q) {
      total += static_cast<std::size_t>(
          tree.radiusSearch((*points)[q * stride], radius, found, distances));
    }
    benchmark::DoNotOptimize(total);
  }
}
BENCHMARK(BM_RadiusSearchPclFlann)->Arg(30)->Arg(100)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace antipode
