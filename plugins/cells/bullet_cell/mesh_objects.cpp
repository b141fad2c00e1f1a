#include "mesh_objects.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>

#include "antipode/core/error.hpp"
#include "convex_decomposition.hpp"
#include "mesh_io.hpp"

namespace fs = std::filesystem;

namespace antipode::cells {
namespace {

double smallest_width(const TriangleMesh& mesh) {
  const Eigen::Vector3f size = mesh.bounds().sizes();
  return std::min(size.x(), size.y());
}

// Mass from the enclosed volume; scans that are not closed fall back to half their box.
double mass_of(const TriangleMesh& mesh, double density) {
  double volume = std::abs(mesh.volume());
  const double box = double(mesh.bounds().volume());
  if (!(volume > 0.05 * box)) volume = 0.5 * box;
  return std::max(0.005, volume * density);
}

// A visual mesh as read and its convex decomposition, both at the file's scale.
struct MeshShapes {
  TriangleMesh visual;
  std::vector<TriangleMesh> hulls;
};

// Reading and decomposing a 16k-triangle scan takes a good part of a second, and scenes are
// rebuilt for every seed: each file is read and decomposed once per process.
const MeshShapes& mesh_shapes(const std::string& path) {
  static std::mutex mutex;
  static std::map<std::string, MeshShapes> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(path);
  if (it == cache.end()) {
    MeshShapes shapes;
    shapes.visual = read_obj(path);
    shapes.hulls = convex_decomposition(shapes.visual);
    if (shapes.hulls.empty()) throw Error("mesh '" + path + "' encloses no volume");
    it = cache.emplace(path, std::move(shapes)).first;
  }
  return it->second;
}

// An object on the cell's table is under a metre across: a larger mesh is almost always in
// other units (millimetres), and would drop off the table without a word.
void check_size(const TriangleMesh& visual, const std::string& name, const std::string& folder,
                double scale) {
  const double extent_m = double(visual.bounds().sizes().maxCoeff());
  if (extent_m <= 1.0) return;
  char size[64];
  std::snprintf(size, sizeof(size), "%.3g m across at scale %g", extent_m, scale);
  throw Error("object '" + name + "' of '" + folder + "' is " + size +
              ": object meshes must be in metres (a mesh in millimetres needs scaling by 0.001: "
              "convert the file, or give its scene entry a `scale`)");
}

}  // namespace

std::vector<std::string> list_mesh_objects(const std::string& folder) {
  if (!fs::is_directory(folder)) throw Error("mesh object folder '" + folder + "' not found");
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.is_directory() && fs::exists(entry.path() / "visual.obj"))
      names.push_back(entry.path().filename().string());
    else if (entry.path().extension() == ".obj")
      names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  if (names.empty()) throw Error("mesh object folder '" + folder + "' holds no object");
  return names;
}

ObjectModel load_mesh_object(const std::string& folder, const std::string& name, double scale,
                             double density, double friction) {
  const fs::path dir = fs::path(folder) / name;
  const bool nested = fs::exists(dir / "visual.obj");
  const MeshShapes& shapes =
      mesh_shapes(nested ? (dir / "visual.obj").string() : dir.string() + ".obj");
  TriangleMesh visual = shapes.visual;
  std::vector<TriangleMesh> hulls = shapes.hulls;
  const Eigen::Affine3f scaling(Eigen::Scaling(float(scale)));
  visual.transform(scaling);
  for (auto& hull : hulls) hull.transform(scaling);
  check_size(visual, name, folder, scale);
  centre_on_mass(visual, hulls);
  ObjectModel model;
  model.name = name;
  model.mass_kg = mass_of(visual, density);
  model.graspable_width_m = smallest_width(visual);
  model.visual = std::make_shared<const TriangleMesh>(std::move(visual));
  model.collision.kind = CollisionKind::kHulls;
  model.collision.hulls = std::move(hulls);
  model.friction = friction;
  return model;
}

}  // namespace antipode::cells
