#pragma once
// The folder a render writes into (`render --out`, `simulate --render-out`,
// `pressure --frames`) may hold an older render and the user's own files.
// A render is drawn into a staging folder inside it (support/staging_folder.h)
// and published when complete: the files an older render left there are
// removed first, so the folder never holds a mix of old and new frames, and
// a file the render does not own (a user's notes, an ffmpeg.log of their
// own) is never touched. A render that fails leaves the folder as it was.

#include <string>

#include "support/staging_folder.h"

namespace railjoint {

/// The names a render owns: frame_NNNNN.png (five or more digits),
/// crossing.mp4, crossing.gif, crossing.glb and crossing_ffmpeg.log.
bool is_render_output(const std::string& name);

/// Removes the older render's files from staging.folder() and moves the
/// staged render there. ffmpeg's messages (the renderer's ffmpeg.log) are
/// kept as crossing_ffmpeg.log when ffmpeg said anything, and dropped when
/// it said nothing. Returns `note` (a report's text naming staged files) as
/// it reads after publishing.
std::string publish_render(StagingFolder& staging, const std::string& note);

}  // namespace railjoint
