#include <vector>

#include <gtest/gtest.h>

#include "antipode/core/cloud.hpp"
#include "antipode/core/error.hpp"
#include "antipode/core/hand.hpp"
#include "antipode/core/hand_geometry.hpp"

namespace antipode {
namespace {

TEST(HandGeometryTest, BaxterDefaultsAreValid) {
  const HandGeometry baxter;
  EXPECT_NO_THROW(baxter.validate());
  EXPECT_DOUBLE_EQ(baxter.min_aperture_m, 0.029);
  EXPECT_DOUBLE_EQ(baxter.max_aperture_m, 0.072);
}

TEST(HandGeometryTest, InconsistentValuesNameTheField) {
  HandGeometry hand;
  hand.min_aperture_m = 0.08;
  EXPECT_THROW(hand.validate(), Error);
  hand = HandGeometry();
  hand.depth_m = -1.0;
  try {
    hand.validate();
    FAIL();
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("depth_m"), std::string::npos);
  }
}

TEST(CloudTest, ValidateChecksPerPointArrays) {
  Cloud cloud;
  cloud.points_m = {{0, 0, 0}, {1, 0, 0}};
  EXPECT_NO_THROW(cloud.validate());
  cloud.normals = {{0, 0, 1}};
  EXPECT_THROW(cloud.validate(), Error);
  cloud.normals = {{0, 0, 1}, {0, 1, 0}};
  cloud.view_masks = {1u, 2u};
  EXPECT_THROW(cloud.validate(), Error);  // view 1 has no origin
  cloud.view_origins_m = {{0, 0, 0}, {1, 1, 1}};
  EXPECT_NO_THROW(cloud.validate());
}

TEST(HandTest, AxesAreRotationColumns) {
  Hand hand;
  hand.X_FrameHand.linear() << 0, 0, 1,  //
      1, 0, 0,                           //
      0, 1, 0;
  EXPECT_TRUE(hand.approach().isApprox(Eigen::Vector3d(0, 1, 0)));
  EXPECT_TRUE(hand.closing().isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_TRUE(hand.axis().isApprox(Eigen::Vector3d(1, 0, 0)));
}

// A plugin's own rejection reason is what is printed and counted; a code's name otherwise.
TEST(HandTest, APluginsOwnRejectionReasonIsPrintedAndCounted) {
  std::vector<Hand> hands(4);
  reject_for(hands[0], "too tilted");
  reject_for(hands[1], "too tilted");
  hands[2].rejection = Rejection::kLowScore;
  EXPECT_EQ(hands[0].rejection, Rejection::kPluginReason);
  EXPECT_EQ(rejection_reason(hands[0]), "too tilted");
  EXPECT_EQ(rejection_reason(hands[2]), "low score");
  EXPECT_EQ(rejection_counts(hands, false), "2 too tilted, 1 low score");
  EXPECT_EQ(rejection_counts(hands), "2 too tilted, 1 low score, 1 none");
  hands[3].rejection = Rejection::kPluginReason;  // no text given
  EXPECT_EQ(rejection_reason(hands[3]), "a plugin's reason");
  // A reason stays one line and is never taken for a code or for a kept hand.
  reject_for(hands[3], "none");
  EXPECT_EQ(rejection_reason(hands[3]), "none (a plugin's)");
  reject_for(hands[3], "too\ntilted");
  EXPECT_EQ(rejection_reason(hands[3]), "too tilted");
}

}  // namespace
}  // namespace antipode
