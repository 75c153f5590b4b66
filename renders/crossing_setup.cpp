#include "renders/crossing_setup.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "renders/palette.h"

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

}  // namespace

CrossingSetup::CrossingSetup(const RenderSettings& settings_in, const RailJointMesh& rails, const TriangleMesh& wheel,
                             const Trajectory& trajectory_in)
    : settings(settings_in), trajectory(trajectory_in) {
  window = frame_window(settings, trajectory);  // checks the settings too
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
  wheel_radius_m = radius;
  wheel_half_width_m = half_width;
  exaggeration = {settings.exaggeration, settings.reference_z_m};
  const double k = exaggeration.factor;
  wheel_y_m = trajectory.samples.front().centre_m.y();
  // Wheel decorations (rim ticks, bar, path) lie just outside the wheel's faces
  // so the face they lie on never hides them.
  face_offset_m = std::max(0.0005, 0.05 * half_width);

  rail_top_max_m = -std::numeric_limits<double>::infinity();
  for (const auto* mesh : {&rails.incoming, &rails.outgoing}) {
    for (const auto& v : mesh->vertices_m) {
      rail_box_m.extend(exaggeration.point(v));
      rail_box_real_m.extend(v);
    }
    for (std::size_t i = 0; i < mesh->triangles.size(); ++i) {
      if (mesh->tags[i] != FaceTag::top) continue;
      for (int c = 0; c < 3; ++c) {
        rail_top_max_m = std::max(rail_top_max_m, mesh->vertices_m[static_cast<std::size_t>(mesh->triangles[i][c])].z());
      }
    }
  }
  if (!std::isfinite(rail_top_max_m)) rail_top_max_m = rail_box_real_m.max().z();
  rail_half_width_m = 0.5 * (rail_box_real_m.max().y() - rail_box_real_m.min().y());
  framing.rail_width_m = rail_box_m.max().y() - rail_box_m.min().y();

  // Everything the drawn wheel covers over the run (close views), and the
  // range of its centre's x and of its drawn lowest point over the window.
  Eigen::AlignedBox3d wheel_box;
  const Eigen::Vector3d wheel_extent(radius, half_width + 2.0 * face_offset_m, k * radius);
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;
  double z_lo = x_lo, z_hi = -x_lo;
  auto in_window = [&](const WheelSample& s) {
    const Eigen::Vector3d low = exaggeration.lowest_wheel_point(s.centre_m, radius);
    x_lo = std::min(x_lo, s.centre_m.x());
    x_hi = std::max(x_hi, s.centre_m.x());
    z_lo = std::min(z_lo, low.z());
    z_hi = std::max(z_hi, low.z());
  };
  for (const auto& s : trajectory.samples) {
    Eigen::Vector3d low = s.centre_m - Eigen::Vector3d(0.0, 0.0, radius);
    low.y() = wheel_y_m - half_width - 2.0 * face_offset_m;
    const Eigen::Vector3d centre = exaggeration.point(s.centre_m);
    wheel_box.extend(centre - wheel_extent);
    wheel_box.extend(centre + wheel_extent);
    wheel_box.extend(exaggeration.point(low));
    if (s.time_s >= window.t_start_s && s.time_s <= window.t_end_s) in_window(s);
  }
  for (double t : {window.t_start_s, window.t_end_s}) in_window(sample_at(trajectory, t));
  window_x_lo_m = x_lo;
  window_x_hi_m = x_hi;
  fixed_focus_m = Eigen::Vector3d(0.5 * (x_lo + x_hi), wheel_y_m, 0.5 * (z_lo + z_hi));

  // Ground 2 mm (drawn) below the rail bottoms, 20 tiles beyond everything drawn.
  constexpr double tile_m = 0.1;
  ground.z_m = rail_box_real_m.min().z() - 0.002 / k;
  ground.x_lo_m = std::floor(std::min(rail_box_m.min().x(), wheel_box.min().x()) / tile_m - 20.0) * tile_m;
  ground.x_hi_m = std::ceil(std::max(rail_box_m.max().x(), wheel_box.max().x()) / tile_m + 20.0) * tile_m;
  ground.y_half_m = 1.5;

  framing.scene_bounds = rail_box_m;
  framing.scene_bounds.extend(exaggeration.point(Eigen::Vector3d(ground.x_lo_m, -ground.y_half_m, ground.z_m)));
  framing.scene_bounds.extend(exaggeration.point(Eigen::Vector3d(ground.x_hi_m, ground.y_half_m, ground.z_m)));
  framing.scene_bounds.extend(wheel_box);

  straightedge = straightedge_over(rails);  // also checks that both rails have a top face
}

void CrossingSetup::open_gl(const std::vector<MeshVertex>& rails, const TriangleMesh& wheel, double view_width_m,
                            double px_per_m) {
  gl = std::make_unique<OffscreenRenderer>(settings.width_px, settings.height_px, settings.antialiasing);
  rails_mesh = gl->add_triangles(rails);
  wheel_mesh = gl->add_triangles(wheel_body_vertices(wheel, 0.0));
  close_marks_mesh = gl->add_triangles(contact_view_wheel_marks(wheel_radius_m,
                                                                rim_inner_radius(wheel, wheel_radius_m),
                                                                wheel_half_width_m, face_offset_m, view_width_m,
                                                                1.0 / px_per_m, exaggeration.factor));
}

const ImpactEvent* CrossingSetup::impact_within_one_frame(double t_s) const {
  const ImpactEvent* current = nullptr;
  for (const auto& impact : trajectory.impacts) {
    if (std::abs(t_s - impact.time_s) <= window.period_s()) current = &impact;
  }
  return current;
}

float CrossingSetup::text_scale() const {
  // 2x at 720p, 3x at 1080p.
  return std::max(1.0f, std::round(static_cast<float>(settings.height_px) / 360.0f));
}

float CrossingSetup::impact_border_px() const {
  return std::max(4.0f, static_cast<float>(settings.height_px) / 90.0f);
}

std::vector<MeshVertex> CrossingSetup::checker_ground() const {
  constexpr double tile_m = 0.1;
  const double z = ground.z_m, y_half = ground.y_half_m;
  std::vector<MeshVertex> out;
  for (long long i = 0; ground.x_lo_m + static_cast<double>(i) * tile_m < ground.x_hi_m - 1e-9; ++i) {
    for (long long j = 0; -y_half + static_cast<double>(j) * tile_m < y_half - 1e-9; ++j) {
      const double x0 = ground.x_lo_m + static_cast<double>(i) * tile_m, y0 = -y_half + static_cast<double>(j) * tile_m;
      const double x1 = x0 + tile_m, y1 = y0 + tile_m;
      const long long parity = static_cast<long long>(std::llround(x0 / tile_m)) + j;
      add_quad(out, {x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z},
               (parity % 2 + 2) % 2 == 0 ? palette::ground_a : palette::ground_b);
    }
  }
  return out;
}

std::vector<LineVertex> CrossingSetup::lowest_point_path() const {
  std::vector<LineVertex> path;
  path.reserve(trajectory.samples.size());
  for (const auto& s : trajectory.samples) {
    Eigen::Vector3d low = s.centre_m - Eigen::Vector3d(0.0, 0.0, wheel_radius_m);
    low.y() = wheel_y_m - wheel_half_width_m - 2.0 * face_offset_m;
    path.push_back({low.cast<float>(), palette::centre_path});
  }
  return path;
}

MeshDraw CrossingSetup::path_up_to(MeshHandle path, const Eigen::Matrix4f& model, double t_s) const {
  const auto& samples = trajectory.samples;
  const auto upto = std::upper_bound(samples.begin(), samples.end(), t_s,
                                     [](double t, const WheelSample& s) { return t < s.time_s; });
  return {path, model, static_cast<int>(upto - samples.begin())};
}

MeshDraw CrossingSetup::rails_draw(const Eigen::Matrix4f& model) const {
  MeshDraw rails{rails_mesh, model};
  rails.cull_back_faces = true;
  return rails;
}

void CrossingSetup::append_close_wheel(SceneDraw& scene, const WheelSample& sample) const {
  // Exaggeration after the rigid pose: the wheel's circle is drawn as an ellipse k times taller than wide.
  const Eigen::Matrix4f model = exaggeration.matrix().cast<float>() * wheel_pose(sample);
  MeshDraw body{wheel_mesh, model};
  body.cull_back_faces = true;
  scene.meshes.push_back(body);
  scene.meshes.push_back({close_marks_mesh, model});
}

float CrossingSetup::close_marker_px() const { return std::max(6.0f, static_cast<float>(settings.height_px) / 90.0f); }

SceneDraw scene_seen_by(const Camera& camera, const Eigen::Vector3f& to_light) {
  SceneDraw scene;
  scene.view = camera.view.cast<float>();
  scene.projection = camera.projection.cast<float>();
  scene.orthographic = camera.orthographic;
  scene.eye_m = camera.eye_m.cast<float>();
  scene.to_viewer = camera.to_viewer.cast<float>();
  scene.to_light = to_light;
  scene.background = palette::background;
  return scene;
}

Eigen::Matrix4f wheel_pose(const WheelSample& sample) {
  const Eigen::Affine3d pose =
      Eigen::Translation3d(sample.centre_m) * Eigen::AngleAxisd(sample.spin_angle_rad, Eigen::Vector3d::UnitY());
  return pose.matrix().cast<float>();
}

void append_contact_markers(SceneDraw& scene, const CrossingSetup& setup, double t_s, const WheelSample& sample,
                            float marker_px, bool exaggerated) {
  auto drawn = [&](const Eigen::Vector3d& p) {
    return Eigen::Vector3f((exaggerated ? setup.exaggeration.point(p) : p).cast<float>());
  };
  for (const auto& contact : sample.contacts) {
    if (contact.distance_m > kTouchingGap_m) continue;
    scene.markers.push_back({drawn(contact.point_on_rail_m), palette::contact, marker_px});
  }
  for (const auto& impact : setup.trajectory.impacts) {
    const Eigen::Vector3f where = drawn(impact.contact_point_m);
    if (std::abs(t_s - impact.time_s) <= setup.window.period_s()) {
      scene.markers.push_back({where, palette::impact, 3.0f * marker_px, true});
    } else if (impact.time_s < t_s) {
      scene.markers.push_back({where, palette::past_impact, 0.8f * marker_px});
    }
  }
}

Eigen::Vector2f project_to_pixel(const Camera& camera, const PixelRect& rect, const Eigen::Vector3d& point_m) {
  const Eigen::Vector4d clip = camera.projection * camera.view * point_m.homogeneous();
  const double u = 0.5 * (clip.x() / clip.w() + 1.0), v = 0.5 * (1.0 - clip.y() / clip.w());
  return {static_cast<float>(rect.x + u * rect.width), static_cast<float>(rect.y + v * rect.height)};
}

}  // namespace railjoint
