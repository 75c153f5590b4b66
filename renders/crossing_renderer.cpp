#include "renders/crossing_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "renders/palette.h"
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
    default: colour = palette::rail_side; break;
  }
  return outgoing ? Eigen::Vector3f(colour * palette::outgoing_rail_shade) : colour;
}

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), pattern, a, b, c, d);
  return buffer;
}

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

  double radius = 0.0;
  for (const auto& v : wheel.vertices_m) {
    radius = std::max(radius, std::hypot(v.x(), v.z()));
    wheel_half_width_m_ = std::max(wheel_half_width_m_, std::abs(v.y()));
  }
  if (!(radius > 0.0)) throw std::invalid_argument("render: the wheel mesh has zero radius");
  exaggeration_ = {settings_.exaggeration, settings_.reference_z_m, radius};

  // Rails, in drawn (exaggerated) coordinates; normals of the drawn faces.
  std::vector<MeshVertex> rail_vertices;
  Eigen::AlignedBox3d rail_box;
  for (const auto* mesh : {&rails.incoming, &rails.outgoing}) {
    const bool outgoing = mesh == &rails.outgoing;
    for (std::size_t i = 0; i < mesh->triangles.size(); ++i) {
      const Eigen::Vector3i& t = mesh->triangles[i];
      const Eigen::Vector3d a = exaggeration_.point(mesh->vertices_m[static_cast<std::size_t>(t[0])]);
      const Eigen::Vector3d b = exaggeration_.point(mesh->vertices_m[static_cast<std::size_t>(t[1])]);
      const Eigen::Vector3d c = exaggeration_.point(mesh->vertices_m[static_cast<std::size_t>(t[2])]);
      add_triangle(rail_vertices, a, b, c, rail_colour(mesh->tags[i], outgoing));
      rail_box.extend(a);
      rail_box.extend(b);
      rail_box.extend(c);
    }
  }

  // The wheel-centre path, drawn the way the wheel centre is drawn.
  std::vector<LineVertex> path;
  path.reserve(trajectory_.samples.size());
  Eigen::AlignedBox3d path_box;
  double window_x_lo = std::numeric_limits<double>::infinity(), window_x_hi = -window_x_lo;
  for (const auto& s : trajectory_.samples) {
    const Eigen::Vector3d c = exaggeration_.wheel_centre(s.centre_m);
    path.push_back({to_float(c), palette::centre_path});
    path_box.extend(c);
    if (s.time_s >= window_.t_start_s && s.time_s <= window_.t_end_s) {
      window_x_lo = std::min(window_x_lo, c.x());
      window_x_hi = std::max(window_x_hi, c.x());
    }
  }
  for (double t : {window_.t_start_s, window_.t_end_s}) {
    const double x = sample_at(trajectory_, t).centre_m.x();
    window_x_lo = std::min(window_x_lo, x);
    window_x_hi = std::max(window_x_hi, x);
  }
  fixed_centre_x_m_ = 0.5 * (window_x_lo + window_x_hi);

  // Ground checker just below the drawn rail bottoms, 0.1 m tiles aligned with
  // world x so that a following camera shows the motion in top and perspective views.
  constexpr double tile_m = 0.1;
  const double ground_z = rail_box.min().z() - 0.002;
  const double x_lo = std::floor(std::min(rail_box.min().x(), path_box.min().x()) / tile_m - 20.0) * tile_m;
  const double x_hi = std::ceil(std::max(rail_box.max().x(), path_box.max().x()) / tile_m + 20.0) * tile_m;
  const double y_half = 1.5;
  std::vector<MeshVertex> ground;
  for (long long i = 0; x_lo + static_cast<double>(i) * tile_m < x_hi - 1e-9; ++i) {
    for (long long j = 0; -y_half + static_cast<double>(j) * tile_m < y_half - 1e-9; ++j) {
      const double x0 = x_lo + static_cast<double>(i) * tile_m, y0 = -y_half + static_cast<double>(j) * tile_m;
      const double x1 = x0 + tile_m, y1 = y0 + tile_m;
      const long long parity = static_cast<long long>(std::llround(x0 / tile_m)) + j;
      add_quad(ground, {x0, y0, ground_z}, {x1, y0, ground_z}, {x1, y1, ground_z}, {x0, y1, ground_z},
               (parity % 2 + 2) % 2 == 0 ? palette::ground_a : palette::ground_b);
    }
  }

  framing_.wheel_radius_m = radius;
  framing_.rail_width_m = rail_box.max().y() - rail_box.min().y();
  framing_.reference_z_m = settings_.reference_z_m;
  framing_.wheel_lateral_m = trajectory_.samples.front().centre_m.y();
  framing_.scene_bounds = rail_box;
  framing_.scene_bounds.extend(Eigen::Vector3d(x_lo, -y_half, ground_z));
  framing_.scene_bounds.extend(Eigen::Vector3d(x_hi, y_half, ground_z));
  framing_.scene_bounds.extend(path_box.min() - Eigen::Vector3d::Constant(radius + wheel_half_width_m_));
  framing_.scene_bounds.extend(path_box.max() + Eigen::Vector3d::Constant(radius + wheel_half_width_m_));

  // Datum: a line at the reference height just in front of the near rail side
  // (seen in the side view), ticks hanging below it every 50 mm, longer every
  // 100 mm. Sized in pixels of the side view so they stay thin but visible.
  const double px_m = (settings_.view_width_m ? *settings_.view_width_m / settings_.width_px
                                              : 2.6 * radius / settings_.height_px);
  const double y_datum = rail_box.min().y() - 0.001;
  const double zr = settings_.reference_z_m;
  std::vector<MeshVertex> datum;
  const double line_half = 0.75 * px_m;
  add_quad(datum, {x_lo, y_datum, zr - line_half}, {x_hi, y_datum, zr - line_half}, {x_hi, y_datum, zr + line_half},
           {x_lo, y_datum, zr + line_half}, palette::datum);
  for (long long k = static_cast<long long>(std::ceil(x_lo / 0.05)); k * 0.05 <= x_hi; ++k) {
    const double x = static_cast<double>(k) * 0.05;
    const double length = (k % 2 == 0 ? 16.0 : 8.0) * px_m;
    add_quad(datum, {x - line_half, y_datum, zr - length}, {x + line_half, y_datum, zr - length},
             {x + line_half, y_datum, zr}, {x - line_half, y_datum, zr}, palette::datum);
  }

  // Wheel in its own frame (axle along y), plus a dark bar across each face
  // and a knob on one end of the bar: the bar shows the spin, the knob its sign.
  std::vector<MeshVertex> wheel_vertices;
  for (std::size_t i = 0; i < wheel.triangles.size(); ++i) {
    const Eigen::Vector3i& t = wheel.triangles[i];
    add_triangle(wheel_vertices, wheel.vertices_m[static_cast<std::size_t>(t[0])],
                 wheel.vertices_m[static_cast<std::size_t>(t[1])], wheel.vertices_m[static_cast<std::size_t>(t[2])],
                 wheel.tags[i] == FaceTag::wheel_rim ? palette::wheel_rim : palette::wheel_face);
  }
  // Just outside the faces, so the bar is never hidden in the face it lies on.
  const double face_offset = std::max(0.0005, 0.05 * wheel_half_width_m_);
  for (double side : {-1.0, 1.0}) {
    const double y = side * (wheel_half_width_m_ + face_offset);
    const double bar = 0.9 * radius, half = 0.05 * radius;
    add_quad(wheel_vertices, {-bar, y, -half}, {bar, y, -half}, {bar, y, half}, {-bar, y, half}, palette::wheel_spoke);
    const double k0 = 0.55 * radius, k1 = 0.8 * radius, kh = 0.12 * radius;
    add_quad(wheel_vertices, {k0, y, -kh}, {k1, y, -kh}, {k1, y, kh}, {k0, y, kh}, palette::wheel_spoke);
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

Camera CrossingRenderer::camera_at(double t_s) const {
  const WheelSample sample = sample_at(trajectory_, t_s);
  const Eigen::Vector3d centre = exaggeration_.wheel_centre(sample.centre_m);
  CameraFraming framing = framing_;
  framing.wheel_lateral_m = centre.y();
  return make_camera(settings_, framing, settings_.follow_wheel ? centre.x() : fixed_centre_x_m_);
}

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
  const Eigen::Vector3d centre = exaggeration_.wheel_centre(sample.centre_m);
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

  const Eigen::Affine3d wheel_pose =
      Eigen::Translation3d(centre) * Eigen::AngleAxisd(sample.spin_angle_rad, Eigen::Vector3d::UnitY());
  frame.meshes = {{ground_, Eigen::Matrix4f::Identity(), -1},
                  {rails_, Eigen::Matrix4f::Identity(), -1},
                  {datum_, Eigen::Matrix4f::Identity(), -1},
                  {wheel_, wheel_pose.matrix().cast<float>(), -1}};

  // The path up to the last recorded sample at or before t.
  const auto& samples = trajectory_.samples;
  const auto upto = std::upper_bound(samples.begin(), samples.end(), t_s,
                                     [](double t, const WheelSample& s) { return t < s.time_s; });
  frame.line_strips.push_back({path_, Eigen::Matrix4f::Identity(), static_cast<int>(upto - samples.begin())});

  const float h = static_cast<float>(settings_.height_px);
  const float marker_px = std::max(6.0f, h / 60.0f);
  for (const auto& contact : sample.contacts) {
    frame.markers.push_back({to_float(exaggeration_.point(contact.point_on_rail_m)), palette::contact, marker_px});
  }
  const ImpactEvent* current = nullptr;
  for (const auto& impact : trajectory_.impacts) {
    const Eigen::Vector3f where = to_float(exaggeration_.point(impact.contact_point_m));
    if (std::abs(t_s - impact.time_s) <= window_.period_s()) {
      current = &impact;
      frame.markers.push_back({where, palette::impact, 2.2f * marker_px});
    } else if (impact.time_s < t_s) {
      frame.markers.push_back({where, palette::past_impact, 0.8f * marker_px});
    }
  }

  const float scale = std::max(1.0f, std::round(h / 360.0f));
  const float margin = 6.0f * scale;
  std::string label = format("t = %.4f ms   wheel x = %+.2f mm   z = %.3f mm   spin = %.1f deg", t_s * 1e3,
                             sample.centre_m.x() * 1e3, sample.centre_m.z() * 1e3,
                             sample.spin_angle_rad * 180.0 / std::numbers::pi);
  label += '\n';
  label += to_string(settings_.view);
  label += format(" view, heights x%g about z = %g mm", settings_.exaggeration, settings_.reference_z_m * 1e3);
  append_text(frame.overlay, label, margin, margin, scale, palette::text);
  if (current != nullptr) {
    append_text(frame.overlay,
                format("IMPACT at t = %.4f ms: dp_z = %.2f N s", current->time_s * 1e3, current->momentum_jump_Ns),
                margin, margin + 26.0f * scale, scale, palette::impact);
    append_border(frame.overlay, settings_.width_px, settings_.height_px, std::max(4.0f, h / 90.0f), palette::impact);
  }
  return frame;
}

}  // namespace railjoint
