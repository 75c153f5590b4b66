// `railjoint mesh`: writes the rail-joint solids (and optionally the wheel) of
// a scene to a mesh file, for inspection in any 3-D viewer.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "geometry/face_groups.h"
#include "geometry/mesh_export.h"
#include "geometry/rail_joint_mesh.h"
#include "geometry/wheel_mesh.h"
#include "geometry/wheel_placement.h"
#include "models/rail_top.h"
#include "scenes/cli/commands.h"
#include "scenes/cli/output_folder.h"
#include "scenes/cli/scene_command.h"
#include "scenes/scene_file.h"
#include "support/input_error.h"
#include "support/interrupted_run.h"
#include "support/staging_folder.h"

namespace railjoint::cli {

namespace {

// Geometry only: rails with a gap the model would refuse are still rails.
const SceneCommandHelp kHelp = {
    "mesh",
    "Write the joint's rail-head solids (and the wheel) to a mesh file, in metres.\n"
    "x along travel, y lateral (0 on the rail-head centre line), z up; V bottom of the dip at x = 0.\n"
    "Incoming rail: -L/2 <= x <= cut, top z = -tan(beta/2) x; outgoing rail: cut <= x <= L/2,\n"
    "top z = +tan(beta/2) x (step joint: z = 0 and z = u0); cut x = y cot(theta), each rail end set\n"
    "back by gap / (2 sin theta); rail head |y| <= b_t, down to z = -depth.",
    "Scene file (TOML). Keys, SI units:\n"
    "  [joint] kind = \"inclined\"|\"step\", theta_deg (0, 90], beta [rad],\n"
    "          half_width b_t [m], length L [m], depth [m], gap [m] (normal to\n"
    "          the cut), step_height u0 [m] (< 0: step down), crown_radius [m] (0 = flat),\n"
    "          dip_shape, dip_length [m] (formulas: railjoint analytic --help)\n"
    "  [wheel] radius R [m], width b_w [m] (0 = thin disc), y lateral position y_w [m],\n"
    "          conicity (0 = cylinder)",
    "joint.gap=0.005",
    {"joint", "wheel"}};

struct MeshOptions {
  std::string out_path;
  bool wheel = false;
  bool by_face = false;
  int segments = 64;
};

// The wheel as it starts a run: at y_w, touching the incoming rail halfway
// along that rail's length at y_w, well before the joint.
TriangleMesh placed_wheel(const JointParams& joint, const WheelParams& wheel_params, int segments) {
  TriangleMesh wheel = build_wheel_mesh(wheel_params, segments);
  const double contact_x = (-joint.length_m / 2.0 + cut_x_m(joint, wheel_params.lateral_m, 0)) / 2.0;
  const Eigen::Vector3d centre = wheel_centre_on_incoming_rail_m(joint, wheel_params, contact_x);
  for (Eigen::Vector3d& v : wheel.vertices_m) v += centre;
  return wheel;
}

// "incoming_rail" -> "incoming_rail_top", "incoming_rail_cut", ...
std::vector<std::pair<std::string, TriangleMesh>> split_into_face_groups(
    const std::vector<std::pair<std::string, TriangleMesh>>& meshes) {
  std::vector<std::pair<std::string, TriangleMesh>> groups;
  for (const auto& [name, mesh] : meshes) {
    for (auto& [tag, group] : split_by_face_tag(mesh)) groups.emplace_back(name + "_" + to_string(tag), std::move(group));
  }
  return groups;
}

void run_mesh(const Scene& scene, const MeshOptions& options) {
  require_mesh_export();  // an executable without assimp (railjoint-assimp is missing): exit 1, not bad input
  MeshExportFormat format;
  try {
    format = mesh_export_format(options.out_path);
  } catch (const std::runtime_error& error) {
    throw InputError(options.out_path, "--out", error.what());
  }
  const bool single_mesh_format = format.assimp_id.starts_with("ply") || format.assimp_id.starts_with("stl");
  if (options.by_face && single_mesh_format) {
    throw InputError(options.out_path, "--out",
                     options.out_path + ": --by-face needs a format that keeps several named meshes "
                     "(.obj, .glb, .gltf); PLY and STL hold one, so the face groups would be merged");
  }
  // No joint.length given: rails as long as the meshes need, their run-up
  // included (at least the scene's 1 m default).
  JointParams joint_params = scene.joint;
  if (!scene.given("joint.length")) {
    joint_params.length_m = std::max(joint_params.length_m, minimum_rail_length_m(joint_params, scene.wheel));
  }
  check_joint_geometry(joint_params, scene.wheel);

  RailJointMesh joint = build_rail_joint_mesh(joint_params);
  std::vector<std::pair<std::string, TriangleMesh>> meshes = {{"incoming_rail", std::move(joint.incoming)},
                                                              {"outgoing_rail", std::move(joint.outgoing)}};
  if (options.wheel) meshes.emplace_back("wheel", placed_wheel(joint_params, scene.wheel, options.segments));
  if (options.by_face) meshes = split_into_face_groups(meshes);
  // Written beside the target first (with the .mtl or .bin some formats add)
  // and published when all of it is on disk: a failed export leaves no
  // truncated mesh and an older one untouched.
  const std::filesystem::path out_path(options.out_path);
  // Its folder is made, as every other command makes its --out.
  if (!out_path.parent_path().empty()) prepare_output_folder(out_path.parent_path(), "--out");
  StagingFolder staging(out_path.parent_path(), "--out", out_path);
  try {
    export_meshes(meshes, (staging.path() / out_path.filename()).string());
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(staging.published_text(error.what()));
  }
  // The mesh itself first: it is the file that can fail part-way (a link to a
  // device, a full disk), and its .mtl or .bin must not be left without it.
  const std::string mesh_name = out_path.filename().string();
  {
    const PublishingOutputs publishing;  // the mesh and its .mtl together, or neither
    staging.publish(mesh_name, mesh_name);
    for (const std::string& name : staging.files()) staging.publish(name, name);
  }

  std::printf("wrote %s (%s, metres)\n", options.out_path.c_str(), format.description.c_str());
  for (const auto& [name, mesh] : meshes) {
    // A face group is an open surface: its area says something, a volume would not.
    if (options.by_face) {
      std::printf("  %-22s %6zu triangles %6zu vertices  area %.6g m^2\n", name.c_str(), mesh.triangles.size(),
                  mesh.vertices_m.size(), surface_area_m2(mesh));
    } else {
      std::printf("  %-14s %6zu triangles %6zu vertices  volume %.6g m^3\n", name.c_str(), mesh.triangles.size(),
                  mesh.vertices_m.size(), signed_volume_m3(mesh));
    }
  }
}

void add_mesh_options(CLI::App& cmd, MeshOptions& options) {
  cmd.add_option("--out", options.out_path,
                 "Mesh file to write; format from the extension: .obj (+ .mtl), .ply, .stl, .glb, .gltf (+ .bin).\n"
                 "PLY and STL hold one mesh, so the rails (and wheel) are merged there. Coordinates are\n"
                 "single precision in every format (assimp's float; binary STL and glTF are float by their\n"
                 "specifications): 6e-8 m at 1 m. The simulation reads the exact surfaces, not these meshes.")
      ->required();
  cmd.add_flag("--wheel", options.wheel,
               "Also write the wheel (render mesh; width max(b_w, 10 mm)) at y_w, resting on the incoming rail\n"
               "halfway along it");
  cmd.add_flag("--by-face", options.by_face,
               "One named mesh per face of each solid: <solid>_top, _cut, _side, _end, _bottom (wheel_rim,\n"
               "wheel_face). Each group is an open surface; together they are the closed solid. .obj/.glb/.gltf only");
  cmd.add_option("--segments", options.segments, "Sides of the wheel's polygon (with --wheel)")
      ->check(CLI::Range(3, 100000));
}

}  // namespace

void add_mesh_command(CLI::App& app) {
  add_scene_command(app, kHelp, SceneCheck::geometry, add_mesh_options, run_mesh);
}

}  // namespace railjoint::cli
