// Randomly corrupted files: loading each must either succeed or throw antipode::Error.
#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include "antipode/core/error.hpp"
#include "antipode/core/random.hpp"
#include "antipode/io/load_cloud.hpp"
#include "temp_dir.hpp"

namespace antipode {
namespace {

using testing::read_bytes;
using testing::TempDir;
using testing::write_bytes;

// Overwrites, inserts or deletes a few bytes of `bytes`, mostly in its first 300 (the header).
std::string corrupt(std::string bytes, RandomStream& random) {
  const int edits = 1 + static_cast<int>(random.below(4));
  for (int e = 0; e < edits && !bytes.empty(); ++e) {
    const std::size_t limit =
        random.uniform() < 0.7 ? std::min<std::size_t>(bytes.size(), 300) : bytes.size();
    const std::size_t at = static_cast<std::size_t>(random.below(limit));
    const char value = static_cast<char>(random.below(256));
    switch (random.below(3)) {
      case 0:
        bytes[at] = value;
        break;
      case 1:
        bytes.insert(bytes.begin() + static_cast<std::ptrdiff_t>(at), value);
        break;
      default:
        bytes.erase(at, 1 + random.below(8));
        break;
    }
  }
  return bytes;
}

TEST(FuzzCloudTest, CorruptedFilesNeverCrash) {
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 100; ++i) cloud.push_back(pcl::PointXYZ(0.01f * i, 0.02f, 1.0f));
  pcl::io::savePCDFileASCII(dir.file("a.pcd"), cloud);
  pcl::io::savePCDFileBinary(dir.file("b.pcd"), cloud);
  pcl::io::savePCDFileBinaryCompressed(dir.file("c.pcd"), cloud);
  pcl::io::savePLYFileASCII(dir.file("a.ply"), cloud);
  pcl::io::savePLYFileBinary(dir.file("b.ply"), cloud);
  RandomStream random(17);
  int loaded = 0, refused = 0;
  for (const char* name : {"a.pcd", "b.pcd", "c.pcd", "a.ply", "b.ply"}) {
    const std::string original = read_bytes(dir.file(name));
    const std::string path = dir.file(std::string("fuzz_") + name);
    for (int trial = 0; trial < 150; ++trial) {
      write_bytes(path, corrupt(original, random));
      try {
        load_cloud(path);
        ++loaded;
      } catch (const Error& error) {
        EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos);
        ++refused;
      }
    }
  }
  EXPECT_GT(refused, 0);
  EXPECT_EQ(loaded + refused, 750);
}

}  // namespace
}  // namespace antipode
