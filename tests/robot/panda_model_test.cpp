// The Panda of robots/panda against Franka Emika's published kinematics: the URDF's forward
// kinematics equal the modified Denavit-Hartenberg table computed directly (a second,
// independent encoding of the same numbers) at 1,000 random configurations; its limits are
// the published ones; its hand's frames are where the data sheet puts them. And robot files:
// what they read and the errors of bad ones.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "antipode/core/random.hpp"
#include "antipode/robot/robot_file.hpp"
#include "antipode/robot/robot_model.hpp"
#include "support/error_of.hpp"

namespace antipode {
namespace {

using testing::error_of;

const std::string kSource = ANTIPODE_TEST_SOURCE_DIR;
const std::string kPanda = kSource + "/robots/panda/panda.urdf";
constexpr double kPi = 3.14159265358979323846;

// Craig's modified DH transform of one row: RotX(alpha) TransX(a) RotZ(theta) TransZ(d).
Eigen::Isometry3d modified_dh(double a_m, double d_m, double alpha_rad, double theta_rad) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.rotate(Eigen::AngleAxisd(alpha_rad, Eigen::Vector3d::UnitX()));
  X.translate(Eigen::Vector3d(a_m, 0, 0));
  X.rotate(Eigen::AngleAxisd(theta_rad, Eigen::Vector3d::UnitZ()));
  X.translate(Eigen::Vector3d(0, 0, d_m));
  return X;
}

// Franka Emika's table (frankaemika.github.io/docs/control_parameters.html): link0 -> flange.
Eigen::Isometry3d panda_dh_flange(const Eigen::VectorXd& q) {
  const double a[] = {0, 0, 0, 0.0825, -0.0825, 0, 0.088};
  const double d[] = {0.333, 0, 0.316, 0, 0.384, 0, 0};
  const double alpha[] = {0, -kPi / 2, kPi / 2, kPi / 2, -kPi / 2, kPi / 2, kPi / 2};
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  for (int i = 0; i < 7; ++i) X = X * modified_dh(a[i], d[i], alpha[i], q[i]);
  return X * modified_dh(0, 0.107, 0, 0);
}

TEST(PandaModelTest, ForwardKinematicsEqualTheDhTableAtRandomConfigurations) {
  const RobotModel robot = RobotModel::load(kPanda);
  const KinematicChain arm = robot.chain("panda_link0", "panda_link8");
  ASSERT_EQ(arm.dof(), 7u);
  RandomStream random(48);
  double worst_m = 0.0, worst_rad = 0.0;
  for (int k = 0; k < 1000; ++k) {
    const Eigen::VectorXd q = arm.random_configuration(random);
    const Eigen::Isometry3d urdf = arm.forward(q), dh = panda_dh_flange(q);
    worst_m = std::max(worst_m, (urdf.translation() - dh.translation()).norm());
    worst_rad =
        std::max(worst_rad, Eigen::AngleAxisd(urdf.linear().transpose() * dh.linear()).angle());
  }
  EXPECT_LT(worst_m, 1e-6);
  EXPECT_LT(worst_rad, 1e-6);
}

TEST(PandaModelTest, JointLimitsAreThePublishedOnes) {
  const KinematicChain arm = RobotModel::load(kPanda).chain("panda_link0", "panda_link8");
  const double lower[] = {-2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973};
  const double upper[] = {2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973};
  const double velocity[] = {2.175, 2.175, 2.175, 2.175, 2.61, 2.61, 2.61};
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_DOUBLE_EQ(arm.limits()[i].lower, lower[i]) << arm.joint_names()[i];
    EXPECT_DOUBLE_EQ(arm.limits()[i].upper, upper[i]) << arm.joint_names()[i];
    EXPECT_DOUBLE_EQ(arm.limits()[i].velocity, velocity[i]) << arm.joint_names()[i];
  }
}

// The grasp frame: 0.0629 m down the flange's z axis (the palm face, 5 cm behind the
// fingertips' ends at 0.1129 m), approaching along the flange's z, closing along the hand's
// y (the flange's y turned -45 degrees about z), whatever the joints.
TEST(PandaModelTest, GraspFrameFollowsTheFlangeAsTheHandIsMounted) {
  const RobotModel robot = RobotModel::load(kPanda);
  const KinematicChain to_flange = robot.chain("base", "panda_link8");
  const KinematicChain to_grasp = robot.chain("base", "panda_grasp");
  RandomStream random(7);
  for (int k = 0; k < 20; ++k) {
    const Eigen::VectorXd q = to_grasp.random_configuration(random);
    const Eigen::Isometry3d flange = to_flange.forward(q), grasp = to_grasp.forward(q);
    const Eigen::Vector3d flange_z = flange.linear().col(2);
    EXPECT_LT((grasp.translation() - (flange.translation() + 0.0629 * flange_z)).norm(), 1e-9);
    EXPECT_LT((grasp.linear().col(0) - flange_z).norm(), 1e-9);  // approach
    const Eigen::Vector3d closing = flange.linear() *
                                    Eigen::AngleAxisd(-kPi / 4, Eigen::Vector3d::UnitZ()) *
                                    Eigen::Vector3d::UnitY();
    EXPECT_LT((grasp.linear().col(1) - closing).norm(), 1e-9);
  }
  // The mount: link0 stands on the table top (z = -0.295) at (0.1, -0.2).
  const KinematicChain to_link1 = robot.chain("base", "panda_link1");
  const std::vector<std::string> links = to_link1.link_names();
  const auto link0 = std::find(links.begin(), links.end(), "panda_link0") - links.begin();
  ASSERT_LT(std::size_t(link0), links.size());
  const Eigen::Isometry3d X_link0 = to_link1.link_poses(Eigen::VectorXd::Zero(1))[link0];
  EXPECT_LT((X_link0.translation() - Eigen::Vector3d(0.1, -0.2, -0.295)).norm(), 1e-12);
}

TEST(RobotFileTest, ThePandaFileNamesItsArmHomeGripperAndModel) {
  const RobotFile panda = read_robot_file(kSource + "/robots/panda/panda.yaml");
  EXPECT_EQ(panda.name, "Franka Emika Panda");
  EXPECT_EQ(panda.arm_tip, "panda_grasp");
  EXPECT_EQ(panda.gripper_from, "panda_hand");
  EXPECT_EQ(panda.home_rad.size(), 7u);
  // The gripper file's apertures are the fingers' stroke in the URDF: 0-40 mm each.
  EXPECT_DOUBLE_EQ(panda.gripper.max_aperture_m, 0.08);
  EXPECT_EQ(std::filesystem::path(panda.model_path).filename(), "hog_svm_franka.model");
  EXPECT_EQ(panda.points_unchecked,
            (std::vector<std::string>{"panda_leftfinger", "panda_rightfinger"}));
  const RobotFile baxter = read_robot_file(kSource + "/robots/baxter/baxter.yaml");
  EXPECT_EQ(baxter.arm_tip, "right_gripper");
  EXPECT_DOUBLE_EQ(baxter.gripper.max_aperture_m, 0.072);
  EXPECT_EQ(baxter.points_unchecked, std::vector<std::string>{"right_hand"});
}

class RobotFileErrorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("antipode_robot_file_" +
            std::to_string(::testing::UnitTest::GetInstance()->current_test_info()->line()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  // The error of reading a robot file with `text`, its URDF and gripper the Panda's.
  std::string error_with(const std::string& text) {
    const std::string path = (dir_ / "robot.yaml").string();
    std::ofstream(path) << "urdf: " << kPanda << "\ngripper: " << kSource
                        << "/robots/grippers/franka_hand.yaml\n"
                        << text;
    return error_of([&] { read_robot_file(path); });
  }
  std::filesystem::path dir_;
};

TEST_F(RobotFileErrorTest, BadFilesGiveOneLineNamingTheKey) {
  const std::string home = "home_rad: [0, -0.785, 0, -2.356, 0, 1.571, 0.785]\n";
  EXPECT_NE(
      error_with("arm_tip: panda_grsp\ngripper_from: panda_hand\n" + home)
          .find("arm_tip: no link 'panda_grsp' in " + kPanda + " (did you mean 'panda_grasp'?)"),
      std::string::npos);
  EXPECT_NE(error_with("arm_tip: panda_grasp\ngripper_from: panda_leftfinger\n" + home)
                .find("gripper_from: link 'panda_leftfinger' is not on the arm"),
            std::string::npos);
  const std::string short_home =
      error_with("arm_tip: panda_grasp\ngripper_from: panda_hand\nhome_rad: [0, 1]\n");
  EXPECT_NE(short_home.find("robot.yaml:5:"), std::string::npos) << short_home;
  EXPECT_NE(short_home.find("home_rad: 2 values for the 7 joints of the arm (panda_joint1 ... "
                            "panda_joint7)"),
            std::string::npos)
      << short_home;
  EXPECT_NE(error_with("arm_tip: panda_grasp\ngripper_from: panda_hand\nhome_rad: [0, 0, 0, 0, "
                       "0, 0, 0]\n")
                .find("home_rad: panda_joint4 = 0.000000 is outside its limits [-3.071800, "
                      "-0.069800]"),
            std::string::npos);
  EXPECT_NE(error_with("arm_tip: panda_grasp\ngripper_from: panda_link5\n" + home)
                .find("gripper_from: joints move between 'panda_link5' and the grasp frame"),
            std::string::npos);
  EXPECT_NE(
      error_with("arm_tip: panda_grasp\n" + home).find("missing required parameter 'gripper_from'"),
      std::string::npos);
  EXPECT_NE(error_with("arm_tip: panda_grasp\ngripper_from: panda_hand\nhome: []\n" + home)
                .find("'home'"),
            std::string::npos);
}

TEST_F(RobotFileErrorTest, AUrdfIsNotARobotFile) {
  const std::string error = error_of([] { read_robot_file(kPanda); });
  EXPECT_NE(error.find("a URDF, not a robot file"), std::string::npos) << error;
  EXPECT_NE(error.find("robots/baxter/baxter.yaml"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

}  // namespace
}  // namespace antipode
