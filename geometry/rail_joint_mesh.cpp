#include "geometry/rail_joint_mesh.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "models/dip_profile.h"
#include "models/inclined_joint.h"
#include "models/parameter_checks.h"
#include "models/rail_head.h"
#include "models/rail_top.h"
#include "support/input_error.h"

namespace railjoint {

namespace {

// Straight travel the wheel gets before the cut and beyond its contact point past it.
constexpr double kRunUp_m = 0.05;

// One rail end: a prism over the footprint x_start(y) <= x <= x_end(y),
// |y| <= b_t (both bounds linear in y), between z = -depth and the rail top.
// The top is a grid of `pieces` quads along x (the dip's) by `columns`
// across y (the crown's; 1 for a flat head, whose four corners define it);
// the bottom and the walls follow the same grid so every edge is shared by
// exactly two triangles.
TriangleMesh build_rail_end(const JointParams& joint, int rail, double flat_approach_m) {
  const int dip_pieces = joint.kind == JointKind::step ? 1 : dip_pieces_along_x(joint);
  // A flat approach is one more piece in front of the incoming rail's dip.
  const int flat_pieces = rail == 0 && flat_approach_m > 0.0 ? 1 : 0;
  const int pieces = dip_pieces + flat_pieces;
  // A crown drawn in 2 mm strips (20 across a 40 mm head): its chord sags by
  // at most (1 mm)^2 / (2 rho) = 2.5 um on a 200 mm crown. The model and the
  // simulation read the exact arc (models/rail_head.h, sim/rail_surface.h).
  const int columns = has_flat_head(joint) ? 1 : std::max(2, static_cast<int>(std::ceil(joint.half_width_m / 1e-3)));
  const double half_width = joint.half_width_m;
  const double half_length = joint.length_m / 2.0;
  const auto x_start = [&](double y) { return rail == 0 ? -half_length : cut_x_m(joint, y, 1); };
  const auto x_end = [&](double y) { return rail == 0 ? cut_x_m(joint, y, 0) : half_length; };
  const double flat_height_m = rail_surface_height_m(joint, 0, -half_length);

  TriangleMesh mesh;
  // Vertex (i, j) of a layer: i = 0..pieces along x, j = 0..columns from y = -b_t to +b_t.
  for (const bool top_layer : {true, false}) {
    for (int i = 0; i <= pieces; ++i) {
      for (int j = 0; j <= columns; ++j) {
        const double y = j == columns ? half_width : -half_width + 2.0 * half_width * j / columns;
        assert(x_end(y) > x_start(y));
        const int dip_i = i - flat_pieces;
        const double x = dip_i < 0 ? -half_length - flat_approach_m
                                   : x_start(y) + (x_end(y) - x_start(y)) * dip_i / dip_pieces;
        const double top_z = head_top_height_m(joint, y) + (dip_i < 0 ? flat_height_m : rail_surface_height_m(joint, rail, x));
        const double z = top_layer ? top_z : -joint.depth_m;
        assert(z > -joint.depth_m || !top_layer);
        mesh.vertices_m.emplace_back(x, y, z);
      }
    }
  }
  const int row = columns + 1;
  const int layer_size = row * (pieces + 1);
  const auto top = [row](int i, int j) { return row * i + j; };
  const auto bottom = [row, layer_size](int i, int j) { return layer_size + row * i + j; };
  // a, b, c, d counter-clockwise seen from outside.
  const auto quad = [&mesh](int a, int b, int c, int d, FaceTag tag) {
    mesh.triangles.emplace_back(a, b, c);
    mesh.triangles.emplace_back(a, c, d);
    mesh.tags.insert(mesh.tags.end(), 2, tag);
  };
  // x -> y is counter-clockwise seen from +z. A wall over a footprint edge
  // a -> b traversed counter-clockwise from above is (a_bottom, b_bottom, b_top, a_top).
  for (int i = 0; i < pieces; ++i) {
    for (int j = 0; j < columns; ++j) {
      quad(top(i, j), top(i + 1, j), top(i + 1, j + 1), top(i, j + 1), FaceTag::top);
      quad(bottom(i, j), bottom(i, j + 1), bottom(i + 1, j + 1), bottom(i + 1, j), FaceTag::bottom);
    }
    quad(bottom(i, 0), bottom(i + 1, 0), top(i + 1, 0), top(i, 0), FaceTag::side);  // y = -b_t
    quad(bottom(i + 1, columns), bottom(i, columns), top(i, columns), top(i + 1, columns), FaceTag::side);  // y = +b_t
  }
  for (int j = 0; j < columns; ++j) {
    quad(bottom(0, j + 1), bottom(0, j), top(0, j), top(0, j + 1), rail == 0 ? FaceTag::end : FaceTag::cut);
    quad(bottom(pieces, j), bottom(pieces, j + 1), top(pieces, j + 1), top(pieces, j), rail == 0 ? FaceTag::cut : FaceTag::end);
  }
  return mesh;
}

}  // namespace

RailJointMesh build_rail_joint_mesh(const JointParams& joint) {
  return {build_rail_end(joint, 0, 0.0), build_rail_end(joint, 1, 0.0)};
}

RailJointMesh build_rail_joint_mesh(const JointParams& joint, const RailJointMeshOptions& options) {
  if (!(options.flat_approach_m >= 0.0 && std::isfinite(options.flat_approach_m))) {
    throw InputError("sim.flat_approach", "flat approach length must be >= 0 m, got " + metres_text(options.flat_approach_m));
  }
  return {build_rail_end(joint, 0, options.flat_approach_m), build_rail_end(joint, 1, 0.0)};
}

double flat_approach_height_m(const JointParams& joint) { return rail_surface_height_m(joint, 0, -joint.length_m / 2.0); }

double minimum_rail_length_m(const JointParams& joint, const WheelParams& wheel) {
  return minimum_joint_length_m(joint, wheel, kRunUp_m);
}

void check_joint_geometry(const JointParams& joint, const WheelParams& wheel) {
  check_parameters(joint, wheel, kRunUp_m);
  if (!(joint.depth_m > 0.0 && std::isfinite(joint.depth_m))) {
    throw InputError("joint.depth", "rail-head depth must be a finite length > 0 m");
  }

  const double half_length = joint.length_m / 2.0;
  // Tops are monotone in x along each rail end, so the lowest point is a corner.
  double lowest_top = std::numeric_limits<double>::infinity();
  for (const double y : {-joint.half_width_m, joint.half_width_m}) {
    for (const double x : {-half_length, cut_x_m(joint, y, 0)}) {
      lowest_top = std::min(lowest_top, rail_surface_height_m(joint, 0, x));
    }
    for (const double x : {cut_x_m(joint, y, 1), half_length}) {
      lowest_top = std::min(lowest_top, rail_surface_height_m(joint, 1, x));
    }
  }
  if (!(-joint.depth_m < lowest_top)) {
    throw InputError("joint.depth",
                         "rail-head depth must be > " + metres_text(-lowest_top) +
                             " so the bottom z = -depth lies below the lowest point of the rail tops, got " +
                             metres_text(joint.depth_m));
  }
}

}  // namespace railjoint
