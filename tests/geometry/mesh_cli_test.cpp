// `railjoint mesh` run as a user runs it: files written, wheel placement, errors naming the key.

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include "tests/support/run_cli.h"

#include <array>
#include <assimp/Importer.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <set>
#include <string>
#include "tests/support/scratch_dir.h"

namespace {

using railjoint::testing_support::RunResult;
using railjoint::testing_support::run_railjoint;

RunResult run(const std::string& arguments) { return run_railjoint(arguments); }

const std::string kDefaultScene = std::string(RAILJOINT_SOURCE_DIR) + "/scenes/default.toml";

std::string temp_path(const std::string& name) {
  return railjoint::testing_support::scratch_path(name).string();
}

// Default scene: thesis joint (theta 30 deg, beta 0.03, L 1 m, b_t 20 mm), wheel
// R = 0.475 m, y_w = 15 mm, thin disc drawn 10 mm wide. The wheel touches the
// incoming rail halfway along it at y_w: contact x_c = (-0.5 + 15 mm cot 30 deg) / 2
// = -0.23701 m; its centre is R above the top plane z = -t x (t = tan 0.015).
TEST(MeshCli, WritesRailsAndWheel) {
  const std::string out = temp_path("default.glb");
  const RunResult r = run("mesh " + kDefaultScene + " --out " + out + " --wheel --segments 32");
  std::cout << r.output;
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("incoming_rail"), std::string::npos);
  EXPECT_NE(r.output.find("12 triangles"), std::string::npos);
  EXPECT_NE(r.output.find("128 triangles"), std::string::npos) << "wheel: 4 x 32";

  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(out, aiProcess_JoinIdenticalVertices);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  ASSERT_EQ(scene->mNumMeshes, 3u);
  const aiMesh* wheel = nullptr;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    if (std::string(scene->mMeshes[m]->mName.C_Str()) == "wheel") wheel = scene->mMeshes[m];
  }
  ASSERT_NE(wheel, nullptr);
  // 32 sides include the angles 0, 90, 180, 270 deg, so the box centre is the wheel centre.
  aiVector3D lo(1e9f, 1e9f, 1e9f), hi(-1e9f, -1e9f, -1e9f);
  for (unsigned i = 0; i < wheel->mNumVertices; ++i) {
    const aiVector3D& v = wheel->mVertices[i];
    lo = aiVector3D(std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z));
    hi = aiVector3D(std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z));
  }
  const double x = (lo.x + hi.x) / 2.0, y = (lo.y + hi.y) / 2.0, z = (lo.z + hi.z) / 2.0;
  const double t = std::tan(0.015), R = 0.475;
  const double x_c = (-0.5 + 0.015 / std::tan(std::numbers::pi / 6.0)) / 2.0;
  std::cout << "wheel centre " << x << ", " << y << ", " << z << " m\n";
  // Float storage: ~1e-7 m.
  EXPECT_NEAR(y, 0.015, 1e-6);
  EXPECT_NEAR(x, x_c + R * std::sin(0.015), 1e-6);
  EXPECT_NEAR((z + t * x) / std::sqrt(1.0 + t * t), R, 1e-6);
  EXPECT_NEAR(hi.y - lo.y, 0.01, 1e-6);
}

TEST(MeshCli, EveryFormatAndAStepScene) {
  for (const char* extension : {"obj", "ply", "stl", "gltf"}) {
    const std::string out = temp_path(std::string("step.") + extension);
    const RunResult r =
        run("mesh " + kDefaultScene + " --set joint.kind=step --set joint.step_height=-0.002 --out " + out);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(out)) << out;
  }
}

TEST(MeshCli, ErrorsNameTheKey) {
  RunResult r = run("mesh " + kDefaultScene + " --set joint.length=0.2 --out " + temp_path("short.stl"));
  std::cout << r.output;
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("joint.length"), std::string::npos);
  EXPECT_NE(r.output.find("default.toml"), std::string::npos) << "names the file";

  r = run("mesh " + kDefaultScene + " --set joint.depth=0.0001 --out " + temp_path("shallow.stl"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("joint.depth"), std::string::npos) << r.output;

  r = run("mesh " + kDefaultScene + " --out " + temp_path("mesh.xyz"));
  std::cout << r.output;
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--out"), std::string::npos);

  // A folder that cannot be made (a file stands in its place; a missing
  // folder is made, see below).
  const std::string not_a_folder = temp_path("not_a_folder");
  std::fclose(std::fopen(not_a_folder.c_str(), "w"));
  r = run("mesh " + kDefaultScene + " --out " + not_a_folder + "/x.stl");
  std::cout << r.output;
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find(not_a_folder), std::string::npos);

  r = run("mesh " + kDefaultScene);
  EXPECT_NE(r.exit_code, 0) << "--out is required";
}

TEST(MeshCli, ByFaceWritesOneNamedMeshPerFace) {
  const std::string out = temp_path("by_face.obj");
  const RunResult r = run("mesh " + kDefaultScene + " --by-face --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(out, 0);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  // Two rail ends of 12 triangles in five faces each (face_groups_test).
  std::set<std::string> names;
  unsigned triangles = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    names.insert(scene->mMeshes[m]->mName.C_Str());
    triangles += scene->mMeshes[m]->mNumFaces;
  }
  EXPECT_EQ(triangles, 24u);
  for (const char* rail : {"incoming_rail", "outgoing_rail"}) {
    for (const char* face : {"top", "cut", "side", "end", "bottom"}) {
      EXPECT_TRUE(names.contains(std::string(rail) + "_" + face)) << rail << "_" << face << " missing in " << out;
    }
  }
  // PLY and STL keep one mesh: the groups would merge, so it is refused.
  const RunResult stl = run("mesh " + kDefaultScene + " --by-face --out " + temp_path("by_face.stl"));
  EXPECT_EQ(stl.exit_code, 2) << stl.output;
  EXPECT_NE(stl.output.find("--by-face needs a format that keeps several named meshes"), std::string::npos)
      << stl.output;
}

TEST(MeshCli, RailsWithAGapTheWheelDropsIntoAreExported) {
  // A level joint with a 6 mm end post, and a gap the wheel drops into:
  // outside the thesis's model, inside the general one (analytic answers).
  for (const std::string& sets : {std::string(" --set joint.beta=0 --set joint.gap=0.006"),
                                 std::string(" --set joint.gap=0.02")}) {
    const RunResult r = run("mesh " + kDefaultScene + sets + " --out " + temp_path("gap.obj"));
    EXPECT_EQ(r.exit_code, 0) << sets << ": " << r.output;
    EXPECT_EQ(run("analytic " + kDefaultScene + sets).exit_code, 0) << sets;
  }
}

// Issue 29, item 9: `mesh --out dir/joint.obj` failed when dir did not
// exist, where every other command makes its --out folder.
TEST(MeshCli, MakesTheFolderOfItsOutput) {
  const std::string out = temp_path("new/folders/joint.obj");
  const RunResult r = run("mesh " + kDefaultScene + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::is_regular_file(out)) << r.output;
  EXPECT_TRUE(std::filesystem::is_regular_file(temp_path("new/folders/joint.mtl"))) << r.output;
}

TEST(MeshCli, HelpExplainsUnits) {
  const RunResult r = run("mesh --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* text : {"--out", "--wheel", "--segments", "[m]", "theta", ".glb"}) {
    EXPECT_NE(r.output.find(text), std::string::npos) << text;
  }
}

}  // namespace

namespace {

// railjoint links no assimp (its relocations cost every run 1.5 ms at
// start-up) and hands the commands that write mesh files to railjoint-assimp
// beside it: the tests above ran through that hand-over.
TEST(MeshCli, RailjointLinksNoAssimpAndHandsMeshesOver) {
  const RunResult ldd = railjoint::testing_support::run_shell(std::string("ldd ") + RAILJOINT_EXE);
  ASSERT_EQ(ldd.exit_code, 0) << ldd.output;
  for (const char* library : {"libassimp", "libdraco", "libmpi"}) {
    EXPECT_EQ(ldd.output.find(library), std::string::npos) << library << " is linked:\n" << ldd.output;
  }
  // Alone in a folder, it says where meshes are written instead of writing none silently.
  const std::filesystem::path alone = railjoint::testing_support::scratch_path("alone");
  std::filesystem::create_directories(alone);
  std::filesystem::copy_file(RAILJOINT_EXE, alone / "railjoint", std::filesystem::copy_options::overwrite_existing);
  const std::string out = temp_path("alone.glb");
  const RunResult r = railjoint::testing_support::run_shell((alone / "railjoint").string() + " mesh " + kDefaultScene +
                                                            " --out " + out);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("railjoint-assimp"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
