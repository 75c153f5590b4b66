#pragma once
// A corner of a label triangle (text, boxes, call-out lines), in the
// picture's pixels: what the views lay over a frame (FrameDrawList::overlay).

#include <Eigen/Core>

namespace railjoint {

struct OverlayVertex {
  Eigen::Vector2f position_px;  ///< origin at the top-left corner, y down
  Eigen::Vector3f colour;       ///< linear RGB in [0, 1]
};

}  // namespace railjoint
