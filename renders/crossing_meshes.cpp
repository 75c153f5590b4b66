#include "renders/crossing_meshes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "renders/palette.h"

namespace railjoint {

namespace {

const Eigen::Vector3d& vertex(const TriangleMesh& mesh, int index) {
  return mesh.vertices_m[static_cast<std::size_t>(index)];
}

Eigen::Vector3f rail_colour(FaceTag tag, bool outgoing) {
  Eigen::Vector3f colour;
  switch (tag) {
    case FaceTag::top: return palette::rail_top;  // both rails: the running surface reads as one band
    case FaceTag::cut: return palette::rail_cut;
    case FaceTag::end: colour = palette::rail_end; break;
    case FaceTag::bottom: colour = palette::rail_bottom; break;
    default: colour = palette::rail_side; break;  // side faces and the side view's section faces
  }
  return outgoing ? Eigen::Vector3f(colour * palette::outgoing_rail_shade) : colour;
}

// A flat ring between radii r0 and r1 in the plane y = y_m (wheel frame), `segments` quads.
void add_ring(std::vector<MeshVertex>& out, double r0, double r1, double y_m, int segments,
              const Eigen::Vector3f& colour) {
  for (int j = 0; j < segments; ++j) {
    const double a0 = 2.0 * std::numbers::pi * j / segments, a1 = 2.0 * std::numbers::pi * (j + 1) / segments;
    const Eigen::Vector3d e0(std::cos(a0), 0.0, std::sin(a0)), e1(std::cos(a1), 0.0, std::sin(a1));
    const Eigen::Vector3d at(0.0, y_m, 0.0);
    add_quad(out, at + r0 * e0, at + r1 * e0, at + r1 * e1, at + r0 * e1, colour);
  }
}

// The dark bar across a face with a knob on its +x end (the knob gives the spin's sign).
void add_spin_bar(std::vector<MeshVertex>& out, double radius_m, double y_m) {
  const double bar = 0.9 * radius_m, half = 0.05 * radius_m;
  add_quad(out, {-bar, y_m, -half}, {bar, y_m, -half}, {bar, y_m, half}, {-bar, y_m, half}, palette::wheel_spoke);
  const double k0 = 0.55 * radius_m, k1 = 0.8 * radius_m, kh = 0.12 * radius_m;
  add_quad(out, {k0, y_m, -kh}, {k1, y_m, -kh}, {k1, y_m, kh}, {k0, y_m, kh}, palette::wheel_spoke);
}

}  // namespace

void add_triangle(std::vector<MeshVertex>& out, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                  const Eigen::Vector3d& c, const Eigen::Vector3f& colour) {
  Eigen::Vector3d n = (b - a).cross(c - a);
  // A degenerate triangle covers no pixel; any unit normal keeps the shader finite.
  n = n.norm() > 0.0 ? n.normalized() : Eigen::Vector3d::UnitZ();
  for (const auto* p : {&a, &b, &c}) out.push_back({p->cast<float>(), n.cast<float>(), colour});
}

void add_quad(std::vector<MeshVertex>& out, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
              const Eigen::Vector3d& c, const Eigen::Vector3d& d, const Eigen::Vector3f& colour) {
  add_triangle(out, a, b, c, colour);
  add_triangle(out, a, c, d, colour);
}

std::vector<MeshVertex> rail_pair_vertices(const TriangleMesh& incoming, const TriangleMesh& outgoing) {
  std::vector<MeshVertex> out;
  out.reserve((incoming.triangles.size() + outgoing.triangles.size()) * 3);
  for (const bool is_outgoing : {false, true}) {
    const TriangleMesh& rail = is_outgoing ? outgoing : incoming;
    for (std::size_t i = 0; i < rail.triangles.size(); ++i) {
      const Eigen::Vector3i& t = rail.triangles[i];
      add_triangle(out, vertex(rail, t[0]), vertex(rail, t[1]), vertex(rail, t[2]), rail_colour(rail.tags[i], is_outgoing));
    }
  }
  return out;
}

std::vector<MeshVertex> wheel_body_vertices(const TriangleMesh& wheel, double dish) {
  std::vector<MeshVertex> out;
  out.reserve(wheel.triangles.size() * 3);
  double radius = 0.0;
  for (const auto& v : wheel.vertices_m) radius = std::max(radius, std::hypot(v.x(), v.z()));
  for (std::size_t i = 0; i < wheel.triangles.size(); ++i) {
    const Eigen::Vector3i& t = wheel.triangles[i];
    if (wheel.tags[i] != FaceTag::wheel_rim) {
      add_triangle(out, vertex(wheel, t[0]), vertex(wheel, t[1]), vertex(wheel, t[2]), palette::wheel_face);
      if (dish > 0.0 && radius > 0.0) {
        for (std::size_t v = out.size() - 3; v < out.size(); ++v) {
          const Eigen::Vector3f& p = out[v].position_m;
          const Eigen::Vector3f outward(p.x(), 0.0f, p.z());
          out[v].normal = (out[v].normal + static_cast<float>(dish / radius) * outward).normalized();
        }
      }
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& p = vertex(wheel, t[k]);
      const Eigen::Vector3d radial = Eigen::Vector3d(p.x(), 0.0, p.z()).normalized();
      out.push_back({p.cast<float>(), radial.cast<float>(), palette::wheel_rim});
    }
  }
  return out;
}

std::vector<MeshVertex> whole_wheel_marks(double radius_m, double half_width_m, double face_offset_m) {
  std::vector<MeshVertex> out;
  for (double side : {-1.0, 1.0}) {
    const double y = side * (half_width_m + face_offset_m);
    add_ring(out, 0.90 * radius_m, radius_m, y, 256, palette::wheel_rim);   // tyre
    add_ring(out, 0.0, 0.13 * radius_m, y, 64, palette::wheel_spoke);       // hub
    add_ring(out, 0.50 * radius_m, 0.52 * radius_m, y, 128, palette::wheel_rim);  // web edge
    add_spin_bar(out, radius_m, y + side * face_offset_m);
  }
  return out;
}

std::vector<MeshVertex> contact_view_wheel_marks(double radius_m, double rim_inner_m, double half_width_m,
                                                 double face_offset_m, double view_width_m, double px_m, double k) {
  std::vector<MeshVertex> out;
  const double tick_spacing_m = view_width_m / 6.0;
  const int ticks = static_cast<int>(
      std::clamp(std::round(2.0 * std::numbers::pi * radius_m / tick_spacing_m), 12.0, 720.0));
  const double tick_half_width = std::min(1.5 * px_m, 0.01 * radius_m);
  const double tick_gap = std::min(3.0 * px_m / k, 0.02 * radius_m);
  for (double side : {-1.0, 1.0}) {
    const double y = side * (half_width_m + face_offset_m);
    add_spin_bar(out, radius_m, y);
    for (int j = 0; j < ticks; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / ticks;
      const Eigen::Vector3d e(std::cos(phi), 0.0, std::sin(phi)), tangent(-std::sin(phi), 0.0, std::cos(phi));
      const double length = std::min((j % 4 == 0 ? 36.0 : 20.0) * px_m / k, 0.2 * radius_m);
      const double r_out = rim_inner_m - tick_gap, r_in = r_out - length;
      const Eigen::Vector3d at_y(0.0, y, 0.0), w = tick_half_width * tangent;
      add_quad(out, at_y + r_in * e - w, at_y + r_out * e - w, at_y + r_out * e + w, at_y + r_in * e + w,
               palette::wheel_spoke);
    }
  }
  return out;
}

std::vector<MeshVertex> cut_line_on_top(const RailJointMesh& rails, double width_m) {
  // The cut face's two highest vertices are the ends of its top edge.
  std::vector<Eigen::Vector3d> corners;
  for (std::size_t i = 0; i < rails.incoming.triangles.size(); ++i) {
    if (rails.incoming.tags[i] != FaceTag::cut) continue;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& p = vertex(rails.incoming, rails.incoming.triangles[i][k]);
      if (std::none_of(corners.begin(), corners.end(), [&](const Eigen::Vector3d& q) { return (q - p).norm() < 1e-12; })) {
        corners.push_back(p);
      }
    }
  }
  std::vector<MeshVertex> out;
  if (corners.size() < 2) return out;
  std::sort(corners.begin(), corners.end(), [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return a.z() > b.z(); });
  const Eigen::Vector3d lift(0.0, 0.0, 2e-4);
  const Eigen::Vector3d a = corners[0] + lift, b = corners[1] + lift;
  const Eigen::Vector3d across = 0.5 * width_m * (b - a).cross(Eigen::Vector3d::UnitZ()).normalized();
  add_quad(out, a - across, b - across, b + across, a + across, palette::rail_cut);
  return out;
}

Straightedge straightedge_over(const RailJointMesh& rails) {
  // The highest top-face vertex of each rail (a V dip: its far end; with a
  // flat approach: anywhere on the flat, take the one nearest the joint).
  auto highest = [](const TriangleMesh& rail, bool incoming) {
    Eigen::Vector3d best = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < rail.triangles.size(); ++i) {
      if (rail.tags[i] != FaceTag::top) continue;
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d& p = vertex(rail, rail.triangles[i][k]);
        const bool nearer = incoming ? p.x() > best.x() : p.x() < best.x();
        if (std::isnan(best.z()) || p.z() > best.z() + 1e-12 || (std::abs(p.z() - best.z()) <= 1e-12 && nearer)) {
          best = p;
        }
      }
    }
    if (std::isnan(best.z())) throw std::invalid_argument("render: a rail mesh has no top face for the straightedge");
    return best;
  };
  Straightedge edge;
  edge.start_m = highest(rails.incoming, true);
  edge.end_m = highest(rails.outgoing, false);
  edge.start_m.y() = edge.end_m.y() = 0.0;
  const double span = edge.end_m.x() - edge.start_m.x();
  for (const auto* rail : {&rails.incoming, &rails.outgoing}) {
    for (std::size_t i = 0; i < rail->triangles.size(); ++i) {
      if (rail->tags[i] != FaceTag::top) continue;
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d& p = vertex(*rail, rail->triangles[i][k]);
        if (p.x() < edge.start_m.x() || p.x() > edge.end_m.x() || !(span > 0.0)) continue;
        const double line_z = edge.start_m.z() + (edge.end_m.z() - edge.start_m.z()) * (p.x() - edge.start_m.x()) / span;
        edge.dip_m = std::max(edge.dip_m, line_z - p.z());
      }
    }
  }
  return edge;
}

std::vector<MeshVertex> straightedge_bar(const Straightedge& edge, double y_m, double thickness_m) {
  std::vector<MeshVertex> out;
  const Eigen::Vector3d a(edge.start_m.x(), y_m, edge.start_m.z()), b(edge.end_m.x(), y_m, edge.end_m.z());
  const Eigen::Vector3d across(0.0, thickness_m / 2.0, 0.0), down(0.0, 0.0, -thickness_m);
  // Four long faces of a square bar hanging below the line a-b (it rests on the rail ends).
  add_quad(out, a - across, b - across, b + across, a + across, palette::straightedge);
  add_quad(out, a - across + down, b - across + down, b + across + down, a + across + down, palette::straightedge);
  add_quad(out, a - across, b - across, b - across + down, a - across + down, palette::straightedge);
  add_quad(out, a + across, b + across, b + across + down, a + across + down, palette::straightedge);
  return out;
}

std::vector<MeshVertex> running_band(const Trajectory& trajectory, double t_s, double y_lo_m, double y_hi_m,
                                     double z_m) {
  std::vector<MeshVertex> out;
  if (!(y_hi_m > y_lo_m)) return out;
  // Intervals of x touched by consecutive touching samples.
  bool open = false;
  double x0 = 0.0, x1 = 0.0;
  auto close = [&] {
    if (open && x1 > x0) {
      add_quad(out, {x0, y_lo_m, z_m}, {x1, y_lo_m, z_m}, {x1, y_hi_m, z_m}, {x0, y_hi_m, z_m}, palette::running_band);
    }
    open = false;
  };
  for (const WheelSample& s : trajectory.samples) {
    if (s.time_s > t_s) break;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const ContactSample& c : s.contacts) {
      if (c.distance_m > kTouchingGap_m) continue;
      lo = std::min(lo, c.point_on_rail_m.x());
      hi = std::max(hi, c.point_on_rail_m.x());
    }
    if (!(hi >= lo)) {  // in flight
      close();
      continue;
    }
    if (!open) {
      open = true;
      x0 = lo;
      x1 = hi;
    } else {
      x0 = std::min(x0, lo);
      x1 = std::max(x1, hi);
    }
  }
  close();
  return out;
}

}  // namespace railjoint
