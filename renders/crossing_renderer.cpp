#include "renders/crossing_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "renders/palette.h"
#include "renders/slab_section.h"
#include "renders/text_overlay.h"

namespace railjoint {

namespace {

void check_mesh(const TriangleMesh& mesh, const std::string& name) {
  if (mesh.tags.size() != mesh.triangles.size()) {
    throw std::invalid_argument("render: " + name + " mesh has " + std::to_string(mesh.triangles.size()) +
                                " triangles but " + std::to_string(mesh.tags.size()) + " face tags");
  }
  const int n = static_cast<int>(mesh.vertices_m.size());
  for (const auto& t : mesh.triangles) {
    if (t.minCoeff() < 0 || t.maxCoeff() >= n) {
      throw std::invalid_argument("render: " + name + " mesh has a triangle index outside its " + std::to_string(n) +
                                  " vertices");
    }
  }
}

Eigen::Vector3f to_float(const Eigen::Vector3d& v) { return v.cast<float>(); }

void add_triangle(std::vector<MeshVertex>& out, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                  const Eigen::Vector3d& c, const Eigen::Vector3f& colour) {
  Eigen::Vector3d n = (b - a).cross(c - a);
  // A degenerate triangle covers no pixel; any unit normal keeps the shader finite.
  n = n.norm() > 0.0 ? n.normalized() : Eigen::Vector3d::UnitZ();
  for (const auto* p : {&a, &b, &c}) out.push_back({to_float(*p), to_float(n), colour});
}

void add_quad(std::vector<MeshVertex>& out, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
              const Eigen::Vector3d& c, const Eigen::Vector3d& d, const Eigen::Vector3f& colour) {
  add_triangle(out, a, b, c, colour);
  add_triangle(out, a, c, d, colour);
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

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), pattern, a, b, c, d);
  return buffer;
}

// 1, 2 or 5 times a power of ten: the largest such length not above `at_most`.
double nice_length(double at_most) {
  const double decade = std::pow(10.0, std::floor(std::log10(at_most)));
  for (double m : {5.0, 2.0}) {
    if (m * decade <= at_most) return m * decade;
  }
  return decade;
}

std::string length_text(double length_m) {
  return length_m >= 1.0 ? format("%g m", length_m) : format("%g mm", length_m * 1e3);
}

// How far from the axle the wheel polygon's edges come: the smallest distance
// from the axle (the y axis) to the plane of a rim triangle (rim planes are
// parallel to the axle). The inscribed circle of the polygon.
double rim_inner_radius(const TriangleMesh& wheel, double radius_m) {
  double inner = radius_m;
  for (std::size_t i = 0; i < wheel.triangles.size(); ++i) {
    if (wheel.tags[i] != FaceTag::wheel_rim) continue;
    const Eigen::Vector3i& t = wheel.triangles[i];
    const Eigen::Vector3d& a = wheel.vertices_m[static_cast<std::size_t>(t[0])];
    Eigen::Vector3d n = (wheel.vertices_m[static_cast<std::size_t>(t[1])] - a)
                            .cross(wheel.vertices_m[static_cast<std::size_t>(t[2])] - a);
    n.y() = 0.0;
    if (!(n.norm() > 0.0)) continue;
    inner = std::min(inner, std::abs(n.normalized().dot(a)));
  }
  return inner;
}

// Gap between the drawn section face of the rails and the wheel's near face
// [m]: the section lies this far behind the wheel face, so where the wheel
// overlaps the rails (a simulated penetration) the wheel is drawn in front
// and the overlap shows. 2 um moves the section's corner at the cut by
// 2 um cot(theta) (0.04 px at 0.12 m over 1280 px, theta = 30 deg) and is
// ten steps of the 24-bit depth buffer over the side view's 3.5 m depth range.
constexpr double kSectionInset_m = 2e-6;

// A recorded contact is drawn when its gap is below this [m]. The simulation
// also reports contacts that are still open (up to its contact breaking
// threshold, 2 mm by default) so that it sees a gap closing; those touch
// nothing yet. Touching contacts overlap by the slop (4 um) or less.
constexpr double kTouchingGap_m = 1e-6;

}  // namespace

CrossingRenderer::CrossingRenderer(const RenderSettings& settings, const RailJointMesh& rails,
                                   const TriangleMesh& wheel, const Trajectory& trajectory)
    : settings_(settings), trajectory_(trajectory) {
  window_ = frame_window(settings_, trajectory_);  // checks the settings too
  check_mesh(rails.incoming, "incoming rail");
  check_mesh(rails.outgoing, "outgoing rail");
  check_mesh(wheel, "wheel");
  if (rails.incoming.triangles.empty() && rails.outgoing.triangles.empty()) {
    throw std::invalid_argument("render: both rail meshes are empty");
  }
  if (wheel.triangles.empty()) throw std::invalid_argument("render: the wheel mesh is empty");

  double radius = 0.0, half_width = 0.0;
  for (const auto& v : wheel.vertices_m) {
    radius = std::max(radius, std::hypot(v.x(), v.z()));
    half_width = std::max(half_width, std::abs(v.y()));
  }
  if (!(radius > 0.0)) throw std::invalid_argument("render: the wheel mesh has zero radius");
  if (settings_.view == RenderView::side && !(half_width > kSectionInset_m)) {
    throw std::invalid_argument("render: the side view cuts the rails to the wheel's width, but the wheel mesh is " +
                                std::to_string(2.0 * half_width) + " m wide; give it a positive width (> 4 um)");
  }
  wheel_radius_m_ = radius;
  wheel_half_width_m_ = half_width;
  exaggeration_ = {settings_.exaggeration, settings_.reference_z_m};
  const double k = exaggeration_.factor;
  const double wheel_y = trajectory_.samples.front().centre_m.y();
  const bool side_view = settings_.view == RenderView::side;
  // Wheel decorations (rim ticks, bar, path) lie just outside the wheel's faces
  // so the face they lie on never hides them.
  const double face_offset = std::max(0.0005, 0.05 * half_width);

  // Rails in drawn coordinates (normals of the drawn faces). The side view
  // draws the section through the wheel's width only (slab_section.h).
  std::vector<MeshVertex> rail_vertices;
  Eigen::AlignedBox3d rail_box;
  for (const auto* mesh : {&rails.incoming, &rails.outgoing}) {
    const bool outgoing = mesh == &rails.outgoing;
    for (const auto& v : mesh->vertices_m) rail_box.extend(exaggeration_.point(v));
    const TriangleMesh drawn =
        side_view ? cut_convex_solid_to_slab(*mesh, wheel_y - half_width + kSectionInset_m, wheel_y + half_width)
                  : *mesh;
    for (std::size_t i = 0; i < drawn.triangles.size(); ++i) {
      const Eigen::Vector3i& t = drawn.triangles[i];
      add_triangle(rail_vertices, exaggeration_.point(drawn.vertices_m[static_cast<std::size_t>(t[0])]),
                   exaggeration_.point(drawn.vertices_m[static_cast<std::size_t>(t[1])]),
                   exaggeration_.point(drawn.vertices_m[static_cast<std::size_t>(t[2])]),
                   rail_colour(drawn.tags[i], outgoing));
    }
  }
  framing_.rail_width_m = rail_box.max().y() - rail_box.min().y();
  const double view_width_m = visible_width_m(settings_, framing_);
  px_per_m_ = static_cast<double>(settings_.width_px) / view_width_m;

  // The path of the wheel's lowest point (the point R below the centre),
  // drawn just in front of the wheel's near face so the wheel never hides it.
  std::vector<LineVertex> path;
  path.reserve(trajectory_.samples.size());
  Eigen::AlignedBox3d wheel_box;  // everything the drawn wheel covers over the run
  const Eigen::Vector3d wheel_extent(radius, half_width + 2.0 * face_offset, k * radius);
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;  // window: centre x
  double z_lo = x_lo, z_hi = -x_lo;                                     // window: drawn lowest point
  auto in_window = [&](const WheelSample& s) {
    const Eigen::Vector3d low = exaggeration_.lowest_wheel_point(s.centre_m, radius);
    x_lo = std::min(x_lo, s.centre_m.x());
    x_hi = std::max(x_hi, s.centre_m.x());
    z_lo = std::min(z_lo, low.z());
    z_hi = std::max(z_hi, low.z());
  };
  for (const auto& s : trajectory_.samples) {
    Eigen::Vector3d low = exaggeration_.lowest_wheel_point(s.centre_m, radius);
    low.y() = wheel_y - half_width - 2.0 * face_offset;
    path.push_back({to_float(low), palette::centre_path});
    const Eigen::Vector3d centre = exaggeration_.point(s.centre_m);
    wheel_box.extend(centre - wheel_extent);
    wheel_box.extend(centre + wheel_extent);
    wheel_box.extend(low);
    if (s.time_s >= window_.t_start_s && s.time_s <= window_.t_end_s) in_window(s);
  }
  for (double t : {window_.t_start_s, window_.t_end_s}) in_window(sample_at(trajectory_, t));
  fixed_focus_m_ = Eigen::Vector3d(0.5 * (x_lo + x_hi), wheel_y, 0.5 * (z_lo + z_hi));

  // Ground checker just below the drawn rail bottoms, 0.1 m tiles aligned with
  // world x so that a following camera shows the motion in top and perspective views.
  constexpr double tile_m = 0.1;
  const double ground_z = rail_box.min().z() - 0.002;
  const double ground_x_lo = std::floor(std::min(rail_box.min().x(), wheel_box.min().x()) / tile_m - 20.0) * tile_m;
  const double ground_x_hi = std::ceil(std::max(rail_box.max().x(), wheel_box.max().x()) / tile_m + 20.0) * tile_m;
  const double y_half = 1.5;
  std::vector<MeshVertex> ground;
  for (long long i = 0; ground_x_lo + static_cast<double>(i) * tile_m < ground_x_hi - 1e-9; ++i) {
    for (long long j = 0; -y_half + static_cast<double>(j) * tile_m < y_half - 1e-9; ++j) {
      const double x0 = ground_x_lo + static_cast<double>(i) * tile_m, y0 = -y_half + static_cast<double>(j) * tile_m;
      const double x1 = x0 + tile_m, y1 = y0 + tile_m;
      const long long parity = static_cast<long long>(std::llround(x0 / tile_m)) + j;
      add_quad(ground, {x0, y0, ground_z}, {x1, y0, ground_z}, {x1, y1, ground_z}, {x0, y1, ground_z},
               (parity % 2 + 2) % 2 == 0 ? palette::ground_a : palette::ground_b);
    }
  }

  framing_.scene_bounds = rail_box;
  framing_.scene_bounds.extend(Eigen::Vector3d(ground_x_lo, -y_half, ground_z));
  framing_.scene_bounds.extend(Eigen::Vector3d(ground_x_hi, y_half, ground_z));
  framing_.scene_bounds.extend(wheel_box);

  // Datum: a thin light line at the reference height (the height the
  // exaggeration keeps), BEHIND the rails and the wheel, so it shows only
  // where nothing else is and never reads as part of the geometry. Lengths
  // are read off the scale bars instead of ticks.
  const double px_m = 1.0 / px_per_m_;
  const double y_datum = rail_box.max().y() + 0.001;
  const double zr = settings_.reference_z_m;
  std::vector<MeshVertex> datum;
  const double line_half = 0.5 * px_m;
  add_quad(datum, {ground_x_lo, y_datum, zr - line_half}, {ground_x_hi, y_datum, zr - line_half},
           {ground_x_hi, y_datum, zr + line_half}, {ground_x_lo, y_datum, zr + line_half}, palette::datum);

  // Wheel in its own frame (axle along y). Its spin shows as dark ticks just
  // inside the rim, on both faces, about one sixth of the view apart (every
  // fourth longer), so a few are always in the contact view, and a dark bar
  // across each face with a knob on one end (the knob gives the sign).
  // Tick sizes are chosen in drawn pixels at the wheel's bottom, where radial
  // lengths are stretched k-fold: 20 px (36 px) long, 3 px wide, 3 px in from the rim.
  std::vector<MeshVertex> wheel_vertices;
  for (std::size_t i = 0; i < wheel.triangles.size(); ++i) {
    const Eigen::Vector3i& t = wheel.triangles[i];
    add_triangle(wheel_vertices, wheel.vertices_m[static_cast<std::size_t>(t[0])],
                 wheel.vertices_m[static_cast<std::size_t>(t[1])], wheel.vertices_m[static_cast<std::size_t>(t[2])],
                 wheel.tags[i] == FaceTag::wheel_rim ? palette::wheel_rim : palette::wheel_face);
  }
  const double inner = rim_inner_radius(wheel, radius);
  const double tick_spacing_m = view_width_m / 6.0;
  const int ticks = static_cast<int>(
      std::clamp(std::round(2.0 * std::numbers::pi * radius / tick_spacing_m), 12.0, 720.0));
  const double tick_half_width = std::min(1.5 * px_m, 0.01 * radius);
  const double tick_gap = std::min(3.0 * px_m / k, 0.02 * radius);
  for (double side : {-1.0, 1.0}) {
    const double y = side * (half_width + face_offset);
    const double bar = 0.9 * radius, half = 0.05 * radius;
    add_quad(wheel_vertices, {-bar, y, -half}, {bar, y, -half}, {bar, y, half}, {-bar, y, half}, palette::wheel_spoke);
    const double k0 = 0.55 * radius, k1 = 0.8 * radius, kh = 0.12 * radius;
    add_quad(wheel_vertices, {k0, y, -kh}, {k1, y, -kh}, {k1, y, kh}, {k0, y, kh}, palette::wheel_spoke);
    for (int j = 0; j < ticks; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / ticks;
      const Eigen::Vector3d e(std::cos(phi), 0.0, std::sin(phi)), tangent(-std::sin(phi), 0.0, std::cos(phi));
      const double length = std::min((j % 4 == 0 ? 36.0 : 20.0) * px_m / k, 0.2 * radius);
      const double r_out = inner - tick_gap, r_in = r_out - length;
      const Eigen::Vector3d at_y(0.0, y, 0.0), w = tick_half_width * tangent;
      add_quad(wheel_vertices, at_y + r_in * e - w, at_y + r_out * e - w, at_y + r_out * e + w, at_y + r_in * e + w,
               palette::wheel_spoke);
    }
  }

  gl_ = std::make_unique<OffscreenRenderer>(settings_.width_px, settings_.height_px);
  rails_ = gl_->add_triangles(rail_vertices);
  ground_ = gl_->add_triangles(ground);
  datum_ = gl_->add_triangles(datum);
  wheel_ = gl_->add_triangles(wheel_vertices);
  path_ = gl_->add_line_strip(path);
}

CrossingRenderer::~CrossingRenderer() = default;

const std::string& CrossingRenderer::gl_version() const { return gl_->gl_version(); }
const std::string& CrossingRenderer::gl_renderer() const { return gl_->gl_renderer(); }

Eigen::Vector3d CrossingRenderer::focus_at(double t_s) const {
  if (!settings_.follow_wheel) return fixed_focus_m_;
  return exaggeration_.lowest_wheel_point(sample_at(trajectory_, t_s).centre_m, wheel_radius_m_);
}

Camera CrossingRenderer::camera_at(double t_s) const { return make_camera(settings_, framing_, focus_at(t_s)); }

void CrossingRenderer::render_frame(long long k, RgbImage& out) {
  if (k < 0 || k >= window_.count) {
    throw std::out_of_range("render: frame " + std::to_string(k) + " is outside 0 .. " +
                            std::to_string(window_.count - 1));
  }
  render_at(window_.time_s(k), out);
}

void CrossingRenderer::render_at(double t_s, RgbImage& out) { gl_->draw(frame_at(t_s), out); }

FrameDrawList CrossingRenderer::frame_at(double t_s) const {
  const WheelSample sample = sample_at(trajectory_, t_s);
  const Camera camera = camera_at(t_s);

  FrameDrawList frame;
  frame.view = camera.view.cast<float>();
  frame.projection = camera.projection.cast<float>();
  frame.orthographic = camera.orthographic;
  frame.eye_m = camera.eye_m.cast<float>();
  frame.to_viewer = camera.to_viewer.cast<float>();
  // Key light from the viewer's side of the track, above and a little behind.
  frame.to_light = Eigen::Vector3f(-0.35f, -0.8f, 0.5f).normalized();
  frame.background = palette::background;

  // The wheel goes through the same map as the rails: exaggeration after the
  // rigid pose, so its circle is drawn as an ellipse k times taller than wide.
  const Eigen::Affine3d pose =
      Eigen::Translation3d(sample.centre_m) * Eigen::AngleAxisd(sample.spin_angle_rad, Eigen::Vector3d::UnitY());
  const Eigen::Matrix4d wheel_model = exaggeration_.matrix() * pose.matrix();
  frame.meshes = {{ground_, Eigen::Matrix4f::Identity(), -1},
                  {rails_, Eigen::Matrix4f::Identity(), -1},
                  {datum_, Eigen::Matrix4f::Identity(), -1},
                  {wheel_, wheel_model.cast<float>(), -1}};

  if (settings_.view != RenderView::top) {  // seen from above the path is a straight line under the wheel
    // The path up to the last recorded sample at or before t.
    const auto& samples = trajectory_.samples;
    const auto upto = std::upper_bound(samples.begin(), samples.end(), t_s,
                                       [](double t, const WheelSample& s) { return t < s.time_s; });
    frame.line_strips.push_back({path_, Eigen::Matrix4f::Identity(), static_cast<int>(upto - samples.begin())});
  }

  const float w = static_cast<float>(settings_.width_px);
  const float h = static_cast<float>(settings_.height_px);
  const float marker_px = std::max(6.0f, h / 90.0f);
  for (const auto& contact : sample.contacts) {
    if (contact.distance_m > kTouchingGap_m) continue;
    frame.markers.push_back({to_float(exaggeration_.point(contact.point_on_rail_m)), palette::contact, marker_px});
  }
  const ImpactEvent* current = nullptr;
  for (const auto& impact : trajectory_.impacts) {
    const Eigen::Vector3f where = to_float(exaggeration_.point(impact.contact_point_m));
    if (std::abs(t_s - impact.time_s) <= window_.period_s()) {
      current = &impact;
      frame.markers.push_back({where, palette::impact, 3.0f * marker_px, true});
    } else if (impact.time_s < t_s) {
      frame.markers.push_back({where, palette::past_impact, 0.8f * marker_px});
    }
  }

  // Labels on opaque boxes. The block of labels sits at the bottom left, over
  // the rails' interior in the side view (the geometry of interest, the
  // contact and a lift-off, lies at and above the wheel's lowest point in the
  // middle); the impact line at the top left; the scale bars at the bottom right.
  const float scale = std::max(1.0f, std::round(h / 360.0f));
  const float margin = 6.0f * scale, pad = 3.0f * scale;
  struct Box {
    float x0, y0, x1, y1;
    bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
  };
  auto boxed_text = [&](const std::string& text, float x, float y, const Eigen::Vector3f& colour) {
    const Eigen::Vector2f size = text_size_px(text, scale);
    const Box box{x - pad, y - pad, x + size.x() + pad, y + size.y() + pad};
    append_rectangle(frame.overlay, box.x0, box.y0, box.x1, box.y1, palette::background);
    append_text(frame.overlay, text, x, y, scale, colour);
    return box;
  };
  const double k = exaggeration_.factor;
  std::string label = format("t = %.4f ms   wheel x = %+.3f mm   z = %.4f mm   spin = %.2f deg", t_s * 1e3,
                             sample.centre_m.x() * 1e3, sample.centre_m.z() * 1e3,
                             sample.spin_angle_rad * 180.0 / std::numbers::pi);
  label += '\n';
  if (settings_.view == RenderView::side) {
    const double y = trajectory_.samples.front().centre_m.y();
    label += format("side view, rails cut to the wheel's width (y = %.2f .. %.2f mm)\n",
                    (y - wheel_half_width_m_) * 1e3, (y + wheel_half_width_m_) * 1e3);
  } else {
    label += std::string(to_string(settings_.view)) + " view\n";
  }
  label += format("heights x%g about z = %g mm, the wheel too (drawn as an ellipse)\n", k, settings_.reference_z_m * 1e3);
  label += "magenta: contact points   orange ring: impact point\n";
  label += format("green: path of the wheel's lowest point   grey line: z = %g mm", settings_.reference_z_m * 1e3);
  const Box labels = boxed_text(label, margin + pad, h - margin - pad - text_size_px(label, scale).y(), palette::text);
  Box impact_box{0.0f, 0.0f, 0.0f, 0.0f};
  if (current != nullptr) {
    impact_box =
        boxed_text(format("IMPACT at t = %.4f ms: dp_z = %.2f N s", current->time_s * 1e3, current->momentum_jump_Ns),
                   margin + pad, margin + pad, palette::impact);
    append_border(frame.overlay, settings_.width_px, settings_.height_px, std::max(4.0f, h / 90.0f), palette::impact);
  }

  // Scale bars (orthographic views): a horizontal one in true length and, in
  // the side view, a vertical one in true length drawn k-fold, meeting at
  // the lower right corner. Bottom right, else top right, else none.
  if (camera.orthographic) {
    const double bar_x_m = nice_length(camera.visible_width_m / 6.0);
    const float bar_x_px = static_cast<float>(bar_x_m * px_per_m_);
    const float thick = 2.0f * scale, gap = 3.0f * scale;
    const std::string x_text = length_text(bar_x_m);
    const Eigen::Vector2f x_size = text_size_px(x_text, scale);
    std::string z_text;
    float bar_z_px = 0.0f;
    Eigen::Vector2f z_size = Eigen::Vector2f::Zero();
    if (settings_.view == RenderView::side) {
      const double bar_z_m = nice_length(camera.visible_height_m / (4.0 * k));
      bar_z_px = static_cast<float>(bar_z_m * k * px_per_m_);
      z_text = length_text(bar_z_m) + format(" (drawn x%g)", k);
      z_size = text_size_px(z_text, scale);
    }
    // Layout relative to the corner (cx, cy) where the bars meet: the
    // horizontal bar runs left from it, its length below; the vertical bar up.
    const float content_w = std::max({bar_x_px, x_size.x(), thick + gap + z_size.x()});
    const float content_h = std::max(bar_z_px, z_size.y()) + thick + gap + x_size.y();
    Box box{w - margin - content_w - 2.0f * pad, h - margin - content_h - 2.0f * pad, w - margin, h - margin};
    if (box.overlaps(labels)) {
      const float shift = margin - box.y0;
      box.y0 += shift;
      box.y1 += shift;
    }
    const bool fits = box.x0 >= 0.0f && box.y1 <= h && !box.overlaps(labels) &&
                      (current == nullptr || !box.overlaps(impact_box));
    if (fits) {
      const float cx = box.x1 - pad, cy = box.y1 - pad - x_size.y() - gap - thick;
      append_rectangle(frame.overlay, box.x0, box.y0, box.x1, box.y1, palette::background);
      append_rectangle(frame.overlay, cx - bar_x_px, cy, cx, cy + thick, palette::text);
      append_text(frame.overlay, x_text, cx - x_size.x(), cy + thick + gap, scale, palette::text);
      if (bar_z_px > 0.0f) {
        append_rectangle(frame.overlay, cx - thick, cy - bar_z_px, cx, cy + thick, palette::text);
        append_text(frame.overlay, z_text, cx - thick - gap - z_size.x(), cy - bar_z_px, scale, palette::text);
      }
    }
  }
  return frame;
}

}  // namespace railjoint
