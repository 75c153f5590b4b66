// The animated glTF read back with assimp's importer (an independent parser
// of the file): node names and hierarchy, the exaggeration as the parent
// node's scale, and the wheel's keys against the trajectory they came from.

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "geometry/rail_joint_mesh.h"
#include "geometry/wheel_mesh.h"
#include "renders/crossing_gltf.h"
#include "tests/support/scratch_dir.h"

namespace railjoint {
namespace {

// A made-up crossing: 31 samples 10 us apart, the wheel rising and spinning
// so every key differs in x, z and angle.
Trajectory made_up() {
  Trajectory t;
  for (int i = 0; i <= 30; ++i) {
    WheelSample s;
    s.time_s = 1e-3 + i * 1e-5;
    s.centre_m = {-0.02 + 5e-4 * i, 0.015, 0.475 + 1e-5 * i * i};
    s.spin_angle_rad = 0.1 + 0.01 * i;
    t.samples.push_back(s);
  }
  return t;
}

const aiNode* find(const aiNode* node, const std::string& name) {
  if (name == node->mName.C_Str()) return node;
  for (unsigned i = 0; i < node->mNumChildren; ++i) {
    if (const aiNode* found = find(node->mChildren[i], name)) return found;
  }
  return nullptr;
}

TEST(CrossingGltf, ReimportedNodesAndWheelKeysMatchTheTrajectory) {
  RenderSettings settings;  // exaggeration 20, fps 20000, video_fps 25: 800x slow motion
  settings.t_start_s = 1.05e-3;  // samples 5 .. 25 lie in the window: 21 keys
  settings.t_end_s = 1.25e-3;
  const Trajectory trajectory = made_up();
  WheelParams wheel;
  wheel.width_m = 0.001;
  const auto path = testing_support::scratch_path("crossing_test.glb");
  const GltfReport report = write_crossing_gltf(path, settings, build_rail_joint_mesh(JointParams{}),
                                                build_wheel_mesh(wheel, 64, 0.0), trajectory);
  std::cout << "wrote " << report.path << ": " << report.keys << " keys, " << report.slow_motion << "x, "
            << report.duration_s << " s, " << std::filesystem::file_size(path) << " bytes\n";
  EXPECT_EQ(report.keys, 21);
  EXPECT_DOUBLE_EQ(report.slow_motion, 800.0);

  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path.string(), 0);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();

  // Hierarchy: exaggeration -> incoming_rail, outgoing_rail, wheel.
  const aiNode* exaggeration = find(scene->mRootNode, kGltfExaggerationNode);
  ASSERT_NE(exaggeration, nullptr);
  for (const char* name : {kGltfIncomingRailNode, kGltfOutgoingRailNode, kGltfWheelNode}) {
    const aiNode* node = find(scene->mRootNode, name);
    ASSERT_NE(node, nullptr) << name;
    EXPECT_EQ(node->mParent, exaggeration) << name;
    EXPECT_GE(node->mNumMeshes, 1u) << name;
  }
  // The exaggeration is the parent's scale: (1, 1, k) about z_ref = 0.
  aiVector3D scaling, position;
  aiQuaternion rotation;
  exaggeration->mTransformation.Decompose(scaling, rotation, position);
  std::cout << "exaggeration node scale (" << scaling.x << ", " << scaling.y << ", " << scaling.z << ")\n";
  EXPECT_FLOAT_EQ(scaling.x, 1.0f);
  EXPECT_FLOAT_EQ(scaling.y, 1.0f);
  EXPECT_FLOAT_EQ(scaling.z, 20.0f);

  // One animation with one channel for the wheel; 21 keys each.
  ASSERT_EQ(scene->mNumAnimations, 1u);
  const aiAnimation* animation = scene->mAnimations[0];
  const aiNodeAnim* channel = nullptr;
  for (unsigned i = 0; i < animation->mNumChannels; ++i) {
    if (std::string(animation->mChannels[i]->mNodeName.C_Str()) == kGltfWheelNode) channel = animation->mChannels[i];
  }
  ASSERT_NE(channel, nullptr);
  ASSERT_EQ(channel->mNumPositionKeys, 21u);
  ASSERT_EQ(channel->mNumRotationKeys, 21u);
  const double ticks_per_second = animation->mTicksPerSecond > 0.0 ? animation->mTicksPerSecond : 1.0;
  std::cout << "ticks per second " << animation->mTicksPerSecond << ", last key at "
            << channel->mPositionKeys[20].mTime << " ticks\n";
  double worst_position_m = 0.0, worst_angle_rad = 0.0, worst_time_s = 0.0;
  for (unsigned i = 0; i < 21; ++i) {
    const WheelSample& s = trajectory.samples[5 + i];
    const aiVector3D& p = channel->mPositionKeys[i].mValue;
    worst_position_m = std::max(worst_position_m, (Eigen::Vector3d(p.x, p.y, p.z) - s.centre_m).norm());
    // A rotation by a about +y: quaternion (cos a/2, 0, sin a/2, 0).
    const aiQuaternion& q = channel->mRotationKeys[i].mValue;
    const double angle = 2.0 * std::atan2(static_cast<double>(q.y), static_cast<double>(q.w));
    worst_angle_rad = std::max(worst_angle_rad, std::abs(angle - s.spin_angle_rad));
    EXPECT_NEAR(q.x, 0.0f, 1e-7f);
    EXPECT_NEAR(q.z, 0.0f, 1e-7f);
    // Playback time: (t - t_start) x 800.
    const double playback_s = channel->mPositionKeys[i].mTime / ticks_per_second;
    worst_time_s = std::max(worst_time_s, std::abs(playback_s - (s.time_s - 1.05e-3) * 800.0));
  }
  std::cout << "largest differences: position " << worst_position_m << " m, angle " << worst_angle_rad
            << " rad, playback time " << worst_time_s << " s\n";
  // Floats: 6e-8 relative, 3e-8 m on a 0.5 m coordinate; a key time of
  // 0.16 s to 1e-8 s. Ten times that.
  EXPECT_LT(worst_position_m, 3e-7);
  EXPECT_LT(worst_angle_rad, 1e-6);
  EXPECT_LT(worst_time_s, 1e-6);
}

}  // namespace
}  // namespace railjoint
