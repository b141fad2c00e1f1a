#pragma once
// `antipode detect --camera-pose`: a camera's pose in a robot's frame, given inline or as an
// extrinsics file (docs/your-own-data.md).

#include <array>
#include <cstddef>
#include <string>

namespace antipode::cli {

/// The sensor's pose in `frame`: [x, y, z] in metres, then a unit quaternion [qw, qx, qy, qz].
struct CameraPose {
  std::array<double, 7> xyz_wxyz{};
  std::string frame;  ///< the file's `frame`, or "" (inline, or a file without one)

  /// "[x, y, z, qw, qx, qy, qz]": the LoadCloud port's text.
  std::string port_text() const;
};

/// "[a, b, ...]" for `count` numbers at `values`, with every digit a double holds: a YAML
/// list for a port or a `--set` value.
std::string yaml_list(const double* values, std::size_t count);

/// `text` is seven numbers separated by spaces or commas (x y z qw qx qy qz), or the path of
/// a YAML file with `translation_m: [x, y, z]`, `quaternion_wxyz: [qw, qx, qy, qz]` and,
/// optionally, `frame: NAME`. Throws antipode::Error naming what is wrong: a missing file,
/// an unknown key, a count other than 3 and 4, a number that is not finite, a quaternion
/// whose norm is not 1 within 1e-3.
CameraPose read_camera_pose(const std::string& text);

}  // namespace antipode::cli
