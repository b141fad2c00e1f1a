#pragma once
// Reading meshes: Wavefront OBJ (vertices and faces; polygons are fanned). Throws
// antipode::Error naming the file.

#include <string>

#include "triangle_mesh.hpp"

namespace antipode::cells {

TriangleMesh read_obj(const std::string& path);

}  // namespace antipode::cells
