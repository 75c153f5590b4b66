#pragma once
// The crossing as an animated glTF 2.0 binary (.glb) that any glTF viewer or
// Blender opens: the two rail ends as meshes and the wheel as a node whose
// translation and rotation are keyed at the recorded states, written through
// assimp. Positions stay exact (the recorded ones, as float): the vertical
// exaggeration is the transform of a parent node "exaggeration" (scale k
// along z about z_ref) that holds the rails and the wheel, so a viewer shows
// what the frames show and removing that one scale gives the true geometry.
// The root node turns the project's z-up axes into glTF's y-up.
// The animation plays in slow motion, the frames' rate over the video's
// (render.fps / render.video_fps, 800x by default), so the ~3 ms around
// the impact last seconds.

#include <filesystem>

#include "geometry/rail_joint_mesh.h"
#include "geometry/triangle_mesh.h"
#include "renders/frame_schedule.h"
#include "renders/render_settings.h"
#include "sim/trajectory.h"

namespace railjoint {

/// Node and animation names in the file (the test and viewers look them up).
inline constexpr const char* kGltfExaggerationNode = "exaggeration";
inline constexpr const char* kGltfIncomingRailNode = "incoming_rail";
inline constexpr const char* kGltfOutgoingRailNode = "outgoing_rail";
inline constexpr const char* kGltfWheelNode = "wheel";
inline constexpr const char* kGltfAnimation = "crossing";

struct GltfReport {
  std::filesystem::path path;
  long long keys = 0;          ///< translation keys (= rotation keys) of the wheel
  double slow_motion = 1.0;    ///< playback seconds per simulated second
  double duration_s = 0.0;     ///< playback length [s]
};

/// Writes `path` (.glb): every recorded sample within the window of
/// `settings` (frame_window) becomes one key at playback time
/// (t - t_start) * slow_motion, slow_motion = settings.fps / settings.video_fps.
/// The wheel mesh is centred at the origin with its axle along y. Throws
/// std::runtime_error naming the file when assimp cannot write it.
GltfReport write_crossing_gltf(const std::filesystem::path& path, const RenderSettings& settings,
                               const RailJointMesh& rails, const TriangleMesh& wheel, const Trajectory& trajectory);

}  // namespace railjoint
