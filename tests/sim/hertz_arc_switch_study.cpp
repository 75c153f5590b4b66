// Study (label study): does a jump of Hertz's constant G within the
// elliptical law, where the touching point runs from one of 60E1's arcs to
// the next, or onto the wheel's rim, cost a force run its accuracy?
// (docs/not-done.md, "Force runs": that switch is not located in time, the
// face-to-cut-edge one is, elastic_crossing_run.cpp law_switch_within.)
//
// Seeded random force runs on 60E1 (cone or a measured-like curved tread,
// 70 mm wide, y_w across the head, cuts 20-90 deg, 20-80 m/s, lumped and
// discrete tracks). Each run at the default step is scanned sample by
// sample: a rail's bearing touching point that moves from one arc of the
// head (|y| below 10.228 mm: 300 mm, to 26.0265 mm: 80 mm, beyond: 13 mm,
// rail_head.h) to another, or between a face and the wheel's rim, while
// that rail bears in both samples is a crossing, and G on either side is
// the law's (ForceContactGeometry::hertz_at). A crossing onto or off the
// rail end's cut edge is the located switch and is not counted. P1 and P2
// at the default step are compared with Richardson's value from every step
// at 1e-6 and 0.5e-6 s, (4 P(h/2) - P(h)) / 3; the 4e-6, 2e-6 and 1e-6 s
// runs show the order (ratio of successive differences, 4 for second
// order). RAILJOINT_ARC_STUDY_COUNT sets the scenes per seed (default 40).
// Measured (docs/forces.md, "Where G jumps between 60E1's arcs"): no random
// run crosses, in the force runs or the envelope sweeps below; a run made
// to cross on a cosine dip stays second order and within 1e-5.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "models/contact_curvatures.h"
#include "models/dip_profile.h"
#include "models/hertz_ellipse.h"
#include "models/parameter_checks.h"
#include "models/profile_curve.h"
#include "models/rail_head.h"
#include "models/rail_top.h"
#include "models/wheel_rail_envelope.h"
#include "sim/crossing_model.h"
#include "sim/force_contact_geometry.h"
#include "sim/simulate_crossing.h"

namespace railjoint {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kArc1EndM = 0.020456 / 2.0;  // 300 mm arc to 80 mm (rail_head.h)
constexpr double kArc2EndM = 0.052053 / 2.0;  // 80 mm arc to 13 mm

struct Scene {
  JointParams joint;
  WheelParams wheel;
  bool discrete = false;
  std::string tread;
};

// Where a bearing contact touches: 0-2 the head's arcs, 3 the wheel's rim,
// 4 the cut edge.
int region_of(const JointParams& joint, const WheelParams& wheel, const ContactSample& c) {
  const Eigen::Vector3d& q = c.point_on_rail_m;
  if (std::abs(q.x() - cut_x_m(joint, q.y(), c.rail_index)) < 1e-12) return 4;
  const LateralSpan span = wheel_span_on_head(joint, wheel);
  if (std::abs(q.y() - span.lo_m) < 1e-9 || std::abs(q.y() - span.hi_m) < 1e-9) return 3;
  const double a = std::abs(q.y());
  return a <= kArc1EndM ? 0 : a <= kArc2EndM ? 1 : 2;
}

Scene random_scene(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Scene s;
  s.joint.rail_profile = RailProfile::en_60e1;
  s.joint.half_width_m = 0.036;
  s.joint.theta_rad = (20.0 + 70.0 * u(rng)) * kPi / 180.0;
  s.joint.beta_rad = 0.01 + 0.04 * u(rng);
  s.wheel.width_m = 0.07;
  s.wheel.lateral_m = -0.03 + 0.06 * u(rng);
  s.wheel.speed_m_per_s = 20.0 + 60.0 * u(rng);
  s.discrete = u(rng) < 0.5;
  const double conicity = 0.01 + 0.05 * u(rng);  // touches 300 mm arc below 0.034, the 80 mm one above
  if (u(rng) < 0.5) {
    s.wheel.conicity = conicity;
    char b[64];
    std::snprintf(b, sizeof b, "cone %.4f", conicity);
    s.tread = b;
  } else {
    // A measured-like tread: the cone bent by a 0.2-1 m crown, points every mm.
    const double crown_m = 0.2 + 0.8 * u(rng);
    std::ostringstream csv;
    csv.precision(10);
    for (int i = -36; i <= 36; ++i) {  // a little wider than the wheel, as a gauge measures it
      const double y = i * 1e-3;
      csv << y << ',' << 0.475 - conicity * y - y * y / (2.0 * crown_m) << '\n';
    }
    s.wheel.measured_tread =
        std::make_shared<const ProfileCurve>(read_profile_csv(csv.str(), "tread.csv", ProfileKind::wheel_tread));
    s.wheel.radius_m = s.wheel.measured_tread->value_m(0.0);
    char b[64];
    std::snprintf(b, sizeof b, "tread %.4f/%.2f", conicity, crown_m);
    s.tread = b;
  }
  return s;
}

SimSettings settings_of(const Scene& s, double step_s, bool every_step) {
  SimSettings settings;
  if (every_step) settings.refined_time_step_s = step_s;
  ElasticCrossingSettings& e = settings.make_inertial().contact.emplace<ElasticCrossingSettings>();
  if (s.discrete) {
    e.discrete_track.emplace();
  } else {
    e.track.emplace();
  }
  settings.make_inertial().force_time_step_s = step_s;
  return settings;
}

struct Run {
  ForceOutcome forces;
  SimulationResult result;
};

Run run_of(const Scene& s, double step_s, bool every_step) {
  const SimSettings settings = settings_of(s, step_s, every_step);
  JointParams joint = s.joint;
  joint.length_m = std::max(1.0, rail_length_needed_m(joint, s.wheel, settings));
  auto model = std::make_shared<const CrossingModel>(build_crossing_model(joint, s.wheel, settings));
  Run r;
  r.result = simulate_crossing(model);
  r.forces = *r.result.inertial()->forces;
  return r;
}

struct Crossing {
  int count = 0;
  std::string visited;      // regions the bearing contacts touched: 0-2 arcs, 3 rim, 4 cut edge
  double max_g_jump = 0.0;  // |G_after / G_before - 1|
  std::string kinds;
};

Crossing crossings_of(const Scene& s, const Run& run) {
  const SimSettings settings = settings_of(s, 4e-6, false);
  JointParams joint = s.joint;
  joint.length_m = std::max(1.0, rail_length_needed_m(joint, s.wheel, settings));
  const CrossingModel model = build_crossing_model(joint, s.wheel, settings);
  const ForceContactGeometry geometry(model.force_contact_inputs());
  Crossing out;
  std::array<int, 2> last_region{-1, -1};
  std::array<Eigen::Vector3d, 2> last_point;
  for (const WheelSample& sample : run.result.trajectory.samples) {
    std::array<bool, 2> bears{false, false};
    for (const ContactSample& c : sample.contacts) {
      if (!(c.normal_impulse_Ns > 0.0) || c.rail_index < 0 || c.rail_index > 1) continue;
      const std::size_t k = static_cast<std::size_t>(c.rail_index);
      bears[k] = true;
      const int region = region_of(joint, model.simulated_wheel, c);
      const int before = last_region[k];
      const std::string name = std::to_string(region);
      if (out.visited.find(name) == std::string::npos) out.visited += name;
      if (before >= 0 && before != region && before != 4 && region != 4) {
        const double g0 = geometry.hertz_at(c.rail_index, last_point[k], false).hertz_constant_m_per_N2_3;
        const double g1 = geometry.hertz_at(c.rail_index, c.point_on_rail_m, false).hertz_constant_m_per_N2_3;
        ++out.count;
        out.max_g_jump = std::max(out.max_g_jump, std::abs(g1 / g0 - 1.0));
        out.kinds += std::to_string(before) + ">" + std::to_string(region) + " ";
      }
      last_region[k] = region;
      last_point[k] = c.point_on_rail_m;
    }
    for (std::size_t k = 0; k < 2; ++k) {
      if (!bears[k]) last_region[k] = -1;
    }
  }
  return out;
}

struct Errors {
  std::vector<double> p1, p2;
};

void print_group(const char* name, Errors e) {
  const auto stats = [](std::vector<double> v) {
    if (v.empty()) return std::string("-");
    std::sort(v.begin(), v.end());
    char b[96];
    std::snprintf(b, sizeof b, "%.2e | %.2e | %.2e", v[v.size() / 2], v[static_cast<std::size_t>(0.9 * (v.size() - 1))],
                  v.back());
    return std::string(b);
  };
  std::printf("| %s | %zu | %s | %zu | %s |\n", name, e.p1.size(), stats(e.p1).c_str(), e.p2.size(),
              stats(e.p2).c_str());
}

void study(unsigned seed) {
  const char* env = std::getenv("RAILJOINT_ARC_STUDY_COUNT");
  const int count = env ? std::atoi(env) : 40;
  std::mt19937_64 rng(seed);
  Errors with, without;
  int skipped = 0;
  for (int i = 0; i < count; ++i) {
    const Scene s = random_scene(rng);
    try {
      const Run def = run_of(s, 4e-6, false);
      const Crossing crossing = crossings_of(s, def);
      std::array<Run, 4> every{run_of(s, 4e-6, true), run_of(s, 2e-6, true), run_of(s, 1e-6, true),
                               run_of(s, 0.5e-6, true)};
      const double r1 = (4.0 * every[3].forces.p1_N - every[2].forces.p1_N) / 3.0;
      const double e1 = def.forces.p1_N / r1 - 1.0;
      const double order1 = (every[0].forces.p1_N - every[1].forces.p1_N) / (every[1].forces.p1_N - every[2].forces.p1_N);
      Errors& group = crossing.count > 0 ? with : without;
      group.p1.push_back(std::abs(e1));
      double e2 = std::nan("");
      if (def.forces.p2 && every[2].forces.p2 && every[3].forces.p2) {
        const double r2 = (4.0 * every[3].forces.p2->force_N - every[2].forces.p2->force_N) / 3.0;
        e2 = def.forces.p2->force_N / r2 - 1.0;
        group.p2.push_back(std::abs(e2));
      }
      std::printf("seed %u #%d %s %s theta %.1f beta %.4f y_w %+.4f v %.1f: regions %s, crossings %d (%s) max |dG/G| %.3f; "
                  "P1 %.1f N err %+.2e (order ratio %.2f), P2 err %+.2e%s\n",
                  seed, i, s.discrete ? "discrete" : "lumped", s.tread.c_str(), s.joint.theta_rad * 180.0 / kPi,
                  s.joint.beta_rad, s.wheel.lateral_m, s.wheel.speed_m_per_s, crossing.visited.c_str(), crossing.count, crossing.kinds.c_str(),
                  crossing.max_g_jump, def.forces.p1_N, e1, order1, e2,
                  def.result.verdict.ok ? "" : (" SUSPECT: " + def.result.verdict.reason).c_str());
    } catch (const std::exception& error) {
      ++skipped;
      std::printf("seed %u #%d skipped: %s\n", seed, i, error.what());
    }
  }
  std::printf("| seed %u | runs | P1 err median | p90 | max | runs with P2 | P2 err median | p90 | max |\n", seed);
  print_group("with a crossing", with);
  print_group("without", without);
  // A crossing of an arc or the rim under load, where one happens, keeps
  // P1 within the project's 1e-5 (none happened in seeds 1 and 2).
  for (const double e : with.p1) EXPECT_LT(e, 1e-5);
  std::printf("skipped %d\n", skipped);
}

// The mechanism without a force run: the models' own envelope
// (rail_support) with the wheel's centre swept along the track in 0.1 mm
// steps, 0.3 m either side of the joint, on each rail, on a linear,
// quadratic or cosine dip: how far the touching point on a face moves
// across the head, and whether it changes arc or reaches the rim. Every
// lateral line of the head carries the same dip (rail_head.h) and the wheel
// only translates along x, so the point on a face sits where the tread's
// slope meets the head's divided by sqrt(1 + dip slope^2): fixed on a linear
// dip, a few um of travel on a curved one. And how much G jumps (the
// elliptical law, hertz_at's) if the point did cross the 300/80 mm boundary
// nearest it.
void envelope_sweep(unsigned seed, int count) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int scenes = 0, threw = 0;
  std::array<int, 3> face_changes{};  // per dip shape
  std::array<double, 3> max_travel_m{};  // per dip shape
  std::array<int, 5> visited{};
  std::vector<double> g_jumps;
  for (int i = 0; i < count; ++i) {
    Scene s = random_scene(rng);
    s.wheel.lateral_m = -0.036 + 0.072 * u(rng);  // across the whole head: the rim too
    const int dip = static_cast<int>(3.0 * u(rng)) % 3;
    s.joint.dip_shape = dip == 0 ? DipShape::linear : dip == 1 ? DipShape::quadratic : DipShape::cosine;
    try {
      check_parameters(s.joint, s.wheel);
    } catch (const std::exception&) {
      continue;
    }
    ++scenes;
    try {
      double touch_y_m = std::nan("");
      for (const int rail : {0, 1}) {
        int last = -1;
        double y_lo = 1.0, y_hi = -1.0;
        for (int j = -3000; j <= 3000; ++j) {
          const RailSupport support = rail_support(s.joint, s.wheel, rail, j * 1e-4);
          if (!std::isfinite(support.centre_z_m)) {
            last = -1;
            continue;
          }
          ContactSample c;
          c.point_on_rail_m = support.contact_m;
          c.rail_index = rail;
          const int region = support.at_cut_edge ? 4 : region_of(s.joint, s.wheel, c);
          ++visited[static_cast<std::size_t>(region)];
          if (region < 3) touch_y_m = c.point_on_rail_m.y();
          if (region != 4) {
            y_lo = std::min(y_lo, c.point_on_rail_m.y());
            y_hi = std::max(y_hi, c.point_on_rail_m.y());
            if (last >= 0 && last != 4 && last != region) {
              ++face_changes[static_cast<std::size_t>(dip)];
              std::printf("seed %u #%d rail %d: %d > %d at x %.4f m\n", seed, i, rail, last, region, j * 1e-4);
            }
          }
          last = region;
        }
        if (y_hi >= y_lo) max_travel_m[static_cast<std::size_t>(dip)] = std::max(max_travel_m[static_cast<std::size_t>(dip)], y_hi - y_lo);
      }
      if (std::isfinite(touch_y_m)) {
        // G either side of the 300/80 mm boundary on the contact's side, 0.2 m before the joint.
        const double edge_m = std::copysign(kArc1EndM, touch_y_m);
        const auto g_at = [&](double y_m) {
          const auto e = elliptical_hertz(relative_curvatures(contact_curvatures_at(s.joint, s.wheel, 0, -0.2, y_m)),
                                          HertzMaterial{});
          return e ? e->hertz_constant_m_per_N2_3 : std::nan("");
        };
        // 5 um either side: clear of the curvatures' 1 um difference window (contact_curvatures.h).
        const double off_m = std::copysign(5e-6, touch_y_m);
        // Only where the wheel stands over the boundary: elsewhere the
        // curvatures would read the tread outside its points.
        const LateralSpan span = wheel_span_on_head(s.joint, s.wheel);
        const bool over_boundary = span.lo_m <= edge_m - 5e-6 && edge_m + 5e-6 <= span.hi_m;
        const double jump = over_boundary ? g_at(edge_m + off_m) / g_at(edge_m - off_m) - 1.0 : std::nan("");
        if (std::isfinite(jump)) g_jumps.push_back(std::abs(jump));
      }
    } catch (const std::exception& error) {
      ++threw;
      std::printf("seed %u #%d %s y_w %.5f threw: %s\n", seed, i, s.tread.c_str(), s.wheel.lateral_m, error.what());
    }
  }
  std::sort(g_jumps.begin(), g_jumps.end());
  std::printf("seed %u: %d scenes (%d threw), positions on the 300/80/13 mm arcs, the rim, the cut edge: %d %d %d %d %d; "
              "changes of arc or rim on a face on a linear, quadratic, cosine dip %d %d %d; largest lateral travel of a face contact on a linear, quadratic, "
              "cosine dip %.2e %.2e %.2e m; |G jump| at the 300/80 mm boundary min %.3f median %.3f max %.3f\n",
              seed, scenes, threw, visited[0], visited[1], visited[2], visited[3], visited[4], face_changes[0], face_changes[1], face_changes[2],
              max_travel_m[0], max_travel_m[1], max_travel_m[2], g_jumps.empty() ? 0.0 : g_jumps.front(),
              g_jumps.empty() ? 0.0 : g_jumps[g_jumps.size() / 2], g_jumps.empty() ? 0.0 : g_jumps.back());
  // On the thesis's linear dip the point on a face cannot move (to the
  // root search's round-off, 6e-17 m measured): no arc or rim is ever crossed.
  EXPECT_EQ(face_changes[0], 0);
  EXPECT_LT(max_travel_m[0], 1e-12);
}

// The rare case made on purpose: a cone on a cosine dip whose conicity puts
// the touching point on the 300 mm arc on the level rail and carries it
// over the 300/80 mm boundary where the dip's slope reaches a fraction phi
// of its largest (the point sits where the head's slope over sqrt(1 + dip
// slope^2) meets the cone's, so kappa = f'(y_b) / sqrt(1 + (phi s_max)^2)).
// Not a random scene: how large the unlocated jump's error can get.
void cosine_dip_crossing(double phi, bool discrete) {
  Scene s;
  s.joint.rail_profile = RailProfile::en_60e1;
  s.joint.half_width_m = 0.036;
  s.joint.theta_rad = 60.0 * kPi / 180.0;
  s.joint.beta_rad = 0.04;
  s.joint.dip_shape = DipShape::cosine;
  s.wheel.width_m = 0.07;
  s.wheel.speed_m_per_s = 50.0;
  s.discrete = discrete;
  double s_max = 0.0;
  for (int j = -3000; j <= 0; ++j) s_max = std::max(s_max, std::abs(dip_slope(s.joint, 0, j * 1e-4)));
  const double head_slope = std::abs(head_top_slope(s.joint, -kArc1EndM));
  s.wheel.conicity = head_slope / std::sqrt(1.0 + phi * phi * s_max * s_max);
  s.tread = "cone";
  // Where the envelope's face contact crosses, on each rail.
  std::string where;
  for (const int rail : {0, 1}) {
    int last = -1;
    for (int j = -3000; j <= 3000; ++j) {
      const RailSupport support = rail_support(s.joint, s.wheel, rail, j * 1e-4);
      if (!std::isfinite(support.centre_z_m) || support.at_cut_edge) {
        last = -1;
        continue;
      }
      ContactSample c;
      c.point_on_rail_m = support.contact_m;
      c.rail_index = rail;
      const int region = region_of(s.joint, s.wheel, c);
      if (last >= 0 && region != last) where += "rail " + std::to_string(rail) + " at x " + std::to_string(j * 1e-4) + " m; ";
      last = region;
    }
  }
  const Run def = run_of(s, 4e-6, false);
  const Crossing crossing = crossings_of(s, def);
  std::array<Run, 3> every{run_of(s, 1e-6, true), run_of(s, 0.5e-6, true), run_of(s, 0.25e-6, true)};
  const double r1 = (4.0 * every[2].forces.p1_N - every[1].forces.p1_N) / 3.0;
  const double order = (every[0].forces.p1_N - every[1].forces.p1_N) / (every[1].forces.p1_N - every[2].forces.p1_N);
  std::printf("cosine dip, %s, phi %.2f, kappa %.6f: envelope crosses %s force run: crossings %d (%s) |dG/G| %.4f; "
              "P1 %.2f N at %.5f s, every step 1e-6/0.5e-6/0.25e-6 s %.2f %.2f %.2f (ratio %.2f), default %+.2e\n",
              discrete ? "discrete" : "lumped", phi, s.wheel.conicity, where.c_str(), crossing.count,
              crossing.kinds.c_str(), crossing.max_g_jump, def.forces.p1_N, def.forces.p1_time_s, every[0].forces.p1_N,
              every[1].forces.p1_N, every[2].forces.p1_N, order, def.forces.p1_N / r1 - 1.0);
  // The run does cross (the case is made to), and the curvatures' 1 um
  // difference window turns G's 17 % step into a ramp over the point's
  // slow drift: second order on the lumped track (measured 3.97-4.08; the
  // discrete track's P1 moves by 1e-6 of itself and its ratio is noise),
  // the default step within the project's 1e-5 (measured -4.2e-6 lumped,
  // 4e-7 discrete).
  EXPECT_GT(crossing.count, 0);
  if (!discrete) {
    EXPECT_GT(order, 3.0);
    EXPECT_LT(order, 5.0);
  }
  EXPECT_NEAR(def.forces.p1_N / r1, 1.0, 1e-5);
}

TEST(HertzArcSwitchStudy, CosineDipCrossing) {
  for (const bool discrete : {false, true}) {
    for (const double phi : {0.3, 0.7, 0.95}) cosine_dip_crossing(phi, discrete);
  }
}

TEST(HertzArcSwitchStudy, EnvelopeSeed1) { envelope_sweep(1, 300); }
TEST(HertzArcSwitchStudy, EnvelopeSeed2) { envelope_sweep(2, 300); }

TEST(HertzArcSwitchStudy, Seed1) { study(1); }
TEST(HertzArcSwitchStudy, Seed2) { study(2); }

}  // namespace
}  // namespace railjoint
