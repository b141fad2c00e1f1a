// Every malformed input must end in one antipode::Error naming the file - never a crash, a
// hang or an allocation the file's size does not justify.
#include <algorithm>
#include <chrono>
#include <cstring>
#include <limits>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>
#include <filesystem>

#include "antipode/core/error.hpp"
#include "antipode/io/load_cloud.hpp"
#include "temp_dir.hpp"

namespace antipode {
namespace {

using testing::read_bytes;
using testing::TempDir;
using testing::write_bytes;

pcl::PointCloud<pcl::PointXYZ> cloud_of(int n) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < n; ++i) cloud.push_back(pcl::PointXYZ(0.001f * i, 0.002f * i, 1.0f));
  return cloud;
}

// The message of the Error that loading `path` throws ("" when it does not throw).
std::string load_error(const std::string& path) {
  try {
    load_cloud(path);
  } catch (const Error& error) {
    const std::string what = error.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_NE(what.find(path), std::string::npos) << what;
    return what;
  }
  return "";
}

void expect_error(const std::string& path, const std::string& fragment) {
  const std::string what = load_error(path);
  EXPECT_NE(what.find(fragment), std::string::npos)
      << "'" << what << "' lacks '" << fragment << "'";
}

const std::string kHeader =
    "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";

std::string header_for(int points, const std::string& data) {
  return kHeader + "WIDTH " + std::to_string(points) + "\nHEIGHT 1\nPOINTS " +
         std::to_string(points) + "\nDATA " + data + "\n";
}

TEST(MalformedCloudTest, MissingFileEmptyFileAndUnknownExtension) {
  TempDir dir;
  expect_error(dir.file("missing.pcd"), "cannot open cloud file");
  write_bytes(dir.file("empty.pcd"), "");
  expect_error(dir.file("empty.pcd"), "empty");
  write_bytes(dir.file("cloud.xyz"), "1 2 3\n");
  expect_error(dir.file("cloud.xyz"), "unknown extension '.xyz'");
  expect_error(dir.file(""), "no extension");
}

// A folder or a FIFO named like a cloud: one clear error, not a crash or a read that never
// ends.
TEST(MalformedCloudTest, AFolderOrAFifoIsNotACloud) {
  TempDir dir;
  std::filesystem::create_directories(dir.file("folder.pcd"));
  expect_error(dir.file("folder.pcd"), "not a regular file (a folder)");
  ASSERT_EQ(::mkfifo(dir.file("pipe.ply").c_str(), 0600), 0);
  expect_error(dir.file("pipe.ply"), "not a regular file (a device or FIFO)");
}

TEST(MalformedCloudTest, GarbageIsNotAPcdOrPly) {
  TempDir dir;
  std::string garbage;
  for (int i = 0; i < 300; ++i) garbage += static_cast<char>((i * 37) % 256);
  write_bytes(dir.file("g.pcd"), garbage);
  write_bytes(dir.file("g.ply"), garbage);
  expect_error(dir.file("g.pcd"), "not a PCD");
  expect_error(dir.file("g.ply"), "not a PLY file");
}

// Cuts each file at 50 lengths short of `keep_up_to` and at every length around the end of
// its header: every cut must be an Error.
void expect_every_cut_fails(const std::string& full_path, std::size_t keep_up_to) {
  const std::string bytes = read_bytes(full_path);
  TempDir dir;
  const std::string cut_path = dir.file("cut" + full_path.substr(full_path.size() - 4));
  std::vector<std::size_t> lengths;
  for (std::size_t i = 0; i < 50; ++i) lengths.push_back(keep_up_to * i / 50);
  const std::size_t data = std::min(bytes.find("DATA"), bytes.find("end_header"));
  for (std::size_t length = data; length < data + 40 && length < keep_up_to; ++length) {
    lengths.push_back(length);
  }
  for (const std::size_t length : lengths) {
    write_bytes(cut_path, bytes.substr(0, length));
    EXPECT_NE(load_error(cut_path), "") << "cut at " << length << " of " << bytes.size();
  }
}

TEST(MalformedCloudTest, TruncatedPcdInEveryEncodingIsAnError) {
  TempDir dir;
  const auto cloud = cloud_of(300);
  pcl::io::savePCDFileASCII(dir.file("a.pcd"), cloud);
  pcl::io::savePCDFileBinary(dir.file("b.pcd"), cloud);
  pcl::io::savePCDFileBinaryCompressed(dir.file("c.pcd"), cloud);
  const std::string ascii = read_bytes(dir.file("a.pcd"));
  // Cutting only the last line's end may leave a complete cloud, so stop before it.
  expect_every_cut_fails(dir.file("a.pcd"), ascii.rfind('\n', ascii.size() - 2));
  expect_every_cut_fails(dir.file("b.pcd"), read_bytes(dir.file("b.pcd")).size());
  expect_every_cut_fails(dir.file("c.pcd"), read_bytes(dir.file("c.pcd")).size());
  write_bytes(dir.file("half.pcd"), read_bytes(dir.file("b.pcd")).substr(0, 2000));
  expect_error(dir.file("half.pcd"), "truncated PCD file");
}

TEST(MalformedCloudTest, HugeDeclaredSizesFailFast) {
  TempDir dir;
  write_bytes(dir.file("a.pcd"), header_for(2000000000, "ascii") + "1 2 3\n");
  write_bytes(dir.file("b.pcd"), header_for(400000000, "binary") + std::string(1200, '\0'));
  write_bytes(dir.file("v.ply"),
              "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\n"
              "property float x\nproperty float y\nproperty float z\nend_header\n" +
                  std::string(1200, '\0'));
  const auto start = std::chrono::steady_clock::now();
  expect_error(dir.file("a.pcd"), "truncated PCD file");
  expect_error(dir.file("b.pcd"), "truncated PCD file");
  expect_error(dir.file("v.ply"), "truncated PLY file");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
}

TEST(MalformedCloudTest, CorruptCompressedData) {
  TempDir dir;
  pcl::io::savePCDFileBinaryCompressed(dir.file("c.pcd"), cloud_of(300));
  const std::string bytes = read_bytes(dir.file("c.pcd"));
  const std::size_t data = bytes.find("DATA binary_compressed\n") + 23;
  std::string scrambled = bytes;
  for (std::size_t i = data + 8; i < scrambled.size(); i += 3) scrambled[i] = '\xff';
  write_bytes(dir.file("scrambled.pcd"), scrambled);
  expect_error(dir.file("scrambled.pcd"), "corrupt PCD file");
  std::string wrong_size = bytes;
  wrong_size[data + 4] = '\x01';  // uncompressed size no longer matches POINTS
  write_bytes(dir.file("wrong_size.pcd"), wrong_size);
  expect_error(dir.file("wrong_size.pcd"), "corrupt PCD file");
}

TEST(MalformedCloudTest, BadHeadersAreLocated) {
  TempDir dir;
  const std::string path = dir.file("h.pcd");
  write_bytes(path, kHeader + "WIDTH 2\nHEIGHT 1\nPOINTS 3\nDATA ascii\n1 2 3\n4 5 6\n");
  expect_error(path, ":9: POINTS 3 differs from WIDTH * HEIGHT = 2");
  write_bytes(path, "# .PCD\nFIELDS x y\nSIZE 4 4\nTYPE F F\nWIDTH 1\nDATA ascii\n1 2\n");
  expect_error(path, ":6: the cloud has no 'z' field");
  write_bytes(path, "FIELDS x y z\nSIZE 4 4\n");
  expect_error(path, ":2: SIZE has 2 entries for 3 fields");
  write_bytes(path, kHeader + "WIDTH 1\nDATA jpeg\n");
  expect_error(path, ":8: DATA 'jpeg' is not ascii, binary or binary_compressed");
  write_bytes(path, kHeader + "WIDTH 1\n");
  expect_error(path, "no DATA line");
}

TEST(MalformedCloudTest, BadAsciiValuesAreLocated) {
  TempDir dir;
  const std::string path = dir.file("v.pcd");
  write_bytes(path, header_for(3, "ascii") + "1 2 3\nfoo bar baz\n4 5 6\n");
  expect_error(path, ":12: coordinate 'foo' is not a number");
  write_bytes(path, header_for(2, "ascii") + "1 2 3\n4 5\n");
  expect_error(path, ":12: data line has 2 values, the header declares 3");
}

TEST(MalformedCloudTest, EmptyAndNonFiniteClouds) {
  TempDir dir;
  write_bytes(dir.file("zero.pcd"), header_for(0, "ascii"));
  expect_error(dir.file("zero.pcd"), "the cloud has no points");
  pcl::PointCloud<pcl::PointXYZ> nans;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (int i = 0; i < 20; ++i) nans.push_back(pcl::PointXYZ(nan, i % 2 ? inf : 0.0f, 1.0f));
  nans.is_dense = false;
  pcl::io::savePCDFileBinary(dir.file("nan.pcd"), nans);
  pcl::io::savePCDFileASCII(dir.file("nan_ascii.pcd"), nans);
  expect_error(dir.file("nan.pcd"), "no finite point (all 20 are NaN or infinite)");
  expect_error(dir.file("nan_ascii.pcd"), "no finite point");
}

// Found by fuzzing: PCL's PLY reader aborts on a list among the vertex properties.
TEST(MalformedCloudTest, AListAmongTheVertexPropertiesIsAnError) {
  TempDir dir;
  for (const char* format : {"ascii", "binary_little_endian"}) {
    write_bytes(
        dir.file("list.ply"),
        std::string("ply\nformat ") + format +
            " 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
            "property float z\nproperty list uchar int ids\nend_header\n" +
            (std::string(format) == "ascii" ? std::string("0 0 1 1 7\n") : std::string(17, '\1')));
    expect_error(dir.file("list.ply"), "the PLY vertices have a list property ('ids')");
  }
}

TEST(MalformedCloudTest, TruncatedAndHeaderlessPly) {
  TempDir dir;
  pcl::io::savePLYFileBinary(dir.file("b.ply"), cloud_of(300));
  pcl::io::savePLYFileASCII(dir.file("a.ply"), cloud_of(300));
  expect_every_cut_fails(dir.file("b.ply"), read_bytes(dir.file("b.ply")).size() / 2);
  expect_every_cut_fails(dir.file("a.ply"), read_bytes(dir.file("a.ply")).size() / 2);
  write_bytes(dir.file("n.ply"), "ply\nformat ascii 1.0\nelement face 0\nend_header\n");
  expect_error(dir.file("n.ply"), "no vertex element");
}

// A binary vertex list that declares more items than the file holds (PCL's reader aborted the
// process on it): an error naming the list, and a well-formed list still loads.
TEST(MalformedCloudTest, BinaryPlyListsMustFitTheFile) {
  TempDir dir;
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\n"
      "property float y\nproperty float z\nelement face 2\nproperty list uchar int extra\n"
      "end_header\n";
  std::string vertices(24, '\0');
  const float xyz[6] = {0.1f, 0.5f, 1.0f, 0.2f, 0.5f, 1.0f};
  std::memcpy(vertices.data(), xyz, 24);
  const auto face = [](unsigned char items) {
    return std::string(1, char(items)) + std::string(4 * std::size_t(items), '\0');
  };
  write_bytes(dir.file("good.ply"), header + vertices + face(1) + face(0));
  EXPECT_EQ(load_cloud(dir.file("good.ply")).size(), 2u);
  std::string bad = header + vertices + face(1) + face(0);
  bad[header.size() + 24] = char(200);  // the first list claims 200 ints
  write_bytes(dir.file("bad.ply"), bad);
  expect_error(dir.file("bad.ply"), "the list 'extra' of element 'face' record 0 declares 200");
}

// A VIEWPOINT whose rotation is no rotation (a zero or non-finite quaternion) is refused.
TEST(MalformedCloudTest, AViewpointRotationMustBeARotation) {
  TempDir dir;
  const std::string header =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\n";
  for (const char* rotation : {"0 0 0 0", "1 nan 0 0"}) {
    write_bytes(dir.file("v.pcd"),
                header + "VIEWPOINT 0 0 0 " + rotation + "\nPOINTS 1\nDATA ascii\n0.1 0.2 0.3\n");
    expect_error(dir.file("v.pcd"), "VIEWPOINT rotation (qw qx qy qz) is not a rotation");
  }
  write_bytes(dir.file("ok.pcd"),
              header + "VIEWPOINT 0 0 0 0 1 0 0\nPOINTS 1\nDATA ascii\n0.1 0.2 0.3\n");
  EXPECT_EQ(load_cloud(dir.file("ok.pcd")).size(), 1u);
}

// The PLY layouts a reader must handle, written by hand: elements with lists before the
// vertices, coordinates in double precision and big-endian order among other properties.
TEST(MalformedCloudTest, PlyLayoutsAreReadAndBadValuesAreLocated) {
  TempDir dir;
  write_bytes(dir.file("a.ply"),
              "ply\nformat ascii 1.0\nelement face 2\nproperty list uchar int ids\n"
              "element vertex 2\nproperty uchar red\nproperty double z\nproperty float y\n"
              "property float x\nend_header\n3 0 1 2\n0\n7 3.5 2 1\n8 -1e-2 nan 4\n");
  const Cloud ascii = load_cloud(dir.file("a.ply"));
  ASSERT_EQ(ascii.size(), 1u);  // the second point's y is NaN
  EXPECT_EQ(ascii.points_m[0], Eigen::Vector3f(1.0f, 2.0f, 3.5f));

  std::string binary =
      "ply\nformat binary_big_endian 1.0\nelement vertex 1\nproperty double x\n"
      "property short label\nproperty float y\nproperty double z\nend_header\n";
  const auto big_endian = [&binary](const auto value) {
    char raw[sizeof value];
    std::memcpy(raw, &value, sizeof value);
    for (std::size_t k = sizeof value; k > 0; --k) binary += raw[k - 1];
  };
  big_endian(0.25);
  big_endian(std::int16_t{-3});
  big_endian(-0.5f);
  big_endian(1.125);
  write_bytes(dir.file("b.ply"), binary);
  const Cloud big = load_cloud(dir.file("b.ply"));
  ASSERT_EQ(big.size(), 1u);
  EXPECT_EQ(big.points_m[0], Eigen::Vector3f(0.25f, -0.5f, 1.125f));

  write_bytes(dir.file("int.ply"),
              "ply\nformat ascii 1.0\nelement vertex 1\nproperty int x\nproperty float y\n"
              "property float z\nend_header\n1 2 3\n");
  expect_error(dir.file("int.ply"), "field 'x' is not floating point");
  write_bytes(dir.file("word.ply"),
              "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
              "property float z\nend_header\n1 2 3\n1 two 3\n");
  expect_error(dir.file("word.ply"), ":9: not a number: 'two'");
  write_bytes(dir.file("short.ply"),
              "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
              "property float z\nend_header\n1 2 3 1 2\n");
  expect_error(dir.file("short.ply"), "truncated PLY file: element 'vertex' record 1");
}

}  // namespace
}  // namespace antipode
