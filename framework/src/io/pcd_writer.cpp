// Binary PCD output, written here rather than by PCL (a test-only dependency): Debian's
// libpcl_io pulls in 67 shared libraries (31 of them VTK's and Boost's; `ldd libpcl_io.so`)
// for what is a header of ten lines and one block of floats.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"
#include "antipode/io/save_cloud.hpp"

namespace antipode {
namespace {

std::string pcd_header(std::size_t points, bool views) {
  const std::string n = std::to_string(points);
  return std::string("# .PCD v0.7 - Point Cloud Data file format (antipode)\nVERSION 0.7\n") +
         (views ? "FIELDS x y z view\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n"
                : "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n") +
         "WIDTH " + n + "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + n + "\nDATA binary\n";
}

}  // namespace

void save_cloud_pcd(const Cloud& cloud, const std::string& path) {
  const bool views = cloud.view_masks.size() == cloud.points_m.size() && !cloud.empty();
  const std::size_t stride = views ? 16 : 12;
  std::vector<char> data(stride * cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    std::memcpy(&data[i * stride], cloud.points_m[i].data(), 12);  // x, y, z: little-endian
    if (views) std::memcpy(&data[i * stride + 12], &cloud.view_masks[i], 4);
  }
  write_file_atomically(path, [&](const std::string& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    out << pcd_header(cloud.size(), views);
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
    out.close();
    if (!out) throw Error("cannot write the cloud");
  });
}

}  // namespace antipode
