#pragma once
// Colours of the crossing pictures (linear RGB in [0, 1], before lighting).
// Chosen so that a pixel's hue tells what it shows even after shading (the
// shader scales a colour by 0.30 .. 1.0): the wheel is the only thing drawn in
// clear blues (blue well above red and green), the rails in golds, reds and
// neutral greys, markers in magenta and orange, the ground in greens.

#include <Eigen/Core>

namespace railjoint::palette {

inline const Eigen::Vector3f background{0.93f, 0.95f, 0.98f};
inline const Eigen::Vector3f rail_top{0.92f, 0.80f, 0.40f};    ///< running surface
inline const Eigen::Vector3f rail_cut{0.85f, 0.18f, 0.15f};    ///< the (inclined) cut faces
inline const Eigen::Vector3f rail_side{0.60f, 0.57f, 0.53f};   ///< incoming rail; the outgoing one is drawn darker
inline const Eigen::Vector3f rail_end{0.47f, 0.45f, 0.42f};
inline const Eigen::Vector3f rail_bottom{0.36f, 0.35f, 0.33f};
inline const float outgoing_rail_shade = 0.82f;
inline const Eigen::Vector3f wheel_rim{0.16f, 0.30f, 0.72f};
inline const Eigen::Vector3f wheel_face{0.30f, 0.50f, 0.95f};
inline const Eigen::Vector3f wheel_spoke{0.05f, 0.10f, 0.42f};  ///< the bar that shows the spin
inline const Eigen::Vector3f ground_a{0.62f, 0.72f, 0.55f};
inline const Eigen::Vector3f ground_b{0.52f, 0.62f, 0.46f};
inline const Eigen::Vector3f datum{0.55f, 0.55f, 0.60f};        ///< reference line at z_ref (behind everything)
inline const Eigen::Vector3f centre_path{0.10f, 0.55f, 0.20f};
inline const Eigen::Vector3f contact{0.90f, 0.10f, 0.85f};
inline const Eigen::Vector3f impact{1.00f, 0.45f, 0.00f};       ///< marker, border and label at an impact
inline const Eigen::Vector3f past_impact{0.60f, 0.05f, 0.05f};
inline const Eigen::Vector3f text{0.08f, 0.08f, 0.10f};
inline const Eigen::Vector3f straightedge{0.20f, 0.20f, 0.22f};  ///< the bar laid over the joint (dark steel)
inline const Eigen::Vector3f running_band{0.35f, 0.33f, 0.30f};  ///< rolled-over rail head (a dull steel grey)
/// The local model's contact patch (thesis chapters 5-6): where it bears on
/// the rail ends (teal, apart from the wheel's blues) and its part over the
/// end-post gap, the reduction area (red).
inline const Eigen::Vector3f patch_bearing{0.05f, 0.55f, 0.55f};
inline const Eigen::Vector3f patch_over_gap{0.90f, 0.20f, 0.15f};
inline const Eigen::Vector3f panel{0.86f, 0.88f, 0.92f};         ///< behind the inset and legend of the perspective view

}  // namespace railjoint::palette
