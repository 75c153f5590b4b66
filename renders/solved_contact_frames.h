#pragma once
// The solved contact crossing the end-post gap, frame by frame (`pressure
// --frames` with contact_patch.shape = "solved"): a top view of the grid
// that follows the wheel, the pressure as a colour map on one scale for the
// whole crossing (black 0, through red and yellow, to white at the
// crossing's peak), the end-post gap and the head beyond it grey, the two
// cut faces drawn as lines, a bar at the bottom showing the step's load
// against the largest. Drawn on the CPU into RGB images (no GL: a grid of
// 128 x 96 cells is a few thousand rectangles), written by png_file.h and
// piped to ffmpeg for the videos (renders/video_assembly.h).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "models/parameters.h"
#include "models/rail_end_fields.h"
#include "renders/rgb_image.h"
#include "renders/video_files.h"

namespace railjoint {

/// The frame of one step: `scale_Pa` is the colour scale's top (the
/// crossing's peak), `largest_load_N` the load bar's full length.
RgbImage solved_contact_frame(const JointParams& joint, const RailEndField& field, double scale_Pa,
                              double largest_load_N, int width_px, int height_px);

struct SolvedContactFrames : VideoFiles {
  long long frames_written = 0;
};

/// Writes out_dir/frame_00000.png ... one a field, and pipes each frame to
/// ffmpeg for out_dir/crossing.mp4 and crossing.gif (renders/video_assembly.h,
/// 30 frames a second, as the patch's `pressure --frames`) when ffmpeg is on
/// PATH. Throws std::runtime_error naming a file that cannot be written, or
/// when ffmpeg ran and failed (VideoPipe::finish).
SolvedContactFrames write_solved_contact_frames(const JointParams& joint, const std::vector<RailEndField>& fields,
                                                const std::filesystem::path& out_dir, int width_px, int height_px);

}  // namespace railjoint
