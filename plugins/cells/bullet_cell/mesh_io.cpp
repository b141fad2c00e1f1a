#include "mesh_io.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>

#include "antipode/core/error.hpp"
#include "antipode/core/input_file.hpp"

namespace antipode::cells {
namespace {

// Throws "PATH: BEFORE LINE AFTER" for a vertex line that cannot be used.
[[noreturn]] void fail_vertex(const std::string& path, const std::string& line, const char* before,
                              const char* after) {
  throw Error(path + ": " + before + line + after);
}

// The vertex index of an OBJ face token "v", "v/vt", "v//vn" or "v/vt/vn" (1-based or
// negative = relative to the end), as a 0-based index.
int face_index(const std::string& token, int vertex_count, const std::string& path) {
  const std::string number = token.substr(0, token.find('/'));
  long long raw = 0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), raw);
  if (error != std::errc() || end != number.data() + number.size())
    throw Error(path + ": face vertex '" + token + "' is not a vertex number");
  const long long index = raw < 0 ? vertex_count + raw : raw - 1;
  if (index < 0 || index >= vertex_count)
    throw Error(path + ": face refers to vertex " + number + " of " + std::to_string(vertex_count));
  return int(index);
}

// Vertex coordinates beyond this (metres) are no object the cell can hold.
constexpr float kMaxCoordinate = 1000.0f;

}  // namespace

TriangleMesh read_obj(const std::string& path) {
  require_regular_file(path, "an OBJ mesh file");
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot open");
  TriangleMesh mesh;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string tag;
    fields >> tag;
    if (tag == "v") {
      Eigen::Vector3f v;
      if (!(fields >> v.x() >> v.y() >> v.z())) fail_vertex(path, line, "bad vertex line '", "'");
      if (!(v.cwiseAbs().maxCoeff() <= kMaxCoordinate))
        fail_vertex(path, line, "vertex '", "' lies beyond 1000 m (or is not finite)");
      mesh.vertices.push_back(v);
    } else if (tag == "f") {
      std::vector<int> face;
      for (std::string token; fields >> token;)
        face.push_back(face_index(token, int(mesh.vertices.size()), path));
      for (std::size_t k = 2; k < face.size(); ++k)
        mesh.triangles.emplace_back(face[0], face[k - 1], face[k]);
    }
  }
  if (mesh.empty()) throw Error(path + ": no faces");
  return mesh;
}

}  // namespace antipode::cells
