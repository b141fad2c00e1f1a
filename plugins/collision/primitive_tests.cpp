#include "primitive_tests.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace antipode::collision {

namespace {

using Kind = CollisionPrimitive::Kind;

// An oriented box: centre, axes (columns) and half sizes.
struct Obb {
  Eigen::Vector3d centre;
  Eigen::Matrix3d axes;
  Eigen::Vector3d half;
};

// Axes A_i x B_j shorter than this (edges within about 1e-6 rad of parallel) are skipped: the
// box pair's separating axes then lie among the faces' normals.
constexpr double kShortAxis = 1e-6;

// The largest gap between the projections of a and b onto the separating axis test's 15 axes
// (each axis of unit length): positive, they are apart by at least that; negative, they overlap
// by at least its magnitude along every axis, and so meet.
double separation(const Obb& a, const Obb& b) {
  const Eigen::Matrix3d R = a.axes.transpose() * b.axes;
  const Eigen::Matrix3d abs_R = R.cwiseAbs();
  const Eigen::Vector3d t = a.axes.transpose() * (b.centre - a.centre);
  const Eigen::Vector3d &ha = a.half, &hb = b.half;
  double gap = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) gap = std::max(gap, std::abs(t(i)) - ha(i) - abs_R.row(i).dot(hb));
  for (int j = 0; j < 3; ++j)
    gap = std::max(gap, std::abs(t.dot(R.col(j))) - abs_R.col(j).dot(ha) - hb(j));
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const double length = std::sqrt(std::max(0.0, 1.0 - R(i, j) * R(i, j)));
      if (length < kShortAxis) continue;
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double ra = ha(i1) * abs_R(i2, j) + ha(i2) * abs_R(i1, j);
      const double rb = hb(j1) * abs_R(i, j2) + hb(j2) * abs_R(i, j1);
      const double projection = std::abs(t(i2) * R(i1, j) - t(i1) * R(i2, j));
      gap = std::max(gap, (projection - ra - rb) / length);
    }
  }
  return gap;
}

Obb box_of(const PlacedPrimitive& p) {
  return {p.X_FrameShape.translation(), p.X_FrameShape.linear(), 0.5 * p.size_m};
}

// A cylinder's inscribed box (the square of side R sqrt(2) about its axis), turned by `turn_rad`
// about the axis.
Obb inscribed_box(const PlacedPrimitive& p, double turn_rad) {
  const double side = p.size_m.x() / std::sqrt(2.0);
  return {p.X_FrameShape.translation(),
          p.X_FrameShape.linear() * Eigen::AngleAxisd(turn_rad, Eigen::Vector3d::UnitZ()),
          Eigen::Vector3d(side, side, 0.5 * p.size_m.y())};
}

// How far a box or cylinder reaches from its centre along the unit direction n.
double support(const PlacedPrimitive& p, const Eigen::Vector3d& n) {
  const Eigen::Vector3d local = p.X_FrameShape.linear().transpose() * n;
  if (p.kind == Kind::kBox) return 0.5 * p.size_m.dot(local.cwiseAbs());
  const double along = std::abs(local.z());
  return along * 0.5 * p.size_m.y() + p.size_m.x() * std::sqrt(std::max(0.0, 1.0 - along * along));
}

// The gap between a and b along direction d (any length; none when too short to tell).
double gap_along(const PlacedPrimitive& a, const PlacedPrimitive& b, const Eigen::Vector3d& d) {
  const double length = d.norm();
  if (length < kShortAxis) return -std::numeric_limits<double>::infinity();
  const Eigen::Vector3d n = d / length;
  return std::abs(n.dot(b.X_FrameShape.translation() - a.X_FrameShape.translation())) -
         support(a, n) - support(b, n);
}

// The point of box b nearest to the axis of cylinder c, and the axis point it is nearest to,
// both in the frame: a golden-section search along the axis (the distance from a convex set is
// convex along a line), to within a two-thousandth of the axis (either point serves as a
// witness and their line as an axis wherever it lies).
std::pair<Eigen::Vector3d, Eigen::Vector3d> nearest_to_axis(const PlacedPrimitive& c,
                                                            const PlacedPrimitive& b) {
  const Eigen::Isometry3d X_BoxCylinder = b.X_FrameShape.inverse() * c.X_FrameShape;
  const double half_length = 0.5 * c.size_m.y();
  const Eigen::Vector3d half = 0.5 * b.size_m;
  const Eigen::Vector3d start = X_BoxCylinder * Eigen::Vector3d(0, 0, -half_length);
  const Eigen::Vector3d step = X_BoxCylinder.linear().col(2) * (2.0 * half_length);
  const auto nearest = [&](double t) {
    return Eigen::Vector3d((start + t * step).cwiseMax(-half).cwiseMin(half));
  };
  const auto gap = [&](double t) { return (start + t * step - nearest(t)).squaredNorm(); };
  const double kGolden = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = 0.0, hi = 1.0;
  double t1 = hi - kGolden * (hi - lo), t2 = lo + kGolden * (hi - lo);
  double g1 = gap(t1), g2 = gap(t2);
  for (int k = 0; k < 16; ++k) {
    if (g1 <= g2) {
      hi = t2, t2 = t1, g2 = g1;
      t1 = hi - kGolden * (hi - lo), g1 = gap(t1);
    } else {
      lo = t1, t1 = t2, g1 = g2;
      t2 = lo + kGolden * (hi - lo), g2 = gap(t2);
    }
  }
  const double t = g1 <= g2 ? t1 : t2;
  return {b.X_FrameShape * nearest(t), b.X_FrameShape * (start + t * step)};
}

// The points of the axes of cylinders a and b nearest each other (frame coordinates): the
// closest points of two segments, clamped in turn (Ericson, Real-Time Collision Detection, 5.1.9).
std::pair<Eigen::Vector3d, Eigen::Vector3d> nearest_on_axes(const PlacedPrimitive& a,
                                                            const PlacedPrimitive& b) {
  const auto ends = [](const PlacedPrimitive& c) {
    const Eigen::Vector3d half = c.X_FrameShape.linear().col(2) * (0.5 * c.size_m.y());
    return std::pair{Eigen::Vector3d(c.X_FrameShape.translation() - half),
                     Eigen::Vector3d(2 * half)};
  };
  const auto [p1, d1] = ends(a);
  const auto [p2, d2] = ends(b);
  const Eigen::Vector3d r = p1 - p2;
  const double aa = d1.squaredNorm(), ee = d2.squaredNorm(), f = d2.dot(r), c = d1.dot(r);
  const double bb = d1.dot(d2), denominator = aa * ee - bb * bb;
  double s =
      denominator > 1e-12 * aa * ee ? std::clamp((bb * f - c * ee) / denominator, 0.0, 1.0) : 0.0;
  double t = (bb * s + f) / ee;
  if (t < 0.0 || t > 1.0) {
    t = std::clamp(t, 0.0, 1.0);
    s = std::clamp((bb * t - c) / aa, 0.0, 1.0);
  }
  return {p1 + s * d1, p2 + t * d2};
}

// Whether point (frame coordinates) lies inside cylinder c by kMargin_m.
bool inside_cylinder(const PlacedPrimitive& c, const Eigen::Vector3d& point) {
  const Eigen::Vector3d p = c.X_FrameShape.inverse() * point;
  return std::hypot(p.x(), p.y()) < c.size_m.x() - kMargin_m &&
         std::abs(p.z()) < 0.5 * c.size_m.y() - kMargin_m;
}

// A cylinder and a box, or two cylinders. Apart: the gap along one of the candidate axes - each
// shape's axes, their cross products, the line between the centres, and the line from the box's
// point nearest the cylinder's axis to that axis (for two cylinders, between their axes' nearest
// points) - is positive (the supports are exact, so a positive gap is a separating plane).
// Meeting: a point found inside both (that point of the box; a point between the two axes), or
// inscribed boxes (two per cylinder, turned 45 degrees) meet.
Verdict with_cylinder(const PlacedPrimitive& a, const PlacedPrimitive& b) {
  // The cheap axes first: each shape's own (a box's three, a cylinder's axis), their cross
  // products and the line between the centres.
  const auto own = [](const PlacedPrimitive& p) { return p.kind == Kind::kBox ? 3 : 1; };
  const auto axis = [](const PlacedPrimitive& p, int k) -> Eigen::Vector3d {
    return p.X_FrameShape.linear().col(p.kind == Kind::kBox ? k : 2);
  };
  for (int i = 0; i < own(a); ++i) {
    if (gap_along(a, b, axis(a, i)) > kMargin_m) return Verdict::kApart;
    for (int j = 0; j < own(b); ++j)
      if (gap_along(a, b, axis(a, i).cross(axis(b, j))) > kMargin_m) return Verdict::kApart;
  }
  for (int j = 0; j < own(b); ++j)
    if (gap_along(a, b, axis(b, j)) > kMargin_m) return Verdict::kApart;
  if (gap_along(a, b, b.X_FrameShape.translation() - a.X_FrameShape.translation()) > kMargin_m)
    return Verdict::kApart;
  // Then inscribed boxes (two per cylinder, turned 45 degrees) meeting.
  const auto inner = [](const PlacedPrimitive& p, int k) {
    return p.kind == Kind::kBox ? box_of(p) : inscribed_box(p, k * M_PI / 4.0);
  };
  for (int i = 0; i < (a.kind == Kind::kBox ? 1 : 2); ++i)
    for (int j = 0; j < (b.kind == Kind::kBox ? 1 : 2); ++j)
      if (separation(inner(a, i), inner(b, j)) < -kMargin_m) return Verdict::kMeet;
  // Last the nearest points: their line as an axis, and a point inside both - the box's point
  // nearest the cylinder's axis, or for two cylinders a point between their axes' nearest points.
  const bool mixed = a.kind != b.kind;
  const PlacedPrimitive& cylinder = a.kind == Kind::kCylinder ? a : b;
  const PlacedPrimitive& box = a.kind == Kind::kCylinder ? b : a;
  const auto [p, q] = mixed ? nearest_to_axis(cylinder, box) : nearest_on_axes(a, b);
  if (gap_along(a, b, q - p) > kMargin_m) return Verdict::kApart;
  if (mixed) return inside_cylinder(cylinder, p) ? Verdict::kMeet : Verdict::kUndecided;
  for (const double t : {0.5, 0.25, 0.75})
    if (inside_cylinder(a, p + t * (q - p)) && inside_cylinder(b, p + t * (q - p)))
      return Verdict::kMeet;
  return Verdict::kUndecided;
}

// Distance from `point` (frame coordinates) to the solid shape p; 0 inside.
double distance_to(const PlacedPrimitive& p, const Eigen::Vector3d& point) {
  const Eigen::Vector3d local = p.X_FrameShape.inverse() * point;
  switch (p.kind) {
    case Kind::kBox:
      return (local.cwiseAbs() - 0.5 * p.size_m).cwiseMax(0.0).norm();
    case Kind::kCylinder:
      return std::hypot(std::max(0.0, std::hypot(local.x(), local.y()) - p.size_m.x()),
                        std::max(0.0, std::abs(local.z()) - 0.5 * p.size_m.y()));
    case Kind::kSphere:
      return std::max(0.0, local.norm() - p.size_m.x());
  }
  return 0.0;
}

Verdict by_gap(double gap) {
  if (gap > kMargin_m) return Verdict::kApart;
  if (gap < -kMargin_m) return Verdict::kMeet;
  return Verdict::kUndecided;
}

}  // namespace

Verdict quick_test(const PlacedPrimitive& a, const PlacedPrimitive& b) {
  if (a.kind == Kind::kSphere)
    return by_gap(distance_to(b, a.X_FrameShape.translation()) - a.size_m.x());
  if (b.kind == Kind::kSphere)
    return by_gap(distance_to(a, b.X_FrameShape.translation()) - b.size_m.x());
  if (a.kind == Kind::kBox && b.kind == Kind::kBox) return by_gap(separation(box_of(a), box_of(b)));
  return with_cylinder(a, b);
}

}  // namespace antipode::collision
