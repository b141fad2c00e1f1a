#include "antipode/grasp/training_set.hpp"

#include <algorithm>
#include <cmath>

#include "antipode/core/binary_file.hpp"
#include "antipode/core/error.hpp"
#include "image_options_io.hpp"

namespace antipode {
namespace {
constexpr const char* kMagic = "ANTPDATA";
// 1: options as raw structs; 2: descriptors without the alignment counts; 3: four alignment
// angles and no occlusion statistics; 4: no view statistics. None is read: its descriptors
// are not today's.
constexpr std::uint32_t kVersion = 5;

// Field by field, so that the bytes depend only on the values (no struct padding).
void put_descriptor(BinaryWriter& w, const HandImageOptions& o, const HandGeometry& g) {
  detail::put_image_options(w, o);
  for (const double v : {g.finger_width_m, g.outer_diameter_m, g.depth_m, g.height_m, g.init_bite_m,
                         g.min_aperture_m, g.max_aperture_m}) {
    w.put(v);
  }
}

void get_descriptor(BinaryReader& r, HandImageOptions& o, HandGeometry& g) {
  o = detail::get_image_options(r);
  for (double* v : {&g.finger_width_m, &g.outer_diameter_m, &g.depth_m, &g.height_m, &g.init_bite_m,
                    &g.min_aperture_m, &g.max_aperture_m}) {
    *v = r.get<double>();
  }
}

}  // namespace

std::size_t TrainingSet::positives() const {
  return static_cast<std::size_t>(std::count(labels.begin(), labels.end(), std::int8_t{1}));
}

void TrainingSet::add(const std::vector<float>& descriptor, bool positive, std::int32_t group,
                      std::int32_t source) {
  if (descriptor.empty()) throw Error("training set: empty descriptor");
  if (dimension == 0 && empty()) dimension = descriptor.size();
  if (descriptor.size() != dimension) {
    throw Error("training set: descriptor of " + std::to_string(descriptor.size()) +
                " numbers, but the set holds descriptors of " + std::to_string(dimension));
  }
  if (!std::all_of(descriptor.begin(), descriptor.end(),
                   [](float v) { return std::isfinite(v); })) {
    throw Error("training set: descriptor with a non-finite number");
  }
  features.insert(features.end(), descriptor.begin(), descriptor.end());
  labels.push_back(positive ? 1 : -1);
  groups.push_back(group);
  sources.push_back(source);
}

std::int32_t TrainingSet::next_group() const {
  return groups.empty() ? 0 : *std::max_element(groups.begin(), groups.end()) + 1;
}

TrainingSet TrainingSet::subset(const std::vector<std::size_t>& indices) const {
  TrainingSet out;
  out.descriptor = descriptor;
  out.geometry = geometry;
  out.dimension = dimension;
  out.features.reserve(indices.size() * dimension);
  for (const std::size_t i : indices) {
    if (i >= size()) throw InternalError("training set: subset index out of range");
    out.features.insert(out.features.end(), row(i), row(i) + dimension);
    out.labels.push_back(labels[i]);
    out.groups.push_back(groups[i]);
    out.sources.push_back(sources[i]);
  }
  return out;
}

void TrainingSet::validate() const {
  const std::size_t n = labels.size();
  if (groups.size() != n || sources.size() != n || features.size() != n * dimension) {
    throw Error("training set: columns of different lengths");
  }
  for (const auto label : labels) {
    if (label != 1 && label != -1) throw Error("training set: a label that is not +1 or -1");
  }
}

void save_training_set(const TrainingSet& set, const std::string& path) {
  set.validate();
  BinaryWriter writer(kMagic, kVersion);
  put_descriptor(writer, set.descriptor, set.geometry);
  writer.put<std::uint64_t>(set.dimension);
  writer.put_vector(set.labels);
  writer.put_vector(set.groups);
  writer.put_vector(set.sources);
  writer.put_vector(set.features);
  writer.write(path);
}

TrainingSet load_training_set(const std::string& path) {
  BinaryReader reader(path, kMagic, kVersion, "training set");
  TrainingSet set;
  if (reader.version() < kVersion) {
    reader.fail("format version " + std::to_string(reader.version()) +
                " was written by an older antipode; re-create the file");
  }
  get_descriptor(reader, set.descriptor, set.geometry);
  set.dimension = static_cast<std::size_t>(reader.get<std::uint64_t>());
  set.labels = reader.get_vector<std::int8_t>();
  set.groups = reader.get_vector<std::int32_t>();
  set.sources = reader.get_vector<std::int32_t>();
  set.features = reader.get_vector<float>();
  reader.expect_end();
  try {
    set.descriptor.validate();
    set.geometry.validate();
    set.validate();
  } catch (const Error& e) {
    reader.fail(e.message());
  }
  return set;
}

}  // namespace antipode
