#include "renders/crossing_gltf.h"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <assimp/Exporter.hpp>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "renders/palette.h"

namespace railjoint {

namespace {

aiMesh* to_assimp(const std::string& name, const TriangleMesh& mesh, unsigned material) {
  auto out = std::make_unique<aiMesh>();
  out->mName = name;
  out->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  out->mMaterialIndex = material;
  out->mNumVertices = static_cast<unsigned>(mesh.vertices_m.size());
  out->mVertices = new aiVector3D[out->mNumVertices];
  for (unsigned i = 0; i < out->mNumVertices; ++i) {
    const Eigen::Vector3d& v = mesh.vertices_m[i];
    out->mVertices[i] = aiVector3D(static_cast<ai_real>(v.x()), static_cast<ai_real>(v.y()), static_cast<ai_real>(v.z()));
  }
  out->mNumFaces = static_cast<unsigned>(mesh.triangles.size());
  out->mFaces = new aiFace[out->mNumFaces];
  for (unsigned i = 0; i < out->mNumFaces; ++i) {
    out->mFaces[i].mNumIndices = 3;
    out->mFaces[i].mIndices = new unsigned[3];
    for (int k = 0; k < 3; ++k) out->mFaces[i].mIndices[k] = static_cast<unsigned>(mesh.triangles[i][k]);
  }
  return out.release();
}

aiMaterial* material(const char* name, const Eigen::Vector3f& colour) {
  auto* m = new aiMaterial;
  const aiString material_name(name);
  m->AddProperty(&material_name, AI_MATKEY_NAME);
  const aiColor4D base(colour.x(), colour.y(), colour.z(), 1.0f);
  m->AddProperty(&base, 1, AI_MATKEY_BASE_COLOR);
  const aiColor3D diffuse(colour.x(), colour.y(), colour.z());
  m->AddProperty(&diffuse, 1, AI_MATKEY_COLOR_DIFFUSE);
  const float metallic = 0.6f, roughness = 0.45f;  // steel
  m->AddProperty(&metallic, 1, AI_MATKEY_METALLIC_FACTOR);
  m->AddProperty(&roughness, 1, AI_MATKEY_ROUGHNESS_FACTOR);
  return m;
}

aiNode* mesh_node(const char* name, unsigned mesh, aiNode* parent) {
  auto* node = new aiNode(name);
  node->mParent = parent;
  node->mNumMeshes = 1;
  node->mMeshes = new unsigned[1]{mesh};
  return node;
}

}  // namespace

GltfReport write_crossing_gltf(const std::filesystem::path& path, const RenderSettings& settings,
                               const RailJointMesh& rails, const TriangleMesh& wheel, const Trajectory& trajectory) {
  const FrameWindow window = frame_window(settings, trajectory);  // checks the settings and the window
  GltfReport report;
  report.path = path;
  report.slow_motion = settings.fps / settings.video_fps;

  // aiScene's destructor frees everything hung on it with delete/delete[].
  aiScene scene;
  scene.mNumMaterials = 2;
  scene.mMaterials = new aiMaterial*[2]{material("rail", palette::rail_top), material("wheel", palette::wheel_face)};
  scene.mNumMeshes = 3;
  scene.mMeshes = new aiMesh*[3]{to_assimp(kGltfIncomingRailNode, rails.incoming, 0),
                                 to_assimp(kGltfOutgoingRailNode, rails.outgoing, 0),
                                 to_assimp(kGltfWheelNode, wheel, 1)};

  // root -> exaggeration (z stretched k-fold about z_ref) -> rails, wheel.
  // glTF's up is +y; the project's is +z: the root turns -90 deg about x so
  // viewers show the track upright (its children keep the project's axes).
  scene.mRootNode = new aiNode("railjoint");
  aiMatrix4x4::RotationX(static_cast<ai_real>(-std::numbers::pi / 2.0), scene.mRootNode->mTransformation);
  auto* exaggeration = new aiNode(kGltfExaggerationNode);
  exaggeration->mParent = scene.mRootNode;
  const double k = settings.exaggeration;
  exaggeration->mTransformation = aiMatrix4x4(1, 0, 0, 0,  //
                                              0, 1, 0, 0,  //
                                              0, 0, static_cast<ai_real>(k),
                                              static_cast<ai_real>((1.0 - k) * settings.reference_z_m),  //
                                              0, 0, 0, 1);
  scene.mRootNode->mNumChildren = 1;
  scene.mRootNode->mChildren = new aiNode*[1]{exaggeration};
  aiNode* wheel_node = mesh_node(kGltfWheelNode, 2, exaggeration);
  exaggeration->mNumChildren = 3;
  exaggeration->mChildren = new aiNode*[3]{mesh_node(kGltfIncomingRailNode, 0, exaggeration),
                                           mesh_node(kGltfOutgoingRailNode, 1, exaggeration), wheel_node};

  // The wheel's keys: every recorded sample in the window.
  std::vector<const WheelSample*> keyed;
  for (const WheelSample& s : trajectory.samples) {
    if (s.time_s >= window.t_start_s - 1e-12 && s.time_s <= window.t_end_s + 1e-12) keyed.push_back(&s);
  }
  if (keyed.empty()) keyed.push_back(&trajectory.samples.front());
  const WheelSample& first = *keyed.front();
  wheel_node->mTransformation =
      aiMatrix4x4(aiVector3D(1, 1, 1), aiQuaternion(aiVector3D(0, 1, 0), static_cast<ai_real>(first.spin_angle_rad)),
                  aiVector3D(static_cast<ai_real>(first.centre_m.x()), static_cast<ai_real>(first.centre_m.y()),
                             static_cast<ai_real>(first.centre_m.z())));

  auto* channel = new aiNodeAnim;
  channel->mNodeName = kGltfWheelNode;
  const unsigned n = static_cast<unsigned>(keyed.size());
  channel->mNumPositionKeys = n;
  channel->mPositionKeys = new aiVectorKey[n];
  channel->mNumRotationKeys = n;
  channel->mRotationKeys = new aiQuatKey[n];
  channel->mNumScalingKeys = 1;
  channel->mScalingKeys = new aiVectorKey[1];
  channel->mScalingKeys[0] = aiVectorKey(0.0, aiVector3D(1, 1, 1));
  // assimp counts key times in ticks; one tick = one millisecond of playback.
  constexpr double kTicksPerSecond = 1000.0;
  for (unsigned i = 0; i < n; ++i) {
    const WheelSample& s = *keyed[i];
    const double playback_s = (s.time_s - window.t_start_s) * report.slow_motion;
    const double ticks = playback_s * kTicksPerSecond;
    channel->mPositionKeys[i] =
        aiVectorKey(ticks, aiVector3D(static_cast<ai_real>(s.centre_m.x()), static_cast<ai_real>(s.centre_m.y()),
                                      static_cast<ai_real>(s.centre_m.z())));
    // Spin about the axle (+y), positive rolling forward, as the renderer turns it.
    channel->mRotationKeys[i] = aiQuatKey(ticks, aiQuaternion(aiVector3D(0, 1, 0), static_cast<ai_real>(s.spin_angle_rad)));
    report.duration_s = playback_s;
  }
  auto* animation = new aiAnimation;
  animation->mName = kGltfAnimation;
  animation->mTicksPerSecond = kTicksPerSecond;
  animation->mDuration = report.duration_s * kTicksPerSecond;
  animation->mNumChannels = 1;
  animation->mChannels = new aiNodeAnim*[1]{channel};
  scene.mNumAnimations = 1;
  scene.mAnimations = new aiAnimation*[1]{animation};
  report.keys = n;

  Assimp::Exporter exporter;
  if (exporter.Export(&scene, "glb2", path.string()) != aiReturn_SUCCESS) {
    throw std::runtime_error("cannot write the glTF file '" + path.string() + "': " + exporter.GetErrorString());
  }
  return report;
}

}  // namespace railjoint
