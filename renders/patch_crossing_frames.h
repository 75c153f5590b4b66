#pragma once
// A top view of the local model (thesis chapters 5-6): the contact patch
// sliding over the end-post gap, frame by frame, with the part over the gap
// (the reduction area) marked and the uniform pressure written on each frame.
// Drawn flat, as 2-D triangles in pixel coordinates through OffscreenRenderer's
// overlay (no lighting, no depth); PNG frames, and
// crossing.mp4 / crossing.gif when ffmpeg is on PATH.

#include <filesystem>
#include <optional>
#include <string>

#include "models/pressure_traversal.h"
#include "renders/video_files.h"

namespace railjoint {

struct PatchCrossingFrames : VideoFiles {
  long long frames_written = 0;
  double draw_ms_per_frame = 0.0;  ///< GL draw + read-back + RGB rows, mean [ms]
};

/// frame_count frames (>= 2) at equal steps of x_front from 0 to x_end into
/// out_dir/frame_00000.png ...; throws std::runtime_error when rendering is
/// unavailable, a file cannot be written or ffmpeg fails (VideoPipe::finish).
PatchCrossingFrames render_patch_crossing(const PressureInputs& inputs, const std::filesystem::path& out_dir,
                                          int frame_count, int width_px, int height_px);

}  // namespace railjoint
