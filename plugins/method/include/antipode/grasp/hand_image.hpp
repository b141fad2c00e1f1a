#pragma once
/// @file
/// The grasp hypothesis image of a hand and its HOG descriptor (paper section 4.2): the
/// cloud points in the hand's closing region projected onto its closing plane (approach x
/// closing), rasterised as a binary occupancy image, encoded by a histogram of oriented
/// gradients (OpenCV's HOGDescriptor, used privately: no OpenCV type appears here).

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "antipode/core/hand.hpp"
#include "antipode/core/hand_geometry.hpp"
#include "antipode/geometry/occlusion.hpp"
#include "antipode/interfaces/hand_set.hpp"

namespace antipode {

/// The image layout and the HOG parameters. The image covers the closing region exactly:
/// `cells_along` x `cell_px` rows span the finger depth along the approach (row 0 at the
/// palm face, the last row at the fingertips), `cells_across` x `cell_px` columns span the
/// aperture along the closing direction (column 0 at the finger at -y). With the defaults
/// and the Baxter hand (6 cm deep, 7.2 cm open), a pixel is 1 mm square and the image
/// 60 x 72 pixels is covered by 10 x 12 HOG cells, as in the paper.
struct HandImageOptions {
  int cells_along = 10;   ///< HOG cells along the approach (image rows / cell_px)
  int cells_across = 12;  ///< HOG cells along the closing direction (columns / cell_px)
  int cell_px = 6;        ///< cell side in pixels
  int block_cells = 2;    ///< HOG block side in cells (blocks step by one cell)
  int bins = 9;           ///< orientation bins (unsigned gradients, 0-180 degrees)
  /// Each point is drawn as a filled disc of this radius in pixels (0: one pixel). Points
  /// of a voxelised cloud lie a voxel (3 mm) apart; discs of 2 px at 1 mm pixels join them
  /// into the surface's silhouette, whose edges HOG then describes (single pixels would
  /// make every point an edge of its own).
  int point_radius_px = 2;
  /// Appends surface-normal statistics, alignment counts and view statistics to the HOG
  /// numbers (normal_statistics()). The paper's descriptor is the occupancy HOG alone (false); with
  /// them, accuracy on novel objects rises by several points (docs/results.md).
  bool normal_features = true;
  /// Appends, per block, the share of the closing region the cloud's sensors could not see
  /// (occlusion_statistics()). A view that shows a surface facing one finger and nothing
  /// facing the other cannot tell an absent surface from a hidden one; this says which.
  bool occlusion_features = true;

  int rows() const { return cells_along * cell_px; }
  int cols() const { return cells_across * cell_px; }
  /// Length of the HOG part: blocks x cells per block x bins.
  std::size_t hog_size() const;
  /// Length of the normal statistics: 3 numbers per block of block_cells x block_cells
  /// cells tiling the image (partial blocks at the far edges count), 12 alignment counts and
  /// 5 view statistics; 0 without them.
  std::size_t normal_features_size() const;
  /// Length of the occlusion statistics: one number per block as above, 0 without them.
  std::size_t occlusion_features_size() const;
  /// Length of a descriptor: hog_size() + normal_features_size() + occlusion_features_size().
  std::size_t descriptor_size() const;
  /// Throws antipode::Error naming the offending field (all >= 1, block_cells no larger
  /// than either cell count).
  void validate() const;
};

/// A binary occupancy image, row-major: 255 where a closing-region point projects, else 0.
struct HandImage {
  int rows = 0;
  int cols = 0;
  std::vector<std::uint8_t> pixels;

  std::uint8_t at(int row, int col) const {
    return pixels[static_cast<std::size_t>(row) * static_cast<std::size_t>(cols) +
                  static_cast<std::size_t>(col)];
  }
};

/// The grasp hypothesis image of `hand`: each of its closing points (indices into `cloud`),
/// in hand coordinates (x along the approach in [0, depth_m], y along closing in
/// (-max_aperture_m / 2, max_aperture_m / 2)), sets the pixel it falls in; points outside
/// the region (a hand from another geometry) are clamped to the border. Throws
/// antipode::Error for a closing point outside the cloud or invalid options.
HandImage hand_image(const Cloud& cloud, const Hand& hand, const HandGeometry& geometry,
                     const HandImageOptions& options = {});

/// The HOG descriptor of `image` (which must be options.rows() x options.cols()): one
/// window over the whole image, blocks of block_cells x block_cells cells stepping one cell,
/// L2-Hys block normalisation. An empty image gives all zeros.
std::vector<float> hog_descriptor(const HandImage& image, const HandImageOptions& options = {});

/// Normal statistics of a hand's closing region, what HOG cannot see: Definition 3 counts
/// points whose normal is near the closing direction, and HOG, normalised block by block,
/// keeps neither how many points there are nor which way their surface turns out of the
/// image plane. The image is tiled into blocks as normal_features_size() says; per block
/// (row-major), over the closing points drawn in it that have a normal: the mean of
/// n . closing, the mean of |n . axis| (surface tilted out of the closing plane) and
/// log(1 + points) / log(1 + 64). Then, over the whole region, log(1 + k) / log(1 + 64) of
/// the number k of points whose normal lies within 10, 15, 20, 25, 30 and 45 degrees of
/// +closing, then the same six of -closing (Definition 3's counts, which a mirrored closing
/// direction swaps). The block numbers are times 4, the counts times 12 (see hand_image.cpp).
/// Last, the 5 numbers of view_statistics(). `normals` is indexed like the cloud (zero = no
/// normal).
std::vector<float> normal_statistics(const Cloud& cloud, const Hand& hand,
                                     const HandGeometry& geometry, const HandImageOptions& options,
                                     const std::vector<Eigen::Vector3f>& normals);

/// How the sensors saw a hand's closing region, 5 numbers times 4: for the points whose
/// normal lies within 25 degrees of +closing, the mean of n . u, u the unit direction from
/// the point to the sensors that saw it (Cloud::direction_to_sensors(); 1: seen face on,
/// 0: at a grazing angle; 0 when there is no such point); the same for -closing; then the
/// mean of u over the closing points (zero for points without a normal) along the approach,
/// closing and hand axis. The labels come from normals fitted to every view's points, and
/// where a view saw a surface obliquely a second view is more likely to have seen it too and
/// to turn its normals. A hand turned half a turn about its approach swaps the first two and
/// negates the last two. A cloud without view origins gives zeros.
std::vector<float> view_statistics(const Cloud& cloud, const Hand& hand,
                                   const std::vector<Eigen::Vector3f>& normals);

/// The share of the closing region hidden from every view of `occlusion`'s cloud, per block
/// of the image (tiled as for normal_statistics()), times 4. Each HOG cell stands for the
/// column of the region behind it along the hand axis, sampled at its centre and a quarter
/// of the hand height either side; a sample is hidden when it lies more than 3 mm behind an
/// observed surface in every view (OcclusionMap). A cloud without view origins gives zeros.
std::vector<float> occlusion_statistics(const OcclusionMap& occlusion, const Hand& hand,
                                        const HandGeometry& geometry,
                                        const HandImageOptions& options);

/// hand_image() then hog_descriptor() for every hand of `set`, in parallel (`threads`
/// workers, 0: all); one descriptor per hand, in order, identical for any thread count.
/// With normal_features, the normals of all closing points are estimated once
/// (estimate_normals() with its defaults) and normal_statistics() appended; with
/// occlusion_features, one OcclusionMap of the cloud is built and occlusion_statistics()
/// appended.
std::vector<std::vector<float>> hand_descriptors(const HandSet& set, const HandGeometry& geometry,
                                                 const HandImageOptions& options = {},
                                                 int threads = 0);

}  // namespace antipode
