#pragma once
// Reading meshes: Wavefront OBJ (vertices and faces; polygons are fanned) and binary STL
// (vertices welded where they coincide). Both throw antipode::Error naming the file.

#include <string>

#include "triangle_mesh.hpp"

namespace antipode::cells {

TriangleMesh read_obj(const std::string& path);
TriangleMesh read_binary_stl(const std::string& path);

}  // namespace antipode::cells
