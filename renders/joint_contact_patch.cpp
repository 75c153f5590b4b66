#include "renders/joint_contact_patch.h"

#include <algorithm>
#include <cmath>

#include "models/contact_patch.h"
#include "models/end_post_gap.h"
#include "models/patch_gap_overlap.h"
#include "renders/palette.h"

namespace railjoint {

namespace {

// A convex polygon (global x, y) as a triangle fan at height z, facing up.
void add_fan(std::vector<MeshVertex>& out, const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& shift,
             double z_m, const Eigen::Vector3f& colour) {
  auto at = [&](const Eigen::Vector2d& p) {
    return MeshVertex{Eigen::Vector3f(static_cast<float>(p.x() + shift.x()), static_cast<float>(p.y() + shift.y()),
                                      static_cast<float>(z_m)),
                      Eigen::Vector3f::UnitZ(), colour};
  };
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    out.push_back(at(polygon[0]));
    out.push_back(at(polygon[i]));
    out.push_back(at(polygon[i + 1]));
  }
}

}  // namespace

PatchPlacement place_contact_patch(const PressureInputs& inputs, const Eigen::Vector2d& centre_m,
                                   double rail_half_width_m) {
  const double a = inputs.patch.length_m, b = inputs.patch.width_m;
  const double reach = std::max(0.0, rail_half_width_m - b / 2.0);
  const double y_c = std::clamp(centre_m.y(), -reach, reach);
  const double y0 = y_c - b / 2.0;
  const double x0 = y0 / std::tan(inputs.gap.theta_rad) - longitudinal_gap_m(inputs.gap) / 2.0;
  PatchPlacement placement;
  placement.local_origin_m = {x0, y0};
  placement.x_front_m = centre_m.x() - x0 + a / 2.0;
  placement.state = pressure_state(inputs, placement.x_front_m);
  return placement;
}

std::vector<MeshVertex> contact_patch_vertices(const PressureInputs& inputs, const PatchPlacement& placement,
                                               double z_m) {
  std::vector<MeshVertex> out;
  const std::vector<Eigen::Vector2d> outline = patch_outline_m(inputs.patch, placement.x_front_m);
  add_fan(out, outline, placement.local_origin_m, z_m, palette::patch_bearing);
  for (const auto& piece : outline_over_gap_m(outline, inputs.gap, inputs.patch.width_m)) {
    add_fan(out, piece, placement.local_origin_m, z_m + 1e-6, palette::patch_over_gap);
  }
  return out;
}

}  // namespace railjoint
