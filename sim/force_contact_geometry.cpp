#include "sim/force_contact_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "models/contact_curvatures.h"
#include "models/rail_head.h"
#include "models/rail_top.h"
#include "models/wheel_rail_envelope.h"
#include "models/wheel_tread.h"
#include "sim/hertz_law.h"
#include "sim/rail_end_patch_share.h"

namespace railjoint {

ForceContactGeometry::ForceContactGeometry(const ForceContactInputs& in)
    : joint_(in.joint),
      simulated_wheel_(in.simulated_wheel),
      analytic_(runs_on_analytic_rail_tops(in.joint, in.wheel, in.settings)) {
  for (const int r : {0, 1}) {
    const TriangleMesh& mesh = r == 0 ? in.rails.incoming : in.rails.outgoing;
    if (analytic_) {
      rails_.emplace_back(mesh, AnalyticRailTop{in.joint, in.simulated_wheel, r});
    } else {
      rails_.emplace_back(mesh);
    }
  }
  const ElasticCrossingSettings* elastic = in.settings.inertial() ? in.settings.inertial()->elastic() : nullptr;
  if (elastic != nullptr) {
    given_m_per_N2_3_ = elastic->contact.hertz_constant_m_per_N2_3;
    material_.youngs_modulus_Pa = elastic->contact.youngs_modulus_Pa;
    material_.poisson_ratio = elastic->contact.poisson_ratio;
  }
  empirical_m_per_N2_3_ = default_hertz_constant_m_per_N2_3(in.wheel.radius_m);
}

HertzAtContact ForceContactGeometry::hertz_at(int rail, const Eigen::Vector3d& point_m, bool at_edge) const {
  HertzAtContact out;
  out.given = given_m_per_N2_3_.has_value();
  out.hertz_constant_m_per_N2_3 = given_m_per_N2_3_.value_or(empirical_m_per_N2_3_);
  // The thesis's geometry is a line contact; a thin disc and a cut edge are
  // edges (see the header).
  const WheelParams& wheel = simulated_wheel_;
  if (!analytic_ || at_edge || !(wheel.width_m > 0.0)) return out;
  // The wheel's own lateral rim on the head is an edge too.
  const LateralSpan span = wheel_span_on_head(joint_, wheel);
  const double y = point_m.y();
  if (std::abs(y - span.lo_m) < 1e-9 || std::abs(y - span.hi_m) < 1e-9) return out;
  out.ellipse = elliptical_hertz(relative_curvatures(contact_curvatures_at(joint_, wheel, rail, point_m.x(), y)), material_);
  if (out.ellipse && !out.given) out.hertz_constant_m_per_N2_3 = out.ellipse->hertz_constant_m_per_N2_3;
  return out;
}

ForceContact ForceContactGeometry::find(int rail, const WheelCylinder& wheel, double max_distance_m) const {
  ForceContact out;
  out.contact = wheel_rail_contact(wheel, rails_[static_cast<std::size_t>(rail)], max_distance_m);
  if (!out.contact.found) return out;
  if (analytic_) {
    // The surface's normal: the slice's (x, z) normal tilted across by the
    // head's slope; the gap along it is the slice's gap times the cosine
    // between them (the surfaces are planes to first order).
    const Eigen::Vector3d slice = out.contact.normal;
    const double head_slope = head_top_slope(joint_, out.contact.point_on_rail_m.y());
    const Eigen::Vector3d surface = Eigen::Vector3d(slice.x(), -head_slope * slice.z(), slice.z()).normalized();
    out.contact.distance_m *= slice.dot(surface);
    out.contact.normal = surface;
  }
  out.hertz = hertz_at(rail, out.contact.point_on_rail_m, out.contact.at_edge);
  return out;
}

WheelCylinder ForceContactGeometry::wheel_at(const Eigen::Vector3d& centre_m) const {
  WheelCylinder cylinder;
  cylinder.centre_m = centre_m;
  cylinder.radius_m = simulated_wheel_.radius_m;
  cylinder.half_width_m = 0.5 * simulated_wheel_.width_m;
  return cylinder;
}

bool ForceContactGeometry::law_can_switch() const {
  return analytic_ && simulated_wheel_.width_m > 0.0 && !given_m_per_N2_3_;
}

bool ForceContactGeometry::near_law_switch(int rail, const ForceContact& contact, double reach_m) const {
  if (!law_can_switch() || !contact.contact.found) return false;
  if (!contact.hertz.ellipse) return true;
  const Eigen::Vector3d& q = contact.contact.point_on_rail_m;
  return std::abs(q.x() - cut_x_m(joint_, q.y(), rail)) <= reach_m;
}

std::optional<bool> ForceContactGeometry::elliptical_law_at(int rail, const WheelCylinder& wheel) const {
  const ForceContact c = find(rail, wheel, std::numeric_limits<double>::infinity());
  if (!c.contact.found) return std::nullopt;
  return c.hertz.ellipse.has_value();
}

double ForceContactGeometry::spanning_coupling_modulus_Pa() const {
  double e_star_Pa = railjoint::contact_modulus_Pa(material_);
  if (given_m_per_N2_3_) {
    const double G = *given_m_per_N2_3_;
    e_star_Pa = std::sqrt(9.0 / (16.0 * simulated_wheel_.radius_m * G * G * G));
  }
  return (joint_.gap_m > 0.0 ? 2.0 : 1.0) * e_star_Pa;
}

double patch_semi_length_m(const HertzAtContact& hertz, double penetration_m, double wheel_radius_m) {
  if (!(penetration_m > 0.0)) return 0.0;
  if (hertz.ellipse) {
    return hertz_patch(*hertz.ellipse, hertz_force_N(hertz.hertz_constant_m_per_N2_3, penetration_m)).semi_axis_x_m;
  }
  return rolling_semi_length_m(wheel_radius_m, penetration_m);
}

ForceContact force_start_contact(const ForceContactInputs& in, const Eigen::Vector3d& start_centre_m) {
  const ForceContactGeometry geometry(in);
  return geometry.find(0, geometry.wheel_at(start_centre_m), 1e-3);
}

namespace {

// The law a contact's Hertz constant comes from, as HertzAtPeak::law names it.
const char* law_name(const HertzAtContact& hertz) {
  return hertz.given ? "given" : hertz.ellipse ? "elliptical" : "empirical";
}

// A recorded contact's Hertz law; exactly on the cut: the narrow phase's
// edge (rail_support's x' = cut(y)).
HertzAtContact hertz_of_sample(const ForceContactGeometry& geometry, const JointParams& joint, const ContactSample& c) {
  const Eigen::Vector3d& q = c.point_on_rail_m;
  const bool at_edge = geometry.analytic() && std::abs(q.x() - cut_x_m(joint, q.y(), c.rail_index)) < 1e-12;
  return geometry.hertz_at(c.rail_index, q, at_edge);
}

HertzAtPeak hertz_at_sample(const ForceContactGeometry& geometry, const ForceContactInputs& in, const WheelSample& s,
                            double step_s) {
  const JointParams& joint = in.joint;
  HertzAtPeak out;
  const ContactSample* bearing = nullptr;
  for (const ContactSample& c : s.contacts) {
    if (!bearing || c.normal_impulse_Ns > bearing->normal_impulse_Ns) bearing = &c;
  }
  if (!bearing || !(bearing->normal_impulse_Ns > 0.0)) return out;
  const Eigen::Vector3d& p = bearing->point_on_rail_m;
  const auto hertz_of = [&](const ContactSample& c) { return hertz_of_sample(geometry, joint, c); };
  const HertzAtContact hertz = hertz_of(*bearing);
  out.law = law_name(hertz);
  out.hertz_constant_m_per_N2_3 = hertz.hertz_constant_m_per_N2_3;
  out.normal_force_N = bearing->normal_impulse_Ns / step_s;
  out.contact_y_m = p.y();
  out.rail = bearing->rail_index;
  const double radius_m = in.simulated_wheel.radius_m;
  for (const ContactSample& c : s.contacts) {
    if (c.rail_index == bearing->rail_index || !(c.normal_impulse_Ns > 0.0)) continue;
    out.other_rail_normal_force_N += c.normal_impulse_Ns / step_s;
    const double semi_m = std::max(patch_semi_length_m(hertz, -bearing->distance_m, radius_m),
                                   patch_semi_length_m(hertz_of(c), -c.distance_m, radius_m));
    if (semi_m > 0.0) out.spanning_apart = std::abs(c.point_on_rail_m.x() - p.x()) / semi_m;
  }
  // Each bearing rail end against its own cut's edge: rail 0 (incoming)
  // ends at cut_x_m(y, 0), its face before it; rail 1 (outgoing) starts at
  // cut_x_m(y, 1), its face after it (a gap apart where joint.gap > 0).
  for (const int r : {0, 1}) {
    for (const ContactSample& c : s.contacts) {
      if (c.rail_index != r || !(c.normal_impulse_Ns > 0.0)) continue;
      const Eigen::Vector3d& q = c.point_on_rail_m;
      const HertzAtContact h = hertz_of(c);
      RailEndAtPeak end;
      end.rail = r;
      end.normal_force_N = c.normal_impulse_Ns / step_s;
      end.law = law_name(h);
      const double edge_x_m = cut_x_m(joint, q.y(), r);
      const double d_m = r == 0 ? edge_x_m - q.x() : q.x() - edge_x_m;
      // On the edge to round-off: the analytic tops' narrow phase puts it
      // exactly on cut(y), the meshes' on their cut edge (the flat head).
      end.at_cut_edge = std::abs(d_m) < 1e-12;
      const double semi_m = patch_semi_length_m(h, -c.distance_m, radius_m);
      end.cut_edge_distance_semi_lengths =
          end.at_cut_edge ? 0.0
                          : semi_m > 0.0 ? d_m / semi_m : (d_m > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
      out.rail_ends.push_back(end);
    }
  }
  if (hertz.ellipse) out.patch = hertz_patch(*hertz.ellipse, out.normal_force_N);
  return out;
}

}  // namespace

ForceHertzPatches force_hertz_patches(const ForceContactInputs& in, const Trajectory& trajectory, double p1_time_s,
                                      std::optional<double> p2_time_s) {
  ForceHertzPatches out;
  const InertialSettings* inertial = in.settings.inertial();
  if (trajectory.samples.empty() || inertial == nullptr || inertial->elastic() == nullptr) return out;
  const ForceContactGeometry geometry(in);
  const double step_s = inertial->force_time_step_s;
  out.at_p0 = hertz_at_sample(geometry, in, trajectory.samples.front(), step_s);
  // The sample nearest a time (the first of two as near).
  const auto nearest_sample = [&](double time_s) {
    const WheelSample* nearest = &trajectory.samples.front();
    for (const WheelSample& s : trajectory.samples) {
      if (std::abs(s.time_s - time_s) < std::abs(nearest->time_s - time_s)) nearest = &s;
    }
    return nearest;
  };
  const WheelSample* at_p1 = nearest_sample(p1_time_s);
  out.at_p1 = hertz_at_sample(geometry, in, *at_p1, step_s);
  if (p2_time_s) out.at_p2 = hertz_at_sample(geometry, in, *nearest_sample(*p2_time_s), step_s);
  for (const WheelSample& s : trajectory.samples) {
    if (s.time_s > at_p1->time_s) break;
    std::array<double, 2> rail_N{0.0, 0.0};
    for (const ContactSample& c : s.contacts) {
      if (c.rail_index == 0 || c.rail_index == 1) rail_N[static_cast<std::size_t>(c.rail_index)] += c.normal_impulse_Ns;
    }
    const double total = rail_N[0] + rail_N[1];
    if (total > 0.0) out.spanning_share_to_p1 = std::max(out.spanning_share_to_p1, std::min(rail_N[0], rail_N[1]) / total);
    // The merged law's shares as the run took them (merged_spanning_contact
    // at the sample's penetrations), found by penetration rather than force, which
    // a share of 0 leaves at 0 while the rail end still bears.
    std::array<const ContactSample*, 2> touching{nullptr, nullptr};
    for (const ContactSample& c : s.contacts) {
      if ((c.rail_index == 0 || c.rail_index == 1) && c.distance_m < 0.0) touching[c.rail_index] = &c;
    }
    if (touching[0] && touching[1]) {
      std::array<HertzAtContact, 2> hertz;
      for (std::size_t k = 0; k < 2; ++k) hertz[k] = hertz_of_sample(geometry, in.joint, *touching[k]);
      const SpanningContact spanning = merged_spanning_contact(
          {-touching[0]->distance_m, -touching[1]->distance_m},
          [&](int i, double penetration_m) -> RailEndPatch {
            const auto k = static_cast<std::size_t>(i);
            const double x_m = touching[k]->point_on_rail_m.x();
            if (!(penetration_m > 0.0)) return {x_m, 0.0, 0.0};
            return {x_m, patch_semi_length_m(hertz[k], penetration_m, in.simulated_wheel.radius_m),
                    hertz_force_N(hertz[k].hertz_constant_m_per_N2_3, penetration_m)};
          },
          geometry.spanning_coupling_modulus_Pa());
      if (std::min(spanning.share[0], spanning.share[1]) < kMergedLawFlaggedShare) out.patches_overlapped_to_p1 = true;
    }
  }
  return out;
}

}  // namespace railjoint
