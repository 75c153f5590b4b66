#include "renders/crossing_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geometry/wheel_mesh.h"
#include "renders/palette.h"
#include "renders/slab_section.h"
#include "renders/wheel_tessellation.h"

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

// The perspective overview looks from behind the wheel (the incoming side),
// on the same side as the side view (y < 0, travel left to right) and from
// above: at about 30 deg to the rail it sees the wheel's face as a disc and
// the rail head's top with the cut across it. The inset looks at the contact
// from the same side, lower and more along the rail, so the V, the cut and
// the struck corner read in 3-D.
const Eigen::Vector3d kOverviewToEye = Eigen::Vector3d(-0.50, -0.80, 0.42).normalized();
const Eigen::Vector3d kInsetToEye = Eigen::Vector3d(-0.75, -0.80, 0.50).normalized();
const Eigen::Vector3f kOverviewToLight = Eigen::Vector3f(-0.30f, -0.60f, 0.75f).normalized();
const double kOverviewFovy_rad = 30.0 * std::numbers::pi / 180.0;
const double kInsetFovy_rad = 40.0 * std::numbers::pi / 180.0;
// Visible width of the inset at the contact: wider than the side view's
// default so both rail ends' slopes show beside the step.
constexpr double kInsetViewWidth_m = 0.16;

// Share of the image width the perspective overview takes; the rest is the
// panel with the inset above the legend.
constexpr double kOverviewShare = 0.64;

Eigen::Matrix4f pose_matrix(const WheelSample& sample) {
  const Eigen::Affine3d pose =
      Eigen::Translation3d(sample.centre_m) * Eigen::AngleAxisd(sample.spin_angle_rad, Eigen::Vector3d::UnitY());
  return pose.matrix().cast<float>();
}

}  // namespace

CrossingRenderer::CrossingRenderer(const RenderSettings& settings, const RailJointMesh& rails,
                                   const TriangleMesh& wheel, const Trajectory& trajectory,
                                   std::optional<GlBackend> backend)
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
  const bool side_view = settings_.view == RenderView::side;
  if (side_view && !(half_width > kSectionInset_m)) {
    throw std::invalid_argument("render: the side view cuts the rails to the wheel's width, but the wheel mesh is " +
                                std::to_string(2.0 * half_width) + " m wide; give it a positive width (> 4 um)");
  }
  wheel_radius_m_ = radius;
  wheel_half_width_m_ = half_width;
  exaggeration_ = {settings_.exaggeration, settings_.reference_z_m};
  const double k = exaggeration_.factor;
  const double wheel_y = trajectory_.samples.front().centre_m.y();
  wheel_y_m_ = wheel_y;
  // Wheel decorations (rim ticks, bar, path) lie just outside the wheel's faces
  // so the face they lie on never hides them.
  const double face_offset = std::max(0.0005, 0.05 * half_width);

  // Rails in real coordinates; each view draws them through its own
  // exaggeration. The side view draws the section through the wheel's width
  // only (slab_section.h).
  std::vector<MeshVertex> rail_list;
  Eigen::AlignedBox3d rail_box, rail_box_real;  // drawn (close views) / real
  rail_top_max_m_ = -std::numeric_limits<double>::infinity();
  for (const auto* mesh : {&rails.incoming, &rails.outgoing}) {
    for (const auto& v : mesh->vertices_m) {
      rail_box.extend(exaggeration_.point(v));
      rail_box_real.extend(v);
    }
    for (std::size_t i = 0; i < mesh->triangles.size(); ++i) {
      if (mesh->tags[i] != FaceTag::top) continue;
      for (int c = 0; c < 3; ++c) {
        rail_top_max_m_ = std::max(rail_top_max_m_, mesh->vertices_m[static_cast<std::size_t>(mesh->triangles[i][c])].z());
      }
    }
    const TriangleMesh drawn =
        side_view ? cut_convex_solid_to_slab(*mesh, wheel_y - half_width + kSectionInset_m, wheel_y + half_width)
                  : *mesh;
    const std::vector<MeshVertex> part = rail_vertices(drawn, mesh == &rails.outgoing);
    rail_list.insert(rail_list.end(), part.begin(), part.end());
  }
  if (!std::isfinite(rail_top_max_m_)) rail_top_max_m_ = rail_box_real.max().z();
  rail_box_real_ = rail_box_real;
  rail_half_width_m_ = 0.5 * (rail_box_real.max().y() - rail_box_real.min().y());
  framing_.rail_width_m = rail_box.max().y() - rail_box.min().y();
  if (side_view) {
    side_framing_.emplace(std::vector<const TriangleMesh*>{&rails.incoming, &rails.outgoing}, wheel_y, radius,
                          exaggeration_);
    // A flight the default width cannot show with the rails under it widens
    // the view for the whole render; a width the scene gives is kept.
    if (settings_.follow_wheel && !settings_.view_width_m) {
      const double aspect = static_cast<double>(settings_.width_px) / static_cast<double>(settings_.height_px);
      const double width_m = visible_width_m(settings_, framing_);
      const double needed_m = side_framing_->width_for_flights(trajectory_, window_, width_m, aspect);
      if (needed_m > width_m) settings_.view_width_m = needed_m;
    }
  }

  // Where things go in the image: the whole picture, or (perspective) the
  // overview on the left and the panel with the inset above the legend.
  const int w = settings_.width_px, h = settings_.height_px;
  if (settings_.view == RenderView::perspective) {
    const int pad = std::max(2, h / 90);
    const int overview_w = static_cast<int>(std::lround(kOverviewShare * w));
    const int panel_w = std::max(1, w - overview_w - 2 * pad);
    const int inset_h = std::max(1, static_cast<int>(std::lround(0.56 * h)) - pad);
    overview_rect_ = {0, 0, overview_w, h};
    inset_rect_ = {overview_w + pad, pad, panel_w, inset_h};
    legend_rect_ = {overview_w + pad, pad + inset_h + pad, panel_w, std::max(1, h - inset_h - 3 * pad)};
  } else {
    overview_rect_ = inset_rect_ = legend_rect_ = {0, 0, w, h};
  }
  const double view_width_m = settings_.view == RenderView::perspective
                                  ? settings_.view_width_m.value_or(kInsetViewWidth_m)
                                  : visible_width_m(settings_, framing_);
  px_per_m_ = static_cast<double>(inset_rect_.width) / view_width_m;

  // The path of the wheel's lowest point (the point R below the centre), in
  // real coordinates, just in front of the wheel's near face so the wheel never hides it.
  std::vector<LineVertex> path;
  path.reserve(trajectory_.samples.size());
  Eigen::AlignedBox3d wheel_box;  // everything the drawn wheel covers over the run (close views)
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
    Eigen::Vector3d low = s.centre_m - Eigen::Vector3d(0.0, 0.0, radius);
    low.y() = wheel_y - half_width - 2.0 * face_offset;
    path.push_back({to_float(low), palette::centre_path});
    const Eigen::Vector3d centre = exaggeration_.point(s.centre_m);
    wheel_box.extend(centre - wheel_extent);
    wheel_box.extend(centre + wheel_extent);
    wheel_box.extend(exaggeration_.point(low));
    if (s.time_s >= window_.t_start_s && s.time_s <= window_.t_end_s) in_window(s);
  }
  for (double t : {window_.t_start_s, window_.t_end_s}) in_window(sample_at(trajectory_, t));
  fixed_focus_m_ = Eigen::Vector3d(0.5 * (x_lo + x_hi), wheel_y, 0.5 * (z_lo + z_hi));

  // Ground checker 2 mm (drawn) below the rail bottoms, 0.1 m tiles aligned
  // with world x so that a following camera shows the motion in top and perspective views.
  constexpr double tile_m = 0.1;
  const double ground_z_real = rail_box_real.min().z() - 0.002 / k;
  const double ground_x_lo = std::floor(std::min(rail_box.min().x(), wheel_box.min().x()) / tile_m - 20.0) * tile_m;
  const double ground_x_hi = std::ceil(std::max(rail_box.max().x(), wheel_box.max().x()) / tile_m + 20.0) * tile_m;
  const double y_half = 1.5;
  std::vector<MeshVertex> ground;
  for (long long i = 0; ground_x_lo + static_cast<double>(i) * tile_m < ground_x_hi - 1e-9; ++i) {
    for (long long j = 0; -y_half + static_cast<double>(j) * tile_m < y_half - 1e-9; ++j) {
      const double x0 = ground_x_lo + static_cast<double>(i) * tile_m, y0 = -y_half + static_cast<double>(j) * tile_m;
      const double x1 = x0 + tile_m, y1 = y0 + tile_m;
      const long long parity = static_cast<long long>(std::llround(x0 / tile_m)) + j;
      add_quad(ground, {x0, y0, ground_z_real}, {x1, y0, ground_z_real}, {x1, y1, ground_z_real},
               {x0, y1, ground_z_real}, (parity % 2 + 2) % 2 == 0 ? palette::ground_a : palette::ground_b);
    }
  }

  framing_.scene_bounds = rail_box;
  framing_.scene_bounds.extend(exaggeration_.point(Eigen::Vector3d(ground_x_lo, -y_half, ground_z_real)));
  framing_.scene_bounds.extend(exaggeration_.point(Eigen::Vector3d(ground_x_hi, y_half, ground_z_real)));
  framing_.scene_bounds.extend(wheel_box);

  // Datum (side view): a thin light line at the reference height (the height
  // the exaggeration keeps), BEHIND the rails and the wheel, so it shows only
  // where nothing else is and never reads as part of the geometry. Lengths
  // are read off the scale bars instead of ticks. Drawn coordinates.
  const double px_m = 1.0 / px_per_m_;
  std::vector<MeshVertex> datum;
  if (side_view) {
    const double y_datum = rail_box.max().y() + 0.001;
    const double zr = settings_.reference_z_m;
    const double line_half = 0.5 * px_m;
    add_quad(datum, {ground_x_lo, y_datum, zr - line_half}, {ground_x_hi, y_datum, zr - line_half},
             {ground_x_hi, y_datum, zr + line_half}, {ground_x_lo, y_datum, zr + line_half}, palette::datum);
  }

  // The straightedge on both rail ends, beside the rail head on the side the
  // overview camera looks from, so its lower edge and the rail's top edge
  // show the dip as the gap between them.
  straightedge_ = straightedge_over(rails);
  const double bar_m = 0.006;
  const std::vector<MeshVertex> bar = straightedge_bar(straightedge_, rail_box_real.min().y() - 0.5 * bar_m - 0.002, bar_m);

  if (settings_.view == RenderView::perspective) {
    // Frame the wheel over the window and the rails within 1.3 R of it.
    std::vector<Eigen::Vector3d> points;
    const double reach = 1.3 * radius;
    const double rx_lo = std::max(rail_box_real.min().x(), x_lo - reach);
    const double rx_hi = std::min(rail_box_real.max().x(), x_hi + reach);
    for (double x : {rx_lo, rx_hi}) {
      for (double y : {rail_box_real.min().y(), rail_box_real.max().y()}) {
        for (double z : {rail_box_real.min().z(), rail_top_max_m_}) points.emplace_back(x, y, z);
      }
    }
    for (double t : {window_.t_start_s, window_.t_end_s}) {
      const Eigen::Vector3d c = sample_at(trajectory_, t).centre_m;
      for (int j = 0; j < 24; ++j) {
        const double phi = 2.0 * std::numbers::pi * j / 24.0;
        for (double side : {-1.0, 1.0}) {
          points.push_back(c + Eigen::Vector3d(radius * std::cos(phi), side * half_width, radius * std::sin(phi)));
        }
      }
    }
    Eigen::AlignedBox3d bounds = rail_box_real;
    for (const auto& p : points) bounds.extend(p);
    const double aspect = static_cast<double>(overview_rect_.width) / static_cast<double>(overview_rect_.height);
    overview_camera_ = fit_perspective_camera(points, kOverviewToEye, kOverviewFovy_rad, aspect, 0.06, bounds);
  }

  gl_ = std::make_unique<OffscreenRenderer>(settings_.width_px, settings_.height_px,
                                            backend ? *backend : gl_backend_from_environment(), settings_.antialiasing);
  rails_ = gl_->add_triangles(rail_list);
  ground_ = gl_->add_triangles(ground);
  if (!datum.empty()) datum_ = gl_->add_triangles(datum);
  wheel_ = gl_->add_triangles(wheel_body_vertices(wheel, 0.0));
  close_marks_ = gl_->add_triangles(contact_view_wheel_marks(radius, rim_inner_radius(wheel, radius), half_width,
                                                             face_offset, view_width_m, px_m, k));
  if (settings_.view == RenderView::perspective) {
    // The overview's camera stands still: one plain ground quad instead of
    // the checker (whose edges cost anti-aliasing and PNG bytes for nothing).
    std::vector<MeshVertex> plain;
    add_quad(plain, {ground_x_lo, -y_half, ground_z_real}, {ground_x_hi, -y_half, ground_z_real},
             {ground_x_hi, y_half, ground_z_real}, {ground_x_lo, y_half, ground_z_real}, palette::ground_a);
    plain_ground_ = gl_->add_triangles(plain);
    whole_marks_ = gl_->add_triangles(whole_wheel_marks(radius, half_width, face_offset));
    std::vector<MeshVertex> joint_marks = bar;  // the straightedge and the cut line on the rail head
    const std::vector<MeshVertex> cut = cut_line_on_top(rails, 0.004);
    joint_marks.insert(joint_marks.end(), cut.begin(), cut.end());
    straightedge_bar_ = gl_->add_triangles(joint_marks);
    // The whole wheel is drawn a few hundred pixels across: as many sides as
    // keep its outline within a quarter pixel of the circle there (about 90
    // at 720p), not the contact view's 1,400. Its drawn radius is taken as
    // 1.5 times the farthest projected rim point from the projected centre:
    // the margin covers the rim seen at a slant (an ellipse with semi-axes
    // a > b is flattest at the ends of b, with radius a^2 / b; the overview
    // sees the wheel with a / b about 1.1).
    double drawn_radius_px = 0.0;
    for (double t : {window_.t_start_s, window_.t_end_s}) {
      const Eigen::Vector3d c = sample_at(trajectory_, t).centre_m;
      for (int j = 0; j < 24; ++j) {
        const double phi = 2.0 * std::numbers::pi * j / 24.0;
        const Eigen::Vector3d rim = c + Eigen::Vector3d(radius * std::cos(phi), 0.0, radius * std::sin(phi));
        drawn_radius_px = std::max(drawn_radius_px, static_cast<double>((project_overview(rim) - project_overview(c)).norm()));
      }
    }
    WheelParams coarse;
    coarse.radius_m = radius;
    coarse.width_m = 2.0 * half_width;
    overview_wheel_sides_ = polygon_sides_for_radius_px(1.5 * std::max(drawn_radius_px, 1.0));
    dished_wheel_ = gl_->add_triangles(wheel_body_vertices(build_wheel_mesh(coarse, overview_wheel_sides_, 0.0), 0.3));
  }
  if (settings_.view == RenderView::top) {
    band_ = gl_->add_triangles({});
    straightedge_bar_ = gl_->add_triangles(cut_line_on_top(rails, 2.0 * px_m));  // the cut on the head, 2 px wide
  }
  path_ = gl_->add_line_strip(path);
}

CrossingRenderer::~CrossingRenderer() = default;

const std::string& CrossingRenderer::gl_version() const { return gl_->gl_version(); }
const std::string& CrossingRenderer::gl_renderer() const { return gl_->gl_renderer(); }
GlBackend CrossingRenderer::gl_backend() const { return gl_->backend(); }

Eigen::Vector3d CrossingRenderer::focus_at(double t_s) const {
  if (!settings_.follow_wheel) return fixed_focus_m_;
  const Eigen::Vector3d centre = sample_at(trajectory_, t_s).centre_m;
  if (side_framing_) return side_framing_->focus(centre);
  return exaggeration_.lowest_wheel_point(centre, wheel_radius_m_);
}

Camera CrossingRenderer::camera_at(double t_s) const {
  if (settings_.view != RenderView::perspective) return make_camera(settings_, framing_, focus_at(t_s));
  const double aspect = static_cast<double>(inset_rect_.width) / static_cast<double>(inset_rect_.height);
  return look_at_focus(focus_at(t_s), kInsetToEye, kInsetFovy_rad, aspect,
                       settings_.view_width_m.value_or(kInsetViewWidth_m), framing_.scene_bounds);
}

void CrossingRenderer::show_contact_patch(const PressureInputs& inputs) {
  if (settings_.view != RenderView::top) return;
  contact_patch_ = inputs;
  if (patch_ < 0) patch_ = gl_->add_triangles({});
}

std::optional<PatchPlacement> CrossingRenderer::contact_patch_at(double t_s) const {
  if (!contact_patch_) return std::nullopt;
  // The foremost touching contact: at the impact the wheel touches both rail
  // ends and its load goes over to the outgoing one.
  const WheelSample sample = sample_at(trajectory_, t_s);
  std::optional<double> contact_x_m;
  for (const ContactSample& contact : sample.contacts) {
    if (contact.distance_m > kTouchingGap_m) continue;
    contact_x_m = std::max(contact_x_m.value_or(contact.point_on_rail_m.x()), contact.point_on_rail_m.x());
  }
  // From the located impact instant to the end of the steps that carried it
  // the wheel touches the struck point, though the nearer recorded sample
  // (sample_at's contacts) may be the one before the impact: the impact frame
  // (--impact-frame, t = the impact time) would put the patch back on the
  // incoming rail, away from the impact ring.
  for (const ImpactEvent& impact : trajectory_.impacts) {
    if (impact.last_sample >= trajectory_.samples.size()) continue;
    if (t_s < impact.time_s || t_s > trajectory_.samples[impact.last_sample].time_s) continue;
    contact_x_m = std::max(contact_x_m.value_or(impact.contact_point_m.x()), impact.contact_point_m.x());
  }
  if (!contact_x_m) return std::nullopt;  // in flight
  return place_contact_patch(*contact_patch_, {*contact_x_m, wheel_y_m_}, rail_half_width_m_);
}

void CrossingRenderer::render_frame(long long k, RgbImage& out) {
  ReadBackFrame read_back;
  draw_frame(k, read_back);
  finish_frame(read_back, out);
}

void CrossingRenderer::draw_frame(long long k, ReadBackFrame& out) {
  if (k < 0 || k >= window_.count) {
    throw std::out_of_range("render: frame " + std::to_string(k) + " is outside 0 .. " +
                            std::to_string(window_.count - 1));
  }
  draw_at(window_.time_s(k), out);
}

void CrossingRenderer::render_at(double t_s, RgbImage& out) {
  ReadBackFrame read_back;
  draw_at(t_s, read_back);
  finish_frame(read_back, out);
}

void CrossingRenderer::draw_at(double t_s, ReadBackFrame& out) {
  if (band_ >= 0) {
    // Just above the highest rail top: seen from above it lies on the rail head.
    const double y_lo = std::max(wheel_y_m_ - wheel_half_width_m_, -rail_half_width_m_);
    const double y_hi = std::min(wheel_y_m_ + wheel_half_width_m_, rail_half_width_m_);
    gl_->update_triangles(band_, running_band(trajectory_, t_s, y_lo, y_hi, rail_top_max_m_ + 1e-5));
  }
  if (patch_ >= 0) {
    // Over the running band (which lies 10 um above the highest rail top).
    const std::optional<PatchPlacement> placement = contact_patch_at(t_s);
    gl_->update_triangles(patch_, placement ? contact_patch_vertices(*contact_patch_, *placement, rail_top_max_m_ + 2e-5)
                                            : std::vector<MeshVertex>{});
  }
  gl_->draw(frame_at(t_s), out);
}

const ImpactEvent* CrossingRenderer::impact_within_one_frame(double t_s) const {
  const ImpactEvent* current = nullptr;
  for (const auto& impact : trajectory_.impacts) {
    if (std::abs(t_s - impact.time_s) <= window_.period_s()) current = &impact;
  }
  return current;
}

SceneDraw CrossingRenderer::close_scene(double t_s, const WheelSample& sample, const Camera& camera) const {
  SceneDraw scene;
  scene.view = camera.view.cast<float>();
  scene.projection = camera.projection.cast<float>();
  scene.orthographic = camera.orthographic;
  scene.eye_m = camera.eye_m.cast<float>();
  scene.to_viewer = camera.to_viewer.cast<float>();
  // Key light from the viewer's side of the track, above and a little behind.
  scene.to_light = Eigen::Vector3f(-0.35f, -0.8f, 0.5f).normalized();
  scene.background = palette::background;
  if (settings_.view == RenderView::perspective) {
    scene.viewport = inset_rect_;
    scene.to_light = kOverviewToLight;
  }

  // Everything through the same map: exaggeration after the rigid pose, so
  // the wheel's circle is drawn as an ellipse k times taller than wide.
  const Eigen::Matrix4f e = exaggeration_.matrix().cast<float>();
  const Eigen::Matrix4f wheel_model = e * pose_matrix(sample);
  const bool top = settings_.view == RenderView::top;
  // The perspective inset is too close to the contact to see the ground.
  if (settings_.view != RenderView::perspective) scene.meshes.push_back({ground_, e});
  MeshDraw rails{rails_, e};
  rails.cull_back_faces = true;
  scene.meshes.push_back(rails);
  if (datum_ >= 0) scene.meshes.push_back({datum_});
  if (band_ >= 0) scene.meshes.push_back({band_, e});
  if (patch_ >= 0) scene.meshes.push_back({patch_, e});
  if (top && straightedge_bar_ >= 0) scene.meshes.push_back({straightedge_bar_, e});
  MeshDraw body{wheel_, wheel_model};
  body.cull_back_faces = true;
  if (top) {
    // Seen from above the wheel lies over its own footprint: drawn
    // translucent, so the running band and the contacts show through it.
    body.opacity = 0.35f;
    scene.meshes.push_back(body);
  } else {
    scene.meshes.push_back(body);
    scene.meshes.push_back({close_marks_, wheel_model});
    // The path up to the last recorded sample at or before t (seen from above
    // it is a straight line under the wheel).
    const auto& samples = trajectory_.samples;
    const auto upto = std::upper_bound(samples.begin(), samples.end(), t_s,
                                       [](double t, const WheelSample& s) { return t < s.time_s; });
    scene.line_strips.push_back({path_, e, static_cast<int>(upto - samples.begin())});
  }

  const float marker_px = std::max(6.0f, static_cast<float>(settings_.height_px) / 90.0f);
  for (const auto& contact : sample.contacts) {
    if (contact.distance_m > kTouchingGap_m) continue;
    scene.markers.push_back({to_float(exaggeration_.point(contact.point_on_rail_m)), palette::contact, marker_px});
  }
  for (const auto& impact : trajectory_.impacts) {
    const Eigen::Vector3f where = to_float(exaggeration_.point(impact.contact_point_m));
    if (std::abs(t_s - impact.time_s) <= window_.period_s()) {
      scene.markers.push_back({where, palette::impact, 3.0f * marker_px, true});
    } else if (impact.time_s < t_s) {
      scene.markers.push_back({where, palette::past_impact, 0.8f * marker_px});
    }
  }
  return scene;
}

SceneDraw CrossingRenderer::overview_scene(double t_s, const WheelSample& sample) const {
  const Camera& camera = overview_camera_;
  SceneDraw scene;
  scene.view = camera.view.cast<float>();
  scene.projection = camera.projection.cast<float>();
  scene.orthographic = false;
  scene.eye_m = camera.eye_m.cast<float>();
  scene.to_viewer = camera.to_viewer.cast<float>();
  scene.to_light = kOverviewToLight;
  scene.background = palette::background;
  scene.viewport = overview_rect_;
  const Eigen::Matrix4f pose = pose_matrix(sample);
  MeshDraw rails{rails_};
  rails.cull_back_faces = true;
  MeshDraw body{dished_wheel_, pose};
  body.cull_back_faces = true;
  body.specular = 0.45f;  // the highlight runs round the rim
  // Nearest first, so the depth test rejects what they hide before it is shaded.
  scene.meshes = {body, {whole_marks_, pose}, rails, {straightedge_bar_}, {plain_ground_}};

  const float marker_px = std::max(5.0f, static_cast<float>(settings_.height_px) / 110.0f);
  for (const auto& contact : sample.contacts) {
    if (contact.distance_m > kTouchingGap_m) continue;
    scene.markers.push_back({to_float(contact.point_on_rail_m), palette::contact, marker_px});
  }
  for (const auto& impact : trajectory_.impacts) {
    const Eigen::Vector3f where = to_float(impact.contact_point_m);
    if (std::abs(t_s - impact.time_s) <= window_.period_s()) {
      scene.markers.push_back({where, palette::impact, 3.0f * marker_px, true});
    } else if (impact.time_s < t_s) {
      scene.markers.push_back({where, palette::past_impact, 0.8f * marker_px});
    }
  }
  return scene;
}

FrameDrawList CrossingRenderer::frame_at(double t_s) const {
  const WheelSample sample = sample_at(trajectory_, t_s);
  const ImpactEvent* current = impact_within_one_frame(t_s);
  FrameDrawList list;
  if (settings_.view == RenderView::perspective) {
    // The overview's and the inset's colour, cleared once for both (the
    // panel behind the inset and the legend is laid with the labels).
    list.background = palette::background;
    list.scenes.push_back(overview_scene(t_s, sample));
    list.scenes.push_back(close_scene(t_s, sample, camera_at(t_s)));
    append_perspective_labels(list, t_s, sample, current);
  } else {
    const Camera camera = camera_at(t_s);
    list.scenes.push_back(close_scene(t_s, sample, camera));
    append_close_view_labels(list, t_s, sample, camera, current);
  }
  return list;
}

}  // namespace railjoint
