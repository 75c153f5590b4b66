// Export through assimp and read back through assimp: same solids in every format.

#include "geometry/mesh_export.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <set>
#include <stdexcept>

#include "geometry/rail_joint_mesh.h"
#include "geometry/wheel_mesh.h"
#include "tests/geometry/joint_cases.h"
#include "tests/geometry/mesh_checks.h"
#include "tests/support/scratch_dir.h"

namespace railjoint {
namespace {

std::string temp_path(const std::string& name) {
  return railjoint::testing_support::scratch_path(name).string();
}

// All meshes of a file as one TriangleMesh each. Every format is read the same
// way: normals (STL stores one per face, which would keep a corner shared by
// differently facing triangles apart), texture coordinates and colours are
// dropped, then identical positions are joined. STL stores three corners per
// triangle and OBJ/PLY readers also split corners, so before joining their
// vertex counts differ; after joining each solid has its own corner count back.
std::vector<std::pair<std::string, TriangleMesh>> read_back(const std::string& path) {
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS | aiComponent_TEXCOORDS | aiComponent_COLORS |
                                                          aiComponent_TANGENTS_AND_BITANGENTS);
  const aiScene* scene = importer.ReadFile(path, aiProcess_RemoveComponent | aiProcess_JoinIdenticalVertices);
  EXPECT_NE(scene, nullptr) << importer.GetErrorString();
  std::vector<std::pair<std::string, TriangleMesh>> meshes;
  if (scene == nullptr) return meshes;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* in = scene->mMeshes[m];
    TriangleMesh mesh;
    for (unsigned i = 0; i < in->mNumVertices; ++i) {
      mesh.vertices_m.emplace_back(in->mVertices[i].x, in->mVertices[i].y, in->mVertices[i].z);
    }
    for (unsigned i = 0; i < in->mNumFaces; ++i) {
      EXPECT_EQ(in->mFaces[i].mNumIndices, 3u);
      const unsigned* f = in->mFaces[i].mIndices;
      mesh.triangles.emplace_back(f[0], f[1], f[2]);
      mesh.tags.push_back(FaceTag::top);
    }
    meshes.emplace_back(in->mName.C_Str(), std::move(mesh));
  }
  return meshes;
}

std::vector<std::pair<std::string, TriangleMesh>> sample_meshes() {
  test::JointCase shallow = test::joint_cases()[2];  // theta 1 deg: long cut faces, coordinates up to 1.5 m
  EXPECT_EQ(shallow.name, "shallow_1deg");
  RailJointMesh thesis = build_rail_joint_mesh(JointParams{});
  RailJointMesh shallow_mesh = build_rail_joint_mesh(shallow.joint);
  WheelParams wheel;
  wheel.width_m = 0.03;
  return {{"incoming_rail", thesis.incoming},
          {"outgoing_rail_1deg", shallow_mesh.outgoing},
          {"wheel", build_wheel_mesh(wheel, 24)}};
}

class MeshExportTest : public testing::TestWithParam<std::string> {};

// Coordinates are written as float: rounding moves each by at most
// 2^-24 |x| = 9e-8 m at 1.5 m. The bounding box may move that much; the
// volume by about that relative amount times a few (three coordinates per
// term, terms partly cancelling). Seen: 4.7e-8 m and 4.6e-8 relative (the
// 24-sided wheel); tolerances ten times that.
TEST_P(MeshExportTest, OneMeshPerFileRoundTrips) {
  const std::string extension = GetParam();
  for (const auto& [name, mesh] : sample_meshes()) {
    const std::string path = temp_path(name + "." + extension);
    export_meshes({{name, mesh}}, path);
    const auto back = read_back(path);
    ASSERT_EQ(back.size(), 1u) << path;
    const TriangleMesh& read = back[0].second;
    EXPECT_EQ(test::manifold_defects(read), "") << path;
    EXPECT_EQ(read.vertices_m.size(), mesh.vertices_m.size()) << path;
    EXPECT_EQ(read.triangles.size(), mesh.triangles.size()) << path;
    const test::Box a = test::bounding_box(mesh), b = test::bounding_box(read);
    const double box_error = std::max((a.min - b.min).cwiseAbs().maxCoeff(), (a.max - b.max).cwiseAbs().maxCoeff());
    const double volume_error = std::abs(signed_volume_m3(read) - signed_volume_m3(mesh)) / signed_volume_m3(mesh);
    std::cout << path << ": " << read.vertices_m.size() << " vertices, " << read.triangles.size()
              << " triangles, bounding-box error " << box_error << " m, relative volume error " << volume_error << "\n";
    EXPECT_LT(box_error, 5e-7);
    EXPECT_LT(volume_error, 5e-7);
  }
}

// Several meshes in one file: OBJ and glTF keep them apart with their names;
// PLY and STL hold one mesh, so assimp merges them (documented). Either way
// every triangle arrives and the total volume is the sum.
TEST_P(MeshExportTest, SeveralMeshesInOneFile) {
  const std::string extension = GetParam();
  const auto meshes = sample_meshes();
  const std::string path = temp_path("all." + extension);
  export_meshes(meshes, path);
  const auto back = read_back(path);
  std::size_t triangles = 0, triangles_back = 0;
  double volume = 0.0, volume_back = 0.0;
  for (const auto& [name, mesh] : meshes) triangles += mesh.triangles.size(), volume += signed_volume_m3(mesh);
  std::set<std::string> names;
  for (const auto& [name, mesh] : back) {
    triangles_back += mesh.triangles.size(), volume_back += signed_volume_m3(mesh);
    names.insert(name);
  }
  std::cout << path << ": " << back.size() << " meshes, " << triangles_back << " triangles\n";
  EXPECT_EQ(triangles_back, triangles);
  EXPECT_NEAR(volume_back, volume, 5e-7 * volume);  // as above
  if (extension == "ply" || extension == "stl") {
    EXPECT_EQ(back.size(), 1u);
  } else {
    EXPECT_EQ(back.size(), meshes.size());
    for (const auto& [name, mesh] : meshes) EXPECT_TRUE(names.contains(name)) << name << " missing in " << path;
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, MeshExportTest, testing::Values("obj", "ply", "stl", "glb", "gltf"));

TEST(MeshExport, FormatByExtension) {
  EXPECT_EQ(mesh_export_format("a/b.GLB").assimp_id, "glb2");
  EXPECT_EQ(mesh_export_format("x.stl").assimp_id, "stlb");
  EXPECT_EQ(mesh_export_format("x.ply").assimp_id, "plyb");
  EXPECT_EQ(mesh_export_format("x.gltf").assimp_id, "gltf2");
  EXPECT_EQ(mesh_export_format("x.obj").assimp_id, "obj");
}

TEST(MeshExport, UnknownExtensionIsRejected) {
  const TriangleMesh wheel = build_wheel_mesh(WheelParams{}, 8);
  for (const std::string path : {"mesh.xyz", "mesh"}) {
    try {
      export_meshes({{"wheel", wheel}}, temp_path(path));
      ADD_FAILURE() << path << " accepted";
    } catch (const std::runtime_error& error) {
      const std::string message = error.what();
      std::cout << message << "\n";
      EXPECT_NE(message.find(path), std::string::npos);
      EXPECT_NE(message.find(".glb"), std::string::npos) << "lists the supported extensions";
    }
  }
}

TEST(MeshExport, WriteFailureIsReported) {
  const std::string path = temp_path("no_such_folder/mesh.stl");
  try {
    export_meshes({{"wheel", build_wheel_mesh(WheelParams{}, 8)}}, path);
    FAIL() << "accepted";
  } catch (const std::runtime_error& error) {
    std::cout << error.what() << "\n";
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos);
  }
}

}  // namespace
}  // namespace railjoint
