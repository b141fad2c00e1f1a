#pragma once
// Objects from mesh files: a folder per object holding visual.obj (what the sensor sees), or
// a flat folder of NNN.obj meshes (the blob set). Either collides as the convex
// decomposition of that mesh (convex_decomposition.hpp); other files are not read.

#include <string>
#include <vector>

#include "object_model.hpp"

namespace antipode::cells {

/// Names of the objects in `folder`: its subfolders holding visual.obj, else its *.obj
/// files without extension. Sorted. Throws antipode::Error when the folder is missing.
std::vector<std::string> list_mesh_objects(const std::string& folder);

/// The object `name` of `folder`, its meshes multiplied by `scale`, with the given density
/// and friction. Throws antipode::Error for unreadable files.
ObjectModel load_mesh_object(const std::string& folder, const std::string& name, double scale,
                             double density_kg_m3, double friction);

}  // namespace antipode::cells
